#pragma once
#include <memory>
#include <vector>

#include <ompl/base/StateSampler.h>
#include <ompl/base/StateSpace.h>

#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/statespaces/single_vertex_chain.hpp"

namespace foldkit::statespaces {

// Per-joint angle bounds (radians): [−π, π], narrowed to [0, π] for a mountain and [−π, 0] for a
// valley when `use_assignment` and the pattern assigns the crease.
struct AngleBounds {
  Eigen::VectorXd lower, upper;
  static AngleBounds of(const geometry::CreasePattern& pattern, bool use_assignment);
  bool contains(const geometry::FoldState& state, double slack = 1e-12) const;
};

// The exact, (n − 3)-dimensional space of a single vertex (docs/PLANNING.md): a state holds the
// full angle vector (always closed, to rounding) and its branch. Distance: Euclidean over the
// active angles and the middle passive one (which carries the branch). Interpolation: linear in the active angles, the passive ones solved on the from-state's
// branch (the to-state's when the from-state sits where both branches meet; between two
// branches that do not meet at either end there is no such segment, and the states in between are
// not closed). A state for which
// no root exists is marked not `closed`; the validity checker rejects it.
class SingleVertexStateSpace : public ompl::base::StateSpace {
 public:
  class StateType : public ompl::base::State {
   public:
    double* angles = nullptr;  // one per joint of the pattern
    int branch = 1;
    bool closed = true;
  };

  SingleVertexStateSpace(std::shared_ptr<const SingleVertexChain> chain, AngleBounds bounds);

  const SingleVertexChain& chain() const { return *chain_; }
  const AngleBounds& bounds() const { return bounds_; }
  std::size_t joints() const { return n_; }
  // Where the branches count as meeting: |middle passive angle| below this (radians).
  double meeting_tolerance() const { return meeting_tolerance_; }
  void set_meeting_tolerance(double t) { meeting_tolerance_ = t; }

  // Sets `state` from a full angle vector: the actives are taken, the passives re-solved on the
  // branch of `angles`; false when that fails or moves a passive angle by more than `tolerance`.
  bool from_fold_state(const geometry::FoldState& angles, ompl::base::State* state, double tolerance = 1e-6) const;
  geometry::FoldState to_fold_state(const ompl::base::State* state) const;
  // Solves the passives of `state` (actives already set) on `branch`; sets `closed`.
  void complete(StateType* state, int branch) const;

  unsigned int getDimension() const override;
  double getMaximumExtent() const override;
  double getMeasure() const override;
  void enforceBounds(ompl::base::State* state) const override;
  bool satisfiesBounds(const ompl::base::State* state) const override;
  void copyState(ompl::base::State* destination, const ompl::base::State* source) const override;
  double distance(const ompl::base::State* state1, const ompl::base::State* state2) const override;
  bool equalStates(const ompl::base::State* state1, const ompl::base::State* state2) const override;
  void interpolate(const ompl::base::State* from, const ompl::base::State* to, double t,
                   ompl::base::State* state) const override;
  ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;
  ompl::base::State* allocState() const override;
  void freeState(ompl::base::State* state) const override;
  double* getValueAddressAtIndex(ompl::base::State* state, unsigned int index) const override;
  void printState(const ompl::base::State* state, std::ostream& out) const override;
  void registerProjections() override;

 private:
  std::shared_ptr<const SingleVertexChain> chain_;
  AngleBounds bounds_;
  std::size_t n_;
  double meeting_tolerance_ = 1e-3;
};

// Rejection sampling over the active angles until a root exists and every passive angle is in
// bounds; the branch is drawn at random (near-sampling keeps the near state's branch). A share
// `meeting_fraction` of the uniform samples lies where both branches meet (one active angle moved
// until the middle passive crease is flat): the bridges through which a tree changes branch.
class SingleVertexSampler : public ompl::base::StateSampler {
 public:
  explicit SingleVertexSampler(const SingleVertexStateSpace* space);
  void sampleUniform(ompl::base::State* state) override;
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) override;

  static constexpr int kMaxTries = 1000;
  void set_meeting_fraction(double f) { meeting_fraction_ = f; }

 private:
  bool accept(SingleVertexStateSpace::StateType* s, int branch);
  bool meet(SingleVertexStateSpace::StateType* s);
  const SingleVertexStateSpace* sv_;
  double meeting_fraction_ = 0.2;
};

}  // namespace foldkit::statespaces
