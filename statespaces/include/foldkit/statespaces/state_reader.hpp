#pragma once
/// @file
/// How fold angles are read from an OMPL state: one reader per space, declared next to its space
/// (single_vertex_reader(), driving_reader(), constrained_reader()).
#include <functional>
#include <memory>

#include <Eigen/Core>
#include <ompl/base/State.h>

#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::statespaces {

/// Reads the fold angles of an OMPL state of some space into its second argument; false when
/// the state holds none (a single-vertex state without a root).
using StateReader = std::function<bool(const ompl::base::State*, geometry::FoldState&)>;

/// The reader of a space whose states hold every angle and whether they close (`angles`,
/// `closed`; the space's `joints()` angles): false for a state that is not closed.
template <class Space>
StateReader closed_angles_reader(std::shared_ptr<const Space> space) {
  return [space](const ompl::base::State* state, geometry::FoldState& out) {
    const auto* s = state->template as<typename Space::StateType>();
    if (!s->closed) return false;
    out.angles = Eigen::Map<const Eigen::VectorXd>(s->angles, static_cast<Eigen::Index>(space->joints()));
    return true;
  };
}

}  // namespace foldkit::statespaces
