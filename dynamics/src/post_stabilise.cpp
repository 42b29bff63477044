#include "post_stabilise.hpp"

#include <algorithm>

#include "foldkit/geometry/projection.hpp"

namespace foldkit::dynamics::detail {

// The least-squares correction Δ of the free joints' rates with J_f·Δ = −J·rates (J the closure
// Jacobian, J_f its free columns): (J_fᵀJ_f + λI)Δ = −J_fᵀJ·rates, columns-sized (a Miura-ori has
// more loop rows than creases). λ, tiny against the Jacobian's unit-scale entries, makes the held
// columns' rows (zero) and a sheet with several degrees of freedom solvable: there it picks the
// smallest correction.
Eigen::VectorXd PostStabiliser::tangent_rates(const geometry::FoldState& state, const Eigen::VectorXd& rates,
                                              const std::vector<bool>& held) {
  closure_.evaluate(state, residual_, jacobian_);
  Eigen::SparseMatrix<double> free = jacobian_;
  free.prune([&](Eigen::Index, Eigen::Index col, double) { return !held[static_cast<std::size_t>(col)]; });
  Eigen::SparseMatrix<double> normal = free.transpose() * free;
  for (Eigen::Index j = 0; j < normal.cols(); ++j) normal.coeffRef(j, j) += 1e-10;
  if (analysed_for_ != held) {
    ldlt_.analyzePattern(normal);
    analysed_for_ = held;
  }
  ldlt_.factorize(normal);
  if (ldlt_.info() != Eigen::Success) return rates;
  const Eigen::VectorXd delta = ldlt_.solve(-(free.transpose() * (jacobian_ * rates)));
  return rates + delta;
}

PostStabiliser::Correction PostStabiliser::operator()(OdeSheet& sheet) {
  const geometry::FoldState engine = sheet.state();
  const double before = closure_.max_error(engine);
  if (before <= tolerance_) return {before, before, false};
  const Eigen::Index n = engine.angles.size();
  geometry::ProjectionOptions po;
  po.tolerance = tolerance_;
  // A few Levenberg–Marquardt steps from a state one interval's drift away; a projection that
  // needs more is left for the next interval (the closure checks then see the drift).
  po.max_iterations = 20;
  po.held.resize(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) po.held[j] = sheet.drive(static_cast<int>(j)).kind == JointDrive::Motor;
  geometry::ProjectionResult r = geometry::project(closure_, engine, po);
  if (!r.status.ok() && std::find(po.held.begin(), po.held.end(), true) != po.held.end()) {
    // The motors fix every degree of freedom (a sequence driving every crease): the engine's
    // angles, motors' included, moved least onto the manifold; the motors go on driving from there.
    po.held.assign(po.held.size(), false);
    r = geometry::project(closure_, engine, po);
  }
  if (!r.status.ok()) return {before, before, false};
  Eigen::VectorXd rates(n);
  for (Eigen::Index j = 0; j < n; ++j) rates[j] = sheet.rate(static_cast<int>(j));
  sheet.place(r.state);
  // Velocities on the manifold's tangent too: velocities that open the loops would undo the
  // correction within the next step, the solver's few sweeps not removing their error.
  sheet.set_rates(tangent_rates(r.state, rates, po.held));
  return {before, r.error, true};
}

}  // namespace foldkit::dynamics::detail
