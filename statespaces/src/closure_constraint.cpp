#include "foldkit/statespaces/closure_constraint.hpp"

#include <algorithm>
#include <stdexcept>

#include <Eigen/QR>
#include <Eigen/SparseCore>
#include <ompl/base/ConstrainedSpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/constraint/AtlasStateSpace.h>
#include <ompl/base/spaces/constraint/ProjectedStateSpace.h>
#include <ompl/base/spaces/constraint/TangentBundleStateSpace.h>

#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/null_space.hpp"

namespace foldkit::statespaces {

namespace ob = ompl::base;

unsigned int ClosureConstraint::rank_at(const geometry::ClosureSystem& system, const geometry::FoldState& reference,
                                        std::vector<Eigen::Index>* rows) {
  if (system.rows() == 0) throw std::invalid_argument("constrained space: the pattern has no closed loop");
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> j;
  system.evaluate(reference, r, j);
  // The rank by singular values (the one rank decision of foldkit, geometry::mobility); the rows
  // kept are the first `rank` that column-pivoted QR of Jᵀ picks as independent.
  const Eigen::Index rank = geometry::mobility(system, reference).rank;
  const Eigen::MatrixXd jt = Eigen::MatrixXd(j).transpose();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jt);
  if (rank <= 0 || rank >= system.cols())
    throw std::invalid_argument("constrained space: the closure Jacobian has rank " + std::to_string(rank) + " for " +
                                std::to_string(system.cols()) + " creases at the reference state (no motion)");
  rows->clear();
  for (Eigen::Index i = 0; i < rank; ++i) rows->push_back(qr.colsPermutation().indices()[i]);
  std::sort(rows->begin(), rows->end());
  return static_cast<unsigned int>(rank);
}

ClosureConstraint::ClosureConstraint(const geometry::CreasePattern& pattern, const geometry::FoldState& reference,
                                     bool numerical_jacobian, double tolerance)
    : ob::Constraint(static_cast<unsigned int>(pattern.joints().size()),
                     [&] {
                       geometry::ClosureSystem s(pattern);
                       std::vector<Eigen::Index> r;
                       return rank_at(s, reference, &r);
                     }(),
                     tolerance),
      system_(pattern),
      numerical_(numerical_jacobian) {
  rank_at(system_, reference, &rows_);
  std::vector<Eigen::Triplet<double>> pick;
  for (std::size_t i = 0; i < rows_.size(); ++i) pick.emplace_back(static_cast<Eigen::Index>(i), rows_[i], 1.0);
  select_.resize(static_cast<Eigen::Index>(rows_.size()), system_.rows());
  select_.setFromTriplets(pick.begin(), pick.end());
  setManifoldDimension(static_cast<unsigned int>(system_.cols()) - static_cast<unsigned int>(rows_.size()));
  setMaxIterations(100);
}

// OMPL's Newton projection (Constraint::project) takes full pseudo-inverse steps; near a singular
// Jacobian they can throw x to ±inf, and a non-finite Jacobian then aborts inside Eigen's
// JacobiSVD (seen on Miura-ori). Off the finite box we answer a large residual and a zero
// Jacobian: the steps stop, the projection fails, and the sampler draws again.
void ClosureConstraint::function(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> out) const {
  if (!x.allFinite()) {
    out.setConstant(1e3);
    return;
  }
  const Eigen::VectorXd r = system_.residual(geometry::FoldState{x});
  for (std::size_t i = 0; i < rows_.size(); ++i) out[static_cast<Eigen::Index>(i)] = r[rows_[i]];
}

void ClosureConstraint::jacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::MatrixXd> out) const {
  if (!x.allFinite()) {
    out.setZero();
    return;
  }
  if (numerical_) return ob::Constraint::jacobian(x, out);
  thread_local Eigen::VectorXd r;
  thread_local Eigen::SparseMatrix<double> j;
  system_.evaluate(geometry::FoldState{x}, r, j);
  out.setZero();
  std::vector<Eigen::Index> where(static_cast<std::size_t>(system_.rows()), -1);
  for (std::size_t i = 0; i < rows_.size(); ++i) where[static_cast<std::size_t>(rows_[i])] = static_cast<Eigen::Index>(i);
  for (int k = 0; k < j.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(j, k); it; ++it) {
      const Eigen::Index row = where[static_cast<std::size_t>(it.row())];
      if (row >= 0) out(row, it.col()) = it.value();
    }
}

bool ClosureConstraint::project(Eigen::Ref<Eigen::VectorXd> x) const {
  const double tolerance2 = getTolerance() * getTolerance();
  Eigen::VectorXd f(getCoDimension());
  if (numerical_) {
    // The baseline keeps the dense path: a complete orthogonal decomposition of the
    // finite-difference Jacobian each iteration.
    Eigen::MatrixXd j(getCoDimension(), x.size());
    function(x, f);
    for (unsigned int iteration = 0; !(f.squaredNorm() <= tolerance2); ++iteration) {
      if (iteration >= getMaxIterations() || !f.allFinite()) return false;
      jacobian(x, j);
      const Eigen::VectorXd step = j.completeOrthogonalDecomposition().solve(f);
      if (!step.allFinite()) return false;
      x -= step;
      function(x, f);
    }
    return true;
  }
  // The exact Jacobian is sparse (each loop row touches the creases round one vertex): the
  // least-norm step comes from one sparse LDLᵀ of JᵀJ + εI. A dense decomposition per step took
  // 175 ms per projection of a disturbed Miura 20×20 (bench_constraint_projection), 150× longer.
  thread_local Eigen::VectorXd r, step;
  thread_local Eigen::SparseMatrix<double> j;
  // One solver per thread, shared by every constraint on it: it keeps the sparsity analysis of
  // the last Jacobian it factored (one constraint's Jacobians all share it) and compares the full
  // pattern each time, so switching constraints costs a new analysis, never a stale one.
  thread_local geometry::LeastNormSolver solver(kRankTolerance);
  for (unsigned int iteration = 0;; ++iteration) {
    if (!x.allFinite()) return false;
    system_.evaluate(geometry::FoldState{x}, r, j);
    for (std::size_t i = 0; i < rows_.size(); ++i) f[static_cast<Eigen::Index>(i)] = r[rows_[i]];
    if (f.squaredNorm() <= tolerance2) return true;
    if (iteration >= getMaxIterations() || !f.allFinite()) return false;
    const Eigen::SparseMatrix<double> kept = select_ * j;
    if (!solver.min_norm_step(kept, f, step)) return false;
    x += step;
  }
}

ConstrainedKind parse_constrained_kind(const std::string& name) {
  if (name == "projected") return ConstrainedKind::Projected;
  if (name == "atlas") return ConstrainedKind::Atlas;
  if (name == "tangent-bundle" || name == "tb") return ConstrainedKind::TangentBundle;
  throw std::invalid_argument("unknown constrained space '" + name + "' (projected, atlas, tangent-bundle)");
}

const char* to_string(ConstrainedKind kind) {
  switch (kind) {
    case ConstrainedKind::Atlas: return "atlas";
    case ConstrainedKind::TangentBundle: return "tangent-bundle";
    default: return "projected";
  }
}

ConstrainedSetup make_constrained(const geometry::CreasePattern& pattern, const geometry::FoldState& reference,
                                  ConstrainedKind kind, const AngleBounds& bounds, bool numerical_jacobian, double delta) {
  ConstrainedSetup out;
  out.kind = kind;
  out.constraint = std::make_shared<ClosureConstraint>(pattern, reference, numerical_jacobian);
  const auto n = static_cast<unsigned int>(pattern.joints().size());
  auto ambient = std::make_shared<ob::RealVectorStateSpace>(n);
  ob::RealVectorBounds rb(n);
  for (unsigned int j = 0; j < n; ++j) {
    rb.setLow(j, bounds.lower[j]);
    rb.setHigh(j, bounds.upper[j]);
  }
  ambient->setBounds(rb);
  switch (kind) {
    case ConstrainedKind::Projected:
      out.space = std::make_shared<ob::ProjectedStateSpace>(ambient, out.constraint);
      out.si = std::make_shared<ob::ConstrainedSpaceInformation>(out.space);
      break;
    case ConstrainedKind::Atlas:
      out.space = std::make_shared<ob::AtlasStateSpace>(ambient, out.constraint);
      out.si = std::make_shared<ob::ConstrainedSpaceInformation>(out.space);
      break;
    case ConstrainedKind::TangentBundle:
      out.space = std::make_shared<ob::TangentBundleStateSpace>(ambient, out.constraint);
      out.si = std::make_shared<ob::TangentBundleSpaceInformation>(out.space);
      break;
  }
  out.space->setDelta(delta);
  return out;
}

geometry::FoldState to_fold_state(const ob::ConstrainedStateSpace::StateType* state) {
  return geometry::FoldState{Eigen::VectorXd(*state)};
}

StateReader constrained_reader() {
  return [](const ompl::base::State* state, geometry::FoldState& out) {
    out.angles = *state->as<ompl::base::ConstrainedStateSpace::StateType>();
    return true;
  };
}

}  // namespace foldkit::statespaces
