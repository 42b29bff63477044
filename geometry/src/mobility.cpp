#include "foldkit/geometry/mobility.hpp"

#include <Eigen/SVD>
#include <Eigen/SparseQR>

namespace foldkit::geometry {

Mobility mobility(const ClosureSystem& system, const FoldState& state, double relative_tolerance, Eigen::Index dense_limit) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(state, r, J);
  Mobility m;
  m.creases = static_cast<int>(system.cols());
  if (J.rows() == 0 || J.cols() == 0) {
    m.dof = m.creases;
    m.method = "none";
    return m;
  }
  if (J.cols() <= dense_limit) {
    const Eigen::MatrixXd dense(J);
    Eigen::BDCSVD<Eigen::MatrixXd> svd(dense);
    const auto& s = svd.singularValues();
    m.tolerance = relative_tolerance * std::max(s.size() ? s[0] : 0.0, 1.0);
    for (Eigen::Index i = 0; i < s.size(); ++i) m.rank += s[i] > m.tolerance;
    m.method = "svd";
  } else {
    // Rank of J or of Jᵀ, whichever is tall: SparseQR factors tall matrices.
    Eigen::SparseMatrix<double> A = J.rows() >= J.cols() ? J : Eigen::SparseMatrix<double>(J.transpose());
    A.makeCompressed();
    double largest = 1.0;
    for (Eigen::Index c = 0; c < A.cols(); ++c) largest = std::max(largest, A.col(c).norm());
    m.tolerance = relative_tolerance * largest;
    Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(m.tolerance);
    qr.compute(A);
    m.rank = static_cast<int>(qr.rank());
    m.method = "sparse-qr";
  }
  m.dof = m.creases - m.rank;
  return m;
}

}  // namespace foldkit::geometry
