#include "foldkit/statespaces/closed_angles_space.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include <ompl/util/Exception.h>

namespace foldkit::statespaces {

namespace ob = ompl::base;

ClosedAnglesSpace::ClosedAnglesSpace(const std::string& kind, std::size_t joints, AngleBounds bounds)
    : n_(joints), bounds_(std::move(bounds)) {
  setName(kind + getName());
  if (static_cast<std::size_t>(bounds_.lower.size()) != n_ || static_cast<std::size_t>(bounds_.upper.size()) != n_)
    throw ompl::Exception(kind + "StateSpace: bounds do not hold one range per joint");
}

bool ClosedAnglesSpace::satisfiesBounds(const ob::State* state) const {
  const auto* s = state->as<ClosedAnglesState>();
  if (!s->closed) return false;
  for (std::size_t j = 0; j < n_; ++j) {
    const auto k = static_cast<Eigen::Index>(j);
    if (s->angles[j] < bounds_.lower[k] - 1e-12 || s->angles[j] > bounds_.upper[k] + 1e-12) return false;
  }
  return true;
}

void ClosedAnglesSpace::copyState(ob::State* destination, const ob::State* source) const {
  if (destination == source) return;
  auto* d = destination->as<ClosedAnglesState>();
  const auto* s = source->as<ClosedAnglesState>();
  std::copy(s->angles, s->angles + n_, d->angles);
  d->closed = s->closed;
  copy_extra(*s, *d);
}

unsigned int ClosedAnglesSpace::getSerializationLength() const {
  return static_cast<unsigned int>(n_ * sizeof(double) + extra_bytes() + 1);
}

void ClosedAnglesSpace::serialize(void* serialization, const ob::State* state) const {
  const auto* s = state->as<ClosedAnglesState>();
  auto* out = static_cast<char*>(serialization);
  std::memcpy(out, s->angles, n_ * sizeof(double));
  write_extra(*s, out + n_ * sizeof(double));
  out[n_ * sizeof(double) + extra_bytes()] = s->closed ? 1 : 0;
}

void ClosedAnglesSpace::deserialize(ob::State* state, const void* serialization) const {
  auto* s = state->as<ClosedAnglesState>();
  const auto* in = static_cast<const char*>(serialization);
  std::memcpy(s->angles, in, n_ * sizeof(double));
  read_extra(in + n_ * sizeof(double), *s);
  s->closed = in[n_ * sizeof(double) + extra_bytes()] != 0;
}

ob::State* ClosedAnglesSpace::allocState() const {
  ClosedAnglesState* s = new_state();
  s->angles = new double[n_]();
  return s;
}

void ClosedAnglesSpace::freeState(ob::State* state) const {
  auto* s = state->as<ClosedAnglesState>();
  delete[] s->angles;
  delete s;
}

double* ClosedAnglesSpace::getValueAddressAtIndex(ob::State* state, unsigned int index) const {
  return index < n_ ? state->as<ClosedAnglesState>()->angles + index : nullptr;
}

}  // namespace foldkit::statespaces
