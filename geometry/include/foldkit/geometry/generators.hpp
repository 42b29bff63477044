#pragma once
/// @file
/// Parametric crease patterns (docs/GENERATORS.md).
#include <random>
#include <string>
#include <vector>

#include "foldkit/geometry/pattern_spec.hpp"

/// Parametric crease patterns. Each returns a PatternSpec that build_pattern() accepts without
/// error; actors and joints are numbered from 1 in a documented order (see docs/GENERATORS.md).
/// Lengths are in the pattern's units, angles in radians. Every generator throws
/// std::invalid_argument ("NAME: why") for a count below its minimum, a length that is not
/// positive and finite, or JointDefaults that are not finite and non-negative.
namespace foldkit::geometry::generators {

/// Spring and damping constants given to every joint a generator makes.
struct JointDefaults {
  double spring = 1.0;   ///< PMML SpringConst (finite, ≥ 0)
  double damping = 0.1;  ///< PMML DampConst (finite, ≥ 0)
};

/// One interior vertex at the origin with creases at cumulative sector angles, the first
/// crease along +x; the sheet is the polygon inscribed in the circle of `radius` through the
/// crease ends, with extra corners on the circle splitting every sector wider than π/2 into
/// equal arcs, so that no triangle spans more than π/2 at the vertex.
/// @param sectors  sector angles counter-clockwise, radians: at least 2, each positive and
///                 finite, summing to 2π within 1e-9
/// @param radius   distance of the crease ends from the vertex
/// @param j        constants of every joint
/// @throws std::invalid_argument for sectors or a radius that break these rules
PatternSpec single_vertex(const std::vector<double>& sectors, double radius = 1.0, JointDefaults j = {});

/// `n` positive sector angles (radians) summing to 2π, none below `smallest`: uniform weights
/// drawn from `rng`, scaled into what is left above n·smallest.
/// @throws std::invalid_argument unless n ≥ 3, smallest ≥ 0 and n·smallest < 2π
std::vector<double> random_sectors(int n, std::mt19937& rng, double smallest = 0.05);

/// `panels` (≥ 1) rectangles of panel_width × height in a row along +x, joined by parallel
/// creases (unassigned).
PatternSpec strip(int panels, double panel_width = 1.0, double height = 1.0, JointDefaults j = {});

/// rows × cols (each ≥ 1) square cells of side `cell` (two triangles each), every cell edge
/// inside the sheet a crease (unassigned).
PatternSpec grid(int rows, int cols, double cell = 1.0, JointDefaults j = {});

/// Concentric rings (`rings` ≥ 1, each `ring_width` wide) crossed by `spokes` (≥ 3) radial
/// creases at equal angles; the innermost ring is a fan of triangles around the centre, every
/// arc between spokes a straight crease. Creases unassigned.
PatternSpec circular_lattice(int rings, int spokes, double ring_width = 1.0, JointDefaults j = {});

/// Miura-ori of rows × cols (each ≥ 1) parallelograms: zig-zag columns of width `a`, rows of
/// height `b`, parallelogram angle `angle` (radians, (0, π/2]; π/2 gives a plain grid). The
/// straight creases are the vertical lines x = i·a, odd ones lifted by a / tan(angle), so the
/// row boundaries zig-zag along x. Zig-zag lines mountain/valley alternating from one to the
/// next, straight creases alternating per row (the standard assignment, the one the rigid
/// folding follows).
/// @throws std::invalid_argument also for an angle outside (0, π/2]
PatternSpec miura(int rows, int cols, double a = 1.0, double b = 1.0, double angle = 1.0471975511965976,
                  JointDefaults j = {});

/// Waterbomb tessellation of unit cells: vertices on rows y = k (k = 0..rows), at x = 0, 2, …,
/// 2·units on even rows and x = 1, 3, …, 2·units − 1 (plus both sheet edges) on odd rows;
/// horizontal creases along each row (valley), diagonals to the neighbouring rows (mountain).
/// Degree-6 vertices. `units` and `rows` at least 1.
PatternSpec waterbomb(int units, int rows, JointDefaults j = {});

/// The boat of the paper's Fig. 3: a length × 2·half_width sheet with a keel along y = 0 and
/// three degree-4 vertices in series on it (bow A, middle C, stern B); `bow` is the distance
/// from the sheet's end to A and B.
/// @throws std::invalid_argument also unless bow < length / 2
PatternSpec boat(double length = 4.0, double half_width = 1.0, double bow = 1.0, JointDefaults j = {});

/// The classic square twist: a central square of `side` (sides along x and y, centred on the
/// origin) whose four corners are degree-4 vertices; from each corner two pleats of length
/// `pleat` leave along the square's sides turned by `twist` (radians, (0, π/2)). Square sides
/// valley, pleats one valley and one mountain per corner (3 : 1), so parallel pleats of
/// neighbouring corners form the four pleats of the twist. Not rigidly foldable with this
/// assignment.
/// @throws std::invalid_argument also for a twist outside (0, π/2)
PatternSpec square_twist(double side = 1.0, double twist = 1.0471975511965976, double pleat = 1.0,
                         JointDefaults j = {});

/// The sheet of Fig. 8a: `cubes` (≥ 1) cube nets in a row of square tiles of side `tile`, each
/// net a row of three tiles with a column of caps on the middle one (a cap above; a cap below
/// and a far cap beyond it); the last tile of one net is hinged to the first tile of the next,
/// so that the sheet folds into a straight line of cubes (folding::fold_cube_chain). Numbering
/// and geometry: docs/GENERATORS.md.
PatternSpec cube_sheet(int cubes, double tile = 1.0, JointDefaults j = {});

}  // namespace foldkit::geometry::generators
