#include <algorithm>

#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {

// Between rows y and y + 1 lies a band of 2·units + 1 triangles, t = 0..2·units from left to
// right. Triangle t has its apex at x = t: odd t on the odd row with base [t − 1, t + 1] on the
// even row, even t on the even row with base [t − 1, t + 1] on the odd row, clipped to the sheet
// (so t = 0 and t = 2·units are the half-size triangles at the sheet's edges).
PatternSpec waterbomb(int units, int rows, JointDefaults j) {
  detail::require_count("waterbomb", "units", units, 1);
  detail::require_count("waterbomb", "rows", rows, 1);
  detail::require_joint_defaults("waterbomb", j);

  const int width = 2 * units;
  const int per_band = width + 1;
  auto actor = [&](int band, int t) { return band * per_band + t + 1; };
  // The segment [x − 1, x + 1] on row y, clipped to the sheet.
  auto base = [&](int x, int y) {
    return std::make_pair(Vec2(std::max(x - 1, 0), y), Vec2(std::min(x + 1, width), y));
  };

  detail::SpecBuilder builder("waterbomb " + std::to_string(units) + "x" + std::to_string(rows), j);
  for (int band = 0; band < rows; ++band) {
    const int even_row = band % 2 == 0 ? band : band + 1, odd_row = band % 2 == 0 ? band + 1 : band;
    for (int t = 0; t <= width; ++t) {
      const int apex_row = t % 2 == 0 ? even_row : odd_row, base_row = t % 2 == 0 ? odd_row : even_row;
      const auto [left, right] = base(t, base_row);
      builder.add_fan_actor({Vec2(t, apex_row), left, right});
    }
  }
  for (int band = 0; band < rows; ++band) {
    const int even_row = band % 2 == 0 ? band : band + 1, odd_row = band % 2 == 0 ? band + 1 : band;
    // Diagonal t separates triangles t − 1 and t: it joins the even x of {t − 1, t} on the even
    // row to the odd x on the odd row.
    for (int t = 1; t <= width; ++t) {
      const int even_x = t % 2 == 0 ? t : t - 1, odd_x = t % 2 == 0 ? t - 1 : t;
      builder.add_joint(Vec2(even_x, even_row), Vec2(odd_x, odd_row), actor(band, t - 1), actor(band, t),
                        Assignment::Mountain);
    }
    // Row y = band + 1 is a base for the same triangles t in both bands: even t on odd rows.
    const int y = band + 1;
    if (y < rows)
      for (int t = y % 2 == 0 ? 1 : 0; t <= width; t += 2) {
        const auto [left, right] = base(t, y);
        builder.add_joint(left, right, actor(band, t), actor(band + 1, t), Assignment::Valley);
      }
  }
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
