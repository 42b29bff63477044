#include "foldkit/folding/carpenter_spherical.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include "carpenter_spherical_polygon.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/kinematics.hpp"

namespace foldkit::folding {

using Eigen::Vector3d;
using geometry::FoldState;
using geometry::StatusCode;
namespace sp = detail::spherical;

namespace {

// The vertex as the method sees it: its creases counter-clockwise with their flat directions.
struct Vertex {
  std::vector<int> joints;
  std::vector<double> sectors;  // sectors[i] between creases i and i + 1
  std::vector<Vector3d> flat;   // unit directions in the sheet (z = 0)
};

Vertex read_vertex(const geometry::CreasePattern& pattern) {
  const auto& stars = pattern.interior_vertices();
  if (stars.size() != 1)
    throw std::invalid_argument("spherical Carpenter's rule needs a pattern with one interior vertex; this one has " +
                                std::to_string(stars.size()));
  const geometry::VertexStar& star = stars.front();
  Vertex v;
  v.joints = star.joints;
  v.sectors = star.sectors;
  std::vector<int> sorted = star.joints;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    throw std::invalid_argument("a crease passes straight through the vertex (joint ID " +
                                std::to_string(pattern.joints()[static_cast<std::size_t>(
                                                                    *std::adjacent_find(sorted.begin(), sorted.end()))]
                                                   .id) +
                                "): split it into two joints");
  if (star.joints.size() != pattern.joints().size())
    throw std::invalid_argument("spherical Carpenter's rule needs every crease on the vertex: " +
                                std::to_string(pattern.joints().size() - star.joints.size()) + " of " +
                                std::to_string(pattern.joints().size()) + " joints are elsewhere");
  if (star.joints.size() < 3)
    throw std::invalid_argument("a vertex of degree " + std::to_string(star.joints.size()) + " cannot fold");
  for (std::size_t i = 0; i < star.sectors.size(); ++i)
    if (star.sectors[i] >= M_PI - 1e-9) {
      std::ostringstream m;
      m << "sector " << i << " spans " << star.sectors[i] * 180.0 / M_PI
        << " degrees: spherical Carpenter's rule needs every sector below 180 degrees (split it with a crease)";
      throw std::invalid_argument(m.str());
    }
  for (double d : star.directions) v.flat.emplace_back(std::cos(d), std::sin(d), 0.0);
  return v;
}

double max_abs(const Eigen::VectorXd& v) { return v.size() == 0 ? 0.0 : v.cwiseAbs().maxCoeff(); }

// The state's fold angles read off the polygon (one per crease of the vertex), written into a
// FoldState of the pattern.
FoldState to_state(const geometry::CreasePattern& pattern, const Vertex& v, const std::vector<double>& folds) {
  FoldState s = FoldState::flat(pattern);
  for (std::size_t i = 0; i < v.joints.size(); ++i) s.angles[v.joints[i]] = folds[i];
  return s;
}

// Keeps frames at most `frame_step` apart in every fold angle; every step is itself within it.
class FrameLog {
 public:
  FrameLog(std::vector<FoldState>& frames, double frame_step) : frames_(frames), step_(frame_step) {}
  void add(const FoldState& s) {
    if (frames_.empty()) {
      frames_.push_back(s);
      return;
    }
    if (pending_ && max_abs(s.angles - frames_.back().angles) > step_) {
      frames_.push_back(*pending_);
    }
    pending_ = s;
  }
  void finish() {
    if (pending_) frames_.push_back(*pending_);
    pending_.reset();
  }

 private:
  std::vector<FoldState>& frames_;
  double step_;
  std::optional<FoldState> pending_;
};

}  // namespace

std::vector<Vector3d> crease_directions(const geometry::CreasePattern& pattern, const FoldState& state) {
  const Vertex v = read_vertex(pattern);
  if (state.angles.size() != static_cast<Eigen::Index>(pattern.joints().size()))
    throw std::invalid_argument("the state has " + std::to_string(state.angles.size()) + " angles for " +
                                std::to_string(pattern.joints().size()) + " joints");
  const auto poses = geometry::facet_poses(pattern, geometry::make_tree(pattern), state);
  std::vector<Vector3d> u;
  for (std::size_t i = 0; i < v.joints.size(); ++i) {
    const int actor = pattern.joints()[static_cast<std::size_t>(v.joints[i])].actors[0];
    u.push_back((poses[static_cast<std::size_t>(actor)].linear() * v.flat[i]).normalized());
  }
  return u;
}

CarpenterSphericalResult flatten_single_vertex(const geometry::CreasePattern& pattern, const FoldState& folded,
                                    const CarpenterSphericalOptions& options) {
  if (!(options.step > 0) || !(options.frame_step > 0) || !(options.flat_tolerance > 0) ||
      !(options.straight_tolerance > 0) || options.max_steps < 1 || !(options.speed > 0))
    throw std::invalid_argument("spherical Carpenter's rule: step, frame_step, tolerances, max_steps and speed must be positive");
  const Vertex v = read_vertex(pattern);
  const std::size_t n = v.joints.size();
  const geometry::ClosureSystem closure(pattern);
  if (folded.angles.size() != static_cast<Eigen::Index>(pattern.joints().size()))
    throw std::invalid_argument("the folded state has " + std::to_string(folded.angles.size()) + " angles for " +
                                std::to_string(pattern.joints().size()) + " joints");
  const double input_error = closure.max_error(folded);
  if (!(input_error <= options.closure_tolerance)) {
    std::ostringstream m;
    m << "the folded state does not close: loop error " << input_error << " rad > " << options.closure_tolerance;
    throw std::invalid_argument(m.str());
  }
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(folded.angles[v.joints[i]]) > M_PI)
      throw std::invalid_argument("joint ID " + std::to_string(pattern.joints()[static_cast<std::size_t>(v.joints[i])].id) +
                                  " is folded past 180 degrees: its facets cross");

  std::vector<Vector3d> u = crease_directions(pattern, folded);
  if (const auto crossing = sp::find_crossing(u)) {
    throw std::invalid_argument("the folded state crosses itself (the sectors after creases " + std::to_string((*crossing)[0]) +
                                " and " + std::to_string((*crossing)[1]) +
                                " pass through each other): Carpenter's rule starts from a non-crossing state");
  }

  CarpenterSphericalResult result;
  result.joints = v.joints;
  FrameLog log(result.frames, options.frame_step);
  log.add(folded);
  result.max_closure_error = input_error;
  result.min_distance_growth = std::numeric_limits<double>::infinity();
  result.min_rate = std::numeric_limits<double>::infinity();

  sp::Polygon poly(u, v.sectors);
  poly.restore();
  std::vector<double> reference(n);
  for (std::size_t i = 0; i < n; ++i) reference[i] = folded.angles[v.joints[i]];
  std::vector<double> folds = poly.fold_angles(reference);
  poly.lock_straight(folds, options.straight_tolerance);

  const auto record = [&](const std::vector<double>& f) {
    const FoldState s = to_state(pattern, v, f);
    result.max_closure_error = std::max(result.max_closure_error, closure.max_error(s));
    result.max_sector_error = std::max(result.max_sector_error, poly.sector_error());
    log.add(s);
  };
  record(folds);

  const auto finish = [&](StatusCode code, std::string message) {
    log.finish();
    result.status = {code, std::move(message)};
    if (!std::isfinite(result.min_distance_growth)) result.min_distance_growth = 0.0;
    if (!std::isfinite(result.min_rate)) result.min_rate = 0.0;
    std::vector<FoldState> waypoints(result.frames.rbegin(), result.frames.rend());
    if (!waypoints.empty() && max_abs(waypoints.front().angles) == 0.0) waypoints.erase(waypoints.begin());
    result.folding = geometry::path_sequence(pattern, waypoints, options.speed,
                                             pattern.title() + " folded by spherical Carpenter's rule (unfolding reversed)");
    return result;
  };

  for (int step = 0;; ++step) {
    double largest = 0.0;
    for (double f : folds) largest = std::max(largest, std::abs(f));
    // Three bars with lengths summing to 2π close only on a great circle: flat, to rounding.
    if (largest < options.flat_tolerance || poly.active().size() <= 3) {
      // Flat: every pairwise distance is at its largest there, so this last move expands too.
      const std::vector<double> zero(n, 0.0);
      const std::vector<double> before = poly.all_distances();
      poly.set_flat();
      result.min_distance_growth = std::min(result.min_distance_growth, sp::min_difference(before, poly.all_distances()));
      record(zero);
      std::ostringstream m;
      m << "flat after " << step << " steps";
      return finish(StatusCode::Success, m.str());
    }
    if (step >= options.max_steps) {
      std::ostringstream m;
      m << "stopped after " << step << " steps (max_steps), largest fold angle still " << largest << " rad";
      return finish(StatusCode::LimitReached, m.str());
    }
    if (options.stop && options.stop()) {
      std::ostringstream m;
      m << "stopped after " << step << " steps (asked to stop), largest fold angle still " << largest << " rad";
      return finish(StatusCode::LimitReached, m.str());
    }
    const sp::Velocity vel = poly.expansive_velocity();
    if (vel.status != sp::Velocity::Status::Ok || !(vel.rate > options.min_rate)) {
      std::ostringstream m;
      m << "no strictly expansive motion at step " << step << ": " << vel.message << " (largest fold angle " << largest
        << " rad)";
      // Two creases on one direction (sectors folded flat onto each other): the distance between
      // them is 0, where its first-order change is 0 whatever the motion, so the LP cannot see it grow.
      const auto& dir = poly.directions();
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j)
          if ((i > 0 || j + 1 < n) && sp::distance(dir[i], dir[j]) < 1e-6) {
            m << "; creases " << i << " and " << j << " (joint IDs " << pattern.joints()[static_cast<std::size_t>(v.joints[i])].id
              << ", " << pattern.joints()[static_cast<std::size_t>(v.joints[j])].id
              << ") lie on one direction: start from a state where the folded-flat layers are apart";
            i = n;
            break;
          }
      // A crease folded flat (±180°) stacks two layers whose distances to each other do not
      // change to first order as it opens: the LP sees no growth there.
      for (std::size_t i = 0; i < n; ++i)
        if (std::abs(folds[i]) > M_PI - 1e-6) {
          m << "; joint ID " << pattern.joints()[static_cast<std::size_t>(v.joints[i])].id
            << " is folded flat (180 degrees), where opening it grows no distance to first order: start a little off 180 degrees";
          break;
        }
      return finish(StatusCode::NoProgress, m.str());
    }
    result.min_rate = std::min(result.min_rate, vel.rate);
    const sp::StepOutcome out = poly.advance(vel, options.step, options.frame_step, folds, options.straight_tolerance);
    if (!out.ok) {
      std::ostringstream m;
      m << "step " << step << " failed: " << out.message;
      return finish(StatusCode::NoProgress, m.str());
    }
    ++result.steps;
    result.min_distance_growth = std::min(result.min_distance_growth, out.min_growth);
    folds = out.folds;
    record(folds);
  }
}

}  // namespace foldkit::folding
