#pragma once
// The assertion the Carpenter method tests share: a run succeeded and every frame passes the
// oracle (carpenter_oracle.hpp), which shares nothing with the planner's own certificate.
#include <cstddef>

#include <gtest/gtest.h>

#include "carpenter_oracle.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace foldkit::test::carpenter {

inline void expect_certified(const folding::CarpenterPlanarResult& r, const Frame2& input, bool closed) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_GE(r.frames.size(), 2u);
  const Oracle o = check_frames(r.frames, input, closed);
  // Distances are compared to within rounding, which grows with the coordinates: the layouts sum
  // up to n bars (docs/CARPENTER.md, step size), so the bound is relative to the chain's length:
  // 1e-13 of it is about n·u·length at n = 450 (the 40-gon of the methods test shrinks one
  // distance by 1.8e-12, a few 1e-14 of its length; an absolute 1e-12 failed there).
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < input.size(); ++i) length += (input[i + 1] - input[i]).norm();
  EXPECT_LE(o.length_error, 1e-9);
  EXPECT_GE(o.vertex_growth, -1e-13 * length);
  EXPECT_GE(o.bar_growth, -1e-13 * length);
  EXPECT_GT(o.min_gap, 0.0);
  if (closed)
    EXPECT_TRUE(folding::is_convex(r.frames.back()));
  else
    EXPECT_TRUE(folding::is_straight(r.frames.back()));
}

}  // namespace foldkit::test::carpenter
