#pragma once
/// @file
/// Progress of a long computation, handed to a caller that shows it (the CLI prints it to stderr).
#include <functional>

namespace foldkit::geometry {

/// How far a long computation has got, as passed to a ProgressFn.
struct Progress {
  double done = 0.0;            ///< units of work done
  double total = 0.0;           ///< units in all; 0 when not known in advance
  const char* unit = "";        ///< what a unit is: "events", "steps", "iterations"
  double closure_error = -1.0;  ///< largest loop error of the current state, radians; < 0: none
};

/// Called at every step of the work, however short: the receiver decides what to show and when.
/// It must be cheap and must not throw.
using ProgressFn = std::function<void(const Progress&)>;

}  // namespace foldkit::geometry
