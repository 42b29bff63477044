// The built-in scenes and suites of `foldkit bench`. Goals come from std::mt19937 seeded by the
// scene and the seed (never from OMPL's generator, which seeds once per process), and a goal is
// kept only when it is reachable: the straight way from the start to it (in the active angles of a
// single vertex, as microbench/measure_planning.cpp does; projected onto the closure manifold
// for the other patterns) is closed, within the bounds and free of crossing facets.
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

#include <ompl/base/ScopedState.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/bench/scenes.hpp"
#include "foldkit/io/fold_format.hpp"
#include "fold_fixtures.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::bench {

using planners::PlanOptions;

namespace ob = ompl::base;
namespace gen = geometry::generators;
using geometry::CreasePattern;
using geometry::FoldState;

namespace {

constexpr int kDegrees[] = {4, 8, 12, 16, 32};
// The "-any" scenes: random sectors, goals not filtered for reachability (issue 16, item 4).
constexpr int kAnyDegrees[] = {6, 8, 12, 32};


// Mirror-symmetric sectors: all equal, except degree 4, whose equal sectors fold only about one
// straight line (a degenerate vertex); its symmetric scene is the bird's foot 60°/120°/120°/60°.
std::vector<double> symmetric_sectors(int n) {
  if (n == 4) return {M_PI / 3, 2 * M_PI / 3, 2 * M_PI / 3, M_PI / 3};
  return std::vector<double>(static_cast<std::size_t>(n), 2 * M_PI / n);
}

// As measure_planning's connected_goal: active angles uniform in [−a, a] (a shrinks with the
// degree, so that roots stay likely), largest |angle| ≥ a/4, a random branch; reachable from
// flat along the straight segment in the active angles (the motion validator checks closure,
// jumps and, here, crossing facets).
// With `reachable` false (the "-any" scenes of issue 16's completeness target) the segment is not
// checked: any closed, collision-free state within the bounds is a goal.
FoldState single_vertex_goal(const CreasePattern& p, std::mt19937& rng, int degree, bool reachable = true) {
  const statespaces::AngleBounds bounds = statespaces::AngleBounds::of(p, false);
  auto space = std::make_shared<statespaces::SingleVertexStateSpace>(std::make_shared<statespaces::SingleVertexChain>(p), bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  auto validity = std::make_shared<statespaces::FoldValidity>(p, bounds, true);
  statespaces::FoldMotionValidator motion(si, validity, statespaces::single_vertex_reader(space));
  ob::ScopedState<> from(space), goal(space);
  std::vector<FoldState> way{FoldState::flat(p)};
  if (!space->from_fold_state(way.front(), from.get())) {
    // Flat is singular for the closed form here: start the segment where plan() leaves flat.
    const geometry::ClosureSystem system(p);
    FoldState dir = FoldState::flat(p);
    for (Eigen::Index j = 0; j < dir.angles.size(); ++j) dir.angles[j] = (j % 2 ? -1.0 : 1.0);
    way = geometry::lead_in(system, way.front(), dir, 3, 0.02);
    if (way.empty() || !space->from_fold_state(way.back(), from.get()))
      throw std::runtime_error("bench: no way out of the flat vertex");
  }
  const double a = degree <= 8 ? 2.0 : degree <= 16 ? 1.0 : 0.5;
  std::uniform_real_distribution<double> u(-a, a);
  auto* g = goal->as<statespaces::SingleVertexStateSpace::StateType>();
  for (int k = 0; k < 100000; ++k) {
    for (int j : space->chain().active_joints()) g->angles[j] = u(rng);
    space->complete(g, (rng() & 1u) ? 1 : -1);
    if (!g->closed || !space->satisfiesBounds(g)) continue;
    const FoldState f = space->to_fold_state(g);
    const double largest = f.angles.cwiseAbs().maxCoeff();
    if (largest > 2.0 || largest < 0.25 * a) continue;
    if (!validity->valid(f) || (reachable && !motion.checkMotion(from.get(), goal.get()))) continue;
    return f;
  }
  throw std::runtime_error("bench: no reachable goal for the degree-" + std::to_string(degree) + " vertex");
}

// A closed goal near `guess(rng)` (projection keeping signs), within the options' bounds, whose
// projected straight line from the start is closed and collision-free.
template <class Guess>
FoldState projected_goal(const CreasePattern& p, const PlanOptions& req, std::mt19937& rng, Guess guess, const std::string& name) {
  const geometry::ClosureSystem system(p);
  const statespaces::AngleBounds bounds = statespaces::AngleBounds::of(p, req.use_assignment);
  const statespaces::FoldValidity validity(p, bounds, req.collisions);
  const FoldState start = req.start ? *req.start : FoldState::flat(p);
  geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  for (int k = 0; k < 50; ++k) {
    const Eigen::VectorXd g = guess(rng);
    FoldState goal{g};
    if (system.rows() > 0) {
      const auto r = geometry::project(system, goal, po);
      if (!r.status.ok()) continue;
      goal = r.state;
    }
    if (!bounds.contains(goal, 1e-9) || !validity.valid(goal)) continue;
    const std::vector<FoldState> line = geometry::projected_line(system, start, goal, req.waypoint_step);
    if (line.empty() || (line.back().angles - goal.angles).cwiseAbs().maxCoeff() > 1e-9) continue;
    statespaces::FoldValidity::Motion motion(validity);
    bool ok = motion.valid_first(line.front());
    for (std::size_t i = 1; i < line.size() && ok; ++i) ok = motion.valid_next(line[i]) && bounds.contains(line[i], 1e-9);
    if (ok) return goal;
  }
  throw std::runtime_error("bench: no reachable goal for scene " + name);
}

Eigen::VectorXd assignment_signs(const CreasePattern& p) {
  Eigen::VectorXd s(static_cast<Eigen::Index>(p.joints().size()));
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    s[static_cast<Eigen::Index>(j)] = p.joints()[j].assignment == geometry::Assignment::Valley ? -1.0 : 1.0;
  return s;
}

// Miura-ori rows × cols (the generator's default angle) folded along its rigid mode with every
// zig-zag crease at ±zigzag and every straight crease by the closed form of docs/GENERATORS.md,
// tan(ρ/2) = cos(angle)·tan(ρ_z/2) in magnitude, signs from the assignment; polished by the
// projection, which must move no crease more than 1e-6 rad (else the closed form is wrong).
FoldState miura_folded(const CreasePattern& p, int rows, int cols, double zigzag) {
  const double angle = M_PI / 3;  // gen::miura's default
  const std::size_t straight = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols - 1);
  const double rho = 2.0 * std::atan(std::cos(angle) * std::tan(zigzag / 2.0));
  const Eigen::VectorXd sign = assignment_signs(p);
  Eigen::VectorXd g(sign.size());
  for (Eigen::Index j = 0; j < g.size(); ++j) g[j] = sign[j] * (static_cast<std::size_t>(j) < straight ? rho : zigzag);
  geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  const auto r = geometry::project(geometry::ClosureSystem(p), FoldState{g}, po);
  if (!r.status.ok() || (r.state.angles - g).cwiseAbs().maxCoeff() > 1e-6)
    throw std::runtime_error("bench: the Miura closed form does not close (" + r.status.message + ")");
  return r.state;
}

unsigned int scene_seed(const std::string& name, unsigned int seed) {
  unsigned int h = 2166136261u;  // FNV-1a: stable across compilers, unlike std::hash
  for (unsigned char c : name) h = (h ^ c) * 16777619u;
  return h ^ (seed * 2654435761u);
}

BenchScene scene_of(const std::string& name, CreasePattern pattern, std::string description) {
  BenchScene s;
  s.name = name;
  s.description = std::move(description);
  s.pattern = std::make_shared<const CreasePattern>(std::move(pattern));
  s.options.collisions = true;
  s.options.use_assignment = false;
  s.options.replay = false;
  return s;
}

BenchScene scene_of(const std::string& name, const geometry::PatternSpec& spec, std::string description) {
  return scene_of(name, geometry::build_or_throw(spec), std::move(description));
}

// Flat to a goal near the assignment's direction, each crease scaled by its own draw from
// [lo, hi] (the waterbomb and imported scenes).
BenchScene assignment_scene(BenchScene s, std::mt19937& rng, double lo, double hi) {
  s.options.use_assignment = true;
  s.options.search_margin = 0.2;  // for the constrained spaces (see the Miura scenes)
  const Eigen::VectorXd dir = assignment_signs(*s.pattern);
  s.goal = projected_goal(*s.pattern, s.options, rng, [dir, lo, hi](std::mt19937& r) {
    std::uniform_real_distribution<double> u(lo, hi);
    Eigen::VectorXd g = dir;
    for (Eigen::Index j = 0; j < g.size(); ++j) g[j] *= u(r);
    return g;
  }, s.name);
  return s;
}

// The imported FOLD patterns (bench/data): bird-base and resch; nothing for another name.
std::optional<BenchScene> imported_scene(const std::string& name, std::mt19937& rng) {
  const char* text = name == "bird-base" ? detail::bird_base_fold() : name == "resch" ? detail::resch_fold() : nullptr;
  if (!text) return std::nullopt;
  const std::string description =
      name == "bird-base" ? "bird base imported from FOLD (osbo/rigid-origami, 5 DOF), flat to partly folded"
                          : "Resch tessellation imported from FOLD (robbykraft/Origami, 10 DOF), flat to partly folded";
  return assignment_scene(scene_of(name, io::parse_fold(text, name + ".fold").pattern, description), rng, 0.2, 0.6);
}

// The Miura scenes: miura4x4, miura10x10 and miura20x20 (random partly folded goals), miuraNxN-80 (every
// zig-zag at ±80°); nothing for another name.
std::optional<BenchScene> miura_scene(const std::string& name, std::mt19937& rng) {
  if (name == "miura4x4" || name == "miura10x10" || name == "miura20x20") {
    const int n = name == "miura4x4" ? 4 : name == "miura10x10" ? 10 : 20;
    BenchScene s = scene_of(name, gen::miura(n, n), "Miura-ori " + std::to_string(n) + "×" + std::to_string(n) +
                                                       ", flat to partly folded along its rigid-folding mode");
    s.options.use_assignment = true;
    s.options.search_margin = 0.2;  // see plan_test: Miura's many branches through flat
    const Eigen::VectorXd dir = assignment_signs(*s.pattern);
    s.goal = projected_goal(*s.pattern, s.options, rng, [dir](std::mt19937& r) {
      return Eigen::VectorXd(dir * std::uniform_real_distribution<double>(0.3, 0.9)(r));
    }, name);
    return s;
  }
  for (int n : {10, 20, 40}) {
    if (name != "miura" + std::to_string(n) + "x" + std::to_string(n) + "-80") continue;
    BenchScene s = scene_of(name, gen::miura(n, n), "Miura-ori " + std::to_string(n) + "×" + std::to_string(n) +
                                                       ", flat to every zig-zag crease at ±80° (issue 16); the goal "
                                                       "does not depend on the seed");
    s.options.use_assignment = true;
    s.goal = miura_folded(*s.pattern, n, n, 80.0 * M_PI / 180.0);
    return s;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> bench_scene_names() {
  std::vector<std::string> names;
  for (int d : kDegrees) {
    names.push_back("vertex" + std::to_string(d) + "-random");
    names.push_back("vertex" + std::to_string(d) + "-symmetric");
  }
  for (int d : kAnyDegrees) names.push_back("vertex" + std::to_string(d) + "-any");
  for (const char* n : {"boat", "miura4x4", "miura10x10", "waterbomb", "cube-sheet", "corner-cube", "miura20x20",
                        "waterbomb4x4", "bird-base", "resch", "miura10x10-80", "miura20x20-80", "miura40x40-80"})
    names.emplace_back(n);
  return names;
}

BenchScene make_bench_scene(const std::string& name, unsigned int seed) {
  std::mt19937 rng(scene_seed(name, seed));
  for (int d : kDegrees) {
    const std::string base = "vertex" + std::to_string(d);
    if (name != base + "-random" && name != base + "-symmetric") continue;
    const bool random = name == base + "-random";
    BenchScene s = scene_of(name, gen::single_vertex(random ? gen::random_sectors(d, rng, std::min(0.2, M_PI / d)) : symmetric_sectors(d)),
                            std::string("single vertex of degree ") + std::to_string(d) +
                                (random ? ", random sectors" : ", symmetric sectors") + ", flat to a random folded state");
    s.goal = single_vertex_goal(*s.pattern, rng, d);
    return s;
  }
  for (int d : kAnyDegrees) {
    if (name != "vertex" + std::to_string(d) + "-any") continue;
    BenchScene s = scene_of(name, gen::single_vertex(gen::random_sectors(d, rng, std::min(0.2, M_PI / d))),
                            "single vertex of degree " + std::to_string(d) +
                                ", random sectors, flat to a random closed collision-free state (not filtered for "
                                "reachability)");
    s.goal = single_vertex_goal(*s.pattern, rng, d, false);
    return s;
  }
  if (name == "boat") {
    BenchScene s = scene_of(name, gen::boat(), "the boat of the paper's Fig. 3: keel folded, bow and stern diagonals valley");
    s.goal = projected_goal(*s.pattern, s.options, rng, [](std::mt19937& r) {
      Eigen::VectorXd g(10);
      g << 0.9, 0.9, 0.9, 0.9, -0.5, 0.5, 0.0, 0.0, 0.5, -0.5;
      return Eigen::VectorXd(g * std::uniform_real_distribution<double>(0.5, 1.2)(r));
    }, name);
    return s;
  }
  if (auto s = miura_scene(name, rng)) return *s;
  if (name == "waterbomb" || name == "waterbomb4x4") {
    const int n = name == "waterbomb" ? 2 : 4;
    const std::string size = std::to_string(n) + " units × " + std::to_string(n) + " rows";
    return assignment_scene(scene_of(name, gen::waterbomb(n, n), "waterbomb tessellation, " + size + ", flat to partly folded"),
                            rng, 0.2, 0.6);
  }
  if (auto s = imported_scene(name, rng)) return *s;
  if (name == "cube-sheet") {
    BenchScene s = scene_of(name, gen::cube_sheet(1), "one cube net (Fig. 8a), flat to most of the way to the cube");
    const Eigen::VectorXd dir = assignment_signs(*s.pattern);
    s.goal = projected_goal(*s.pattern, s.options, rng, [dir](std::mt19937& r) {
      std::uniform_real_distribution<double> u(0.5, 0.9);
      Eigen::VectorXd g = dir;
      for (Eigen::Index j = 0; j < g.size(); ++j) g[j] *= u(r) * M_PI / 2;
      return g;
    }, name);
    return s;
  }
  if (name == "corner-cube") {
    const double h = M_PI / 2, q = M_PI / 4;
    BenchScene s = scene_of(name, gen::single_vertex({h, h, h, q, q}),
                            "corner cube of Fig. 4 (sectors 90/90/90/45/45), flat to 0.01 rad short of the corner; "
                            "the goal does not depend on the seed");
    Eigen::VectorXd guess(5);
    guess << 0.778, -h + 0.01, -h + 0.01, 0.778, -M_PI + 0.02;
    geometry::ProjectionOptions po;
    po.tolerance = 1e-12;
    const auto r = geometry::project(geometry::ClosureSystem(*s.pattern), FoldState{guess}, po);
    if (!r.status.ok()) throw std::runtime_error("bench: the corner-cube goal does not close: " + r.status.message);
    s.goal = r.state;
    return s;
  }
  std::string known;
  for (const auto& n : bench_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown scene '" + name + "' (known: " + known + ")");
}

const std::vector<BenchSuite>& bench_suites() {
  static const std::vector<BenchSuite> suites = [] {
    std::vector<BenchSuite> s;
    s.push_back({"quick", "three small scenes, two planners: seconds (tests, CI)",
                 {"vertex4-random", "vertex8-random", "boat"}, {"RRTConnect", "ProjectedLine"}, ""});
    // Every scene but those of "miura-scale" and "vertex-complete", whose suites measure issue
    // 16's targets (and keep "full" comparable with its earlier runs).
    const auto ends_with = [](const std::string& n, const std::string& tail) {
      return n.size() >= tail.size() && n.compare(n.size() - tail.size(), tail.size(), tail) == 0;
    };
    std::vector<std::string> small;
    for (const auto& n : bench_scene_names())
      if (!ends_with(n, "-80") && !ends_with(n, "-any")) small.push_back(n);
    BenchSuite full{"full", "every scene but those of miura-scale and vertex-complete, sampling planners beside the deterministic ones", small,
                    {"RRTConnect", "KPIECE1", "BiTRRT", "PRM", "BKPIECE1", "EST", "RRT"}, ""};
    for (const auto& d : deterministic_planner_names()) full.planners.push_back(d);
    s.push_back(full);
    s.push_back({"spaces", "Miura 4x4, 10x10 and 20x20, waterbomb 4x4 and the boat, RRTConnect: run with --space "
                 "driving,projected,atlas,tangent-bundle for every space side by side in one log per scene (issue 16)",
                 {"miura4x4", "miura10x10", "miura20x20", "waterbomb4x4", "boat"}, {"RRTConnect"}, ""});
    s.push_back({"vertex-complete", "single vertices of degree 6, 8, 12 and 32, random goals not filtered for reachability "
                 "(issue 16's completeness target): RRTConnect alone, with the Carpenter fallback, and the spherical Carpenter alone",
                 {"vertex6-any", "vertex8-any", "vertex12-any", "vertex32-any"},
                 {"RRTConnect", "RRTConnect+Carpenter", "SphericalCarpenter"}, ""});
    s.push_back({"miura-scale", "Miura 10x10, 20x20 and 40x40 from flat to zig-zags at ±80° (issue 16's targets), RRTConnect",
                 {"miura10x10-80", "miura20x20-80", "miura40x40-80"}, {"RRTConnect"}, ""});
    // Issue 38, item 3: cost against time. Total crease rotation, not path length: in the driving
    // space the length is the driving angles' Euclidean distance, for which the straight motion
    // is optimal and the informed trees' first path (straight where it is valid) cannot improve;
    // the rotation of every crease (the passive ones included) is what the actuators travel, and
    // the planners lower it over time. None of these scenes has an obstacle but the sheet itself
    // (facets must not cross), so clearance would measure only how near the folded facets come.
    s.push_back({"optimal", "the optimising planners on Miura 10x10, waterbomb 4x4, the Resch pattern and a degree-12 vertex, "
                 "optimising total crease rotation: best cost against time (run with --time 3 or more)",
                 {"miura10x10", "waterbomb4x4", "resch", "vertex12-random"},
                 {"RRT*", "PRM*", "BIT*", "ABIT*", "AIT*", "RRT#", "FMT", "CForest"},
                 "rotation"});
    return s;
  }();
  return suites;
}

const BenchSuite& bench_suite(const std::string& name) {
  for (const BenchSuite& s : bench_suites())
    if (s.name == name) return s;
  std::string known;
  for (const BenchSuite& s : bench_suites()) known += (known.empty() ? "" : ", ") + s.name;
  throw std::invalid_argument("unknown suite '" + name + "' (known: " + known + ")");
}

}  // namespace foldkit::bench
