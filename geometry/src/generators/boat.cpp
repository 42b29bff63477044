#include <sstream>

#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {

PatternSpec boat(double length, double half_width, double bow, JointDefaults j) {
  detail::require_positive("boat", "length", length);
  detail::require_positive("boat", "half_width", half_width);
  detail::require_positive("boat", "bow", bow);
  if (!(bow < length / 2)) {
    std::ostringstream out;
    out << "bow must be less than length / 2 so that the bow vertex lies before the middle one (got bow " << bow
        << ", length " << length << ")";
    detail::reject("boat", out.str());
  }
  detail::require_joint_defaults("boat", j);

  const double mid = length / 2;
  const Vec2 a(bow, 0.0), c(mid, 0.0), b(length - bow, 0.0);
  const Vec2 bow_end(0.0, 0.0), stern_end(length, 0.0);
  detail::SpecBuilder builder("boat", j);
  // Actors 1–4 above the keel from bow to stern, 5–8 their mirror images below it.
  for (double side : {1.0, -1.0}) {
    const double y = side * half_width;
    builder.add_fan_actor({bow_end, a, Vec2(0.0, y)});
    builder.add_quad_actor(a, c, Vec2(mid, y), Vec2(0.0, y));
    builder.add_quad_actor(c, b, Vec2(length, y), Vec2(mid, y));
    builder.add_fan_actor({b, stern_end, Vec2(length, y)});
  }
  // Keel, bow to stern.
  builder.add_joint(bow_end, a, 1, 5);
  builder.add_joint(a, c, 2, 6);
  builder.add_joint(c, b, 3, 7);
  builder.add_joint(b, stern_end, 4, 8);
  // Bow diagonals, transverse creases, stern diagonals; each upper one before its mirror image.
  builder.add_joint(a, Vec2(0.0, half_width), 1, 2);
  builder.add_joint(a, Vec2(0.0, -half_width), 5, 6);
  builder.add_joint(c, Vec2(mid, half_width), 2, 3);
  builder.add_joint(c, Vec2(mid, -half_width), 6, 7);
  builder.add_joint(b, Vec2(length, half_width), 3, 4);
  builder.add_joint(b, Vec2(length, -half_width), 7, 8);
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
