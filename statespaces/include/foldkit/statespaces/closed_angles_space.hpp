#pragma once
/// @file
/// What the exact state spaces (single-vertex, driving) share: states that hold every fold angle
/// of the pattern and whether they close, within per-joint bounds, and OMPL's storage of them.
#include <cstddef>
#include <string>

#include <ompl/base/StateSpace.h>

#include "foldkit/statespaces/angle_bounds.hpp"

namespace foldkit::statespaces {

/// A state of an exact space: every fold angle and whether they close.
class ClosedAnglesState : public ompl::base::State {
 public:
  double* angles = nullptr;  ///< one per joint of the pattern, radians (owned by the space)
  bool closed = true;        ///< false when the space found no closed state for its coordinates
};

/// The base of the exact spaces: allocation, copy, serialization (the angles, a space's extra
/// bytes, the closed flag), value addresses and the bounds test of states that hold every fold
/// angle. Each space keeps only its own geometry (dimension, distance, interpolation, sampling);
/// one whose state carries more (the single vertex's branch) overrides the extra hooks.
class ClosedAnglesSpace : public ompl::base::StateSpace {
 public:
  /// A space of states with `joints` angles, valid within `bounds`, named `kind` + OMPL's
  /// numbered name ("SingleVertex", "Driving").
  /// @throws ompl::Exception when `bounds` does not hold one range per joint
  ClosedAnglesSpace(const std::string& kind, std::size_t joints, AngleBounds bounds);

  /// The per-joint angle bounds.
  const AngleBounds& bounds() const { return bounds_; }
  /// Number of joints (fold angles per state).
  std::size_t joints() const { return n_; }

  /// Closed, and every angle within its bounds (to 1e-12 rad).
  bool satisfiesBounds(const ompl::base::State* state) const override;
  /// Copies the angles, the closed flag and the extras.
  void copyState(ompl::base::State* destination, const ompl::base::State* source) const override;
  /// The angles, the extra bytes, one byte for the closed flag.
  unsigned int getSerializationLength() const override;
  /// Writes the layout of getSerializationLength().
  void serialize(void* serialization, const ompl::base::State* state) const override;
  /// Reads the layout of getSerializationLength().
  void deserialize(ompl::base::State* state, const void* serialization) const override;
  /// A state of the space's type (new_state()) with its angles, zero.
  ompl::base::State* allocState() const override;
  /// Frees a state of allocState().
  void freeState(ompl::base::State* state) const override;
  /// The address of fold angle `index`, or null past the last joint.
  double* getValueAddressAtIndex(ompl::base::State* state, unsigned int index) const override;

 protected:
  /// A new state of the space's own type, its angles not yet allocated.
  virtual ClosedAnglesState* new_state() const = 0;
  /// Bytes a state carries besides its angles and closed flag.
  virtual std::size_t extra_bytes() const { return 0; }
  /// Writes a state's extras (extra_bytes() of them) to `out`.
  virtual void write_extra(const ClosedAnglesState& /*state*/, char* /*out*/) const {}
  /// Reads a state's extras from `in`.
  virtual void read_extra(const char* /*in*/, ClosedAnglesState& /*state*/) const {}
  /// Copies a state's extras.
  virtual void copy_extra(const ClosedAnglesState& /*from*/, ClosedAnglesState& /*to*/) const {}

  const std::size_t n_;  ///< joints
  AngleBounds bounds_;   ///< per-joint bounds of a valid state
};

}  // namespace foldkit::statespaces
