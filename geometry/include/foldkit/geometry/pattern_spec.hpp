#pragma once
#include <array>
#include <string>
#include <vector>

#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry {

// A crease pattern as written (PMML Table 1): coordinates per triangle, IDs as given.
// Nothing is merged or checked here; build_pattern() turns a spec into a CreasePattern.
struct TriangleSpec {
  std::array<Vec2, 3> corners;
  int line = 0;
};

struct ActorSpec {
  int id = 0;
  std::vector<TriangleSpec> triangles;
  int line = 0;
};

struct JointSpec {
  int id = 0;
  std::array<Vec2, 2> coords;
  std::array<int, 2> actor_ids{};
  double spring = 0.0;
  double damping = 0.0;
  Assignment assignment = Assignment::Unassigned;  // extension: <Assignment>
  int line = 0;
};

struct PatternSpec {
  std::string title;
  std::vector<ActorSpec> actors;
  std::vector<JointSpec> joints;
};

}  // namespace foldkit::geometry
