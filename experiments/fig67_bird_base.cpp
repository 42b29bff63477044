// The paper's Figs. 6 and 7: the origami bird base, displayed and simulated in the editor. The
// paper shows frames and makes no quantitative claim; this program asks what the rigid model
// (rigid facets, revolute creases, loop closure, no self-crossing) finds.
//
//   fig67_bird_base [--out DIR] [--check]
//
// Input: experiments/data/osbo_rigid-origami__birdBase.fold (Origami Simulator's bird base with
// the fold angles of the flat-folded base) and robbykraft_Origami__bird-base-3d.fold.
// 1. All creases simultaneously, in proportion (one CMML event, synchronised): closure residual
//    along the straight line flat → target, and its replay by the simulator.
// 2. A rigid folding: closed states from flat toward the target, each the projection of a step of
//    0.02 rad (angle-space norm) from the last one toward the target, until no step gets closer.
//    DOF along it, how near the target it gets, and where the simulator first finds facets crossing.
// 3. The robbykraft file's fold angles: are they a closed state, and how far is the nearest one.
// Writes fig67_straight.csv, fig67_rigid_path.csv, fig67_bird_base.md, birdbase.pmml, birdbase.svg,
// birdbase-straight.cmml, birdbase-rigid.cmml and snapshots fig7_frame_*.svg.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include "experiment_io.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/io/svg.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "foldkit/simulation/snapshot.hpp"

#ifndef FOLDKIT_EXPERIMENTS_DATA
#define FOLDKIT_EXPERIMENTS_DATA "experiments/data"
#endif

namespace {

using namespace foldkit;
using experiments::num;

constexpr double kStep = 0.02;     // rad, norm of each step of the rigid folding toward the target
constexpr int kMaxSteps = 5000;
constexpr double kDeg = 180 / M_PI;

double max_diff(const geometry::FoldState& a, const geometry::FoldState& b) {
  return (a.angles - b.angles).cwiseAbs().maxCoeff();
}

std::string angles_deg(const geometry::CreasePattern& p, const geometry::FoldState& s) {
  std::string out;
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    out += (out.empty() ? "" : ", ") + std::to_string(p.joints()[j].id) + ": " + num(s.angles[static_cast<Eigen::Index>(j)] * kDeg, 4);
  return out;
}

// Whether segment pq passes through the interior of triangle t (both ends off its plane by more
// than eps, on opposite sides; the crossing point inside by more than eps): a check of the
// simulator's verdict that shares nothing with FCL or CollisionWorld.
bool segment_crosses(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const std::array<Eigen::Vector3d, 3>& t, double eps) {
  const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
  const double dp = (p - t[0]).dot(n), dq = (q - t[0]).dot(n);
  if (std::abs(dp) < eps || std::abs(dq) < eps || dp * dq > 0) return false;
  const Eigen::Vector3d x = p + (q - p) * (dp / (dp - dq));
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = t[(i + 1) % 3] - t[i];
    if (n.dot(e.cross(x - t[i])) / e.norm() < eps) return false;
  }
  return true;
}

// Whether two facets cross at `state`: an edge of a triangle of one through a triangle of the other.
bool facets_cross(const geometry::CreasePattern& p, const geometry::FoldState& state, int id_a, int id_b) {
  const auto poses = geometry::facet_poses(p, geometry::make_tree(p), state);
  const auto triangles = [&](int id) {
    const int a = *p.actor_index(id);
    std::vector<std::array<Eigen::Vector3d, 3>> out;
    for (const auto& t : p.actors()[a].triangles) {
      std::array<Eigen::Vector3d, 3> w;
      for (int k = 0; k < 3; ++k) w[k] = poses[a] * Eigen::Vector3d(p.vertices()[t.v[k]].x(), p.vertices()[t.v[k]].y(), 0.0);
      out.push_back(w);
    }
    return out;
  };
  const double eps = 1e-9 * p.diagonal();
  const auto A = triangles(id_a), B = triangles(id_b);
  for (const auto& a : A)
    for (const auto& b : B)
      for (int k = 0; k < 3; ++k)
        if (segment_crosses(a[k], a[(k + 1) % 3], b, eps) || segment_crosses(b[k], b[(k + 1) % 3], a, eps)) return true;
  return false;
}

// The different angles of a state, in degrees, in order of first appearance.
std::string distinct_deg(const geometry::FoldState& s) {
  std::vector<double> seen;
  std::string out;
  for (Eigen::Index j = 0; j < s.angles.size(); ++j) {
    const double d = s.angles[j] * kDeg;
    if (std::any_of(seen.begin(), seen.end(), [&](double x) { return std::abs(x - d) < 1e-9; })) continue;
    seen.push_back(d);
    out += (out.empty() ? "" : ", ") + num(d, 4);
  }
  return out;
}

// Reads the two bird base files; false (after saying why) when one cannot be read or has no
// fold angles.
bool read_inputs(std::optional<io::FoldImport>& bird, std::optional<io::FoldImport>& second) {
  const std::string data = FOLDKIT_EXPERIMENTS_DATA;
  try {
    bird = io::read_fold(data + "/osbo_rigid-origami__birdBase.fold");
    second = io::read_fold(data + "/robbykraft_Origami__bird-base-3d.fold");
  } catch (const std::exception& e) {
    std::cerr << "fig67: " << e.what() << '\n';
    return false;
  }
  if (!bird->state || !second->state) {
    std::cerr << "fig67: a bird base file has no fold angles\n";
    return false;
  }
  return true;
}

// 1. Every crease in proportion along the straight line flat → target.
struct StraightLine {
  std::string csv;
  double peak = 0, peak_t = 0;  // the largest closure residual, and where
  geometry::FoldSequence sequence;
  simulation::SimulationReport sim;
};

StraightLine fold_straight(const geometry::CreasePattern& pattern, const geometry::ClosureSystem& system,
                           const geometry::FoldState& target) {
  StraightLine out;
  std::ostringstream csv;
  csv << "t,closure_residual_rad,nearest_closed_deg\n";
  for (int k = 0; k <= 40; ++k) {
    const double t = k / 40.0;
    const geometry::FoldState s{t * target.angles};
    const double e = system.max_error(s);
    const geometry::ProjectionResult near = geometry::project(system, s);
    if (e > out.peak) out.peak = e, out.peak_t = t;
    csv << num(t, 4) << ',' << num(e, 6) << ',' << (near.status.ok() ? num(max_diff(near.state, s) * kDeg, 6) : "") << '\n';
  }
  out.csv = csv.str();
  out.sequence = geometry::path_sequence(pattern, {target}, M_PI / 6, "bird base, all creases at once");
  simulation::SimulationOptions sync;
  sync.model = simulation::Actuation::Synchronised;
  out.sim = simulation::simulate(pattern, out.sequence, sync);
  return out;
}

// 2. Closed states from flat toward the target, each the projection of a step from the last.
struct RigidPath {
  std::vector<geometry::FoldState> states;
  std::vector<int> dofs;
  double worst_closure = 0, largest_jump = 0;
  std::string stop = "step limit";
  int dof_min = 99, dof_max = 0;
};

RigidPath fold_rigidly(const geometry::ClosureSystem& system, const geometry::FoldState& flat, const geometry::FoldState& target) {
  RigidPath out;
  geometry::FoldState at = flat;
  double best = (target.angles - flat.angles).norm();
  for (int k = 1; k <= kMaxSteps; ++k) {
    const Eigen::VectorXd d = target.angles - at.angles;
    const geometry::ProjectionResult p = geometry::project(system, geometry::FoldState{at.angles + d * std::min(1.0, kStep / d.norm())});
    if (!p.status.ok()) {
      out.stop = "projection failed: " + p.status.message;
      break;
    }
    const double dist = (p.state.angles - target.angles).norm();
    if (dist >= best - 1e-9) {
      out.stop = "no step gets closer to the target";
      break;
    }
    best = dist;
    out.largest_jump = std::max(out.largest_jump, max_diff(p.state, at));
    out.worst_closure = std::max(out.worst_closure, p.error);
    at = p.state;
    out.states.push_back(at);
    out.dofs.push_back(geometry::mobility(system, at).dof);
  }
  for (int dof : out.dofs) out.dof_min = std::min(out.dof_min, dof), out.dof_max = std::max(out.dof_max, dof);
  return out;
}

// The rigid folding written as CMML, read back and replayed, and where facets first cross.
struct Replay {
  geometry::FoldSequence sequence;
  std::string cmml;
  simulation::SimulationReport sim;
  std::set<int> colliding_events;
  int first_collision = -1;  // index into the path; -1: none
  std::string crossing_pair;
  bool crossing_confirmed = false;  // by facets_cross: that pair crosses there, and not one state before
};

Replay replay_rigid(const geometry::CreasePattern& pattern, const std::vector<geometry::FoldState>& path) {
  Replay out;
  out.sequence = geometry::path_sequence(pattern, path, M_PI / 6, "bird base, rigid folding toward the target");
  out.cmml = io::write_cmml(out.sequence);
  simulation::SimulationOptions replay;
  replay.model = simulation::Actuation::Synchronised;
  out.sim = simulation::simulate(pattern, io::parse_cmml(out.cmml, "birdbase-rigid.cmml"), replay);
  // path_sequence skips no waypoint here (each moves), so event k is waypoint k − 1.
  for (const auto& c : out.sim.collisions) out.colliding_events.insert(c.event);
  out.first_collision = out.colliding_events.empty() ? -1 : *out.colliding_events.begin() - 1;
  if (!out.sim.collisions.empty()) {
    const auto& c = out.sim.collisions.front();
    const int first = out.first_collision;
    out.crossing_pair = std::to_string(c.actors[0]) + " and " + std::to_string(c.actors[1]);
    out.crossing_confirmed = facets_cross(pattern, path[first], c.actors[0], c.actors[1]) &&
                             (first == 0 || !facets_cross(pattern, path[first - 1], c.actors[0], c.actors[1]));
  }
  return out;
}

// The difference to the target twice more, split by whether the replay found facets crossing
// there (one of the two empty), so a plot shows where the path stops being physical.
std::string rigid_path_csv(const geometry::ClosureSystem& system, const RigidPath& rigid, const Replay& replay,
                           const geometry::FoldState& target) {
  std::ostringstream csv;
  csv << "step,max_diff_to_target_deg,distance_to_target_deg,closure_error_rad,dof,crossing,diff_crossing_free_deg,"
         "diff_crossing_deg\n";
  const std::vector<geometry::FoldState>& path = rigid.states;
  for (std::size_t k = 0; k < path.size(); ++k) {
    csv << k + 1 << ',' << num(max_diff(path[k], target) * kDeg, 6) << ',' << num((path[k].angles - target.angles).norm() * kDeg, 6) << ','
        << num(system.max_error(path[k]), 3) << ',' << rigid.dofs[k] << ',';
    const bool crossing = replay.colliding_events.count(static_cast<int>(k) + 1) > 0;
    const std::string diff = num(max_diff(path[k], target) * kDeg, 6);
    csv << crossing << ',' << (crossing ? "" : diff) << ',' << (crossing ? diff : "") << '\n';
  }
  return csv.str();
}

// Everything the report and the checks state.
struct Findings {
  geometry::Mobility m_flat, m_target;
  double target_error = 0;
  StraightLine straight;
  RigidPath rigid;
  Replay replay;
  double reached_diff = 0, crossing_diff = 0, free_diff = 0;  // degrees from the target
  // 3. The second file's angles.
  double second_error = 0;
  geometry::ProjectionResult second_near;
};

Findings study(const geometry::CreasePattern& pattern, const geometry::ClosureSystem& system, const geometry::FoldState& target,
               const io::FoldImport& second) {
  Findings f;
  const geometry::FoldState flat = geometry::FoldState::flat(pattern);
  f.m_flat = geometry::mobility(system, flat);
  f.m_target = geometry::mobility(system, target);
  f.target_error = system.max_error(target);
  f.straight = fold_straight(pattern, system, target);
  f.rigid = fold_rigidly(system, flat, target);
  f.replay = replay_rigid(pattern, f.rigid.states);
  const std::vector<geometry::FoldState>& path = f.rigid.states;
  const int first = f.replay.first_collision;
  f.reached_diff = max_diff(path.empty() ? flat : path.back(), target) * kDeg;
  f.crossing_diff = first >= 0 ? max_diff(path[first], target) * kDeg : 0.0;
  f.free_diff = first > 0 ? max_diff(path[first - 1], target) * kDeg : 0.0;
  const geometry::ClosureSystem second_system(second.pattern);
  f.second_error = second_system.max_error(*second.state);
  f.second_near = geometry::project(second_system, *second.state);
  return f;
}

void summary_table(std::ostream& md, const geometry::CreasePattern& pattern, const geometry::ClosureSystem& system,
                   const Findings& f, const geometry::FoldState& second_state) {
  const RigidPath& r = f.rigid;
  const Replay& replay = f.replay;
  md << "# Figs. 6/7: the bird base under the rigid model\n\n"
     << "The paper shows the bird base drawn (Fig. 6) and frames of its simulation in PhysX (Fig. 7); it states no number. "
     << "Ours is kinematic and rigid: facets do not bend, loops must close, facets must not cross.\n\n"
     << "Pattern: `experiments/data/osbo_rigid-origami__birdBase.fold` (Origami Simulator export): " << pattern.actors().size()
     << " facets, " << pattern.joints().size() << " creases, " << pattern.interior_vertices().size()
     << " interior vertices (one of degree 8, four of degree 4), " << system.rows() << " closure equations. Target: the file's fold "
     << "angles, the flat-folded bird base (its closure error " << num(f.target_error, 2) << " rad: closed to the file's float precision).\n\n"
     << "| quantity | ours |\n|---|---|\n"
     << "| DOF flat | " << f.m_flat.dof << " (rank " << f.m_flat.rank << ") |\n"
     << "| DOF at the closed states of the rigid folding | " << r.dof_min
     << (r.dof_min == r.dof_max ? "" : "–" + std::to_string(r.dof_max)) << " |\n"
     << "| DOF at the flat-folded target (a singular state) | " << f.m_target.dof << " (rank " << f.m_target.rank << ") |\n"
     << "| all creases at once, in proportion: largest closure residual | " << num(f.straight.peak, 3) << " rad ("
     << num(f.straight.peak * kDeg, 3) << "°) at t = " << num(f.straight.peak_t, 2) << " |\n"
     << "| the same as one CMML event, simulated (sync) | " << (f.straight.sim.status.ok() ? "valid" : "invalid") << ": max closure error "
     << num(f.straight.sim.max_closure_error, 3) << " rad, " << f.straight.sim.collision_count << " crossings |\n"
     << "| rigid folding toward the target (" << r.states.size() << " closed states, steps ≤ " << num(r.largest_jump * kDeg, 2)
     << "° per crease) | stops " << num(f.reached_diff, 3) << "° from the target (largest crease difference): " << r.stop << " |\n"
     << "| its largest closure error | " << num(r.worst_closure, 2) << " rad |\n"
     << "| its replay (" << replay.sequence.events.size() << " events, sync) | " << (replay.sim.status.ok() ? "valid" : "invalid")
     << ", max closure error " << num(replay.sim.max_closure_error, 2) << " rad; " << replay.sim.collision_count << " crossings";
  if (replay.first_collision >= 0)
    md << ", the first at state " << replay.first_collision + 1 << " (facets " << replay.crossing_pair << ", "
       << (replay.crossing_confirmed ? "confirmed" : "NOT confirmed")
       << " by an independent segment–triangle test, which also finds them apart one state before), " << num(f.crossing_diff, 3)
       << "° from the target; crossing-free up to " << num(f.free_diff, 3) << "° from it";
  md << " |\n"
     << "| `robbykraft_Origami__bird-base-3d.fold`: its fold angles (" << distinct_deg(second_state)
     << " °) | closure residual " << num(f.second_error, 3) << " rad: not a rigid state; nearest closed state "
     << (f.second_near.status.ok() ? num(max_diff(f.second_near.state, second_state) * kDeg, 3) + "° away" : "not found") << " |\n\n";
}

void remarks(std::ostream& md, const geometry::CreasePattern& pattern, const Findings& f, const geometry::FoldState& reached) {
  md << "Remarks. Folding every crease in proportion (what a one-event CMML with matched velocities does) is not a rigid motion: "
     << "the loops open by up to " << num(f.straight.peak * kDeg, 3) << "° halfway. Letting the creases move out of proportion, a path of closed states "
     << "exists from flat (" << f.m_flat.dof << " DOF) through states of " << f.rigid.dof_min << " DOF to within " << num(f.reached_diff, 2)
     << "° of the flat-folded base, where the mechanism becomes singular (" << f.m_target.dof
     << " DOF) and the projection cannot get closer. That path is not physical all the way: ";
  if (f.replay.first_collision >= 0)
    md << "from " << num(f.crossing_diff, 3) << "° before the end the simulator finds facets " << f.replay.crossing_pair
       << " crossing (red in the last frame). So the rigid model folds the bird base to about " << num(f.free_diff, 2)
       << "° short of flat-folded without bending or crossing, and no further along this path; this path is greedy (each step the "
       << "closed state nearest to a step toward the target), and another one, with another layer order, may get closer.\n";
  else
    md << "the simulator finds no crossing.\n";
  md << "\nFinal state of the rigid folding (joint ID: degrees): " << angles_deg(pattern, reached) << ".\n";
}

// Fig. 7's frames: a quarter, half, three quarters of the crossing-free part, its last state,
// and the first crossing (facets in red).
void write_frames(const experiments::Args& args, const geometry::CreasePattern& pattern, const geometry::FoldState& target,
                  const std::vector<geometry::FoldState>& path, const Replay& replay) {
  const int first_collision = replay.first_collision;
  const geometry::KinematicTree tree = geometry::make_tree(pattern);
  const int free_end = first_collision >= 0 ? first_collision - 1 : static_cast<int>(path.size()) - 1;
  std::vector<int> frames;
  for (int q = 1; q <= 4; ++q) frames.push_back(free_end * q / 4);
  if (first_collision >= 0) frames.push_back(first_collision);
  for (std::size_t f = 0; f < frames.size() && !path.empty(); ++f) {
    const int k = std::max(frames[f], 0);
    simulation::SnapshotOptions so;
    so.size = 360;
    so.caption = "state " + std::to_string(k + 1) + ", " + num(max_diff(path[k], target) * kDeg, 3) + " deg from flat-folded";
    if (k == first_collision)
      for (const auto& c : replay.sim.collisions)
        if (c.event == k + 1)
          for (int id : c.actors) so.marked.push_back(*pattern.actor_index(id));
    experiments::write_output(args, "fig7_frame_" + std::to_string(f + 1) + ".svg",
                              simulation::snapshot_svg(pattern, geometry::facet_poses(pattern, tree, path[k]), so));
  }
}

bool check(const Findings& f) {
  const RigidPath& r = f.rigid;
  bool ok = experiments::expect(f.m_flat.dof == 10 && r.dof_min == 5 && r.dof_max == 5 && f.m_target.dof == 9,
                                "DOF 10 flat, 5 along the rigid folding, 9 at the flat-folded target");
  ok &= experiments::expect(f.straight.peak > 1.2 && f.straight.peak < 1.3 && std::abs(f.straight.peak_t - 0.5) < 1e-9 &&
                                !f.straight.sim.status.ok(),
                            "straight folding: closure residual peaks at 1.2-1.3 rad halfway, simulator says invalid");
  ok &= experiments::expect(r.worst_closure < 1e-9 && r.largest_jump < 0.01 && f.reached_diff < 0.5,
                            "rigid folding: closed states, small steps, within 0.5° of the flat-folded base");
  ok &= experiments::expect(f.replay.first_collision > 0 && f.free_diff > 5 && f.free_diff < 15 && f.replay.sim.max_closure_error < 1e-3,
                            "rigid folding crossing-free until 5-15° before flat-folded, closure kept on replay");
  ok &= experiments::expect(f.replay.crossing_confirmed,
                            "the first crossing confirmed by the segment-triangle test (and absent one state before)");
  ok &= experiments::expect(f.second_error > 0.3 && f.second_near.status.ok(),
                            "second file's angles are not closed; a nearest closed state exists");
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = experiments::parse_args(argc, argv, "experiment-output/fig67",
                                            "usage: fig67_bird_base [--out DIR] [--check]\n"
                                            "  The bird base of the paper's Figs. 6/7 under the rigid model.\n");
  std::optional<io::FoldImport> bird_file, second_file;
  if (!read_inputs(bird_file, second_file)) return 1;
  const geometry::CreasePattern& pattern = bird_file->pattern;
  const geometry::ClosureSystem system(pattern);
  const geometry::FoldState target = *bird_file->state;
  const Findings f = study(pattern, system, target, *second_file);
  const std::vector<geometry::FoldState>& path = f.rigid.states;

  std::ostringstream md;
  summary_table(md, pattern, system, f, *second_file->state);
  remarks(md, pattern, f, path.empty() ? geometry::FoldState::flat(pattern) : path.back());
  std::cout << md.str();
  experiments::write_output(args, "fig67_straight.csv", f.straight.csv);
  experiments::write_output(args, "fig67_rigid_path.csv", rigid_path_csv(system, f.rigid, f.replay, target));
  experiments::write_output(args, "fig67_bird_base.md", md.str());
  experiments::write_output(args, "birdbase.pmml", io::write_pmml(pattern));
  io::SvgOptions svg;
  svg.state = &target;
  experiments::write_output(args, "birdbase.svg", io::write_svg(pattern, svg));
  experiments::write_output(args, "birdbase-straight.cmml", io::write_cmml(f.straight.sequence));
  experiments::write_output(args, "birdbase-rigid.cmml", f.replay.cmml);
  write_frames(args, pattern, target, path, f.replay);
  if (!args.check) return 0;
  return check(f) ? 0 : 1;
}
