// One simulator step (forward kinematics, closure error, self-collision check) on a Miura-ori
// folding along its mode, with three ways of finding crossings side by side:
//   BM_Collision_Ours          — our CollisionWorld: the grid broad phase (the default since issue 35),
//                                then the touching/crossing rules on the pairs whose verdict is not
//                                certified unchanged since their last test;
//   BM_Collision_EveryPair     — the same, testing every pair the broad phase keeps at every step
//                                (CollisionOptions::certificates off, as before issue 35's second part);
//   BM_Collision_Tree          — the same with FCL's dynamic AABB tree as the broad phase (the
//                                default before issue 35): same pairs, same verdicts;
//   BM_Collision_AllPairsRules — the same rules on every pair, no broad phase;
//   BM_Collision_Baseline      — the generic way: fcl::collide on every pair of facet meshes.
#include <map>
#include <memory>

#include <benchmark/benchmark.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/simulation/collision_world.hpp"

namespace {

using namespace foldkit;
using geometry::CreasePattern;
using geometry::FoldState;

// A Miura-ori of n × n facets and states along its fold, from nearly flat to deeply folded and
// back: 24 closed states (projected onto closure by continuation), ten straight steps between two
// (about 0.01 rad per step, as the simulator's checks are), built once per size.
struct Scene {
  CreasePattern pattern;
  std::vector<FoldState> states;
};

const Scene& scene(int n) {
  static std::map<int, std::unique_ptr<Scene>> cache;
  auto& slot = cache[n];
  if (!slot) {
    CreasePattern p = geometry::build_or_throw(geometry::generators::miura(n, n));
    slot = std::make_unique<Scene>(Scene{std::move(p), {}});
    const geometry::ClosureSystem sys(slot->pattern);
    FoldState s = FoldState::flat(slot->pattern);
    for (int k = 1; k <= 24; ++k) {
      const double m = 0.1 * k;
      for (std::size_t j = 0; j < slot->pattern.joints().size(); ++j)
        s.angles[static_cast<Eigen::Index>(j)] =
            (slot->pattern.joints()[j].assignment == geometry::Assignment::Mountain ? 1 : -1) * std::max(m, std::abs(s.angles[static_cast<Eigen::Index>(j)]));
      const auto r = geometry::project(sys, s);
      if (!r.status.ok()) break;
      s = r.state;
      slot->states.push_back(s);
    }
    std::vector<FoldState> path;
    for (std::size_t k = 0; k + 1 < slot->states.size(); ++k)
      for (int i = 0; i < 10; ++i) {
        const auto& a = slot->states[k].angles;
        path.push_back(FoldState{a + (slot->states[k + 1].angles - a) * (i / 10.0)});
      }
    path.push_back(slot->states.back());
    for (std::size_t k = path.size() - 1; k-- > 1;) path.push_back(path[k]);
    slot->states = std::move(path);
  }
  return *slot;
}

void report(benchmark::State& st, const Scene& sc, double pairs, double mesh_tests, double certified = 0.0) {
  st.SetItemsProcessed(st.iterations());  // items = simulator steps
  st.counters["facets"] = static_cast<double>(sc.pattern.actors().size());
  st.counters["states"] = static_cast<double>(sc.states.size());
  st.counters["pairs_per_step"] = benchmark::Counter(pairs, benchmark::Counter::kAvgIterations);
  st.counters["mesh_tests_per_step"] = benchmark::Counter(mesh_tests, benchmark::Counter::kAvgIterations);
  st.counters["certified_per_step"] = benchmark::Counter(certified, benchmark::Counter::kAvgIterations);
}

void run_world(benchmark::State& st, simulation::BroadPhase phase, bool certificates = true) {
  const Scene& sc = scene(static_cast<int>(st.range(0)));
  const geometry::KinematicTree tree = geometry::make_tree(sc.pattern);
  const geometry::ClosureSystem closure(sc.pattern);
  simulation::CollisionOptions o;
  o.broad_phase = phase;
  o.margin = 0.05;
  o.certificates = certificates;
  simulation::CollisionWorld world(sc.pattern, o);
  std::size_t k = 0;
  double pairs = 0, mesh = 0, certified = 0;
  std::size_t crossings = 0;
  for (auto _ : st) {
    const FoldState& s = sc.states[k++ % sc.states.size()];
    const auto poses = geometry::facet_poses(sc.pattern, tree, s);
    benchmark::DoNotOptimize(closure.max_error(s));
    crossings += world.check(poses, s).size();
    pairs += static_cast<double>(world.checked_pairs());
    mesh += static_cast<double>(world.mesh_tests());
    certified += static_cast<double>(world.certified_pairs());
  }
  if (crossings) st.SkipWithError("a Miura-ori along its mode must not cross itself");
  report(st, sc, pairs, mesh, certified);
}

void BM_Collision_Ours(benchmark::State& st) { run_world(st, simulation::BroadPhase::Grid); }
void BM_Collision_EveryPair(benchmark::State& st) { run_world(st, simulation::BroadPhase::Grid, false); }
void BM_Collision_Tree(benchmark::State& st) { run_world(st, simulation::BroadPhase::DynamicAabbTree); }
void BM_Collision_AllPairsRules(benchmark::State& st) { run_world(st, simulation::BroadPhase::AllPairs); }

void BM_Collision_Baseline(benchmark::State& st) {
  const Scene& sc = scene(static_cast<int>(st.range(0)));
  const CreasePattern& p = sc.pattern;
  const geometry::KinematicTree tree = geometry::make_tree(p);
  const geometry::ClosureSystem closure(p);
  std::vector<std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>>> meshes;
  for (const auto& actor : p.actors()) {
    std::vector<fcl::Vector3d> points;
    std::vector<fcl::Triangle> triangles;
    for (const auto& t : actor.triangles) {
      const int base = static_cast<int>(points.size());
      for (int v : t.v) points.emplace_back(p.vertices()[v].x(), p.vertices()[v].y(), 0.0);
      triangles.emplace_back(base, base + 1, base + 2);
    }
    auto m = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    m->beginModel();
    m->addSubModel(points, triangles);
    m->endModel();
    meshes.push_back(m);
  }
  const std::size_t n = meshes.size();
  std::size_t k = 0;
  double pairs = 0;
  for (auto _ : st) {
    const FoldState& s = sc.states[k++ % sc.states.size()];
    const auto poses = geometry::facet_poses(p, tree, s);
    benchmark::DoNotOptimize(closure.max_error(s));
    std::size_t hits = 0;
    fcl::CollisionRequestd request;
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) {
        fcl::CollisionResultd result;
        hits += fcl::collide(meshes[a].get(), poses[a], meshes[b].get(), poses[b], request, result);
      }
    pairs += static_cast<double>(n * (n - 1) / 2);
    benchmark::DoNotOptimize(hits);  // includes every touching neighbour (fcl#502): not a verdict
  }
  report(st, sc, pairs, pairs);
}

}  // namespace

BENCHMARK(BM_Collision_Ours)->Arg(20)->Arg(40)->Arg(60)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Collision_EveryPair)->Arg(20)->Arg(40)->Arg(60)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Collision_Tree)->Arg(20)->Arg(40)->Arg(60)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Collision_AllPairsRules)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Collision_Baseline)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
