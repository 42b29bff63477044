#pragma once
// Post-stabilisation of the engine's poses (DynamicOptions::projection_interval): the angles read
// off the bodies projected onto the closure manifold (geometry::project), the bodies placed there.
#include <utility>
#include <vector>

#include <Eigen/SparseCholesky>

#include "foldkit/geometry/closure.hpp"
#include "ode_sheet.hpp"

namespace foldkit::dynamics::detail {

// Moves the sheet to the closed state nearest its engine's angles, the motor-driven joints held at
// theirs (a motor's angle is what the user commands; the free hinges follow it, as in the
// kinematic fold), and its velocities to the nearest joint rates tangent to the closure manifold.
// An iterative solver leaves the loops open by the error its sweeps did not remove; this
// position- and velocity-level correction removes it without touching the dynamics it did solve.
// Keeps the closure system (rooted where the sheet is: OdeSheet::place) by reference.
class PostStabiliser {
 public:
  // `tolerance`: the loop error a correction leaves, radians.
  PostStabiliser(const geometry::ClosureSystem& closure, double tolerance) : closure_(closure), tolerance_(tolerance) {}
  // What one correction did: the largest loop error before and after it (radians), and whether
  // the sheet was moved (false: closed already, or no projection closed within the tolerance,
  // and the sheet is left as the engine left it, for the closure checks to judge).
  struct Correction {
    double before = 0.0;
    double after = 0.0;
    bool moved = false;
  };
  // Corrects `sheet`: the closed state nearest it with the motor-driven joints held, or, when
  // holding them leaves nothing free to close the loops (every crease a motor), with none held.
  Correction operator()(OdeSheet& sheet);

 private:
  // The joint rates nearest `rates` (rad/s) that keep the loops of `state` closed to first order.
  Eigen::VectorXd tangent_rates(const geometry::FoldState& state, const Eigen::VectorXd& rates, const std::vector<bool>& held);

  const geometry::ClosureSystem& closure_;
  double tolerance_;
  Eigen::SparseMatrix<double> jacobian_;
  Eigen::VectorXd residual_;
  // The normal equations' factorisation, its ordering analysed once per set of held joints (the
  // Jacobian's sparsity is fixed).
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  std::vector<bool> analysed_for_;
};

}  // namespace foldkit::dynamics::detail
