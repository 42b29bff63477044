#include <cmath>
#include <sstream>

#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {

// The central square's corners P_k turn by 90° from one to the next; each corner sends two
// pleats outward, the sides meeting there turned by `twist`, so that the mountain pleat of P_k and
// the valley pleat of P_{k+1} are parallel and bound a parallelogram strip. Sectors at every
// corner (counter-clockwise from the valley pleat): π/2, π/2 − twist, π/2 (the square), π/2 + twist,
// flat-foldable by Kawasaki; the smallest sector lies between the mountain pleat and a valley side
// (big–little–big), the classic 3 valleys : 1 mountain of Maekawa.
PatternSpec square_twist(double side, double twist, double pleat, JointDefaults j) {
  detail::require_positive("square_twist", "side", side);
  detail::require_positive("square_twist", "pleat", pleat);
  constexpr double kHalfPi = 1.57079632679489661923;
  if (!(twist > 0.0 && twist < kHalfPi)) {
    std::ostringstream out;
    out << "twist must lie in (0, π/2) (got " << twist << ")";
    detail::reject("square_twist", out.str());
  }
  detail::require_joint_defaults("square_twist", j);

  const double h = side / 2;
  auto dir = [](double a) { return Vec2(std::cos(a), std::sin(a)); };
  auto turn = [](const Vec2& v, int quarters) {
    Vec2 r = v;
    for (int q = 0; q < ((quarters % 4) + 4) % 4; ++q) r = Vec2(-r.y(), r.x());
    return r;
  };
  Vec2 corner[4], valley_end[4], mountain_end[4];
  for (int k = 0; k < 4; ++k) {
    corner[k] = turn(Vec2(h, h), k);
    valley_end[k] = corner[k] + pleat * dir(twist + k * kHalfPi);
    mountain_end[k] = corner[k] + pleat * dir(twist + (k + 1) * kHalfPi);
  }

  std::ostringstream title;
  title << "square twist " << twist * 90.0 / kHalfPi << " deg";
  detail::SpecBuilder builder(title.str(), j);
  const int square = builder.add_fan_actor({corner[0], corner[1], corner[2], corner[3]});
  int wedge[4], strip[4];
  for (int k = 0; k < 4; ++k) wedge[k] = builder.add_fan_actor({corner[k], valley_end[k], mountain_end[k]});
  for (int k = 0; k < 4; ++k)
    strip[k] = builder.add_quad_actor(corner[k], mountain_end[k], valley_end[(k + 1) % 4], corner[(k + 1) % 4]);
  for (int k = 0; k < 4; ++k) builder.add_joint(corner[k], corner[(k + 1) % 4], square, strip[k], Assignment::Valley);
  for (int k = 0; k < 4; ++k) {
    builder.add_joint(corner[k], valley_end[k], wedge[k], strip[(k + 3) % 4], Assignment::Valley);
    builder.add_joint(corner[k], mountain_end[k], wedge[k], strip[k], Assignment::Mountain);
  }
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
