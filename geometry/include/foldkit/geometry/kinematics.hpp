#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::geometry {

// A spanning forest of the facet graph: each actor reached from its parent through one joint.
// A joint turns the facet on the right of its axis (v[0] → v[1], seen from +z) by +angle about
// that axis, the facet on its left by −angle: positive = mountain (the facets fall below the
// crease), whatever the order of the joint's actors or ends.
struct KinematicTree {
  std::vector<int> order;         // actors, parents before children; roots first in each component
  std::vector<int> parent;        // parent actor, −1 for a root
  std::vector<int> parent_joint;  // joint to the parent, −1 for a root
  std::vector<double> side;       // +1 when the actor is on the right of its parent joint's axis, −1 on its left
  std::vector<bool> in_tree;      // per joint
};

// Breadth-first from `root` (actor index; other components from their lowest actor index).
KinematicTree make_tree(const CreasePattern& pattern, int root = 0);

// A joint's axis in the flat sheet (z = 0): its first end and its unit direction v[0] → v[1].
struct JointAxis {
  Eigen::Vector3d point;
  Eigen::Vector3d direction;
};
JointAxis joint_axis(const CreasePattern& pattern, int joint);

// The rigid motion that turns a facet by `angle` (radians, right-hand rule) about `axis`.
Eigen::Isometry3d joint_motion(const JointAxis& axis, double angle);

// +1 when `actor` lies on the right of the axis of `joint` (v[0] → v[1]), −1 on its left.
double side_of(const CreasePattern& pattern, int joint, int actor);

// Rigid motion of each actor from its flat position (the root stays put).
std::vector<Eigen::Isometry3d> facet_poses(const CreasePattern& pattern, const KinematicTree& tree,
                                           const FoldState& state);

}  // namespace foldkit::geometry
