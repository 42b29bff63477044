#include "foldkit/geometry/mobility.hpp"

namespace foldkit::geometry {

Mobility mobility(const ClosureSystem& system, const FoldState& state, double relative_tolerance, Eigen::Index dense_limit) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(state, r, J);
  Mobility m;
  m.creases = static_cast<int>(system.cols());
  // Closure Jacobians are dimensionless (radians of loop error per radian of crease), entries of
  // order 1: σ_max is floored at 1 so that a Jacobian zero to rounding (a straight crease through
  // a vertex) has rank 0 rather than the rank of its rounding errors.
  LeastNormSolver solver;
  m.decision = solver.decide_rank(J, relative_tolerance, dense_limit, 1.0);
  m.rank = m.decision.rank;
  m.dof = m.creases - m.rank;
  m.tolerance = m.decision.tolerance;
  m.method = m.decision.method;
  return m;
}

}  // namespace foldkit::geometry
