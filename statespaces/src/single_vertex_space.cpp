#include "foldkit/statespaces/single_vertex_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ostream>

#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/util/RandomNumbers.h>

namespace foldkit::statespaces {

namespace ob = ompl::base;
using State = SingleVertexStateSpace::StateType;

namespace {

geometry::FoldState& scratch(std::size_t n) {
  thread_local geometry::FoldState s;
  if (static_cast<std::size_t>(s.angles.size()) != n) s.angles.resize(static_cast<Eigen::Index>(n));
  return s;
}

// Projection for the planners that grid the space (KPIECE1, …): the first two active angles.
class ActiveProjection : public ob::ProjectionEvaluator {
 public:
  explicit ActiveProjection(const SingleVertexStateSpace* space)
      : ob::ProjectionEvaluator(space), sv_(space), dims_(std::min<std::size_t>(2, space->chain().dimension())) {}
  unsigned int getDimension() const override { return static_cast<unsigned int>(dims_); }
  void defaultCellSizes() override { cellSizes_.assign(dims_, 0.2); }
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> projection) const override {
    const auto* s = state->as<State>();
    for (std::size_t i = 0; i < dims_; ++i)
      projection[static_cast<Eigen::Index>(i)] = s->angles[sv_->chain().active_joints()[i]];
  }

 private:
  const SingleVertexStateSpace* sv_;
  std::size_t dims_;
};

}  // namespace

SingleVertexStateSpace::SingleVertexStateSpace(std::shared_ptr<const SingleVertexChain> chain, AngleBounds bounds)
    : ClosedAnglesSpace("SingleVertex", chain->pattern().joints().size(), std::move(bounds)), chain_(std::move(chain)) {
  type_ = ob::STATE_SPACE_TYPE_COUNT + 71;
}

void SingleVertexStateSpace::write_extra(const ClosedAnglesState& state, char* out) const {
  std::memcpy(out, &static_cast<const StateType&>(state).branch, sizeof(int));
}

void SingleVertexStateSpace::read_extra(const char* in, ClosedAnglesState& state) const {
  std::memcpy(&static_cast<StateType&>(state).branch, in, sizeof(int));
}

void SingleVertexStateSpace::copy_extra(const ClosedAnglesState& from, ClosedAnglesState& to) const {
  static_cast<StateType&>(to).branch = static_cast<const StateType&>(from).branch;
}

void SingleVertexStateSpace::complete(StateType* s, int branch) const {
  geometry::FoldState& f = scratch(n_);
  for (std::size_t j = 0; j < n_; ++j) f.angles[static_cast<Eigen::Index>(j)] = s->angles[j];
  s->branch = branch >= 0 ? 1 : -1;
  s->closed = chain_->solve(f, s->branch);
  if (s->closed) {
    for (int j : chain_->passive_joints()) s->angles[j] = f.angles[j];
  } else {
    set_open(s, s->branch);
  }
}

// A state without a root gets passives that depend on its branch alone (middle one at ±π, far
// from where the branches meet; the others 0), not on where the computation started: then
// interpolating on from such a state gives what interpolating straight there gives
// (StateSpace::sanityChecks, "continued interpolation"). The validity checker rejects it anyway.
void SingleVertexStateSpace::set_open(StateType* s, int branch) const {
  s->branch = branch >= 0 ? 1 : -1;
  s->closed = false;
  for (int j : chain_->passive_joints()) s->angles[j] = 0.0;
  s->angles[chain_->passive_joints()[1]] = s->branch * M_PI;
}

bool SingleVertexStateSpace::from_fold_state(const geometry::FoldState& angles, ob::State* state, double tolerance) const {
  if (static_cast<std::size_t>(angles.angles.size()) != n_) return false;
  auto* s = state->as<StateType>();
  for (std::size_t j = 0; j < n_; ++j) s->angles[j] = angles.angles[static_cast<Eigen::Index>(j)];
  complete(s, chain_->branch_of(angles));
  if (!s->closed) return false;
  for (int j : chain_->passive_joints())
    if (std::abs(s->angles[j] - angles.angles[j]) > tolerance) return false;
  return true;
}

geometry::FoldState SingleVertexStateSpace::to_fold_state(const ob::State* state) const {
  const auto* s = state->as<StateType>();
  return geometry::FoldState{Eigen::Map<const Eigen::VectorXd>(s->angles, static_cast<Eigen::Index>(n_))};
}

unsigned int SingleVertexStateSpace::getDimension() const { return static_cast<unsigned int>(chain_->dimension()); }

double SingleVertexStateSpace::getMaximumExtent() const {
  double sum = 0.0;
  for (int j : chain_->active_joints()) sum += std::pow(bounds_.upper[j] - bounds_.lower[j], 2);
  const int m = chain_->passive_joints()[1];
  return std::sqrt(sum + std::pow(bounds_.upper[m] - bounds_.lower[m], 2));
}

double SingleVertexStateSpace::getMeasure() const {
  double m = 1.0;
  for (int j : chain_->active_joints()) m *= bounds_.upper[j] - bounds_.lower[j];
  return 2.0 * m;
}

void SingleVertexStateSpace::enforceBounds(ob::State* state) const {
  auto* s = state->as<StateType>();
  for (int j : chain_->active_joints()) s->angles[j] = std::clamp(s->angles[j], bounds_.lower[j], bounds_.upper[j]);
  complete(s, s->branch);
}

double SingleVertexStateSpace::distance(const ob::State* state1, const ob::State* state2) const {
  // Euclidean over the active angles and the middle passive one: coordinates that determine the
  // state (the middle passive angle carries the branch) and that never wrap, so that the
  // distance to a target shrinks to zero along the interpolation (a distance over all angles
  // would stall where an outer passive angle wraps round ±π, and planners would creep forever).
  const auto* a = state1->as<StateType>();
  const auto* b = state2->as<StateType>();
  double sum = 0.0;
  for (int j : chain_->active_joints()) sum += (a->angles[j] - b->angles[j]) * (a->angles[j] - b->angles[j]);
  const int m = chain_->passive_joints()[1];
  sum += (a->angles[m] - b->angles[m]) * (a->angles[m] - b->angles[m]);
  return std::sqrt(sum);
}

bool SingleVertexStateSpace::equalStates(const ob::State* state1, const ob::State* state2) const {
  const auto* a = state1->as<StateType>();
  const auto* b = state2->as<StateType>();
  if (a->closed != b->closed) return false;
  for (std::size_t j = 0; j < n_; ++j)
    if (std::abs(a->angles[j] - b->angles[j]) > 1e-12) return false;
  return true;
}

void SingleVertexStateSpace::interpolate(const ob::State* from, const ob::State* to, double t, ob::State* state) const {
  const auto* f = from->as<StateType>();
  const auto* g = to->as<StateType>();
  if (t <= 0.0) return copyState(state, from);
  if (t >= 1.0) return copyState(state, to);
  auto* s = state->as<StateType>();
  // Nothing of `from` or `to` is read after its own angle is written, so `state` may be either
  // (OMPL's planners pass `from` again). The passives are solved even from a state that is not
  // closed (see set_open).
  for (int j : chain_->active_joints()) s->angles[j] = f->angles[j] + t * (g->angles[j] - f->angles[j]);
  int branch = f->branch;
  if (f->branch != g->branch) {
    const int middle = chain_->passive_joints()[1];
    if (std::abs(f->angles[middle]) < meeting_tolerance_) {
      branch = g->branch;  // the from-state sits where both roots meet: take the to-state's
    } else if (!(std::abs(g->angles[middle]) < meeting_tolerance_)) {
      // Two branches that do not meet on this segment: no continuous motion joins them along
      // it. Saying so here (rather than following the from-branch, which never gets closer to
      // the to-state) keeps planners from creeping towards the other branch forever.
      set_open(s, f->branch);
      return;
    }
  }
  complete(s, branch);
}

ob::StateSamplerPtr SingleVertexStateSpace::allocDefaultStateSampler() const {
  return std::make_shared<SingleVertexSampler>(this);
}

void SingleVertexStateSpace::printState(const ob::State* state, std::ostream& out) const {
  const auto* s = state->as<StateType>();
  out << "SingleVertexState [";
  for (std::size_t j = 0; j < n_; ++j) out << (j ? " " : "") << s->angles[j];
  out << "] branch " << s->branch << (s->closed ? "" : " (no root)") << '\n';
}

void SingleVertexStateSpace::registerProjections() { registerDefaultProjection(std::make_shared<ActiveProjection>(this)); }

SingleVertexSampler::SingleVertexSampler(const SingleVertexStateSpace* space) : ob::StateSampler(space), sv_(space) {}

bool SingleVertexSampler::accept(State* s, int branch) {
  sv_->complete(s, branch);
  return sv_->satisfiesBounds(s);
}

bool SingleVertexSampler::meet(State* s) {
  // Moves one active angle until the middle passive crease is flat (cos b = 1): on the boundary
  // of the active angles that have a root, where both branches meet.
  const SingleVertexChain& chain = sv_->chain();
  const AngleBounds& b = sv_->bounds();
  const int j = chain.active_joints()[static_cast<std::size_t>(
      rng_.uniformInt(0, static_cast<int>(chain.active_joints().size()) - 1))];
  geometry::FoldState& f = scratch(sv_->joints());
  for (std::size_t k = 0; k < sv_->joints(); ++k) f.angles[static_cast<Eigen::Index>(k)] = s->angles[k];
  auto g = [&](double x) {
    f.angles[j] = x;
    return chain.cos_middle(f) - 1.0;
  };
  constexpr int kGrid = 48;
  const double lo = b.lower[j], hi = b.upper[j];
  const int offset = rng_.uniformInt(0, kGrid - 1);  // start the scan at a random place
  double x0 = lo + (hi - lo) * offset / kGrid, g0 = g(x0);
  for (int i = 1; i <= kGrid; ++i) {
    const double x1 = lo + (hi - lo) * ((offset + i) % (kGrid + 1)) / kGrid, g1 = g(x1);
    if ((g0 < 0.0) != (g1 < 0.0) && std::abs(x1 - x0) < (hi - lo) / 2) {
      double a = x0, c = x1, ga = g0;
      for (int it = 0; it < 60; ++it) {
        const double m = 0.5 * (a + c), gm = g(m);
        if ((gm < 0.0) == (ga < 0.0)) {
          a = m;
          ga = gm;
        } else {
          c = m;
        }
      }
      s->angles[j] = g(a) <= 0.0 ? a : c;  // the side with a root
      sv_->complete(s, 1);
      return sv_->satisfiesBounds(s) && std::abs(s->angles[chain.passive_joints()[1]]) < sv_->meeting_tolerance();
    }
    x0 = x1;
    g0 = g1;
  }
  return false;
}

void SingleVertexSampler::sampleUniform(ob::State* state) {
  auto* s = state->as<State>();
  const AngleBounds& b = sv_->bounds();
  for (int tries = 0; tries < kMaxTries; ++tries) {
    for (int j : sv_->chain().active_joints()) s->angles[j] = rng_.uniformReal(b.lower[j], b.upper[j]);
    if (rng_.uniform01() < meeting_fraction_) {
      if (meet(s)) return;
      continue;
    }
    if (accept(s, rng_.uniformBool() ? 1 : -1)) return;
  }
  s->closed = false;
}

void SingleVertexSampler::sampleUniformNear(ob::State* state, const ob::State* near, double distance) {
  auto* s = state->as<State>();
  const auto* c = near->as<State>();
  const AngleBounds& b = sv_->bounds();
  for (int tries = 0; tries < kMaxTries; ++tries) {
    for (int j : sv_->chain().active_joints())
      s->angles[j] = std::clamp(rng_.uniformReal(c->angles[j] - distance, c->angles[j] + distance), b.lower[j], b.upper[j]);
    const bool meet = std::abs(c->angles[sv_->chain().passive_joints()[1]]) < sv_->meeting_tolerance();
    if (accept(s, meet ? (rng_.uniformBool() ? 1 : -1) : c->branch)) return;
  }
  sv_->copyState(state, near);
}

void SingleVertexSampler::sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) {
  auto* s = state->as<State>();
  const auto* c = mean->as<State>();
  const AngleBounds& b = sv_->bounds();
  for (int tries = 0; tries < kMaxTries; ++tries) {
    for (int j : sv_->chain().active_joints())
      s->angles[j] = std::clamp(rng_.gaussian(c->angles[j], stdDev), b.lower[j], b.upper[j]);
    if (accept(s, c->branch)) return;
  }
  sv_->copyState(state, mean);
}

StateReader single_vertex_reader(std::shared_ptr<const SingleVertexStateSpace> space) {
  return closed_angles_reader(std::move(space));
}

}  // namespace foldkit::statespaces
