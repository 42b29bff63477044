#include "foldkit/geometry/status.hpp"

namespace foldkit::geometry {

const char* to_string(StatusCode code) {
  switch (code) {
    case StatusCode::Unknown: return "unknown";
    case StatusCode::Success: return "success";
    case StatusCode::InvalidInput: return "invalid-input";
    case StatusCode::Collision: return "collision";
    case StatusCode::ClosureViolated: return "closure-violated";
    case StatusCode::Singular: return "singular";
    case StatusCode::NotRigidlyFoldable: return "not-rigidly-foldable";
    case StatusCode::NoSolution: return "no-solution";
    case StatusCode::NoProgress: return "no-progress";
    case StatusCode::LimitReached: return "limit-reached";
  }
  return "unknown";
}

}  // namespace foldkit::geometry
