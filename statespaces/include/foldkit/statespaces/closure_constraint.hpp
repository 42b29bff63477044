#pragma once
/// @file
/// The loop-closure equations as an OMPL constraint, and the constrained planning spaces built on
/// them (projected, atlas, tangent bundle).
#include <memory>
#include <string>
#include <vector>

#include <Eigen/SparseCore>
#include <ompl/base/Constraint.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/constraint/ConstrainedStateSpace.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/statespaces/angle_bounds.hpp"
#include "foldkit/statespaces/state_reader.hpp"

/// OMPL state spaces, samplers and validity checking for planning fold motions on the closure
/// manifold: the exact single-vertex space, the constrained spaces on ClosureConstraint, and the
/// validity of fold states (bounds, closure, collisions). Angles are radians.
namespace foldkit::statespaces {

/// The loop-closure equations of any crease pattern as an OMPL constraint: F = the residual rows
/// of geometry::ClosureSystem, J = its exact sparse Jacobian (or, with `numerical_jacobian`,
/// OMPL's default central differences — the baseline of docs/PLANNING.md). Rows that are
/// redundant (the vertex loops of a Miura sheet are not independent) are dropped: the rows kept
/// are an independent set at `reference`, a folded state where the Jacobian has its generic
/// rank, so that F has exactly co-dimension rows and J full row rank there (Atlas and
/// TangentBundle need it). The manifold dimension is set explicitly to creases − rank. The
/// ambient space has one dimension per joint (radians).
class ClosureConstraint : public ompl::base::Constraint {
 public:
  /// The constraint of `pattern`, its rows chosen at `reference`; at most 100 projection
  /// iterations. Keeps its own geometry::ClosureSystem, which refers to `pattern`: the pattern
  /// must outlive the constraint.
  /// @param pattern             the pattern
  /// @param reference           a folded state (one angle per joint) where the closure Jacobian
  ///                            has its generic rank (geometry::mobility)
  /// @param numerical_jacobian  use OMPL's finite differences instead of the exact Jacobian
  /// @param tolerance           OMPL's constraint tolerance: the largest norm of F accepted as
  ///                            satisfied (radians)
  /// @throws std::invalid_argument when the pattern has no closed loop, or the Jacobian's rank
  ///         at `reference` is 0 or the number of creases (no motion)
  ClosureConstraint(const geometry::CreasePattern& pattern, const geometry::FoldState& reference,
                    bool numerical_jacobian = false, double tolerance = 1e-8);

  using ompl::base::Constraint::function;
  using ompl::base::Constraint::jacobian;
  /// F(x): the kept residual rows at the angles `x` (co-dimension entries); all 1e3 when `x` is
  /// not finite, so that a projection thrown off the finite box fails.
  void function(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> out) const override;
  /// J(x): the kept rows of the exact Jacobian (co-dimension × creases), or OMPL's central
  /// differences with the numerical Jacobian; zero when `x` is not finite.
  void jacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::MatrixXd> out) const override;
  using ompl::base::Constraint::project;
  /// OMPL's Newton projection with minimum-norm steps, made safe and sparse: Constraint::project
  /// of OMPL 1.5.2 aborts inside Eigen's JacobiSVD on some Miura samples (an assertion in
  /// SVD::solve) and factors the dense Jacobian. This one takes each step from a sparse LDLᵀ of
  /// JᵀJ + εI (geometry::LeastNormSolver), or, with the numerical Jacobian (the baseline), from a
  /// complete orthogonal decomposition of the dense one; it gives up on non-finite values.
  /// @param x  the angles, projected in place
  /// @return true when ‖F(x)‖ ≤ the tolerance within the iteration limit
  bool project(Eigen::Ref<Eigen::VectorXd> x) const override;

  /// The full closure equations of the pattern.
  const geometry::ClosureSystem& system() const { return system_; }
  /// The rows of system() kept in F, in increasing order.
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

/// OMPL's constrained state spaces (docs/PLANNING.md).
enum class ConstrainedKind {
  Projected,     ///< ompl::base::ProjectedStateSpace
  Atlas,         ///< ompl::base::AtlasStateSpace
  TangentBundle  ///< ompl::base::TangentBundleStateSpace
};
/// The kind named "projected", "atlas", "tangent-bundle" (also "tb").
/// @throws std::invalid_argument for any other name
ConstrainedKind parse_constrained_kind(const std::string& name);
/// The kind's name: "projected", "atlas" or "tangent-bundle".
const char* to_string(ConstrainedKind kind);

/// A constrained space over a bounded RealVectorStateSpace (one dimension per joint, bounds from
/// `bounds`: no wrap-around), and the SpaceInformation of its kind.
struct ConstrainedSetup {
  std::shared_ptr<ClosureConstraint> constraint;  ///< the closure constraint
  std::shared_ptr<ompl::base::ConstrainedStateSpace> space;  ///< the constrained space
  ompl::base::SpaceInformationPtr si;  ///< its SpaceInformation (no validity checker set)
  ConstrainedKind kind = ConstrainedKind::Projected;  ///< which space
};
/// Builds the constraint and a constrained space of `kind` on it.
/// @param pattern             the pattern (must outlive the setup)
/// @param reference           where the constraint's rows are chosen (ClosureConstraint)
/// @param kind                which constrained space
/// @param bounds              per-joint angle bounds of the ambient box
/// @param numerical_jacobian  OMPL's finite differences instead of the exact Jacobian
/// @param delta               the step of the manifold traversal (radians, ambient distance)
/// @throws std::invalid_argument as ClosureConstraint's constructor
ConstrainedSetup make_constrained(const geometry::CreasePattern& pattern, const geometry::FoldState& reference,
                                  ConstrainedKind kind, const AngleBounds& bounds, bool numerical_jacobian = false,
                                  double delta = 0.05);

/// The fold angles held by a state of a constrained space.
geometry::FoldState to_fold_state(const ompl::base::ConstrainedStateSpace::StateType* state);

/// The reader of states of a constrained space (ompl::base::ConstrainedStateSpace); never false.
StateReader constrained_reader();

}  // namespace foldkit::statespaces
