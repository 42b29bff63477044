#include "foldkit/simulation/collision_world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>

#include "foldkit/geometry/kinematics.hpp"
#include "facet_chain.hpp"
#include "grid_broad_phase.hpp"
#include "pair_budget.hpp"
#include "world_facet.hpp"

namespace foldkit::simulation {

const char* to_string(CrossingKind kind) {
  switch (kind) {
    case CrossingKind::Mesh: return "mesh";
    case CrossingKind::Stacked: return "stacked";
    case CrossingKind::Crease: return "crease";
  }
  return "?";
}

namespace {

using geometry::CreasePattern;

using detail::Facet;
using detail::Side;
using detail::Below;
using detail::On;
using detail::Above;
using detail::Across;
using detail::kDirectTrianglePairs;

struct Memory {
  int side = On;      // last side seen other than On
  long sample = -1;   // check at which the pair was last seen
};

// What the world keeps about a pair the broad phase has kept. Found through the first actor's
// short sorted list (CollisionWorld::Impl::pair), with the chains in one pool: the candidates come
// sorted by first actor, so consecutive lookups touch neighbouring memory. Two hash maps (memory,
// chains) held this before, and their cache misses were a sixth of a check at Miura 40×40.
struct PairState {
  Memory memory;
  int chain_begin = -1;  // into chain_pool; -1 until searched
  int chain_size = 0;
  int apex = -1;         // the vertex every crease of the chain passes through, if any
  // The pair's verdict holds until its chain's weighted travel exceeds spent_at + budget
  // (detail::pair_budget); 0: test it at every check.
  double budget = 0.0;
  double spent_at = 0.0;
  double deadline = 0.0;  // the pair is skipped while the global travel is below this
  double lever_sum = 0.0;  // its chain's weights' sum
};

}  // namespace

struct CollisionWorld::Impl {
  const CreasePattern* pattern = nullptr;
  CollisionOptions options;
  double tol = 0.0;
  std::vector<Facet> facets;
  std::vector<std::vector<int>> hinged;  // per actor: the actors it shares a crease with, sorted
  std::size_t hinged_pairs = 0;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  detail::GridBroadPhase grid;
  std::vector<Eigen::Vector3d> box_lo, box_hi;  // per facet, grown (place)
  std::vector<std::vector<std::pair<int, int>>> slots;  // per first actor: (second actor, PairState index), sorted
  std::vector<PairState> pair_states;
  std::vector<int> chain_pool;
  std::vector<int> chain_actors;  // beside chain_pool: the actor each step enters
  std::vector<double> chain_weight;  // beside chain_pool: a step's lever (1 round an apex)
  // How far the joints have turned over this motion's checks; a pair's chain, weighted by its
  // levers, bounds by it how far its second facet moved in its first's coordinates.
  detail::Travel travel;
  std::vector<double> diameter;  // per actor: the largest distance between two of its points
  std::size_t skipped = 0;       // pairs the last check skipped on their budget
  long sample = 0;
  std::vector<std::pair<int, int>> candidates;
  std::size_t mesh_tests = 0;

  // The creases and their turns at the state being judged, for relative poses along chains.
  std::vector<geometry::JointAxis> axes;                      // per joint
  std::vector<std::array<double, 2>> sides;                   // per joint: side_of each of its actors
  const geometry::FoldState* state = nullptr;
  // Per chain step (joint << 1 | k): the motion of entering actors[k] across the joint, the turn or
  // its inverse, each computed once per state (valid where turn_stamp[joint] == stamp).
  std::vector<Eigen::Isometry3d> enter;
  std::vector<long> turn_stamp;
  long stamp = 0;
  // Relative poses along the current first actor's chains, per actor reached (valid where
  // reach_stamp == reach_epoch): every chain from `reach_from` is a path in one breadth-first tree
  // (chain), so its products share their prefixes, and the candidates come sorted by first actor.
  std::vector<Eigen::Isometry3d> reach;
  std::vector<long> reach_stamp;
  long reach_epoch = 0;
  int reach_from = -1;
  // Chains between pairs (detail::chain_steps, kept in chain_pool). A chain holding only kNoChain
  // means none within reach (the given poses are used).
  static constexpr int kNoChain = detail::kNoChain;
  // Farthest a chain search looks, in facets visited: a pair this far apart in the sheet is not
  // held together by a few loops, and its placement by the tree is as good as any.
  static constexpr std::size_t kMaxVisited = 256;

  Impl(const CreasePattern& p, const CollisionOptions& o) : pattern(&p), options(o), travel(p.joints().size()) {
    tol = o.tolerance * p.diagonal();
    hinged.resize(p.actors().size());
    slots.resize(p.actors().size());
    box_lo.resize(p.actors().size());
    box_hi.resize(p.actors().size());
    for (const auto& j : p.joints()) {
      hinged[j.actors[0]].push_back(j.actors[1]);
      hinged[j.actors[1]].push_back(j.actors[0]);
    }
    for (auto& h : hinged) {
      std::sort(h.begin(), h.end());
      h.erase(std::unique(h.begin(), h.end()), h.end());
      hinged_pairs += h.size();
    }
    hinged_pairs /= 2;
    facets.reserve(p.actors().size());
    for (std::size_t a = 0; a < p.actors().size(); ++a) facets.push_back(detail::make_facet(p, static_cast<int>(a)));
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const auto& joint = p.joints()[j];
      axes.push_back(geometry::joint_axis(p, static_cast<int>(j)));
      sides.push_back({geometry::side_of(p, static_cast<int>(j), joint.actors[0]),
                       geometry::side_of(p, static_cast<int>(j), joint.actors[1])});
    }
    enter.resize(2 * p.joints().size());
    for (const auto& f : facets) {
      double d = 0.0;
      for (const auto& x : f.points)
        for (const auto& y : f.points) d = std::max(d, (x - y).norm());
      diameter.push_back(d);
    }
    turn_stamp.assign(p.joints().size(), -1);
    reach.resize(p.actors().size());
    reach_stamp.assign(p.actors().size(), -1);
    if (o.broad_phase == BroadPhase::DynamicAabbTree) {
      for (auto& f : facets) manager.registerObject(f.object.get());
      manager.setup();
    }
  }

  // How far the given poses disagree across a crease: the two facets of each crease put its ends
  // in different places by up to this much (0 for a closed state's poses, up to round-off).
  double mismatch(const std::vector<Eigen::Isometry3d>& poses) const {
    double worst = 0.0;
    for (const auto& joint : pattern->joints())
      for (int v : joint.v) {
        const Eigen::Vector3d p(pattern->vertices()[v].x(), pattern->vertices()[v].y(), 0.0);
        worst = std::max(worst, (poses[joint.actors[0]] * p - poses[joint.actors[1]] * p).norm());
      }
    return worst;
  }

  void place(const std::vector<Eigen::Isometry3d>& poses) {
    // Pairs judged along their own chains may sit closer than the tree's poses say, by up to the
    // mismatch across the creases in between; twice the largest one keeps them in the broad phase.
    const Eigen::Vector3d grow = Eigen::Vector3d::Constant(options.margin + tol + 2.0 * mismatch(poses));
    for (std::size_t a = 0; a < facets.size(); ++a) {
      Facet& f = facets[a];
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
      for (const auto& p : f.points) {
        const Eigen::Vector3d w = poses[a] * p;
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
      }
      box_lo[a] = lo - grow;
      box_hi[a] = hi + grow;
      if (options.broad_phase == BroadPhase::DynamicAabbTree) {
        f.object->setTransform(poses[a]);
        f.object->set_box(fcl::AABBd(box_lo[a], box_hi[a]));
      }
    }
  }

  // Whether a and b share a crease: a facet has a handful, so a scan beats a hash.
  bool is_hinged(int a, int b) const {
    const auto& h = hinged[a];
    return std::find(h.begin(), h.end(), b) != h.end();
  }

  static bool gather(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
    auto* self = static_cast<Impl*>(data);
    int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
    int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
    if (a > b) std::swap(a, b);
    if (!self->is_hinged(a, b)) self->candidates.emplace_back(a, b);
    return false;
  }

  void find_candidates() {
    candidates.clear();
    if (options.broad_phase == BroadPhase::Grid) {
      grid.overlapping(box_lo, box_hi, candidates);
      candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                      [this](const std::pair<int, int>& c) { return is_hinged(c.first, c.second); }),
                       candidates.end());
      return;
    }
    if (options.broad_phase == BroadPhase::DynamicAabbTree) {
      manager.update();
      manager.collide(this, &Impl::gather);
      // The tree's traversal order depends on its balance; sorted pairs keep reports stable.
      std::sort(candidates.begin(), candidates.end());
      return;
    }
    const int n = static_cast<int>(facets.size());
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (!is_hinged(a, b)) candidates.emplace_back(a, b);
  }

  void start(const geometry::FoldState& s) {
    state = &s;
    ++stamp;
    reach_from = -1;
  }

  const Eigen::Isometry3d& entering(int step) {
    const int joint = step >> 1;
    if (turn_stamp[joint] != stamp) {
      const Eigen::Isometry3d turn = geometry::joint_motion(axes[joint], state->angles[joint]);
      // Entering the facet on the right of the axis turns it by +angle, on the left by −angle.
      for (int k = 0; k < 2; ++k) enter[2 * joint + k] = sides[joint][k] > 0 ? turn : turn.inverse();
      turn_stamp[joint] = stamp;
    }
    return enter[step];
  }

  // The pair's record. check() asks in (a, b) order, so a cursor walks a's list forward; a binary
  // search per pair mispredicted its branches for a tenth of a check.
  PairState& pair(int a, int b) {
    auto& list = slots[a];
    if (a != cursor_actor || cursor > list.size() || (cursor > 0 && list[cursor - 1].first >= b)) {
      cursor_actor = a;
      cursor = static_cast<std::size_t>(std::lower_bound(list.begin(), list.end(), std::make_pair(b, -1)) - list.begin());
    }
    while (cursor < list.size() && list[cursor].first < b) ++cursor;
    if (cursor == list.size() || list[cursor].first != b) {
      list.insert(list.begin() + static_cast<std::ptrdiff_t>(cursor), {b, static_cast<int>(pair_states.size())});
      pair_states.emplace_back();
    }
    return pair_states[list[cursor].second];
  }
  int cursor_actor = -1;
  std::size_t cursor = 0;

  struct Steps {
    const int* begin;
    const int* actors;  // the actor each step enters
    int size;
  };
  Steps chain(int a, int b) { return chain(a, b, pair(a, b)); }
  Steps chain(int a, int b, PairState& ps) {
    if (ps.chain_begin < 0) {
      const std::vector<int> steps = detail::chain_steps(*pattern, a, b, kMaxVisited);
      ps.chain_begin = static_cast<int>(chain_pool.size());
      ps.chain_size = static_cast<int>(steps.size());
      chain_pool.insert(chain_pool.end(), steps.begin(), steps.end());
      for (int step : steps) chain_actors.push_back(step == kNoChain ? -1 : entered(step));
      detail::Levers levers;
      if (steps[0] != kNoChain) levers = detail::chain_levers(*pattern, steps, diameter);
      levers.weights.resize(steps.size(), 0.0);
      ps.apex = levers.apex;
      ps.lever_sum = levers.sum;
      chain_weight.insert(chain_weight.end(), levers.weights.begin(), levers.weights.end());
    }
    return {chain_pool.data() + ps.chain_begin, chain_actors.data() + ps.chain_begin, ps.chain_size};
  }

  // b's coordinates in a's: along their chain at the current state, or from the given poses.
  Eigen::Isometry3d relative(int a, int b, const std::vector<Eigen::Isometry3d>& poses) {
    return relative(a, b, chain(a, b), poses);
  }
  Eigen::Isometry3d relative(int a, int b, Steps steps, const std::vector<Eigen::Isometry3d>& poses) {
    if (steps.begin[0] == kNoChain) return poses[a].inverse() * poses[b];
    if (a != reach_from) {
      reach_from = a;
      ++reach_epoch;
      reach[a] = Eigen::Isometry3d::Identity();
      reach_stamp[a] = reach_epoch;
    }
    // The deepest actor along the chain whose pose is known, then the products on from it, in
    // the same order as composing the whole chain from a: the same numbers, fewer products.
    const int* step = steps.begin;
    int known = steps.size;
    while (known > 0 && reach_stamp[steps.actors[known - 1]] != reach_epoch) --known;
    Eigen::Isometry3d rel = known > 0 ? reach[steps.actors[known - 1]] : Eigen::Isometry3d::Identity();
    for (int i = known; i < steps.size; ++i) {
      rel = rel * entering(step[i]);
      const int f = steps.actors[i];
      reach[f] = rel;
      reach_stamp[f] = reach_epoch;
    }
    return rel;
  }
  // The actor a chain step enters.
  int entered(int step) const { return pattern->joints()[step >> 1].actors[step & 1]; }
  // The chain's weighted travel so far (see travel).
  double spent(Steps steps) const {
    double sum = 0.0;
    const double* w = chain_weight.data() + (steps.begin - chain_pool.data());
    for (int i = 0; i < steps.size; ++i) sum += w[i] * travel.joint(steps.begin[i] >> 1);
    return sum;
  }
  // Whether the pair's last verdict still holds: first by the deadline, then by its own chain,
  // which moves the deadline on by what is left of the budget.
  bool certified(PairState& ps, Steps steps) {
    if (ps.budget <= 0.0) return false;
    if (travel.global() < ps.deadline) return true;
    const double left = ps.budget - (spent(steps) - ps.spent_at);
    if (!(left > 0.0)) return false;
    ps.deadline = travel.global() + left / ps.lever_sum;
    return true;
  }
  // How far the pair may move before it must be tested again, given how it was found now.
  void certify(int a, int b, PairState& ps, Steps steps, const Eigen::Isometry3d& rel, Side side) {
    ps.budget = 0.0;
    // A zero tolerance leaves round-off at a shared corner (1e-16) to decide: no budget is safe.
    if (!options.certificates || !(tol > 0.0) || steps.begin[0] == kNoChain || side == On) return;
    Eigen::Vector3d apex;
    detail::Motion motion{nullptr, tol};
    if (ps.apex >= 0) {
      apex = Eigen::Vector3d(pattern->vertices()[ps.apex].x(), pattern->vertices()[ps.apex].y(), 0.0);
      motion.apex = &apex;
    }
    if (side == Across && facets[a].triangles.size() * facets[b].triangles.size() > kDirectTrianglePairs) return;
    placed.clear();
    for (const auto& p : facets[b].points) placed.push_back(rel * p);
    const detail::PlacedPair pair{facets[a].points, facets[a].triangles, placed, facets[b].triangles, rel.linear().col(2)};
    double budget = detail::pair_budget(pair, motion, side, a_heights, b_heights);
    // Round-off in the heights and angles is far below this.
    budget -= motion.apex ? 1e-12 : 1e-9 * tol;
    if (budget <= 0.0 || !(ps.lever_sum > 0.0)) return;
    ps.budget = budget;
    ps.spent_at = spent(steps);
    ps.deadline = travel.global() + budget / ps.lever_sum;
  }
  std::vector<Eigen::Vector3d> placed;  // certify's scratch
  detail::Heights a_heights, b_heights;
  // The deepest crossing of a's and b's triangles (detail::deepest_crossing), its point in world
  // coordinates by a's pose.
  std::optional<Crossing> mesh_crossing(int a, int b, const Eigen::Isometry3d& rel, const std::vector<Eigen::Isometry3d>& poses) {
    ++mesh_tests;
    const auto deepest = detail::deepest_crossing(facets[a], facets[b], rel, tol);
    if (!deepest) return std::nullopt;
    return Crossing{{a, b}, poses[a] * deepest->point, CrossingKind::Mesh, deepest->depth};
  }

  std::optional<Crossing> test(int a, int b, const std::vector<Eigen::Isometry3d>& poses) {
    PairState& ps = pair(a, b);
    const Steps steps = chain(a, b, ps);
    Memory& m = ps.memory;
    // Certified to be on the same side, crossing nothing, as at its last test (certify): its
    // memory is what that test left, seen now.
    if (certified(ps, steps)) {
      m.sample = sample;
      ++skipped;
      return std::nullopt;
    }
    const Eigen::Isometry3d rel = relative(a, b, steps, poses);
    const Side side = detail::side_of(facets[b], rel, tol);
    const bool seen_last = m.sample == sample - 1;
    const int before = seen_last ? m.side : On;
    m.sample = sample;
    if (side == Across) {
      m.side = On;
      auto crossing = mesh_crossing(a, b, rel, poses);
      if (!crossing) certify(a, b, ps, steps, rel, side);
      return crossing;
    }
    if (side == On) {
      m.side = before;
      return std::nullopt;
    }
    m.side = side;
    ps.budget = 0.0;
    // Wholly on one side of a's plane at the last check and wholly on the other now, without
    // passing across it in between: b went through a unless it went round a's edge.
    if (before != On && before != side && detail::overlap_in_plane(facets[a], facets[b], rel, tol)) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const auto& p : facets[b].points) centre += rel * p;
      centre /= static_cast<double>(facets[b].points.size());
      centre.z() = 0.0;
      return Crossing{{a, b}, poses[a] * centre, CrossingKind::Stacked};
    }
    certify(a, b, ps, steps, rel, side);
    return std::nullopt;
  }

  std::vector<Crossing> check(const std::vector<Eigen::Isometry3d>& poses, const geometry::FoldState& at) {
    if (poses.size() != facets.size())
      throw std::invalid_argument("CollisionWorld::check: " + std::to_string(poses.size()) + " poses for " +
                                  std::to_string(facets.size()) + " actors");
    if (static_cast<std::size_t>(at.angles.size()) != pattern->joints().size())
      throw std::invalid_argument("CollisionWorld::check: state does not hold one angle per joint");
    mesh_tests = 0;
    skipped = 0;
    start(at);
    travel.advance(at.angles);
    place(poses);
    find_candidates();
    std::vector<Crossing> found;
    for (const auto& [a, b] : candidates)
      if (auto c = test(a, b, poses)) found.push_back(*c);
    for (std::size_t j = 0; j < pattern->joints().size(); ++j) {
      // Two facets turning about their common crease meet again only beyond ±180°.
      if (std::abs(at.angles[static_cast<Eigen::Index>(j)]) <= M_PI + 1e-12) continue;
      const auto& joint = pattern->joints()[j];
      const geometry::Vec2 mid = 0.5 * (pattern->vertices()[joint.v[0]] + pattern->vertices()[joint.v[1]]);
      const int a = std::min(joint.actors[0], joint.actors[1]);
      const int b = std::max(joint.actors[0], joint.actors[1]);
      found.push_back({{a, b}, poses[joint.actors[0]] * Eigen::Vector3d(mid.x(), mid.y(), 0.0), CrossingKind::Crease, 0.0});
    }
    ++sample;
    return found;
  }
};

CollisionWorld::CollisionWorld(const CreasePattern& pattern, const CollisionOptions& options) {
  if (!(options.tolerance >= 0.0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument("collision tolerance must be finite and non-negative");
  if (!(options.margin >= 0.0) || !std::isfinite(options.margin))
    throw std::invalid_argument("collision margin must be finite and non-negative");
  impl_ = std::make_unique<Impl>(pattern, options);
}
CollisionWorld::~CollisionWorld() = default;
CollisionWorld::CollisionWorld(CollisionWorld&&) noexcept = default;
CollisionWorld& CollisionWorld::operator=(CollisionWorld&&) noexcept = default;

std::vector<Crossing> CollisionWorld::check(const std::vector<Eigen::Isometry3d>& poses, const geometry::FoldState& state) {
  return impl_->check(poses, state);
}
std::optional<Crossing> CollisionWorld::mesh_crossing(int a, int b, const std::vector<Eigen::Isometry3d>& poses,
                                                      const geometry::FoldState& state) {
  const int n = static_cast<int>(impl_->facets.size());
  if (a < 0 || b < 0 || a >= n || b >= n || a == b || poses.size() != impl_->facets.size() ||
      static_cast<std::size_t>(state.angles.size()) != impl_->pattern->joints().size())
    throw std::invalid_argument("CollisionWorld::mesh_crossing: actors, poses or state out of range");
  if (a > b) std::swap(a, b);
  impl_->start(state);
  return impl_->mesh_crossing(a, b, impl_->relative(a, b, poses), poses);
}

void CollisionWorld::reset() {
  for (auto& state : impl_->pair_states) {
    state.memory = Memory{};
    state.budget = 0.0;
  }
  impl_->travel.reset();
  impl_->sample = 0;
}
double CollisionWorld::tolerance() const { return impl_->tol; }
std::size_t CollisionWorld::checked_pairs() const { return impl_->candidates.size(); }
std::size_t CollisionWorld::mesh_tests() const { return impl_->mesh_tests; }
std::size_t CollisionWorld::skipped_pairs() const { return impl_->hinged_pairs; }
std::size_t CollisionWorld::certified_pairs() const { return impl_->skipped; }

}  // namespace foldkit::simulation
