#include <algorithm>
#include <cmath>
#include <sstream>

#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSumTolerance = 1e-9;
// A sector fanned as one triangle would be a flat sliver when wide and no triangle at all from
// π on; cutting it into arcs of at most π/2 keeps every triangle well-shaped.
constexpr double kMaxArc = kPi / 2;
// A sector of π/2 that rounding left an ulp wider needs no extra corner.
constexpr double kArcSlack = 1e-9;

Vec2 on_circle(double radius, double angle) { return radius * Vec2(std::cos(angle), std::sin(angle)); }

void check_sectors(const std::vector<double>& sectors) {
  constexpr const char* kName = "single_vertex";
  if (sectors.size() < 2) detail::reject(kName, "needs at least 2 sectors (got " + std::to_string(sectors.size()) + ")");
  double sum = 0.0;
  for (std::size_t i = 0; i < sectors.size(); ++i) {
    if (!(sectors[i] > 0.0) || !std::isfinite(sectors[i])) {
      std::ostringstream out;
      out << "sector " << i << " must be positive and finite (got " << sectors[i] << ")";
      detail::reject(kName, out.str());
    }
    sum += sectors[i];
  }
  if (std::abs(sum - 2 * kPi) > kSumTolerance) {
    std::ostringstream out;
    out.precision(17);
    out << "sectors must sum to 2π within " << kSumTolerance << " (sum " << sum << ")";
    detail::reject(kName, out.str());
  }
}

}  // namespace

PatternSpec single_vertex(const std::vector<double>& sectors, double radius, JointDefaults j) {
  check_sectors(sectors);
  detail::require_positive("single_vertex", "radius", radius);
  detail::require_joint_defaults("single_vertex", j);

  const int n = static_cast<int>(sectors.size());
  std::vector<double> start(sectors.size(), 0.0);  // direction of crease i
  for (int i = 1; i < n; ++i) start[i] = start[i - 1] + sectors[i - 1];
  std::vector<Vec2> ends;
  for (double a : start) ends.push_back(on_circle(radius, a));
  ends[0] = Vec2(radius, 0.0);  // exact, since the last sector closes on it

  detail::SpecBuilder builder("single vertex of degree " + std::to_string(n), j);
  const Vec2 centre(0.0, 0.0);
  for (int i = 0; i < n; ++i) {
    const int arcs = std::max(1, static_cast<int>(std::ceil((sectors[i] - kArcSlack) / kMaxArc)));
    std::vector<Vec2> corners{centre, ends[i]};
    for (int k = 1; k < arcs; ++k) corners.push_back(on_circle(radius, start[i] + sectors[i] * k / arcs));
    corners.push_back(ends[(i + 1) % n]);
    builder.add_fan_actor(corners);
  }
  // Crease i separates sector i − 1 (actor i, or n for i = 0) from sector i (actor i + 1).
  for (int i = 0; i < n; ++i) builder.add_joint(centre, ends[i], i == 0 ? n : i, i + 1);
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators

namespace foldkit::geometry::generators {

std::vector<double> random_sectors(int n, std::mt19937& rng, double smallest) {
  if (n < 3) detail::reject("random_sectors", "needs at least 3 sectors (got " + std::to_string(n) + ")");
  if (!(smallest >= 0.0) || !(n * smallest < 2 * kPi))
    detail::reject("random_sectors", "the smallest sector times the degree must stay below 2π");
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> s(static_cast<std::size_t>(n));
  double sum = 0.0;
  for (double& x : s) sum += (x = u(rng));
  for (double& x : s) x = smallest + x / sum * (2 * kPi - n * smallest);
  return s;
}

}  // namespace foldkit::geometry::generators
