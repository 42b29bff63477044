// One status for every algorithm: the names the CLI's JSON prints, and what each algorithm sets.
#include "foldkit/geometry/status.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"

namespace {

using foldkit::geometry::Status;
using foldkit::geometry::StatusCode;

TEST(Status, NamesAreDistinctAndStable) {
  // The CLI's "status" key: scripts compare against these words.
  const std::pair<StatusCode, const char*> names[] = {
      {StatusCode::Unknown, "unknown"},
      {StatusCode::Success, "success"},
      {StatusCode::InvalidInput, "invalid-input"},
      {StatusCode::Collision, "collision"},
      {StatusCode::ClosureViolated, "closure-violated"},
      {StatusCode::Singular, "singular"},
      {StatusCode::NotRigidlyFoldable, "not-rigidly-foldable"},
      {StatusCode::NoSolution, "no-solution"},
      {StatusCode::NoProgress, "no-progress"},
      {StatusCode::LimitReached, "limit-reached"},
  };
  std::set<std::string> seen;
  for (const auto& [code, name] : names) {
    EXPECT_STREQ(to_string(code), name);
    EXPECT_TRUE(seen.insert(name).second) << name;
  }
}

TEST(Status, OnlySuccessIsOk) {
  EXPECT_FALSE(Status().ok());
  EXPECT_EQ(Status().code, StatusCode::Unknown);
  EXPECT_TRUE(Status(StatusCode::Success, "done").ok());
  EXPECT_TRUE(static_cast<bool>(Status(StatusCode::Success, "")));
  for (StatusCode c : {StatusCode::InvalidInput, StatusCode::Collision, StatusCode::ClosureViolated, StatusCode::Singular,
                       StatusCode::NotRigidlyFoldable, StatusCode::NoSolution, StatusCode::NoProgress, StatusCode::LimitReached})
    EXPECT_FALSE(Status(c, "x").ok()) << to_string(c);
}

TEST(Status, ProjectionSetsEachCode) {
  namespace geo = foldkit::geometry;
  const geo::CreasePattern p = geo::build_or_throw(geo::generators::single_vertex({0.7, 0.9, 1.1, 1.3, 0.8, 1.483185307179586}));
  const geo::ClosureSystem system(p);
  geo::FoldState start = geo::FoldState::flat(p);
  start.angles << 0.6, -0.5, 0.7, -0.4, 0.5, -0.6;  // mixed signs: a closed state lies near
  geo::ProjectionOptions free;
  free.keep_signs = false;
  const geo::ProjectionResult closed = geo::project(system, start, free);
  EXPECT_EQ(closed.status.code, StatusCode::Success) << closed.status.message;
  EXPECT_EQ(closed.status.message, "converged");
  geo::ProjectionOptions one = free;
  one.max_iterations = 0;
  const geo::ProjectionResult limited = geo::project(system, start, one);
  EXPECT_EQ(limited.status.code, StatusCode::LimitReached);
  EXPECT_NE(limited.status.message.find("0 iterations"), std::string::npos) << limited.status.message;
  start.angles[0] = std::nan("");
  EXPECT_EQ(geo::project(system, start).status.code, StatusCode::InvalidInput);
}

}  // namespace
