// The driving-crease space: OMPL's own contract (StateSpace::sanityChecks, every flag), states
// closed by ClosureSystem, and interpolation continued from a midpoint equal to interpolation
// straight there, on Miura sheets (1 DOF) and the waterbomb (several).
#include <limits>
#include <memory>

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/driving_chart.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/statespaces/driving_space.hpp"
#include "folded_state.hpp"
#include "spec_helpers.hpp"

namespace {

namespace ob = ompl::base;
namespace gen = foldkit::geometry::generators;
using namespace foldkit::geometry;
using foldkit::statespaces::AngleBounds;
using foldkit::statespaces::DrivingStateSpace;

struct Space {
  std::shared_ptr<const CreasePattern> pattern;
  std::shared_ptr<const ClosureSystem> system;
  FoldState goal;
  std::shared_ptr<DrivingStateSpace> space;
};

// The space of `spec` charted at the assignment's direction folded to `angle`; driving bounds
// on the goal's side of flat, a little off it, and anchors at the goal and at a fifth of it.
Space make_space(const PatternSpec& spec, double angle) {
  Space s;
  s.pattern = std::make_shared<const CreasePattern>(build_or_throw(spec));
  s.system = std::make_shared<const ClosureSystem>(*s.pattern);
  const CreasePattern& p = *s.pattern;
  s.goal = foldkit::test::folded_along_assignment(p, angle);
  const Mobility m = mobility(*s.system, s.goal);
  DrivingChart chart = choose_driving_chart(*s.system, s.goal, m.dof);
  const auto d = static_cast<Eigen::Index>(chart.driving.size());
  Eigen::VectorXd lo(d), hi(d);
  for (Eigen::Index i = 0; i < d; ++i) {
    const double a = s.goal.angles[chart.driving[static_cast<std::size_t>(i)]];
    lo[i] = a > 0 ? 0.3 * a : 1.3 * a;
    hi[i] = a > 0 ? 1.3 * a : 0.3 * a;
  }
  s.space = std::make_shared<DrivingStateSpace>(s.system, std::move(chart), AngleBounds::of(p, true), lo, hi);
  EXPECT_TRUE(s.space->add_anchor(s.goal));
  return s;
}

TEST(DrivingSpace, PassesOmplSanityChecks) {
  ompl::RNG::setSeed(5);
  const double zero = std::numeric_limits<double>::epsilon(), eps = std::numeric_limits<float>::epsilon();
  for (const auto& [name, spec, angle] : {std::make_tuple("miura 4x4", gen::miura(4, 4), 0.8),
                                          std::make_tuple("miura 8x8", gen::miura(8, 8), 0.6),
                                          std::make_tuple("waterbomb", gen::waterbomb(2, 2), 0.4)}) {
    Space s = make_space(spec, angle);
    s.space->setup();
    try {
      s.space->sanityChecks(zero, eps, ~0U);
    } catch (const ompl::Exception& e) {
      ADD_FAILURE() << name << ": " << e.what();
    }
  }
}

TEST(DrivingSpace, SampledAndInterpolatedStatesAreClosed) {
  ompl::RNG::setSeed(9);
  Space s = make_space(gen::miura(6, 6), 0.8);
  s.space->setup();
  auto sampler = s.space->allocDefaultStateSampler();
  ob::ScopedState<> a(s.space), b(s.space), mid(s.space), cont(s.space), straight(s.space);
  int closed = 0;
  for (int k = 0; k < 20; ++k) {
    sampler->sampleUniform(a.get());
    sampler->sampleUniform(b.get());
    if (!s.space->satisfiesBounds(a.get()) || !s.space->satisfiesBounds(b.get())) continue;
    ++closed;
    EXPECT_LE(s.system->max_error(s.space->to_fold_state(a.get())), 1e-12);
    s.space->interpolate(a.get(), b.get(), 0.5, mid.get());
    ASSERT_TRUE(mid->as<DrivingStateSpace::StateType>()->closed);
    EXPECT_LE(s.system->max_error(s.space->to_fold_state(mid.get())), 1e-12);
    // Continued from the midpoint, or straight from the start: the same closed state.
    s.space->interpolate(mid.get(), b.get(), 0.5, cont.get());
    s.space->interpolate(a.get(), b.get(), 0.75, straight.get());
    EXPECT_LT((s.space->to_fold_state(cont.get()).angles - s.space->to_fold_state(straight.get()).angles).cwiseAbs().maxCoeff(),
              1e-9);
    // Aliasing: the output may be the from-state.
    s.space->copyState(cont.get(), a.get());
    s.space->interpolate(cont.get(), b.get(), 0.5, cont.get());
    EXPECT_LT((s.space->to_fold_state(cont.get()).angles - s.space->to_fold_state(mid.get()).angles).cwiseAbs().maxCoeff(), 1e-9);
  }
  EXPECT_GE(closed, 18);
}

TEST(DrivingSpace, StatesOutOfBoundsOrWithoutRootsAreRejected) {
  Space s = make_space(gen::miura(4, 4), 0.8);
  ob::ScopedState<> st(s.space);
  ASSERT_TRUE(s.space->from_fold_state(s.goal, st.get()));
  EXPECT_TRUE(s.space->satisfiesBounds(st.get()));
  // Past fully folded: the continuation gets there (angles are periodic), the bounds refuse it.
  Eigen::VectorXd target = s.space->driving_of(st.get());
  target[0] = target[0] > 0 ? 3.3 : -3.3;
  s.space->solve(target, &s.goal, st.get());
  EXPECT_FALSE(s.space->satisfiesBounds(st.get()));
  // A state that does not close is neither an anchor nor a state of the space.
  FoldState open = s.goal;
  open.angles[0] += 0.1;
  EXPECT_FALSE(s.space->add_anchor(open));
  EXPECT_FALSE(s.space->from_fold_state(open, st.get()));
  EXPECT_FALSE(st->as<DrivingStateSpace::StateType>()->closed);
  EXPECT_FALSE(s.space->satisfiesBounds(st.get()));
  // With no anchor to continue from, a sampled state has no passives: not closed.
  auto bare = std::make_shared<DrivingStateSpace>(s.system, s.space->chart(), s.space->bounds(), s.space->driving_lower(),
                                                  s.space->driving_upper());
  ob::ScopedState<> b(bare);
  bare->allocDefaultStateSampler()->sampleUniform(b.get());
  EXPECT_FALSE(b->as<DrivingStateSpace::StateType>()->closed);
}

}  // namespace

namespace {

// The focus box (set_focus): with share 1 every closed uniform sample lies in it, with share 0
// the samples cover the rest of the driving box too; bad boxes and shares are refused.
TEST(DrivingSpace, FocusBoxTakesItsShareOfTheSamples) {
  ompl::RNG::setSeed(13);
  Space s = make_space(gen::waterbomb(2, 2), 0.4);
  s.space->setup();
  const Eigen::VectorXd lo = s.space->driving_lower(), hi = s.space->driving_upper();
  const Eigen::VectorXd mid = 0.5 * (lo + hi), quarter = 0.25 * (hi - lo);
  s.space->set_focus(mid - quarter, mid + quarter, 1.0);
  auto sampler = s.space->allocDefaultStateSampler();
  ob::ScopedState<> x(s.space);
  const auto inside = [&] {
    const Eigen::VectorXd d = s.space->driving_of(x.get());
    return ((d - mid).cwiseAbs().array() <= quarter.array() + 1e-12).all();
  };
  int closed = 0, in = 0;
  for (int k = 0; k < 100; ++k) {
    sampler->sampleUniform(x.get());
    if (!x->as<DrivingStateSpace::StateType>()->closed) continue;
    ++closed;
    in += inside();
  }
  EXPECT_GT(closed, 50);
  EXPECT_EQ(in, closed);
  s.space->set_focus(mid - quarter, mid + quarter, 0.0);
  int outside = 0;
  for (int k = 0; k < 100; ++k) {
    sampler->sampleUniform(x.get());
    outside += x->as<DrivingStateSpace::StateType>()->closed && !inside();
  }
  EXPECT_GT(outside, 0);
  EXPECT_THROW(s.space->set_focus(mid + quarter, mid - quarter, 0.5), std::invalid_argument);
  EXPECT_THROW(s.space->set_focus(mid, mid, 1.5), std::invalid_argument);
  EXPECT_THROW(s.space->set_focus(Eigen::VectorXd::Zero(lo.size() + 1), Eigen::VectorXd::Zero(lo.size() + 1), 0.5),
               std::invalid_argument);
}

}  // namespace
