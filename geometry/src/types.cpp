#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry {

const char* to_string(Assignment a) {
  switch (a) {
    case Assignment::Mountain: return "M";
    case Assignment::Valley: return "V";
    case Assignment::Flat: return "F";
    case Assignment::Unassigned: break;
  }
  return "U";
}

}  // namespace foldkit::geometry
