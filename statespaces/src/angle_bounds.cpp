#include "foldkit/statespaces/angle_bounds.hpp"

namespace foldkit::statespaces {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

AngleBounds AngleBounds::of(const geometry::CreasePattern& pattern, bool use_assignment) {
  const auto n = static_cast<Eigen::Index>(pattern.joints().size());
  AngleBounds b{Eigen::VectorXd::Constant(n, -kPi), Eigen::VectorXd::Constant(n, kPi)};
  if (use_assignment)
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto a = pattern.joints()[static_cast<std::size_t>(j)].assignment;
      if (a == geometry::Assignment::Mountain) b.lower[j] = 0.0;
      if (a == geometry::Assignment::Valley) b.upper[j] = 0.0;
    }
  return b;
}

bool AngleBounds::contains(const geometry::FoldState& state, double slack) const {
  return state.angles.size() == lower.size() && (state.angles.array() >= lower.array() - slack).all() &&
         (state.angles.array() <= upper.array() + slack).all();
}

}  // namespace foldkit::statespaces
