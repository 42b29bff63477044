#include "foldkit/simulation/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "actuation.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/simulation/corner_motion.hpp"

namespace foldkit::simulation {

const char* to_string(Actuation model) {
  switch (model) {
    case Actuation::Motor: return "motor";
    case Actuation::Spring: return "spring";
    case Actuation::Synchronised: return "sync";
  }
  return "?";
}

Actuation parse_actuation(const std::string& name) {
  if (name == "motor") return Actuation::Motor;
  if (name == "spring") return Actuation::Spring;
  if (name == "sync") return Actuation::Synchronised;
  throw std::invalid_argument("unknown actuation model '" + name + "' (motor, spring or sync)");
}

double smallest_feature(const geometry::CreasePattern& pattern) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& actor : pattern.actors())
    for (const auto& t : actor.triangles) {
      const geometry::Vec2& a = pattern.vertices()[t.v[0]];
      const geometry::Vec2& b = pattern.vertices()[t.v[1]];
      const geometry::Vec2& c = pattern.vertices()[t.v[2]];
      const double area2 = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      smallest = std::min(smallest, area2 / longest);
    }
  return smallest;
}

namespace {

void check_options(const SimulationOptions& o) {
  auto positive = [](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be positive and finite");
  };
  positive(o.time_step, "time step");
  positive(o.closure_tolerance, "closure tolerance");
  positive(o.max_sweep, "max sweep");
  positive(o.max_step_angle, "max step angle");
  positive(o.settle_angle, "settle angle");
  positive(o.settle_speed, "settle speed");
  positive(o.max_event_time, "max event time");
  if (o.max_steps == 0) throw std::invalid_argument("max steps must be positive");
}

std::string seconds(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t << " s";
  return s.str();
}

class Replay {
 public:
  Replay(const geometry::CreasePattern& pattern, const SimulationOptions& options)
      : pattern_(pattern), options_(options), tree_(geometry::make_tree(pattern)), closure_(pattern), motion_(pattern) {
    // Slivers (sector angles of 1e-6 rad) would ask for millions of checks per step; below a
    // thousandth of the sheet's size the bound stops shrinking (docs/SIMULATION.md).
    sweep_ = options.max_sweep * std::max(smallest_feature(pattern), 1e-3 * pattern.diagonal());
    if (options.collisions) {
      CollisionOptions c = options.collision;
      c.margin = sweep_;
      world_.emplace(pattern, c);
    }
    report_.model = options.model;
    report_.time_step = options.time_step;
    report_.closure_tolerance = options.closure_tolerance;
  }

  SimulationReport run(const geometry::FoldSequence& sequence) {
    begin(sequence.events.empty() ? 0 : sequence.events.front().number);
    for (const auto& event : sequence.events) replay(event, sequence.events.size());
    return end();
  }

  // The flat start state, checked as event `first_number`'s (the first event's number, 0 for none).
  void begin(int first_number) {
    state_ = geometry::FoldState::flat(pattern_);
    poses_ = geometry::facet_poses(pattern_, tree_, state_);
    current_ = &start_;
    check(state_, poses_, 0.0, first_number);
    frame(state_, -1);
  }

  // The next event, from the state the last one left; `known`: how many events the progress
  // reports as the whole.
  void replay(const geometry::FoldEvent& event, std::size_t known) {
    report_.events.push_back({event.number, time_, time_, 0.0, true});
    current_ = &report_.events.back();
    detail::EventMotion motion(pattern_, event, state_, options_);
    guard_length(event, motion);
    const std::size_t steps_before = report_.steps;
    while (!motion.done()) {
      const geometry::FoldState before = state_;
      const double h = motion.advance(state_, options_.time_step);
      ++report_.steps;
      sweep(before, state_, time_, h, event.number);
      time_ += h;
      if (options_.record_frames) frame(state_, event.number);
      if (options_.progress)
        options_.progress({static_cast<double>(report_.events.size() - 1), static_cast<double>(known), "events", last_error_});
    }
    current_->end = time_;
    if (!motion.reached()) {
      current_->reached = false;
      problem(geometry::StatusCode::LimitReached, "event " + std::to_string(event.number) + ": " + motion.failure());
    }
    if (!options_.record_frames || report_.steps == steps_before) frame(state_, event.number);
  }

  SimulationReport end() {
    report_.duration = time_;
    report_.final_state = state_;
    if (report_.problems.empty()) report_.status = {geometry::StatusCode::Success, "valid"};
    return std::move(report_);
  }

 private:
  void guard_length(const geometry::FoldEvent& event, const detail::EventMotion& motion) const {
    for (const auto& fold : event.folds)
      if (options_.model != Actuation::Spring && (!(fold.speed > 0.0) || !std::isfinite(fold.speed)))
        throw SequenceError(fold.line, "joint " + std::to_string(fold.joint_id) + ": speed (<Velocity>) must be positive and finite");
    const double steps = motion.planned_duration() / options_.time_step;
    if (steps > static_cast<double>(options_.max_steps)) {
      const int line = event.folds.empty() ? 0 : event.folds.front().line;
      throw SequenceError(line, "event " + std::to_string(event.number) + " would take " + seconds(motion.planned_duration()) +
                                    ", more than " + std::to_string(options_.max_steps) + " steps of " +
                                    seconds(options_.time_step) + "; raise the velocities or the time step");
    }
  }

  // Checks the states between `before` and `after` (a step of h seconds from t), in sub-steps
  // short enough that no facet corner moves more than the sweep bound (up to a rigid motion of
  // the whole sheet: CornerMotion) and no joint more than max_step_angle between two checks.
  void sweep(const geometry::FoldState& before, const geometry::FoldState& after, double t, double h, int event) {
    std::vector<Eigen::Isometry3d> end = geometry::facet_poses(pattern_, tree_, after);
    const double moved = motion_.largest(poses_, end);
    const double turned = (after.angles - before.angles).cwiseAbs().maxCoeff();
    const double parts = std::max({1.0, std::ceil(moved / sweep_), std::ceil(turned / options_.max_step_angle)});
    const int n = static_cast<int>(std::min(parts, 1e6));
    for (int i = 1; i < n; ++i) {
      const double f = static_cast<double>(i) / n;
      geometry::FoldState s{before.angles + (after.angles - before.angles) * f};
      check(s, geometry::facet_poses(pattern_, tree_, s), t + h * f, event);
    }
    poses_ = std::move(end);
    check(after, poses_, t + h, event);
  }

  void check(const geometry::FoldState& state, const std::vector<Eigen::Isometry3d>& poses, double t, int event) {
    ++report_.checks;
    const double error = closure_.max_error(state);
    last_error_ = error;
    current_->max_closure_error = std::max(current_->max_closure_error, error);
    report_.max_closure_error = std::max(report_.max_closure_error, error);
    if (error > options_.closure_tolerance && !closure_reported_) {
      closure_reported_ = true;
      std::ostringstream s;
      s << "event " << event << ": closure error " << error << " rad at t = " << seconds(t) << " exceeds the tolerance "
        << options_.closure_tolerance << " rad";
      problem(geometry::StatusCode::ClosureViolated, s.str());
    }
    if (!world_) return;
    const std::vector<Crossing> crossings = world_->check(poses, state);
    std::optional<geometry::ProjectionResult> closed;
    std::vector<Eigen::Isometry3d> closed_poses;
    for (const Crossing& c : crossings) {
      const std::array<int, 2> ids{pattern_.actors()[c.actors[0]].id, pattern_.actors()[c.actors[1]].id};
      CollisionEvent found{t, event, ids, c.point, c.kind, c.depth, error, -1.0, state};
      // A state between two events closes only to the interpolation's error; a crossing that the
      // nearest closed state does not have is that error's, not the sheet's.
      if (c.kind == CrossingKind::Mesh && error > kClosedEnough) {
        if (!closed) {
          closed = geometry::project(closure_, state);
          closed_poses = geometry::facet_poses(pattern_, tree_, closed->state);
        }
        if (closed->status) {
          const auto again = world_->mesh_crossing(c.actors[0], c.actors[1], closed_poses, closed->state);
          found.closed_depth = again ? again->depth : 0.0;
        }
      }
      if (found.closed_depth == 0.0) {
        if (!numerical_.insert({event, c.actors[0], c.actors[1]}).second) continue;
        ++report_.numerical_count;
        if (report_.numerical.size() < options_.max_collisions) report_.numerical.push_back(std::move(found));
        continue;
      }
      if (!crossed_.insert({event, c.actors[0], c.actors[1]}).second) continue;
      ++report_.collision_count;
      if (report_.collision_count == 1) {
        std::ostringstream s;
        s << "event " << event << ": actors " << ids[0] << " and " << ids[1] << " collide at t = " << seconds(t) << " ("
          << to_string(c.kind);
        if (c.kind == CrossingKind::Mesh) s << ", depth " << c.depth << ", closure error " << error << " rad";
        s << ")";
        problem(geometry::StatusCode::Collision, s.str());
      }
      if (report_.collisions.size() < options_.max_collisions) report_.collisions.push_back(std::move(found));
    }
  }

  // Loop error (radians) below which a state counts as closed and its crossings are not rechecked.
  static constexpr double kClosedEnough = 1e-9;

  void frame(const geometry::FoldState& state, int event) { report_.frames.push_back({time_, event, state}); }
  // The first problem decides the status; every one is listed.
  void problem(geometry::StatusCode code, std::string what) {
    if (report_.problems.empty()) report_.status = {code, what};
    report_.problems.push_back(std::move(what));
  }

  const geometry::CreasePattern& pattern_;
  const SimulationOptions& options_;
  geometry::KinematicTree tree_;
  geometry::ClosureSystem closure_;
  std::optional<CollisionWorld> world_;
  CornerMotion motion_;
  std::vector<Eigen::Isometry3d> poses_;
  double sweep_ = 0.0;
  double time_ = 0.0;
  double last_error_ = 0.0;
  bool closure_reported_ = false;
  std::set<std::tuple<int, int, int>> crossed_;
  std::set<std::tuple<int, int, int>> numerical_;
  geometry::FoldState state_;
  EventReport start_{};  // the flat state's checks count here, in no event
  EventReport* current_ = nullptr;
  SimulationReport report_;
};

}  // namespace

// A Replay with its own copy of the options (the caller's may not outlive it) and whether it has
// begun (the flat state is checked as the first event's, which is not known before it comes).
struct SequenceReplay::Impl {
  Impl(const geometry::CreasePattern& pattern, SimulationOptions o) : options(std::move(o)), replay(pattern, options) {}
  SimulationOptions options;
  Replay replay;
  bool begun = false;
};

SequenceReplay::SequenceReplay(const geometry::CreasePattern& pattern, const SimulationOptions& options) {
  check_options(options);
  impl_ = std::make_unique<Impl>(pattern, options);
}

SequenceReplay::~SequenceReplay() = default;

void SequenceReplay::add(const geometry::FoldEvent& event, std::size_t known) {
  if (!impl_) throw std::logic_error("SequenceReplay::add: the replay has finished (or an event threw)");
  try {
    if (!impl_->begun) impl_->replay.begin(event.number);
    impl_->begun = true;
    impl_->replay.replay(event, known);
  } catch (...) {
    impl_.reset();  // half an event replayed: no report simulate() would give can follow
    throw;
  }
}

SimulationReport SequenceReplay::finish() {
  if (!impl_) throw std::logic_error("SequenceReplay::finish: the replay has finished (or an event threw)");
  if (!impl_->begun) impl_->replay.begin(0);
  SimulationReport report = impl_->replay.end();
  impl_.reset();
  return report;
}

SimulationReport simulate(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                          const SimulationOptions& options) {
  check_options(options);
  return Replay(pattern, options).run(sequence);
}

}  // namespace foldkit::simulation
