#pragma once
/// @file
/// Forward kinematics of a crease pattern: a spanning tree of its facets, the joints' axes and
/// the rigid motion of every facet at a fold state.
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::geometry {

/// A spanning forest of the facet graph: each actor reached from its parent through one joint.
/// A joint turns the facet on the right of its axis (v[0] → v[1], seen from +z) by +angle about
/// that axis, the facet on its left by −angle: positive = mountain (the facets fall below the
/// crease), whatever the order of the joint's actors or ends. Per-actor vectors are indexed by
/// actor index, per-joint ones by joint index.
struct KinematicTree {
  std::vector<int> order;         ///< actors, parents before children; roots first in each component
  std::vector<int> parent;        ///< per actor: parent actor, −1 for a root
  std::vector<int> parent_joint;  ///< per actor: joint to the parent, −1 for a root
  std::vector<double> side;       ///< per actor: +1 when on the right of its parent joint's axis, −1 on its left
  std::vector<bool> in_tree;      ///< per joint: whether it is a tree edge
};

/// Breadth-first spanning forest of `pattern`'s facet graph.
/// @param pattern  the pattern
/// @param root     actor index of the root of its component; other components are rooted at
///                 their lowest actor index
/// @throws std::invalid_argument when `root` is not an actor index
KinematicTree make_tree(const CreasePattern& pattern, int root = 0);

/// A joint's axis in the flat sheet (z = 0).
struct JointAxis {
  Eigen::Vector3d point;      ///< the joint's first end v[0], pattern units
  Eigen::Vector3d direction;  ///< unit direction v[0] → v[1]
};

/// The axis of joint index `joint` (which must be in range) in the flat sheet.
JointAxis joint_axis(const CreasePattern& pattern, int joint);

/// The rigid motion that turns a facet by `angle` (radians, right-hand rule) about `axis`.
Eigen::Isometry3d joint_motion(const JointAxis& axis, double angle);

/// +1 when `actor` lies on the right of the axis of `joint` (v[0] → v[1], seen from +z), −1 on
/// its left; both are indices, and the side is told by the actor's triangle with an edge on the
/// crease.
/// @throws std::logic_error when the actor has no edge on the joint
double side_of(const CreasePattern& pattern, int joint, int actor);

/// Rigid motion of each actor from its flat position (the root of each component stays put).
/// @param pattern  the pattern
/// @param tree     a tree of `pattern` (make_tree())
/// @param state    one angle per joint, radians
/// @return one pose per actor, indexed by actor index
std::vector<Eigen::Isometry3d> facet_poses(const CreasePattern& pattern, const KinematicTree& tree,
                                           const FoldState& state);

}  // namespace foldkit::geometry
