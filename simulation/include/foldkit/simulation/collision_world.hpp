#pragma once
/// @file
/// Collision detection between the facets of a folding sheet, through FCL.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::simulation {

/// How candidate pairs of facets are found before the exact test.
enum class BroadPhase {
  /// a uniform grid over the facets' boxes (the default): the same pairs as DynamicAabbTree, found
  /// for a fraction of its cost on a sheet of many facets of one size
  Grid,
  DynamicAabbTree,  ///< FCL's dynamic AABB tree manager (the default until issue 35)
  AllPairs,         ///< every pair through the narrow phase: the baseline benchmarks compare with
};

/// Tolerances and broad phase of a CollisionWorld.
struct CollisionOptions {
  /// Distance (relative to the sheet's bounding-box diagonal) within which points count as
  /// touching: a facet must pass farther than this through another to cross it. Finite, ≥ 0.
  double tolerance = 1e-6;
  /// Absolute distance (pattern units; finite, ≥ 0) by which every facet's bounding box grows,
  /// so that pairs that may meet before the next check are compared now (the simulator passes
  /// its largest sweep per check).
  double margin = 0.0;
  BroadPhase broad_phase = BroadPhase::Grid;  ///< how candidate pairs are found
  /// Skip a pair until its facets can have moved, relative to each other, far enough to change
  /// its verdict (bounded by how far the creases of its chain have turned since its last test;
  /// docs/SIMULATION.md): the same verdicts for a fraction of the work. Off: every pair the
  /// broad phase keeps is tested at every check.
  bool certificates = true;
};

/// How two facets were found to cross.
enum class CrossingKind {
  Mesh,     ///< the facets' triangles cut through each other
  Stacked,  ///< facets lying flat on each other changed sides between two checks
  Crease,   ///< a crease turned past ±180°: its two facets passed through each other
};
/// The kind's name: "mesh", "stacked" or "crease".
const char* to_string(CrossingKind kind);

/// Two facets that pass through each other.
struct Crossing {
  std::array<int, 2> actors{};  ///< actor indices, smaller first
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< where, in world coordinates (those of the poses)
  CrossingKind kind = CrossingKind::Mesh;  ///< how they cross
  /// Mesh crossings: how far the deepest-crossing pair of triangles interpenetrates (sheet units;
  /// the smaller reach of either triangle through the other's plane). 0 for the other kinds.
  double depth = 0.0;
};

/// The sheet's facets as FCL triangle meshes. Pairs of facets that share a crease are left out of
/// the mesh test and judged by their fold angle instead; every other pair near enough for the
/// broad phase is judged by the rules of docs/SIMULATION.md: touching is allowed, crossing is not.
///
/// A pair is judged in the coordinates of its first facet, with the second placed through the creases
/// of the shortest chain of facets between them (round their common vertex, for facets that share
/// one), not through the poses given: those come from one spanning tree, and a state that closes
/// only to round-off or to an interpolation's error (1e-5 rad) opens, along a tree 100 facets
/// deep, into gaps and overlaps of hundredths of the sheet's unit between facets that hang from
/// different branches. The given poses serve the broad phase (grown by their measured mismatch
/// across the creases outside the tree) and pairs in different components of the sheet.
///
/// A world remembers the motion it checks, so one world serves one thread at a time.
class CollisionWorld {
 public:
  /// Builds the facet meshes of `pattern`. Keeps a reference to `pattern`, which must outlive
  /// the world.
  /// @throws std::invalid_argument when options.tolerance or options.margin is negative or not
  ///         finite
  explicit CollisionWorld(const geometry::CreasePattern& pattern, const CollisionOptions& options = {});
  /// Deleted: the world keeps a reference to its pattern, so a temporary one is refused.
  CollisionWorld(geometry::CreasePattern&&, const CollisionOptions& = {}) = delete;
  ~CollisionWorld();  ///< Frees the meshes.
  CollisionWorld(CollisionWorld&&) noexcept;  ///< Takes over another world (left empty).
  CollisionWorld& operator=(CollisionWorld&&) noexcept;  ///< Takes over another world (left empty).

  /// The crossings at `poses` (one per actor, as from geometry::facet_poses) and `state` (one
  /// angle per joint, radians). Each call remembers on which side of each other nearby stacked
  /// facets lie, so calls must follow the motion in order, close enough that no facet moves
  /// farther than `margin` between two.
  /// @return every crossing found; empty when the state is free of collisions
  /// @throws std::invalid_argument when `poses` or `state` has the wrong size
  std::vector<Crossing> check(const std::vector<Eigen::Isometry3d>& poses, const geometry::FoldState& state);
  /// Forgets that memory (a new motion starts).
  void reset();

  /// Whether facets `a` and `b` (actor indices, not hinged together) cut through each other at
  /// `state`, judged as check() judges a mesh crossing but without its broad phase or memory;
  /// `poses` place facets of different components. Used to test a crossing again at a nearby
  /// state (the simulator's closed-state recheck).
  /// @return the crossing, or nothing when they do not cross
  /// @throws std::invalid_argument when `a` or `b` is out of range, a = b, or `poses` or `state`
  ///         has the wrong size
  std::optional<Crossing> mesh_crossing(int a, int b, const std::vector<Eigen::Isometry3d>& poses,
                                        const geometry::FoldState& state);

  double tolerance() const;                 ///< the touching distance, absolute (pattern units)
  std::size_t checked_pairs() const;        ///< pairs the broad phase passed on the last check
  std::size_t mesh_tests() const;           ///< pairs that went to FCL's narrow phase on the last check
  std::size_t skipped_pairs() const;        ///< facet pairs that share a crease
  std::size_t certified_pairs() const;      ///< pairs the last check skipped, certified unchanged

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foldkit::simulation
