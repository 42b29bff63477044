#pragma once
/// @file
/// Carpenter's rule for planar chains (Connelly, Demaine & Rote 2003; docs/CARPENTER.md): an open
/// chain is straightened and a closed one convexified by strictly expansive motions, each step a
/// velocity field in which bars keep their lengths and every other vertex distance grows, from an
/// LP or carried over from the step before (CarpenterPlanarMethod).
/// Folding is unfolding replayed backwards (reversed()).
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

/// One position per chain vertex, in the chain's length units (io::Frame2 is the same type).
using Frame2 = std::vector<Eigen::Vector2d>;

/// An open chain of bars p0-p1-…-pn, or (closed) the polygon p0-…-pn-p0.
struct PlanarChain {
  Frame2 points;        ///< the vertices p0 … pn, in chain order
  bool closed = false;  ///< whether a bar joins pn back to p0
};

/// How carpenter_planar() finds the expansive motion of each step (docs/CARPENTER.md, "Methods").
enum class CarpenterPlanarMethod {
  /// One Connelly–Demaine–Rote LP per step (constraint generation, Clp), certified on all pairs:
  /// the baseline, `--method lp`.
  Lp,
  /// Open chains: the last step's joint speeds are carried over the step's event (the joint
  /// that went straight drops out) and checked on all pairs; where some pair's weighted rate
  /// fell below `carry_rate`, a small LP over the joints next to the straightened ones and near
  /// the weak pairs' ends mends the field.
  /// The global LP only starts the run and takes over when the mending fails. Closed chains as
  /// Lp (dropping a joint's speed would open the polygon). `--method carried`.
  CarriedField,
  /// Streinu's pseudo-triangulation mechanism: the bars completed to a pointed
  /// pseudo-triangulation, one non-bar convex-hull edge removed; the 1-DOF motion (one sparse
  /// linear solve per step, expansive by Streinu's theorem) is followed to the next event, where
  /// a vertex stops being pointed: a flip, or two bars aligned (the joint merged). Every step is
  /// still checked on all pairs. Experimental: slower than CarriedField, and polygons of 100 or
  /// more vertices do not convexify (docs/CARPENTER.md, Limits). `--method pseudo`.
  PseudoTriangulation,
};
/// The method's name as `foldkit carpenter --method` and Python's `method=` spell it: "lp",
/// "carried" or "pseudo".
const char* to_string(CarpenterPlanarMethod method);
/// The method named "lp", "carried" or "pseudo".
/// @throws std::invalid_argument for any other name
CarpenterPlanarMethod parse_carpenter_method(const std::string& name);
/// Every method's name, the default's first.
std::vector<std::string> carpenter_method_names();

/// Options of carpenter_planar().
struct CarpenterPlanarOptions {
  /// How each step's motion is found.
  CarpenterPlanarMethod method = CarpenterPlanarMethod::CarriedField;
  /// CarriedField: a carried field is used while its smallest weighted strut rate (the LP asks
  /// for ≥ 1) is at least this.
  double carry_rate = 0.5;
  /// CarriedField: largest window LP, as a fraction of the merged joints (at least 64 joints);
  /// a field that needs more is found by the global LP.
  double repair_window = 0.25;
  std::size_t max_steps = 200'000;  ///< steps at most (then StatusCode::LimitReached)
  /// Largest turn of any joint in one step (radians); a step is halved until no vertex distance
  /// shrinks, and ends early where a joint becomes straight.
  double max_turn = 0.2;
  /// Struts the first LP of a step starts with besides last step's binding ones: vertex pairs
  /// closer than this many times the mean merged bar length, or than twice the median distance
  /// from a vertex to its nearest non-adjacent vertex where that is shorter (star-shaped polygons,
  /// whose long spokes crowd the centre; on lattice walks that median is ≈ 1.36 mean bars, so
  /// above ≈ 1.3 it applies to them too). Violated struts are added after. (1.0 ran 20 % faster
  /// than 2.0 at 400 and 1,000 links: fewer rows, about as many rounds.)
  double near_radius = 1.0;
  /// Solve with every strut in the LP from the start (no constraint generation): O(n²) rows,
  /// for comparison only.
  bool all_struts = false;
  /// Record one frame every this many steps (the first and last frames are always kept); 0
  /// counts as 1.
  std::size_t frame_stride = 1;
  /// Called after every LP step: steps so far, unit "steps" (not for the closed-form
  /// straightening of a monotone open chain).
  geometry::ProgressFn progress;
};

/// What carpenter_planar() found.
struct CarpenterPlanarResult {
  std::vector<Frame2> frames;  ///< recorded frames (see frame_stride); frames[0] is the input
  bool closed = false;         ///< whether the chain is closed
  /// StatusCode::Success: straight (open) or convex (closed). Otherwise
  /// StatusCode::LimitReached (max_steps) or StatusCode::NoProgress (an LP failed, no strictly
  /// expansive motion, or no step keeps every distance growing), with the step in the message.
  geometry::Status status;
  std::size_t steps = 0;       ///< steps taken
  std::size_t lp_solves = 0;   ///< LPs solved, every constraint-generation round counted
  std::size_t carried_steps = 0;  ///< steps taken on a carried (perhaps mended) field (CarriedField)
  std::size_t window_lp_solves = 0;  ///< of lp_solves, the small window LPs that mended a carried field
  /// Steps whose field held one end of an open chain rigid because the LP over the whole chain
  /// failed (spirals: the speeds it needs span more than doubles resolve; docs/CARPENTER.md)
  std::size_t held_steps = 0;
  std::size_t max_struts = 0;  ///< most strut rows any LP held
  /// PseudoTriangulation: events where a strut lost pointedness and was replaced (flips).
  std::size_t flips = 0;
  /// PseudoTriangulation: events where two bars aligned and their joint was merged.
  std::size_t straightenings = 0;
  /// PseudoTriangulation: steps taken by the global LP instead, where no PPT could be built
  /// (a vertex within rounding of an event).
  std::size_t pseudo_lp_steps = 0;
  /// PseudoTriangulation: seconds spent in the all-pairs distance check of the steps.
  double certificate_seconds = 0.0;
  double seconds = 0.0;        ///< wall-clock time of the run
  /// Over every recorded frame: max |bar length − input length| (length units).
  double max_length_error = 0.0;
  /// The minimum over consecutive recorded frames and all vertex pairs of d_new − d_old (length
  /// units; ≥ 0 up to rounding for an expansive motion); 0 with a single frame.
  double min_distance_growth = 0.0;
};

/// Checks that `chain` is simple and can be unfolded.
/// @throws std::invalid_argument naming the first problem: too few points (2 open, 3 closed), a
///         non-finite coordinate, a zero-length bar, a bar folded back on its neighbour, or two
///         non-adjacent bars that touch or cross (which includes two vertices at one place)
void check_simple_chain(const PlanarChain& chain);

/// Straightens an open chain or convexifies a closed one. Joints straight in the input are
/// merged first; a monotone open chain is straightened in closed form, without LPs.
/// @param chain    the chain; check_simple_chain() is applied to it first
/// @param options  step limits, LP strategy, frame recording, progress
/// @return the frames of the motion and how it ended (failures are a status, not thrown)
/// @throws std::invalid_argument as check_simple_chain(), for a chain that is not simple, and for
///         options out of range: max_turn not in (0, π], near_radius not positive and finite,
///         carry_rate not in (0, 1] (the LP asks for 1: a higher floor would keep pairs weak for
///         ever), repair_window not in [0, 1]
CarpenterPlanarResult carpenter_planar(const PlanarChain& chain, const CarpenterPlanarOptions& options = {});

/// The frames in reverse order: the folding motion from straight (or convex) to the input.
std::vector<Frame2> reversed(const std::vector<Frame2>& frames);

/// Signed turning angle at each joint, radians in (−π, π], positive to the left (0 = straight):
/// for m points, joints 1 … m−2 of an open chain and 0 … m−1 of a closed one (in that order).
/// @param frame   the chain's vertices
/// @param closed  whether the chain is closed
std::vector<double> turning_angles(const Frame2& frame, bool closed);

/// Pairwise-distance and bar-length figures of a frame sequence, computed from the frames alone.
struct MotionCheck {
  double max_length_error = 0.0;     ///< max |bar length − its length in the first frame| over the frames
  /// Minimum over consecutive frames and all vertex pairs of d_new − d_old; 0 for fewer than two
  /// frames.
  double min_distance_growth = 0.0;
};
/// The MotionCheck of `frames` (all with the same number of vertices) of a chain, open or closed.
MotionCheck check_motion(const std::vector<Frame2>& frames, bool closed);

/// Straight: every turning angle of the open chain within `tolerance` (radians) of 0.
bool is_straight(const Frame2& frame, double tolerance = 1e-9);
/// Convex: the closed polygon has at least 3 vertices, all turns beyond `tolerance` (radians) of
/// one sign (zero turns allowed) and total turning ±2π (to 1e-6).
bool is_convex(const Frame2& frame, double tolerance = 1e-9);

/// The planar chain's frames as CMML (chain files and the CSV/JSON frame writers are
/// io/chain_file.hpp): one event per frame (EventNumber = frame index, from 0; the first event
/// goes from flat to frame 0) setting every joint to its turning angle, joints numbered as in
/// turning_angles() (vertex index). Within an event the joint that turns most moves at 1 rad/s
/// and the others arrive with it (at least 1e-6 rad/s) (docs/CARPENTER.md).
/// @param frames  the frames, in order
/// @param closed  whether the chain is closed
/// @param title   the sequence's title
geometry::FoldSequence turning_angle_sequence(const std::vector<Frame2>& frames, bool closed,
                                              std::string title = {});

}  // namespace foldkit::folding
