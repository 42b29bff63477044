// The side-by-side planning measurement of docs/PLANNING.md ("Measured"): for single vertices of
// degree 8 and 16, flat → a random folded goal with RRTConnect in
//   (a) our single-vertex space,
//   (b) OMPL's ProjectedStateSpace with our analytic Jacobian,
//   (c) ProjectedStateSpace with OMPL's default (numerical) Jacobian,
//   (d) plain joint-space sampling, closure by rejection (closure error ≤ 1e-3 rad).
// Prints a table and writes one CSV row per run.
//
// The goal set is deterministic per (degree, seed) and shares no randomness with OMPL: sector
// angles and the goal's active angles come from std::mt19937, and a goal is kept only when the
// straight segment from flat to it in the active angles is closed at every 0.02 rad (checked by
// the motion validator, which also rejects jumps) and, with --collision, collision-free — so
// every goal is provably connected to flat. OMPL's own stream is seeded once per process
// (ompl::RNG::setSeed only truly seeds once), so a run is repeatable as a whole, not per seed.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using foldkit::geometry::ClosureSystem;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
namespace ss = foldkit::statespaces;

struct Options {
  std::vector<int> degrees{8, 16};
  int seeds = 50;
  int rejection_seeds = 10;  // (d) burns its whole limit on every run
  double time = 5.0;
  bool collision = false;
  std::string methods = "abcd";
  std::string csv = "measure_planning.csv";
};


// A closed goal whose active angles are uniform in [−2, 2] (largest |angle| in [0.5, 2]) on a random
// branch, reachable from flat along the straight segment in the active angles.
FoldState connected_goal(const CreasePattern& p, std::mt19937& rng, bool collision_free) {
  const ss::AngleBounds bounds = ss::AngleBounds::of(p, false);
  auto space = std::make_shared<ss::SingleVertexStateSpace>(std::make_shared<ss::SingleVertexChain>(p), bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  auto validity = std::make_shared<ss::FoldValidity>(p, bounds, collision_free);
  ss::FoldMotionValidator motion(si, validity, ss::single_vertex_reader(space));
  ob::ScopedState<> flat(space), goal(space);
  if (!space->from_fold_state(FoldState::flat(p), flat.get())) throw std::runtime_error("flat is singular here");
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  auto* g = goal->as<ss::SingleVertexStateSpace::StateType>();
  for (int k = 0; k < 200000; ++k) {
    for (int j : space->chain().active_joints()) g->angles[j] = u(rng);
    space->complete(g, (rng() & 1u) ? 1 : -1);
    if (!g->closed || !space->satisfiesBounds(g)) continue;
    const FoldState f = space->to_fold_state(g);
    const double largest = f.angles.cwiseAbs().maxCoeff();
    if (largest > 2.0 || largest < 0.5) continue;
    if (!validity->valid(f) || !motion.checkMotion(flat.get(), goal.get())) continue;
    return f;
  }
  throw std::runtime_error("no connected goal");
}

struct Run {
  char method;
  int degree, seed;
  bool solved;
  double time;
  std::string message;
};

Run run_planner(char method, const CreasePattern& p, const FoldState& goal, const Options& o, int seed) {
  foldkit::planners::PlanOptions req;
  req.space = method == 'a' ? foldkit::planners::SpaceKind::SingleVertex : foldkit::planners::SpaceKind::Projected;
  req.numerical_jacobian = method == 'c';
  req.time = o.time;
  req.seed = static_cast<unsigned>(seed);
  req.collisions = o.collision;
  req.use_assignment = false;
  req.replay = false;  // the planner is measured; tests replay plans in the simulator
  Run r{method, static_cast<int>(p.joints().size()), seed, false, o.time, ""};
  try {
    const foldkit::planners::PlanResult res = foldkit::planners::plan(p, goal, req);
    r.solved = res.status.ok();
    r.time = res.status.ok() ? res.seconds : o.time;
    r.message = res.status.message;
  } catch (const std::exception& e) {
    r.message = e.what();
  }
  return r;
}

// (d): all n angles, bounded, a state valid when every loop closes within 1e-3 rad (and no facets
// cross with --collision); OMPL's default discrete motion validator.
Run run_rejection(const CreasePattern& p, const FoldState& goal, const Options& o, int seed) {
  const auto n = static_cast<unsigned>(p.joints().size());
  auto space = std::make_shared<ob::RealVectorStateSpace>(n);
  space->setBounds(-M_PI, M_PI);
  og::SimpleSetup setup(space);
  auto validity = std::make_shared<ss::FoldValidity>(p, ss::AngleBounds::of(p, false), o.collision, 1e-3);
  setup.setStateValidityChecker([validity, n](const ob::State* s) {
    thread_local FoldState f;
    f.angles = Eigen::Map<const Eigen::VectorXd>(s->as<ob::RealVectorStateSpace::StateType>()->values, n);
    return validity->valid(f);
  });
  setup.setPlanner(std::make_shared<og::RRTConnect>(setup.getSpaceInformation()));
  ob::ScopedState<> start(space), target(space);
  for (unsigned j = 0; j < n; ++j) {
    start[j] = 0.0;
    target[j] = goal.angles[j];
  }
  setup.setStartAndGoalStates(start, target, 1e-9);
  setup.setup();
  const ob::PlannerStatus status = setup.solve(o.time);
  const bool solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  return Run{'d', static_cast<int>(n), seed, solved, solved ? setup.getLastPlanComputationTime() : o.time,
             solved ? "solved" : "no plan"};
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

const char* method_name(char m) {
  switch (m) {
    case 'a': return "(a) single-vertex space";
    case 'b': return "(b) projected, analytic J";
    case 'c': return "(c) projected, numerical J";
    default: return "(d) joint space, rejection";
  }
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--degrees") {
      o.degrees.clear();
      std::stringstream s(next());
      for (std::string d; std::getline(s, d, ',');) o.degrees.push_back(std::stoi(d));
    } else if (a == "--seeds") {
      o.seeds = std::stoi(next());
    } else if (a == "--rejection-seeds") {
      o.rejection_seeds = std::stoi(next());
    } else if (a == "--time") {
      o.time = std::stod(next());
    } else if (a == "--methods") {
      o.methods = next();
    } else if (a == "--csv") {
      o.csv = next();
    } else if (a == "--collision") {
      o.collision = true;
    } else {
      throw std::invalid_argument("usage: measure_planning [--degrees 8,16] [--seeds 50] [--rejection-seeds 10] "
                                  "[--time 5] [--methods abcd] [--collision] [--csv FILE]");
    }
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parse(argc, argv);
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(1);
  std::ofstream csv(o.csv);
  csv << "method,degree,seed,collision,solved,time_s,message\n";
  std::map<std::pair<int, char>, std::vector<Run>> runs;
  for (int degree : o.degrees)
    for (int seed = 1; seed <= o.seeds; ++seed) {
      std::mt19937 rng(static_cast<unsigned>(1000 * degree + seed));
      const CreasePattern p = foldkit::geometry::build_or_throw(foldkit::geometry::generators::single_vertex(foldkit::geometry::generators::random_sectors(degree, rng, 0.2)));
      const FoldState goal = connected_goal(p, rng, o.collision);
      for (char m : o.methods) {
        if (m == 'd' && seed > o.rejection_seeds) continue;
        const Run r = m == 'd' ? run_rejection(p, goal, o, seed) : run_planner(m, p, goal, o, seed);
        runs[{degree, m}].push_back(r);
        csv << m << ',' << degree << ',' << seed << ',' << o.collision << ',' << r.solved << ',' << r.time << ",\""
            << r.message << "\"\n";
        csv.flush();
        std::cerr << "degree " << degree << " seed " << seed << ' ' << m << ": " << (r.solved ? "solved " : "failed ")
                  << r.time << " s" << (r.solved ? "" : " (" + r.message + ")") << '\n';
      }
    }
  std::cout << "RRTConnect, limit " << o.time << " s, collision " << (o.collision ? "on" : "off")
            << ", flat start, goals connected to flat (see docs/PLANNING.md)\n\n"
            << "| degree | method | runs | solved | solved ≤ 1 s | median time of successes (ms) | median time, failures at the limit (ms) |\n"
            << "|---|---|---|---|---|---|---|\n";
  for (const auto& [key, rs] : runs) {
    std::vector<double> ok, all;
    int within = 0;
    for (const Run& r : rs) {
      all.push_back(r.time);
      if (r.solved) ok.push_back(r.time);
      within += r.solved && r.time <= 1.0;
    }
    std::cout << std::fixed << std::setprecision(3) << "| " << key.first << " | " << method_name(key.second) << " | "
              << rs.size() << " | " << ok.size() << " (" << std::setprecision(0) << 100.0 * static_cast<double>(ok.size()) / static_cast<double>(rs.size())
              << "%) | " << within << " | " << std::setprecision(1) << 1e3 * median(ok) << " | " << 1e3 * median(all) << " |\n";
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "measure_planning: " << e.what() << '\n';
  return 2;
}
