#pragma once
// Carpenter's rule for planar chains (Connelly, Demaine & Rote 2003; docs/CARPENTER.md): an open
// chain is straightened and a closed one convexified by strictly expansive motions, each step an
// LP for a velocity field in which bars keep their lengths and every other vertex distance grows.
// Folding is unfolding replayed backwards (reversed()).
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

using Frame2 = std::vector<Eigen::Vector2d>;  // one position per chain vertex

// An open chain of bars p0-p1-…-pn, or (closed) the polygon p0-…-pn-p0.
struct PlanarChain {
  Frame2 points;
  bool closed = false;
};

struct CarpenterPlanarOptions {
  std::size_t max_steps = 200'000;
  // Largest turn of any joint in one step (radians); a step is halved until no vertex distance
  // shrinks, and ends early where a joint becomes straight.
  double max_turn = 0.2;
  // Struts the first LP of a step starts with besides last step's binding ones: vertex pairs
  // closer than this many times the mean merged bar length. Violated struts are added after.
  // (1.0 ran 20 % faster than 2.0 at 400 and 1,000 links: fewer rows, about as many rounds.)
  double near_radius = 1.0;
  // Solve with every strut in the LP from the start (no constraint generation): O(n²) rows,
  // for comparison only.
  bool all_struts = false;
  // Record one frame every this many steps (the first and last frames are always kept).
  std::size_t frame_stride = 1;
  geometry::ProgressFn progress;  // per step
};

struct CarpenterPlanarResult {
  std::vector<Frame2> frames;  // frames[0] is the input
  bool closed = false;
  // Success: straight (open) or convex (closed). Otherwise LimitReached (max_steps) or
  // NoProgress (an LP failed, no strictly expansive motion, or no step keeps every distance
  // growing), with the step in the message.
  geometry::Status status;
  std::size_t steps = 0;
  std::size_t lp_solves = 0;
  std::size_t max_struts = 0;  // most strut rows any LP held
  double seconds = 0.0;
  // Over every recorded frame: max |bar length − input length|, and the minimum over
  // consecutive recorded frames and all vertex pairs of d_new − d_old.
  double max_length_error = 0.0;
  double min_distance_growth = 0.0;
};

// Throws std::invalid_argument naming the first problem: too few points, a non-finite
// coordinate, a zero-length bar, two vertices at one place, a bar folded back on its neighbour,
// or two bars that touch or cross.
void check_simple_chain(const PlanarChain& chain);

// Straightens an open chain or convexifies a closed one (check_simple_chain() first).
CarpenterPlanarResult carpenter_planar(const PlanarChain& chain, const CarpenterPlanarOptions& options = {});

// The frames in reverse order: the folding motion from straight (or convex) to the input.
std::vector<Frame2> reversed(const std::vector<Frame2>& frames);

// Signed turning angle at each joint, radians in (−π, π], positive to the left (0 = straight):
// joints 1 … n−1 of an open chain, 0 … n−1 of a closed one (in that order).
std::vector<double> turning_angles(const Frame2& frame, bool closed);

// Pairwise-distance and bar-length figures of a frame sequence, computed from the frames alone.
struct MotionCheck {
  double max_length_error = 0.0;
  double min_distance_growth = 0.0;
};
MotionCheck check_motion(const std::vector<Frame2>& frames, bool closed);

// Straight: every turning angle within `tolerance` of 0. Convex: all turns of one sign (zero
// turns allowed) and total turning ±2π.
bool is_straight(const Frame2& frame, double tolerance = 1e-9);
bool is_convex(const Frame2& frame, double tolerance = 1e-9);

// The planar chain's frames as CMML (chain files and the CSV/JSON frame writers are
// io/chain_file.hpp): one event per frame (EventNumber = frame index) setting every joint to its
// turning angle, joints numbered as in turning_angles() (vertex index), velocity from the largest
// change between frames (docs/CARPENTER.md).
geometry::FoldSequence turning_angle_sequence(const std::vector<Frame2>& frames, bool closed,
                                              std::string title = {});

}  // namespace foldkit::folding
