// Four folded states of the Resch tessellation (bench/data/robbykraft_resch-tess.fold) as the
// desired crease velocities that fold them out of flat to half (`foldkit fold --fraction 0.5
// --velocity …`, folding::fold_projected): random, U(0.05, 1) times each crease's assignment
// sign. A and B lie on sheets of the closed states that meet only at singular states; C starts
// near a fold of D's driving chart (docs/PLANNING.md, *Start anywhere*).
#pragma once
#include <string>

namespace foldkit::test {

// The Resch pattern the states belong to.
inline std::string resch_path() { return std::string(FOLDKIT_TEST_DATA) + "/../../bench/data/robbykraft_resch-tess.fold"; }

// Desired velocities as ID:VALUE,… (the joint IDs of the imported pattern).
inline const char* const kReschVelocityA =
    "1:-0.137,2:0.844,3:-0.289,4:-0.626,5:1.000,6:0.813,7:0.567,8:0.527,11:-0.877,12:-0.492,13:-0.912,"
    "14:-0.897,15:-0.582,16:-0.269,17:-0.359,18:0.535,19:0.999,20:0.995,21:0.807,22:-0.800,23:-0.394,"
    "24:-0.203,25:-0.729,26:-0.672,27:-0.516,28:-0.526,29:-0.679,30:-0.905,31:-0.383,32:0.512,33:0.944,"
    "34:-0.883,38:0.784,39:0.344,40:-0.346,41:-0.514,44:-0.937";
inline const char* const kReschVelocityB =
    "1:-0.338,2:0.505,3:-0.113,4:-0.572,5:0.810,6:0.261,7:0.313,8:0.836,11:-0.254,12:-0.837,13:-0.810,"
    "14:-0.207,15:-0.646,16:-0.132,17:-0.688,18:0.219,19:0.316,20:0.057,21:0.594,22:-0.856,23:-0.443,"
    "24:-0.459,25:-0.272,26:-0.822,27:-0.127,28:-0.645,29:-0.543,30:-0.716,31:-0.997,32:0.113,33:0.653,"
    "34:-0.312,38:0.464,39:0.653,40:-0.909,41:-0.847,44:-0.314";
inline const char* const kReschVelocityC =
    "1:-0.511,2:0.085,3:-0.680,4:-0.967,5:0.353,6:0.309,7:0.743,8:0.915,11:-0.233,12:-0.680,13:-0.852,"
    "14:-0.991,15:-0.810,16:-0.473,17:-0.768,18:0.143,19:0.609,20:0.837,21:0.512,22:-0.539,23:-0.652,"
    "24:-0.622,25:-0.390,26:-0.135,27:-0.161,28:-0.347,29:-0.411,30:-0.181,31:-0.842,32:0.229,33:0.066,"
    "34:-0.580,38:0.406,39:0.325,40:-0.101,41:-0.614,44:-0.141";
inline const char* const kReschVelocityD =
    "1:-0.633,2:0.182,3:-0.371,4:-0.903,5:0.367,6:0.742,7:0.718,8:0.954,11:-0.199,12:-0.099,13:-0.531,"
    "14:-0.785,15:-0.800,16:-0.923,17:-0.691,18:0.895,19:0.916,20:0.317,21:0.240,22:-0.885,23:-0.901,"
    "24:-0.182,25:-0.453,26:-0.966,27:-0.165,28:-0.901,29:-0.364,30:-0.177,31:-0.526,32:0.561,33:0.449,"
    "34:-0.233,38:0.716,39:0.214,40:-0.101,41:-0.758,44:-0.165";

}  // namespace foldkit::test
