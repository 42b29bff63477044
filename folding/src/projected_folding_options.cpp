#include "projected_folding_options.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace foldkit::folding::detail {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

ProjectedFoldingOptions checked_options(const geometry::CreasePattern& pattern, const ProjectedFoldingOptions& options,
                                        Eigen::VectorXd& desired) {
  const auto n = static_cast<Eigen::Index>(pattern.joints().size());
  if (n == 0) throw std::invalid_argument("fold_projected: the pattern has no crease");
  ProjectedFoldingOptions o = options;
  if (options.toward.size()) {
    if (options.velocity.size()) throw std::invalid_argument("fold_projected: give a desired velocity or target angles, not both");
    if (options.toward.size() != n)
      throw std::invalid_argument("fold_projected: the target angles are " + std::to_string(options.toward.size()) + " for " +
                                  std::to_string(n) + " creases");
    if (!options.toward.allFinite() || !(options.toward.cwiseAbs().maxCoeff() <= kPi))
      throw std::invalid_argument("fold_projected: the target angles must be finite and within ±180 degrees");
    if (!(options.toward.cwiseAbs().maxCoeff() > 0.0))
      throw std::invalid_argument("fold_projected: every target angle is 0 (the flat sheet): nothing to fold toward");
    o.velocity = options.toward;
    o.target_fraction = options.target_fraction * options.toward.cwiseAbs().maxCoeff() / kPi;
  }
  desired = o.velocity.size() ? o.velocity : assignment_velocity(pattern);
  if (desired.size() != n)
    throw std::invalid_argument("fold_projected: the desired velocity has " + std::to_string(desired.size()) +
                                " entries for " + std::to_string(n) + " creases");
  if (!desired.allFinite()) throw std::invalid_argument("fold_projected: the desired velocity is not finite");
  if (!(desired.cwiseAbs().maxCoeff() > 0.0))
    throw std::invalid_argument(options.velocity.size()
                                    ? "fold_projected: the desired velocity is zero"
                                    : "fold_projected: no crease has a mountain/valley assignment; give a desired velocity");
  if (!(options.target_fraction > 0.0 && options.target_fraction <= 1.0))
    throw std::invalid_argument("fold_projected: the target fraction must lie in (0, 1]");
  if (!(options.max_step > 0.0 && options.max_step <= 0.5))
    throw std::invalid_argument("fold_projected: the step must lie in (0, 0.5] rad");
  if (!(options.closure_tolerance > 0.0 && options.closure_tolerance < 1e-3))
    throw std::invalid_argument("fold_projected: the closure tolerance must lie in (0, 1e-3)");
  if (!(options.chord_tolerance == 0.0 || (options.chord_tolerance > options.closure_tolerance && options.chord_tolerance <= 0.1)))
    throw std::invalid_argument("fold_projected: the chord tolerance must be 0 or lie in (closure tolerance, 0.1]");
  if (options.max_steps < 1) throw std::invalid_argument("fold_projected: max_steps must be at least 1");
  if (!(options.lead_in > 0.0 && options.lead_in <= 1.0))
    throw std::invalid_argument("fold_projected: the lead-in amplitude must lie in (0, 1] rad");
  if (!(options.rank_tolerance > 0.0) || !(options.singular_ratio >= 0.0) || !(options.speed > 0.0) ||
      !std::isfinite(options.speed))
    throw std::invalid_argument("fold_projected: the rank tolerance and the CMML speed must be positive");

  return o;
}

}  // namespace foldkit::folding::detail
