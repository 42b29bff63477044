#pragma once
/// @file
/// The exact OMPL state space of a single interior vertex and its sampler.
#include <memory>
#include <vector>

#include <ompl/base/StateSampler.h>
#include <ompl/base/StateSpace.h>

#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/statespaces/angle_bounds.hpp"
#include "foldkit/statespaces/closed_angles_space.hpp"
#include "foldkit/statespaces/state_reader.hpp"
#include "foldkit/statespaces/single_vertex_chain.hpp"

namespace foldkit::statespaces {

/// The exact, (n − 3)-dimensional space of a single vertex (docs/PLANNING.md): a state holds the
/// full angle vector (always closed, to rounding) and its branch. Distance: Euclidean over the
/// active angles and the middle passive one (which carries the branch). Interpolation: linear in the active angles, the passive ones solved on the from-state's
/// branch (the to-state's when the from-state sits where both branches meet; between two
/// branches that do not meet at either end there is no such segment, and the states in between are
/// not closed). A state for which
/// no root exists is marked not `closed`; the validity checker rejects it.
class SingleVertexStateSpace : public ClosedAnglesSpace {
 public:
  /// A state of the space: the full angle vector (`closed` false when no root exists for the
  /// active angles) and its branch.
  class StateType : public ClosedAnglesState {
   public:
    int branch = 1;  ///< +1 or −1: the sign of the middle passive crease
  };

  /// The space of `chain`, sampled and checked within `bounds`.
  /// @throws ompl::Exception when `bounds` does not hold one range per joint
  SingleVertexStateSpace(std::shared_ptr<const SingleVertexChain> chain, AngleBounds bounds);

  /// The chain whose configurations the space holds.
  const SingleVertexChain& chain() const { return *chain_; }
  /// Where the branches count as meeting: |middle passive angle| below this (radians).
  double meeting_tolerance() const { return meeting_tolerance_; }
  /// Sets meeting_tolerance() (radians; default 1e-3).
  void set_meeting_tolerance(double t) { meeting_tolerance_ = t; }

  /// Sets `state` from a full angle vector: the actives are taken, the passives re-solved on the
  /// branch of `angles`.
  /// @return false when `angles` has the wrong size, no root exists, or the re-solved passive
  ///         angles differ from those given by more than `tolerance` (radians)
  bool from_fold_state(const geometry::FoldState& angles, ompl::base::State* state, double tolerance = 1e-6) const;
  /// The fold angles of `state` (one per joint, radians), closed or not.
  geometry::FoldState to_fold_state(const ompl::base::State* state) const;
  /// Solves the passives of `state` (actives already set) on `branch` (+1 / −1; 0 counts as +1);
  /// sets `branch` and `closed`. Without a root the passives are set to values of the branch
  /// alone (the middle one ±π, the others 0).
  void complete(StateType* state, int branch) const;

  /// n − 3: the number of active creases.
  unsigned int getDimension() const override;
  /// Length of the diagonal of the bounds box over the active angles and the middle passive one.
  double getMaximumExtent() const override;
  /// Volume of the bounds box over the active angles, times 2 (the branches).
  double getMeasure() const override;
  /// Clamps the active angles into their bounds and re-solves the passives on the state's branch.
  void enforceBounds(ompl::base::State* state) const override;
  /// Euclidean distance over the active angles and the middle passive one, radians: coordinates
  /// that determine the state and never wrap, so that the distance to a target shrinks to zero
  /// along the interpolation.
  double distance(const ompl::base::State* state1, const ompl::base::State* state2) const override;
  /// Whether both are closed or both not, with every angle within 1e-12 rad.
  bool equalStates(const ompl::base::State* state1, const ompl::base::State* state2) const override;
  /// The state a fraction `t` of the way from `from` to `to`, as described for the class.
  void interpolate(const ompl::base::State* from, const ompl::base::State* to, double t,
                   ompl::base::State* state) const override;
  /// A SingleVertexSampler.
  ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;
  /// The angles, the branch, and "(no root)" for a state that is not closed.
  void printState(const ompl::base::State* state, std::ostream& out) const override;
  /// Registers the default projection (for planners that grid the space): the first two active
  /// angles, cells of 0.2 rad.
  void registerProjections() override;

 protected:
  /// A StateType.
  ClosedAnglesState* new_state() const override { return new StateType; }
  /// The branch, an int.
  std::size_t extra_bytes() const override { return sizeof(int); }
  /// Writes the branch.
  void write_extra(const ClosedAnglesState& state, char* out) const override;
  /// Reads the branch.
  void read_extra(const char* in, ClosedAnglesState& state) const override;
  /// Copies the branch.
  void copy_extra(const ClosedAnglesState& from, ClosedAnglesState& to) const override;

 private:
  void set_open(StateType* state, int branch) const;  // no root: canonical passives
  std::shared_ptr<const SingleVertexChain> chain_;
  double meeting_tolerance_ = 1e-3;
};

/// Rejection sampling over the active angles until a root exists and every passive angle is in
/// bounds; the branch is drawn at random (near-sampling keeps the near state's branch). A share
/// `meeting_fraction` of the uniform samples lies where both branches meet (one active angle moved
/// until the middle passive crease is flat): the bridges through which a tree changes branch.
class SingleVertexSampler : public ompl::base::StateSampler {
 public:
  /// A sampler of `space`, which must outlive it.
  explicit SingleVertexSampler(const SingleVertexStateSpace* space);
  /// A uniform state within the bounds; not closed when kMaxTries draws all fail.
  void sampleUniform(ompl::base::State* state) override;
  /// Active angles within `distance` (radians, per angle) of `near`'s, clamped to the bounds, on
  /// `near`'s branch (a random one when `near` sits where the branches meet); a copy of `near`
  /// when kMaxTries draws fail.
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  /// Active angles drawn from normal distributions about `mean`'s (standard deviation `stdDev`,
  /// radians), clamped to the bounds, on `mean`'s branch; a copy of `mean` when kMaxTries draws
  /// fail.
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) override;

  /// Draws per sample before giving up.
  static constexpr int kMaxTries = 1000;
  /// Sets the share of uniform samples placed where both branches meet (default 0.2).
  void set_meeting_fraction(double f) { meeting_fraction_ = f; }

 private:
  bool accept(SingleVertexStateSpace::StateType* s, int branch);
  bool meet(SingleVertexStateSpace::StateType* s);
  const SingleVertexStateSpace* sv_;
  double meeting_fraction_ = 0.2;
};

/// The reader of SingleVertexStateSpace states: false for a state that is not closed.
StateReader single_vertex_reader(std::shared_ptr<const SingleVertexStateSpace> space);

}  // namespace foldkit::statespaces
