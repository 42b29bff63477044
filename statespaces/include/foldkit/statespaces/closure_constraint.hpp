#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/SparseCore>
#include <ompl/base/Constraint.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/constraint/ConstrainedStateSpace.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"

namespace foldkit::statespaces {

// The loop-closure equations of any crease pattern as an OMPL constraint: F = the residual rows
// of geometry::ClosureSystem, J = its exact sparse Jacobian (or, with `numerical_jacobian`,
// OMPL's default central differences — the baseline of docs/PLANNING.md). Rows that are
// redundant (the vertex loops of a Miura sheet are not independent) are dropped: the rows kept
// are an independent set at `reference`, a folded state where the Jacobian has its generic
// rank, so that F has exactly co-dimension rows and J full row rank there (Atlas and
// TangentBundle need it). The manifold dimension is set explicitly to creases − rank.
class ClosureConstraint : public ompl::base::Constraint {
 public:
  ClosureConstraint(const geometry::CreasePattern& pattern, const geometry::FoldState& reference,
                    bool numerical_jacobian = false, double tolerance = 1e-8);

  using ompl::base::Constraint::function;
  using ompl::base::Constraint::jacobian;
  void function(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> out) const override;
  void jacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::MatrixXd> out) const override;
  // OMPL's Newton projection with minimum-norm steps, made safe and sparse: Constraint::project
  // of OMPL 1.5.2 aborts inside Eigen's JacobiSVD on some Miura samples (an assertion in
  // SVD::solve) and factors the dense Jacobian. This one takes each step from a sparse LDLᵀ of
  // JᵀJ + εI (geometry::LeastNormSolver), or, with the numerical Jacobian (the baseline), from a
  // complete orthogonal decomposition of the dense one; it gives up on non-finite values.
  using ompl::base::Constraint::project;
  bool project(Eigen::Ref<Eigen::VectorXd> x) const override;

  const geometry::ClosureSystem& system() const { return system_; }
  const std::vector<Eigen::Index>& rows() const { return rows_; }

 private:
  static unsigned int rank_at(const geometry::ClosureSystem& system, const geometry::FoldState& reference,
                              std::vector<Eigen::Index>* rows);

  // Singular values below √kRankTolerance·σ_max barely move the least-norm step (as in
  // folding::ProjectedFoldingOptions::rank_tolerance).
  static constexpr double kRankTolerance = 1e-8;

  geometry::ClosureSystem system_;
  std::vector<Eigen::Index> rows_;
  Eigen::SparseMatrix<double> select_;  // picks rows_ out of the full residual
  bool numerical_;
};

enum class ConstrainedKind { Projected, Atlas, TangentBundle };
// "projected", "atlas", "tangent-bundle" (also "tb"); throws std::invalid_argument otherwise.
ConstrainedKind parse_constrained_kind(const std::string& name);
const char* to_string(ConstrainedKind kind);

// A constrained space over a bounded RealVectorStateSpace (one dimension per joint, bounds from
// `bounds`: no wrap-around), and the SpaceInformation of its kind.
struct ConstrainedSetup {
  std::shared_ptr<ClosureConstraint> constraint;
  std::shared_ptr<ompl::base::ConstrainedStateSpace> space;
  ompl::base::SpaceInformationPtr si;
  ConstrainedKind kind = ConstrainedKind::Projected;
};
// `delta`: the step of the manifold traversal (radians, ambient distance).
ConstrainedSetup make_constrained(const geometry::CreasePattern& pattern, const geometry::FoldState& reference,
                                  ConstrainedKind kind, const AngleBounds& bounds, bool numerical_jacobian = false,
                                  double delta = 0.05);

geometry::FoldState to_fold_state(const ompl::base::ConstrainedStateSpace::StateType* state);

}  // namespace foldkit::statespaces
