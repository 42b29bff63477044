#pragma once
// The checks simulate_dynamic() makes before it runs (private to this library).
#include "foldkit/dynamics/dynamic_simulate.hpp"

namespace foldkit::dynamics::detail {

// Radians: the loop error a post-stabilisation leaves, far below any closure tolerance.
inline constexpr double kProjectionTolerance = 1e-9;

// @throws std::invalid_argument for options out of range (simulate_dynamic() lists them).
void check_options(const geometry::CreasePattern& pattern, const DynamicOptions& o);
// @throws std::invalid_argument for a joint the pattern lacks, simulation::SequenceError for a
//         fold angle beyond ±180° or not finite, a motor speed not positive and finite, a spring
//         joint without SpringConst.
void check_sequence(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence, Drive drive);

}  // namespace foldkit::dynamics::detail
