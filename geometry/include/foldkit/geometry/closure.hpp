#pragma once
/// @file
/// The loop-closure equations of a crease pattern (paper Eq. 1) and their exact Jacobian.
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/kinematics.hpp"

namespace foldkit::geometry {

/// The loop-closure equations of a crease pattern (paper Eq. 1): for every interior vertex the
/// product of the rotations about its creases, in counter-clockwise order, is the identity.
/// Residual of a vertex: the rotation vector of that product (3 rows, radians). A sheet with
/// holes also needs the fundamental cycles of the facet graph: for each joint outside the
/// spanning tree, the rigid motion by which the two ways round disagree (6 rows: rotation
/// vector, then translation divided by the pattern's size, CreasePattern::diagonal()). The
/// Jacobian is exact (Eq. 3–4: the crease axes in the current pose, through the inverse left
/// Jacobian of SO(3)). Rows: 3 per vertex loop, then 6 per hole cycle; columns: one per joint.
/// Every state passed in must hold one angle per joint (radians).
class ClosureSystem {
 public:
  /// The equations of `pattern`, with the spanning tree (make_tree()) rooted at actor index
  /// `root`. Keeps a reference to `pattern`, which must outlive the system (hence no temporaries).
  /// @throws std::invalid_argument when `root` is not an actor index
  explicit ClosureSystem(const CreasePattern& pattern, int root = 0);
  /// Deleted: the system keeps a reference to its pattern, so a temporary one is refused.
  ClosureSystem(CreasePattern&&, int = 0) = delete;

  /// Number of equations: 3 per vertex loop + 6 per hole cycle (0 for a pattern without loops).
  Eigen::Index rows() const { return rows_; }
  /// Number of unknowns: one per joint.
  Eigen::Index cols() const { return static_cast<Eigen::Index>(pattern_->joints().size()); }
  /// Number of vertex loops: the interior vertices that have creases.
  std::size_t vertex_loops() const { return loops_.size(); }
  /// Number of hole cycles: joints outside the spanning tree, counted only when the sheet has
  /// holes (hole_count() > 0).
  std::size_t hole_cycles() const { return cycles_.size(); }
  /// The pattern the equations belong to.
  const CreasePattern& pattern() const { return *pattern_; }

  /// The residual at `state`: size rows(), rotation vectors in radians and hole-cycle
  /// translations divided by the pattern's diagonal; zero exactly when every loop closes.
  Eigen::VectorXd residual(const FoldState& state) const;
  /// Residual and Jacobian (rows × creases) in one pass. The Jacobian's sparsity is fixed: a
  /// matrix from an earlier call is refilled in place, without allocating.
  /// @param state     one angle per joint, radians
  /// @param residual  resized to rows() and set
  /// @param jacobian  set to the rows() × cols() Jacobian ∂residual/∂angles
  void evaluate(const FoldState& state, Eigen::VectorXd& residual, Eigen::SparseMatrix<double>& jacobian) const;

  /// One error per loop (vertex loops first): the rotation angle of its product, radians; for a
  /// hole cycle the larger of its rotation angle and its relative translation.
  std::vector<double> loop_errors(const FoldState& state) const;
  /// The largest of loop_errors(); 0 for a pattern without loops.
  double max_error(const FoldState& state) const;
  /// max_error() of the state a residual was computed at (by residual() or evaluate()), read off
  /// the residual without multiplying the loops out again.
  double residual_error(const Eigen::VectorXd& residual) const;

 private:
  struct VertexLoop {
    int vertex;
    std::vector<int> joints;       // counter-clockwise; a crease passing straight through appears twice
    std::vector<Eigen::Vector3d> axes;  // unit direction of each crease leaving the vertex
  };
  struct HoleCycle {
    int joint;      // outside the spanning tree
    int from, to;   // actors: `to` is reached from `from` through `joint`
    double side;    // side of `to` relative to the joint's axis
  };

  // Receives Jacobian entries in a fixed order: collected as triplets once, to lay out the
  // sparsity pattern, then added straight into their slots of the value array.
  struct Sink {
    std::vector<Eigen::Triplet<double>>* triplets = nullptr;
    double* values = nullptr;
    const int* slots = nullptr;
    std::size_t next = 0;
    void add(Eigen::Index row, Eigen::Index col, double v) {
      if (triplets) triplets->emplace_back(row, col, v);
      else values[slots[next++]] += v;
    }
  };

  void evaluate_vertex(const VertexLoop& loop, const FoldState& state, Eigen::Index row, Eigen::VectorXd& r, Sink* jac) const;
  void evaluate_cycles(const FoldState& state, Eigen::VectorXd& r, Sink* jac) const;
  void evaluate_into(const FoldState& state, Eigen::VectorXd& r, Sink* jac) const;

  const CreasePattern* pattern_;
  KinematicTree tree_;
  std::vector<VertexLoop> loops_;
  std::vector<HoleCycle> cycles_;
  double size_ = 1.0;
  Eigen::Index rows_ = 0;
  Eigen::SparseMatrix<double> layout_;   // the Jacobian's structure
  std::vector<int> slots_;               // value index of each entry, in Sink order
};

/// Number of holes of the sheet: components of the facet graph minus its Euler characteristic
/// (never below 0).
int hole_count(const CreasePattern& pattern);

}  // namespace foldkit::geometry
