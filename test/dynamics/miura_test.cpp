// A Miura-ori folded slowly by one motor, gravity off, against the kinematic fold
// (folding::fold_projected, what `foldkit fold` runs) at the same driving angle.
#include <gtest/gtest.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "one_motor_miura.hpp"

using namespace foldkit;

namespace {

// `stabilised`: ODE's iterative solver (20 sweeps) post-stabilised every step, the configuration
// that meets the real-time targets (docs/SIMULATION.md, "Dynamic simulation"); else the
// default direct solver.
void fold_by_one_motor(int n, double time_step, bool stabilised = false) {
  const microbench::OneMotorMiura scene = microbench::one_motor_miura(n);
  const geometry::CreasePattern& p = scene.pattern;
  const geometry::FoldState& goal = scene.kinematic.states.back();
  const int drive = scene.drive;
  dynamics::DynamicOptions o;
  o.start = scene.start;  // past the flat sheet's bifurcation, at rest
  o.max_torque = 1e3;
  o.time_step = time_step;
  if (stabilised) {
    o.solver = dynamics::Solver::Iterative;
    o.iterations = 20;
    o.projection_interval = time_step;
  }
  const geometry::FoldSequence& seq = scene.sequence;  // the fixed actor's most folded crease
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LE(r.max_closure_error, 1e-4);
  EXPECT_NEAR(r.final_state.angles[drive], goal.angles[drive], o.reach_tolerance);
  // Every free crease where the kinematic fold has it, within 1e-3 rad at the same driving angle.
  EXPECT_LE((r.final_state.angles - goal.angles).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT(r.joints[drive].peak_torque, 0.0);
  if (stabilised) {
    // The corrections were used and bounded: one step of the iterative solver opens the loops
    // by at most a few 1e-3 rad (the motor's start and stop; 1e-5 in between), which the
    // projection removes before the next step builds on it.
    EXPECT_GT(r.max_corrected_error, r.max_closure_error);
    EXPECT_LE(r.max_corrected_error, 1e-2);
  }
}

}  // namespace

TEST(DynamicMiura, OneMotorFoldsTheSheetAsTheKinematicFold) { fold_by_one_motor(4, 1e-3); }

TEST(DynamicMiura, StabilisedIterativeSolverFoldsTheSheetAsTheKinematicFold) { fold_by_one_motor(4, 1e-2, true); }

TEST(DynamicMiura, StabilisedIterativeSolverFolds10x10AsTheKinematicFold) { fold_by_one_motor(10, 1e-2, true); }

TEST(AtScale, DynamicMiura10x10OneMotorFoldsAsTheKinematicFold) { fold_by_one_motor(10, 1e-2); }  // 25 s (direct solver)

// Every crease a motor (what `foldkit fold`'s sequences and the browser's Fold command): holding
// the motors in the post-stabilisation leaves nothing free to close the loops, so the correction
// moves every angle instead (it was skipped, silently, and the loops opened 0.036 rad at 4×4).
TEST(DynamicMiura, StabilisedIterativeSolverFoldsWithEveryCreaseDriven) {
  const microbench::OneMotorMiura scene = microbench::one_motor_miura(4);
  const geometry::CreasePattern& p = scene.pattern;
  const geometry::FoldState& goal = scene.kinematic.states.back();
  const geometry::FoldSequence all = geometry::path_sequence(p, {goal}, 0.5, "every crease");
  dynamics::DynamicOptions o;
  o.max_torque = 1e6;
  o.solver = dynamics::Solver::Iterative;
  o.iterations = 20;
  o.time_step = 0.01;
  o.projection_interval = 0.01;
  const auto r = dynamics::simulate_dynamic(p, all, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.failed_corrections, 0u);
  EXPECT_LE(r.max_closure_error, 1e-4);
  EXPECT_GT(r.max_corrected_error, 1e-4);  // the engine alone opens them: the corrections did close them
  EXPECT_LE((r.final_state.angles - goal.angles).cwiseAbs().maxCoeff(), 1e-3);
}
