// A Miura-ori folded slowly by one motor, gravity off, against the kinematic fold
// (folding::fold_projected, what `foldkit fold` runs) at the same driving angle.
#include <gtest/gtest.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/generators.hpp"

using namespace foldkit;

namespace {

void fold_by_one_motor(int n, double time_step) {
  const auto p = geometry::build_or_throw(geometry::generators::miura(n, n));
  folding::ProjectedFoldingOptions fo;
  fo.target_fraction = 0.5;
  fo.replay = false;
  fo.collisions = false;
  const auto kin = folding::fold_projected(p, fo);
  ASSERT_TRUE(kin.status.ok()) << kin.status.message;
  const geometry::FoldState& goal = kin.states.back();
  dynamics::DynamicOptions o;
  // The flat sheet is a bifurcation (one motor does not choose the branch): start 0.2 rad into
  // the kinematic path, at rest.
  for (const auto& s : kin.states)
    if (s.angles.cwiseAbs().maxCoeff() >= 0.2) {
      o.start = s.angles;
      break;
    }
  o.max_torque = 1e3;
  o.time_step = time_step;
  // The motor: the fixed actor's most folded crease.
  int drive = -1;
  for (int j = 0; j < static_cast<int>(p.joints().size()); ++j) {
    const auto& a = p.joints()[j].actors;
    if ((a[0] == 0 || a[1] == 0) && (drive < 0 || std::abs(goal.angles[j]) > std::abs(goal.angles[drive]))) drive = j;
  }
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{p.joints()[drive].id, goal.angles[drive], 0.5, 0}}});
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LE(r.max_closure_error, 1e-4);
  EXPECT_NEAR(r.final_state.angles[drive], goal.angles[drive], o.reach_tolerance);
  // Every free crease where the kinematic fold has it, within 1e-3 rad at the same driving angle.
  EXPECT_LE((r.final_state.angles - goal.angles).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT(r.joints[drive].peak_torque, 0.0);
}

}  // namespace

TEST(DynamicMiura, OneMotorFoldsTheSheetAsTheKinematicFold) { fold_by_one_motor(4, 1e-3); }

TEST(AtScale, DynamicMiura10x10OneMotorFoldsAsTheKinematicFold) { fold_by_one_motor(10, 1e-2); }  // 25 s (direct solver)
