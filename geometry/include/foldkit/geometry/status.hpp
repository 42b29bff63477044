#pragma once
/// @file
/// How an algorithm ended: one status type for every algorithm in foldkit (projection, the
/// stiffness solve, simulation, planning, projected folding, Carpenter's rule, Hamiltonian
/// paths), in the manner of OMPL's ompl::base::PlannerStatus.
#include <string>
#include <utility>

namespace foldkit::geometry {

/// The outcome of an algorithm. Every result struct carries one, in a Status; codes an
/// algorithm cannot produce are simply never set by it (each result's documentation lists its
/// codes).
enum class StatusCode {
  Unknown,             ///< not decided: the default of a result nothing has filled in yet
  Success,             ///< did what was asked: converged, reached the target, found, valid, solved
  InvalidInput,        ///< the input cannot be worked on (e.g. a non-finite start angle)
  Collision,           ///< facets cross (a fold stops before it; a simulated sequence is invalid)
  ClosureViolated,     ///< a state leaves the closure manifold by more than the tolerance
  Singular,            ///< the closure Jacobian (or a linear system) lost rank where it must not
  NotRigidlyFoldable,  ///< no rigid motion follows the asked direction out of the flat sheet
  NoSolution,          ///< shown that no answer exists (e.g. no Hamiltonian path, a goal out of reach)
  NoProgress,          ///< stalled without a proof: no step improves (local minimum, no expansive motion)
  LimitReached,        ///< an iteration, step, node or time budget ran out before an answer
};

/// The code's name in the command line's JSON output: "unknown", "success", "invalid-input",
/// "collision", "closure-violated", "singular", "not-rigidly-foldable", "no-solution",
/// "no-progress", "limit-reached".
const char* to_string(StatusCode code);

/// A StatusCode and the words that explain it ("no convergence in 200 iterations").
struct Status {
  StatusCode code = StatusCode::Unknown;  ///< how it ended
  std::string message;                    ///< why, in words; a short summary on success

  Status() = default;
  /// A status with its code and message.
  Status(StatusCode code_, std::string message_) : code(code_), message(std::move(message_)) {}

  /// True when the code is StatusCode::Success.
  bool ok() const noexcept { return code == StatusCode::Success; }
  /// Same as ok(), so that `if (result.status)` reads naturally.
  explicit operator bool() const noexcept { return ok(); }
};

}  // namespace foldkit::geometry
