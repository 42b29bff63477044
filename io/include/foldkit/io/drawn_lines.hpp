#pragma once
/// @file
/// Crease patterns drawn as loose lines: Origami Simulator's SVG convention and ORIPA's `.cp` and
/// `.opx` formats (issue 34; docs/FORMATS.md). A file is read into its lines, then the lines become
/// a pattern: split where they cross, merged where they meet within a tolerance, the faces of
/// their planar arrangement (CGAL, exact predicates and constructions) taken as the sheet.
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/io/formats.hpp"

namespace foldkit::io {

/// What a drawn line is (Origami Simulator's stroke colours; ORIPA's line types).
enum class LineKind {
  Border,    ///< the sheet's outline (black; .cp type 1)
  Mountain,  ///< a mountain crease (red; .cp type 2)
  Valley,    ///< a valley crease (blue; .cp type 3)
  Cut,       ///< a cut through the sheet (green)
  Facet,     ///< a triangulation line inside one rigid facet (yellow): no joint
  Hinge,     ///< an undriven crease (magenta): a joint without an assignment or target
};

/// The kind's name in messages and docs: "border", "mountain", …
const char* to_string(LineKind kind);

/// One straight line of a file, in the file's coordinates (SVG: after every transform, y down).
struct DrawnLine {
  geometry::Vec2 a = geometry::Vec2::Zero();  ///< one end
  geometry::Vec2 b = geometry::Vec2::Zero();  ///< the other end
  LineKind kind = LineKind::Border;                                        ///< what it is
  /// The crease's target fold angle (radians, positive = mountain): Origami Simulator's stroke
  /// opacity × 180°, signed by the kind; empty where the file gives none (borders, facets,
  /// hinges, .cp files).
  std::optional<double> target;
  int line = 0;  ///< the file's line the element or record starts on
};

/// The lines of an SVG crease pattern in Origami Simulator's convention: `<line>`, `<polyline>`,
/// `<polygon>`, `<rect>` and `<path>` (M/L/H/V/Z, absolute and relative) in nested `<g>`/`<svg>`
/// with `transform`; stroke colour as a name, `#rgb`, `#rrggbb` or `rgb()`; `stroke-opacity` and
/// `opacity` (multiplied down the groups) in attributes or `style`. Elements without a stroke
/// (stroke none or absent: fills, foldkit's facet polygons) and text are not lines.
/// @throws ParseError at the element's line: XML errors, a curve command, a stroke colour that is
///         none of the six, a number that is not finite, an opacity outside [0, 1]
std::vector<DrawnLine> parse_svg_lines(const std::string& text, const std::string& name);

/// The lines of an ORIPA `.cp` file: one line per record `TYPE X1 Y1 X2 Y2` (1 border/cut line,
/// 2 mountain, 3 valley; 0, an auxiliary line, is skipped); blank lines skipped.
/// @throws ParseError at the record's line: a type other than 0–3, a record not of five numbers,
///         a number that is not finite
std::vector<DrawnLine> parse_cp_lines(const std::string& text, const std::string& name);

/// The lines of an ORIPA `.opx` file (java.beans.XMLEncoder XML): every `oripa.OriLineProxy`
/// object with its `type` (as in .cp) and `x0`, `y0`, `x1`, `y1` (a property left out is 0, as
/// the encoder leaves out defaults), at the object's line.
/// @throws ParseError at the object's line: XML errors, a root other than `<java>`, a type
///         other than 0–3, a value that is not a finite number
std::vector<DrawnLine> parse_opx_lines(const std::string& text, const std::string& name);

/// How lines become a pattern.
struct LineImportOptions {
  /// Ends closer than this, relative to the diagonal of the border lines (the sheet: lines far
  /// outside it do not coarsen it), are one vertex; a line that stops
  /// this short of another, or overshoots it by this, meets it. 1e-5: Illustrator writes
  /// coordinates to 0.001, which on the small canvases of Origami Simulator's files (300 units)
  /// leaves ends 3e-6 of the diagonal apart.
  double merge_tolerance = 1e-5;
  geometry::BuildOptions build;  ///< passed to geometry::build_pattern
};

/// The crease pattern the lines draw (y up: the file's y negated), with the targets as its
/// state when any line has one (an unset target is 0 there): lines split at their crossings,
/// ends merged, overlapping lines of one kind merged (a border wins over a crease it covers), the
/// bounded faces of the arrangement the sheet; faces bounded only by facet lines are one actor.
/// @param lines  the file's lines (at least one border line)
/// @param name   the file name of every error and warning
/// @param options  the merge tolerance and the pattern builder's options
/// @throws ParseError at the line of the offending element: no lines, no border, lines that
///         enclose no sheet, a sheet the pattern builder refuses (a cut inside the sheet, …)
/// @throws std::invalid_argument for a merge tolerance outside (0, 0.01]
PatternFile pattern_from_lines(const std::vector<DrawnLine>& lines, const std::string& name,
                               const LineImportOptions& options = {});

/// parse_svg_lines() then pattern_from_lines() of a file.
/// @throws ParseError as both, or when the file cannot be read
PatternFile read_svg_pattern(const std::string& path, const geometry::BuildOptions& options = {});

/// parse_cp_lines() then pattern_from_lines() of a file.
/// @throws ParseError as both, or when the file cannot be read
PatternFile read_cp_pattern(const std::string& path, const geometry::BuildOptions& options = {});

/// parse_opx_lines() then pattern_from_lines() of a file.
/// @throws ParseError as both, or when the file cannot be read
PatternFile read_opx_pattern(const std::string& path, const geometry::BuildOptions& options = {});

}  // namespace foldkit::io
