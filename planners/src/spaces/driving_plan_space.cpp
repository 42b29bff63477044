// The driving-crease space in a plan: DOF-many driving creases chosen at the goal, the rest by
// closure; from a folded start, the way through flat when sampling finds nothing.
#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include "foldkit/geometry/driving_chart.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/statespaces/driving_space.hpp"
#include "space_common.hpp"

namespace foldkit::planners::spaces {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

// The focus box: the box of the plan's start and goal, widened by this (radians), receives this
// share of the uniform samples (docs/PLANNING.md: measured at 0.5 and 0.9).
constexpr double kFocusMargin = 0.2, kFocusShare = 0.9;

// Why the driving space cannot reach `goal` from `from`, or "" when it may; `reaches` says whether
// the straight continuation in the chart from `from` to the goal's driving angles ends at the goal
// (then a direct path exists, collisions aside). With one degree of freedom the closed states near
// `from` are one curve, a graph over the driving crease while the chart stays regular, and every
// motion of the space is a continuation along it. Following it to the goal's driving angle either
// reaches the goal, stops at a singular state (then nothing is known: the planner searches as
// usual), or reaches another closed state: the goal is on another branch (another mode of
// folding), and the planner would only run out its time.
std::string other_branch(const geometry::ClosureSystem& system, const geometry::DrivingChart& chart, const FoldState& from,
                         const FoldState& goal, bool& reaches) {
  geometry::PassiveSolver solver(system, chart);
  FoldState reached;
  reaches = false;
  if (!solver.follow(from, solver.driving_of(goal), reached).ok()) return {};
  Eigen::Index worst = 0;
  const double gap = (reached.angles - goal.angles).cwiseAbs().maxCoeff(&worst);
  reaches = gap <= 1e-6;
  if (reaches || chart.driving.size() != 1) return {};
  const auto& joints = system.pattern().joints();
  const int driving = joints[static_cast<std::size_t>(chart.driving[0])].id, id = joints[static_cast<std::size_t>(worst)].id;
  return "the goal is on another branch than the start: the start's one-DOF motion reaches the goal's driving angle "
         "(crease " + std::to_string(driving) + ") with crease " + std::to_string(id) + " at " +
         std::to_string(reached.angles[worst] * 180.0 / M_PI) + " deg instead of the goal's " +
         std::to_string(goal.angles[worst] * 180.0 / M_PI) + " deg; the branches meet only at a singular state "
         "(flat, for a Miura sheet), which no motion of the driving space passes";
}

class DrivingPlanSpace : public PlanSpace {
 public:
  using PlanSpace::PlanSpace;

  // The larger of the ranks at start and goal: a start below it (flat) is left first.
  Eigen::Index lead_in_rank(const PlanSetup& setup, const PlanOptions&, const statespaces::AngleBounds&) override {
    goal_rank_ = geometry::mobility(*setup.system, setup.goal).rank;
    const Eigen::Index start_rank = geometry::mobility(*setup.system, setup.start).rank;
    rank_ = std::max(goal_rank_, start_rank);
    return start_rank < rank_ ? rank_ : 0;
  }

  // The chart is chosen at the goal (or, when the goal is singular, at the end of the way out of
  // the start).
  void build(PlanSetup& setup, const PlanOptions& options, const statespaces::AngleBounds& bounds) override {
    const geometry::ClosureSystem& system = *setup.system;
    const FoldState& from = setup.prefix.back();
    const FoldState& chart_state = goal_rank_ >= rank_ ? setup.goal : from;
    const int dof = static_cast<int>(system.cols() - rank_);
    if (dof == 0) throw std::invalid_argument("plan: the pattern is rigid (0 degrees of freedom): nothing can move");
    geometry::DrivingChart chart = geometry::choose_driving_chart(system, chart_state, dof, std::max(1u, options.seed));
    // Sampling bounds of each driving crease: its angle bounds, narrowed to the side of flat that
    // both ends of the plan are on (flat is singular; the goal's signs pick the branch).
    // Most uniform samples go to the focus box, that of start and goal widened by kFocusMargin: a
    // box of many driving creases is mostly out of reach, and RRTConnect's extensions towards such
    // samples each cost a continuation (waterbomb 4x4, 13 DOF: 20x faster). The other samples
    // keep the whole box covered.
    Eigen::VectorXd lo(dof), hi(dof), focus_lo(dof), focus_hi(dof);
    for (int i = 0; i < dof; ++i) {
      const int j = chart.driving[static_cast<std::size_t>(i)];
      lo[i] = bounds.lower[j];
      hi[i] = bounds.upper[j];
      if (setup.goal.angles[j] > 0.0 && from.angles[j] > 0.0) lo[i] = std::max(lo[i], 0.0);
      if (setup.goal.angles[j] < 0.0 && from.angles[j] < 0.0) hi[i] = std::min(hi[i], 0.0);
      focus_lo[i] = std::min(setup.goal.angles[j], from.angles[j]) - kFocusMargin;
      focus_hi[i] = std::max(setup.goal.angles[j], from.angles[j]) + kFocusMargin;
    }
    setup.other_branch = other_branch(system, chart, from, setup.goal, setup.continues_to_goal);
    space_ = std::make_shared<statespaces::DrivingStateSpace>(setup.system, std::move(chart), bounds, lo, hi);
    space_->set_focus(focus_lo, focus_hi, kFocusShare);
    if (!space_->add_anchor(from))
      throw PlanInputError(PlanInputError::End::Start, "plan: the start is a singular state of the driving space (try --space projected)");
    if (!space_->add_anchor(setup.goal))
      throw PlanInputError(PlanInputError::End::Goal, "plan: the goal is a singular state of the driving space (try --space projected)");
    setup.space = space_;
    setup.reader = statespaces::driving_reader(space_);
    use_space(setup, options);
  }

  bool write(const FoldState& state, ob::State* out) const override { return space_->from_fold_state(state, out); }

  // Each segment is one continuation whose predictor moves no crease more than 0.9 × `step`: its
  // points are the states, at most `step` apart as a rule (densify() bridges the rare wider gap).
  // Bisecting each segment's interval instead, every midpoint followed from the interval's start,
  // repeated the continuation about once per level (a Miura 40×40 plan: 0.7 s, a planner time).
  // Where the continuation does not end at the segment's end (another branch, a stall), the
  // interval is halved along the space's own motion as before.
  std::vector<FoldState> path_states(const PlanSetup& setup, og::PathGeometric path, double step, const StateSink& sink,
                                     const Stop& stop) const override {
    geometry::PassiveSolverOptions fine;
    // Never coarser than the space's own solver (a large waypoint_step would widen its jump test).
    fine.max_step = std::min(0.9 * step, geometry::PassiveSolverOptions{}.max_step);
    fine.stop = stop;
    bool gave_up = false;
    geometry::PassiveSolver solver(*setup.system, space_->chart(), fine);
    const Motion motion = [&](const ob::State* a, const ob::State* b, double s, ob::State* tmp, const Emit& out) {
      FoldState fa, fb, reached;
      if (gave_up || !setup.reader(a, fa) || !setup.reader(b, fb)) return;
      std::vector<FoldState> points;
      if (solver.follow(fa, solver.driving_of(fb), reached, &points).ok() &&
          (reached.angles - fb.angles).cwiseAbs().maxCoeff() <= 1e-6) {
        // points: fa (closed again where it was not to the tolerance), …, reached ≈ fb.
        for (std::size_t i = 1; i + 1 < points.size(); ++i) out(std::move(points[i]));
        return;
      }
      // The halving borrows the space's shared solvers, whose memory a planner on another thread
      // may be using: a caller with a stop (beside a planner) gets no states instead.
      if (stop) {
        gave_up = true;
        return;
      }
      bisect(setup, a, b, fa, fb, s, tmp, out);
    };
    // After giving up, nothing more reaches the sink (the caller would densify across the gap).
    const StateSink guarded = [&](const FoldState& f) {
      if (!gave_up && sink) sink(f);
    };
    std::vector<FoldState> states = states_along(setup, path, step, motion, guarded);
    if (gave_up) states.clear();
    return states;
  }

  Fallback fallback() const override { return Fallback::ViaFlat; }
  // Every motion of the space is the continuation over a straight segment of driving angles; a
  // path of collinear, ordered segments is the continuation over their union.
  bool straight_paths() const override { return true; }

 private:
  // The states strictly between fa (at a) and fb (at b) along the space's motion: the interval is
  // halved until neighbours differ by at most `step` in every crease (or after 16 halvings;
  // densify() then judges the gap). Near a fold of the chart the passives move much faster than
  // the driving angles, and OMPL's path.interpolate(), spaced by the driving distance, left gaps
  // there that densify()'s straight projections could not bridge (a Resch plan was refused as a
  // jump).
  void bisect(const PlanSetup& setup, const ob::State* a, const ob::State* b, const FoldState& fa, const FoldState& fb, double step,
              ob::State* tmp, const Emit& out) const {
    const std::function<void(double, const FoldState&, double, const FoldState&, int)> fill =
        [&](double ta, const FoldState& sa, double tb, const FoldState& sb, int depth) {
          if (depth == 0 || (sb.angles - sa.angles).cwiseAbs().maxCoeff() <= step) return;
          const double tm = 0.5 * (ta + tb);
          space_->interpolate(a, b, tm, tmp);
          FoldState sm;
          if (!setup.reader(tmp, sm)) return;
          fill(ta, sa, tm, sm, depth - 1);
          out(sm);
          fill(tm, sm, tb, sb, depth - 1);
        };
    fill(0.0, fa, 1.0, fb, 16);
  }

  Eigen::Index goal_rank_ = 0, rank_ = 0;
  std::shared_ptr<statespaces::DrivingStateSpace> space_;
};

}  // namespace

std::shared_ptr<PlanSpace> driving_plan_space(const char* name) { return std::make_shared<DrivingPlanSpace>(name); }

}  // namespace foldkit::planners::spaces
