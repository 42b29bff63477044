#pragma once
/// @file
/// A crease pattern as written in a file, before any check (PMML, paper Table 1).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry {

/// One triangle of an actor as written (PMML `<Triangle>`). Nothing is merged or checked here;
/// build_pattern() turns a PatternSpec into a CreasePattern.
struct TriangleSpec {
  std::array<Vec2, 3> corners;  ///< corner coordinates, pattern units, either orientation
  int line = 0;                 ///< source line; 0 when not read from a file
};

/// An actor (rigid facet) as written (PMML `<Actor>`): an ID and its triangles.
struct ActorSpec {
  int id = 0;                           ///< the actor's ID, as given (unique in a valid pattern)
  std::vector<TriangleSpec> triangles;  ///< its triangles, which must share edges
  int line = 0;                         ///< source line; 0 when not read from a file
};

/// A joint (crease) as written (PMML `<Joint>`): a segment between two actors.
struct JointSpec {
  int id = 0;                       ///< the joint's ID, as given (unique in a valid pattern)
  std::array<Vec2, 2> coords;       ///< the crease's two ends, pattern units
  std::array<int, 2> actor_ids{};   ///< IDs (not indices) of the two actors it joins
  double spring = 0.0;              ///< PMML SpringConst (finite, ≥ 0)
  double damping = 0.0;             ///< PMML DampConst (finite, ≥ 0)
  Assignment assignment = Assignment::Unassigned;  ///< foldkit's PMML extension `<Assignment>`
  int line = 0;                     ///< source line; 0 when not read from a file
  /// foldkit's PMML extension `<MaxTorque>`: the torque limit of this joint's motor in the dynamic
  /// model, N·m (positive, finite); empty: the run's default (dynamics::DynamicOptions::max_torque).
  std::optional<double> max_torque;
};

/// foldkit's PMML extensions that describe the sheet to the dynamic model (docs/FORMATS.md):
/// each empty unless the file sets it; a run's own option overrides it, and it overrides the
/// run's built-in default (dynamics::DynamicOptions). The kinematic models ignore them.
struct PhysicsSpec {
  std::optional<double> density;   ///< `<Density>`: areal density of the sheet, kg/m² (positive, finite)
  std::optional<Vec3> gravity;     ///< `<Gravity>`: m/s², in the axes of the flat sheet (finite)
  std::optional<int> fixed_actor;  ///< `<FixedActor>`: ID of the actor held in place (an actor of the pattern)
  int density_line = 0;            ///< source line of `<Density>`; 0 when not read from a file
  int gravity_line = 0;            ///< source line of `<Gravity>`; 0 when not read from a file
  int fixed_actor_line = 0;        ///< source line of `<FixedActor>`; 0 when not read from a file
};

/// A whole crease pattern as written: coordinates per triangle, IDs as given.
struct PatternSpec {
  std::string title;               ///< free text
  std::vector<ActorSpec> actors;   ///< in file order
  std::vector<JointSpec> joints;   ///< in file order
  PhysicsSpec physics;             ///< foldkit's extensions for the dynamic model (all empty in plain PMML)
};

}  // namespace foldkit::geometry
