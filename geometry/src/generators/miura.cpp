#include <cmath>
#include <sstream>

#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;
// π/2 computed another way may land an ulp above the double nearest π/2; accept it as π/2.
constexpr double kAngleSlack = 1e-12;

// Zig-zag line j (a row boundary) folds all one way, the next line the other way.
Assignment zigzag(int j) { return j % 2 == 1 ? Assignment::Mountain : Assignment::Valley; }

}  // namespace

PatternSpec miura(int rows, int cols, double a, double b, double angle, JointDefaults j) {
  detail::require_count("miura", "rows", rows, 1);
  detail::require_count("miura", "cols", cols, 1);
  detail::require_positive("miura", "a", a);
  detail::require_positive("miura", "b", b);
  if (!(angle > 0.0 && angle <= kHalfPi + kAngleSlack)) {
    std::ostringstream out;
    out << "angle must lie in (0, π/2] (got " << angle << ")";
    detail::reject("miura", out.str());
  }
  detail::require_joint_defaults("miura", j);

  // Straight creases are the vertical lines x = i·a; odd lines are lifted by `rise`, so the row
  // boundaries zig-zag along x and each cell's corner angle between the two is `angle`.
  const double rise = angle >= kHalfPi ? 0.0 : a / std::tan(angle);
  auto corner = [&](int i, int k) { return Vec2(i * a, k * b + (i % 2 == 1 ? rise : 0.0)); };
  // At an even line the zig-zag dips (a V), so the straight crease above the vertex lies between
  // the two acute sectors and is the odd one out of the 3–1 (Maekawa) split; at an odd line the
  // one below is. Either way straight creases alternate along their line, one row to the next.
  auto straight = [](int i, int row) { return zigzag(i % 2 == 0 ? row + 1 : row); };
  auto zig = [](int, int line) { return zigzag(line); };

  detail::SpecBuilder builder("Miura-ori " + std::to_string(rows) + "x" + std::to_string(cols), j);
  detail::add_quad_lattice(builder, rows, cols, corner, straight, zig);
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
