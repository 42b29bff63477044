// Forward kinematics (the pose of every facet from the crease angles), side by side:
//   BM_FK_Ours     — geometry::facet_poses: one pass down the kinematic tree, each pose its
//                    parent's times one joint motion (O(facets));
//   BM_FK_Baseline — the textbook product of exponentials, each facet's 4×4 transform rebuilt
//                    from the root along its own chain of twists (O(facets × depth)), the way a
//                    serial-chain robotics library evaluates every link on its own.
// Argument: n > 0 a degree-n single vertex; n < 0 a Miura-ori of −n × −n facets.
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "bench_patterns.hpp"
#include "foldkit/geometry/kinematics.hpp"

namespace {

using namespace foldkit::geometry;

using foldkit::bench::pattern_for;
using foldkit::bench::some_state;

// exp of the twist of a pure rotation by θ about the unit axis ω through q: [R, (I − R) q; 0, 1].
Eigen::Matrix4d twist_exp(const Eigen::Vector3d& w, const Eigen::Vector3d& q, double theta) {
  const Eigen::Matrix3d W = (Eigen::Matrix3d() << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0).finished();
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() + std::sin(theta) * W + (1 - std::cos(theta)) * W * W;  // Rodrigues
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = R;
  T.topRightCorner<3, 1>() = (Eigen::Matrix3d::Identity() - R) * q;
  return T;
}

// Every facet from scratch: its chain of joints back to the root, then the product root → facet.
std::vector<Eigen::Matrix4d> poses_from_scratch(const CreasePattern& p, const KinematicTree& tree, const FoldState& s,
                                                std::vector<int>& chain) {
  std::vector<Eigen::Matrix4d> out(p.actors().size());
  for (std::size_t a = 0; a < out.size(); ++a) {
    chain.clear();
    for (int b = static_cast<int>(a); tree.parent[b] >= 0; b = tree.parent[b]) chain.push_back(b);
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int j = tree.parent_joint[*it];
      const JointAxis axis = joint_axis(p, j);
      T = T * twist_exp(axis.direction, axis.point, tree.side[*it] * s.angles[j]);
    }
    out[a] = T;
  }
  return out;
}

void counters(benchmark::State& st, const CreasePattern& p) {
  st.counters["facets"] = static_cast<double>(p.actors().size());
  st.counters["creases"] = static_cast<double>(p.joints().size());
}

void BM_FK_Ours(benchmark::State& st) {
  const CreasePattern p = pattern_for(static_cast<int>(st.range(0)));
  const KinematicTree tree = make_tree(p);
  const FoldState s = some_state(p);
  for (auto _ : st) {
    auto poses = facet_poses(p, tree, s);
    benchmark::DoNotOptimize(poses.data());
  }
  counters(st, p);
}

void BM_FK_Baseline(benchmark::State& st) {
  const CreasePattern p = pattern_for(static_cast<int>(st.range(0)));
  const KinematicTree tree = make_tree(p);
  const FoldState s = some_state(p);
  std::vector<int> chain;
  // Both ways must give the same poses, or the comparison means nothing.
  const auto ours = facet_poses(p, tree, s);
  const auto theirs = poses_from_scratch(p, tree, s, chain);
  double worst = 0;
  for (std::size_t a = 0; a < ours.size(); ++a) worst = std::max(worst, (ours[a].matrix() - theirs[a]).cwiseAbs().maxCoeff());
  if (worst > 1e-9) st.SkipWithError(("the product of exponentials disagrees with facet_poses by " + std::to_string(worst)).c_str());
  for (auto _ : st) {
    auto poses = poses_from_scratch(p, tree, s, chain);
    benchmark::DoNotOptimize(poses.data());
  }
  counters(st, p);
  st.counters["max_pose_difference"] = worst;
}

}  // namespace

BENCHMARK(BM_FK_Ours)->Arg(8)->Arg(64)->Arg(-10)->Arg(-20)->Arg(-40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FK_Baseline)->Arg(8)->Arg(64)->Arg(-10)->Arg(-20)->Arg(-40)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
