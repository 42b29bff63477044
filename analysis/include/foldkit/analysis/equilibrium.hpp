#pragma once
/// @file
/// A stiffness problem (structure, stiffness, supports, loads) and its equilibrium equations.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "foldkit/analysis/structure.hpp"

namespace foldkit::analysis {

/// A dead load (fixed direction) at a point of a module, both in the folded state's coordinates.
struct PointLoad {
  int module = 0;  ///< index into Structure::modules
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< force, N
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< point of application, pattern units
};

/// A structure with its stiffness, supports and loads.
struct Problem {
  Structure structure;  ///< the modules and connections
  std::array<Matrix6, 3> stiffness{default_stiffness(ConnectionKind::Hinged), default_stiffness(ConnectionKind::Face),
                                   default_stiffness(ConnectionKind::Edge)};  ///< one matrix per ConnectionKind, indexed by its value
  std::vector<bool> fixed;  ///< per module; empty = none fixed
  std::vector<PointLoad> loads;  ///< dead loads
};

/// The index of a module that no chain of connections ties to a fixed module, or −1.
int unrestrained_module(const Problem& problem);

/// Static equilibrium of the springs in nondimensional units: lengths in L = the tile size,
/// forces in F₀ = the largest load (1 N without loads), moments in F₀·L. Unknowns x: per free
/// module [u/L; φ], its centroid's displacement and rotation vector (pose x ↦ R(φ)(x − c) + c + u).
/// The residual is the gradient of the potential (spring energy minus the work of the loads) with
/// respect to a left perturbation (δu, δφ) of each free module: per module [force; moment about
/// its centroid]; it vanishes at equilibrium. Vectors x, dx and the residual have size(),
/// six entries per free module in free_modules() order.
class EquilibriumSystem {
 public:
  /// Scales and collects the springs and loads of `problem`; fixed modules do not move.
  explicit EquilibriumSystem(const Problem& problem);

  /// Number of unknowns: 6 per free module.
  int size() const { return 6 * static_cast<int>(free_.size()); }
  /// L, the length unit: the structure's tile size (1 when it is not positive).
  double length_unit() const { return length_; }
  /// F₀, the force unit: the largest load's magnitude, N (1 without loads).
  double force_unit() const { return force_; }
  /// Free modules in unknown order (module indices).
  const std::vector<int>& free_modules() const { return free_; }
  /// The position of `module` (an index, which must be in range) in free_modules(); −1 for a
  /// fixed one.
  int index_of(int module) const { return index_[module]; }
  /// The largest stiffness entry in scaled units: with extent() and the displacements it sets
  /// the round-off floor of the residual.
  double stiffness_scale() const { return stiffness_scale_; }
  /// The longest lever from a centroid to a spring, in units of L (at least 1).
  double extent() const { return extent_; }
  /// The round-off level of the residual's entries at `x`, scaled units:
  /// 4 ε · stiffness_scale() · (extent() + largest displacement).
  double residual_floor(const Eigen::VectorXd& x) const;

  /// The residual at `x` with the loads scaled by `load_factor`; scaled units.
  Eigen::VectorXd residual(const Eigen::VectorXd& x, double load_factor = 1.0) const;

  /// ∂residual/∂(δu, δφ) at x (size() × size()). `geometric` false: the small-displacement
  /// stiffness at x = 0 (Σ Dᵀ K D, no geometric or load stiffness), whatever x is.
  Eigen::SparseMatrix<double> tangent(const Eigen::VectorXd& x, double load_factor = 1.0, bool geometric = true) const;

  /// x after the left perturbation dx, applied as the screw motion of the twist whose angular part
  /// is δφ and which moves the centroid at δu: u ← u + J(δφ)·δu, φ ← log(exp(δφ)·exp(φ)).
  /// Each module's six entries are moved on their own, so x and dx may also hold any whole
  /// number of modules (one module's six, as a per-module manifold of Ceres needs).
  Eigen::VectorXd retract(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const;

 private:
  struct Spring {
    int a, b;                  // module indices
    Eigen::Matrix3d q;         // the connection's axes
    Eigen::Vector3d ra, rb;    // the axes' origin from each centroid, scaled
    Eigen::Vector3d ca, cb;    // centroids, scaled
    Matrix6 k;                 // scaled stiffness
  };
  struct Load {
    int module;
    Eigen::Vector3d force, arm;  // scaled
  };

  // The tangent's pattern (dense 6×6 blocks, block rows sorted in each block column), built once:
  // tangent() fills a copy in place. A slot is a block's position within its block column.
  void build_pattern();

  std::vector<Spring> springs_;
  std::vector<Load> loads_;
  std::vector<int> free_, index_;
  Eigen::SparseMatrix<double> pattern_;
  std::vector<std::array<int, 4>> spring_slots_;      // (a,a), (a,b), (b,a), (b,b); −1 when fixed
  std::vector<int> load_slots_;                       // (m,m); −1 when fixed
  double length_ = 1.0, force_ = 1.0, stiffness_scale_ = 0.0, extent_ = 1.0;
};

}  // namespace foldkit::analysis
