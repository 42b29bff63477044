#pragma once
// Two fold sequences equal field by field (title, events, and every fold's joint, angle, speed and
// file line): the io tests' check that two readings of one file agree.
#include <gtest/gtest.h>

#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::test {

inline void expect_same(const geometry::FoldSequence& a, const geometry::FoldSequence& b) {
  EXPECT_EQ(a.title, b.title);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t e = 0; e < a.events.size(); ++e) {
    EXPECT_EQ(a.events[e].number, b.events[e].number);
    ASSERT_EQ(a.events[e].folds.size(), b.events[e].folds.size());
    for (std::size_t f = 0; f < a.events[e].folds.size(); ++f) {
      const auto &x = a.events[e].folds[f], &y = b.events[e].folds[f];
      EXPECT_EQ(x.joint_id, y.joint_id);
      EXPECT_EQ(x.angle, y.angle);
      EXPECT_EQ(x.speed, y.speed);
      EXPECT_EQ(x.line, y.line) << "fold " << f << " of event " << e;
    }
  }
}

}  // namespace foldkit::test
