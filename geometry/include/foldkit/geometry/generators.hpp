#pragma once
#include <random>
#include <string>
#include <vector>

#include "foldkit/geometry/pattern_spec.hpp"

// Parametric crease patterns. Each returns a PatternSpec that build_pattern() accepts without
// error; actors and joints are numbered from 1 in a documented order (see docs/GENERATORS.md).
namespace foldkit::geometry::generators {

struct JointDefaults {
  double spring = 1.0;   // PMML SpringConst
  double damping = 0.1;  // PMML DampConst
};

// One interior vertex at the origin with creases at cumulative sector angles (radians, must be
// positive and sum to 2π), the first crease along +x; the sheet is the polygon inscribed in the
// circle of `radius` through the crease ends, with extra corners on the circle splitting every
// sector wider than π/2 into equal arcs, so that no triangle spans more than π/2 at the vertex.
PatternSpec single_vertex(const std::vector<double>& sectors, double radius = 1.0, JointDefaults j = {});

// n positive sector angles summing to 2π, none below `smallest`: uniform weights drawn from
// `rng`, scaled into what is left above n·smallest. std::invalid_argument unless n ≥ 3 and
// n·smallest < 2π.
std::vector<double> random_sectors(int n, std::mt19937& rng, double smallest = 0.05);

// `panels` rectangles of panel_width × height in a row along +x, joined by parallel creases.
PatternSpec strip(int panels, double panel_width = 1.0, double height = 1.0, JointDefaults j = {});

// rows × cols square cells (two triangles each), every cell edge inside the sheet a crease.
PatternSpec grid(int rows, int cols, double cell = 1.0, JointDefaults j = {});

// Concentric rings crossed by `spokes` radial creases; the innermost ring is a fan of triangles
// around the centre, every arc between spokes a straight crease.
PatternSpec circular_lattice(int rings, int spokes, double ring_width = 1.0, JointDefaults j = {});

// Miura-ori of rows × cols parallelograms: zig-zag columns of width a, rows of height b,
// parallelogram angle `angle` (radians, (0, π/2]; π/2 gives a plain grid). The straight creases
// are the vertical lines x = i·a, odd ones lifted by a / tan(angle), so the row boundaries
// zig-zag along x. Zig-zag lines mountain/valley alternating from one to the next, straight
// creases alternating per row (the standard assignment, the one the rigid folding follows).
PatternSpec miura(int rows, int cols, double a = 1.0, double b = 1.0, double angle = 1.0471975511965976,
                  JointDefaults j = {});

// Waterbomb tessellation: vertices on rows y = k (k = 0..rows), at x = 0, 2, …, 2·units on even
// rows and x = 1, 3, …, 2·units − 1 (plus both sheet edges) on odd rows; horizontal creases
// along each row (valley), diagonals to the neighbouring rows (mountain). Degree-6 vertices.
PatternSpec waterbomb(int units, int rows, JointDefaults j = {});

// The boat of the paper's Fig. 3: a length × 2·half_width sheet with a keel along y = 0 and three
// degree-4 vertices in series on it (bow A, middle C, stern B); bow is the distance from the
// sheet's end to A and B.
PatternSpec boat(double length = 4.0, double half_width = 1.0, double bow = 1.0, JointDefaults j = {});

// The classic square twist: a central square of `side` (sides along x and y, centred on the
// origin) whose four corners are degree-4 vertices; from each corner two pleats of length `pleat`
// leave along the square's sides turned by `twist` (radians, (0, π/2)). Square sides valley,
// pleats one valley and one mountain per corner (3 : 1), so parallel pleats of neighbouring corners
// form the four pleats of the twist. Not rigidly foldable with this assignment.
PatternSpec square_twist(double side = 1.0, double twist = 1.0471975511965976, double pleat = 1.0,
                         JointDefaults j = {});

// The sheet of Fig. 8a: `cubes` cube nets in a row, each a row of three tiles with a column of
// caps on the middle one (a cap above; a cap below and a far cap beyond it); the last tile of one
// net is hinged to the first tile of the next, so that the sheet folds into a straight line of
// cubes (folding::fold_cube_chain). Numbering and geometry: docs/GENERATORS.md.
PatternSpec cube_sheet(int cubes, double tile = 1.0, JointDefaults j = {});

}  // namespace foldkit::geometry::generators
