// Carpenter's rule for planar chains (Connelly, Demaine & Rote; docs/CARPENTER.md): merge straight
// joints, solve the expansive-motion LP, step, restore bar lengths exactly, repeat.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "carpenter_planar_chain.hpp"
#include "carpenter_planar_hold.hpp"
#include "carpenter_planar_velocity.hpp"
#include "carpenter_pseudo.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding {
namespace {

using namespace planar_detail;  // NOLINT: the chain's geometry, private to this folder
using geometry::StatusCode;

// A window LP may always hold this many joints (CarpenterPlanarOptions::repair_window).
constexpr int kMinWindow = 64;

// One run of carpenter_planar: the merged chain, the result it fills and what carries from one
// step to the next.
class PlanarRun {
 public:
  PlanarRun(const PlanarChain& input, const CarpenterPlanarOptions& options)
      : input_(input),
        options_(options),
        closed_(input.closed),
        chain_(input.points, input.closed),
        mean_bar_(mean_bar_length(chain_)),
        stride_(std::max<std::size_t>(1, options.frame_stride)),
        turn_budget_(options.max_turn) {
    result_.closed = closed_;
  }

  CarpenterPlanarResult run() {
    merge_straight_input();
    record(chain_.expand(chain_.q()));
    while (!finished(chain_)) {
      if (result_.steps >= options_.max_steps) {
        result_.status = {StatusCode::LimitReached, "stopped after " + std::to_string(options_.max_steps) + " steps"};
        break;
      }
      if (!closed_ && !monotone_failed_) {
        const std::vector<double> phi = bar_directions(chain_);
        if (monotone(phi)) {
          straighten_monotone(phi);
          continue;
        }
      }
      if (!(pseudo() ? pseudo_step() : lp_step())) break;
    }
    if (!pending_.empty()) record(pending_);
    if (finished(chain_)) result_.status = {StatusCode::Success, closed_ ? "convex" : "straight"};
    if (std::string why = length_drift(input_.points, closed_, result_.max_length_error); !why.empty())
      result_.status = {StatusCode::NoProgress, why};
    result_.min_distance_growth = std::isinf(min_growth_) ? 0.0 : min_growth_;
    result_.flips = mechanism_.counts.flips;
    result_.straightenings = mechanism_.counts.straightenings;
    result_.certificate_seconds = mechanism_.counts.certificate_seconds;
    return std::move(result_);
  }

 private:
  void record(const Frame2& p) {
    if (!last_recorded_.empty()) min_growth_ = std::min(min_growth_, min_distance_growth(last_recorded_, p));
    result_.max_length_error = std::max(result_.max_length_error, bar_length_error(input_.points, p, closed_));
    result_.frames.push_back(p);
    last_recorded_ = p;
  }

  // Every `stride`-th step's frame is recorded, the last one always; the others wait in `pending`.
  void record_step() {
    const Frame2 p = chain_.expand(chain_.q());
    if (result_.steps % stride_ == 0 || finished(chain_)) {
      record(p);
      pending_.clear();
    } else {
      pending_ = p;
    }
  }

  // Joints straight in the input (within rounding) are rigid from the start: an expansive motion
  // cannot open them further, so the LP would have no strictly expansive solution.
  void merge_straight_input() {
    std::vector<int> straight;
    for (int a = 0; a < chain_.vertices(); ++a)
      if (chain_.is_joint(a) && std::abs(chain_.theta(chain_.q(), a)) <= 1e-12) straight.push_back(a);
    if (closed_ && chain_.vertices() - static_cast<int>(straight.size()) < 3) return;  // a flat polygon: rejected earlier
    if (!straight.empty()) chain_.merge(straight);
  }

  // Every bar direction moves linearly to their common direction in `pieces` steps, each checked
  // like an LP step; a failed check hands the chain back to the LP steps for good.
  void straighten_monotone(const std::vector<double>& phi) {
    const double c = common_direction(chain_, phi);
    // Joints turn by θₖ/pieces per step, at most max_turn.
    const int pieces = std::max(1, static_cast<int>(std::ceil(sharpest_joint(chain_) / options_.max_turn)));
    for (int k = 1; k <= pieces && !monotone_failed_; ++k) {
      if (result_.steps >= options_.max_steps) break;
      const double s = static_cast<double>(k) / pieces;
      std::vector<double> to(phi.size());
      for (std::size_t a = 0; a < phi.size(); ++a) to[a] = k == pieces ? c : c + (1.0 - s) * (phi[a] - c);
      const Frame2 next = lay_out(chain_, to);
      // The argument above kMonotoneSpread, checked like every LP step (rounding could only
      // matter at a spread of π, which the threshold keeps away from).
      if (!expansive(chain_, chain_.q(), next)) {
        monotone_failed_ = true;
        break;
      }
      chain_.set_q(next);
      ++result_.steps;
      if (k == pieces) {
        std::vector<int> joints;
        for (int a = 1; a + 1 < chain_.vertices(); ++a) joints.push_back(a);
        chain_.merge(joints);
      }
      record_step();
    }
  }

  // Struts carried over from the last step, renumbered after merges.
  std::vector<std::pair<int, int>> seed_struts() const {
    const int m = chain_.vertices();
    std::vector<int> merged_index(input_.points.size(), -1);
    for (int a = 0; a < m; ++a) merged_index[chain_.key(a)] = a;
    std::vector<std::pair<int, int>> seed;
    for (const auto& [i, j] : carried_)
      if (merged_index[i] >= 0 && merged_index[j] >= 0) seed.emplace_back(merged_index[i], merged_index[j]);
    return seed;
  }

  // The expansive velocity of the current chain; false (with the status set) when there is none.
  bool solve_velocity(detail::ExpansiveVelocity& field) {
    const int m = chain_.vertices();
    std::vector<int> keys(static_cast<std::size_t>(m));
    for (int a = 0; a < m; ++a) keys[a] = chain_.key(a);
    const std::vector<std::pair<int, int>> seed = seed_struts();
    const double mean_merged = mean_bar_length(chain_);
    // CarriedField solves few global LPs on an open chain, the first from nothing: seeded with the
    // pairs within 2 mean bars instead of 1, it took 1.0 s instead of 5–6 s (25 → 7–11 rounds) on
    // the 2,000-link walk. (The Lp method, the baseline, and closed chains are left as measured.)
    const bool first_carried = options_.method == CarpenterPlanarMethod::CarriedField && !closed_ && seed.empty();
    const double radius = options_.near_radius * (first_carried ? 2.0 : 1.0);
    const double near = radius * mean_merged;
    const HeldEnds::Reuse reuse = closed_ ? HeldEnds::Reuse::Expired
                                          : hold_.reuse(chain_, field, keys, seed, near, result_, options_.all_struts);
    held_ = reuse == HeldEnds::Reuse::Used;
    if (reuse == HeldEnds::Reuse::Expired) {
      // While a hold is active the whole chain is a probe: Clp's verdict "infeasible" is not
      // checked by fresh solves, as it would be otherwise; a wrong one only keeps the hold.
      detail::RigidEnds none;
      none.probe = hold_.active();
      field = detail::expansive_velocity(chain_.q(), closed_, seed, near, options_.all_struts, &keys, &basis_memo_, none);
      result_.lp_solves += field.lp_solves;
      result_.max_struts = std::max(result_.max_struts, field.struts);
      if (field.solved) hold_.release();
    }
    if (!held_ && !field.solved && !closed_)
      held_ = hold_.find(chain_, field, keys, seed, near, reuse == HeldEnds::Reuse::Expired, result_, options_.all_struts);
    if (!field.solved) {
      result_.status = {StatusCode::NoProgress,
                        "the expansive-motion LP failed at step " + std::to_string(result_.steps) + " (" + field.status + ")"};
      return false;
    }
    if (!(field.t > 0.0)) {
      result_.status = {StatusCode::NoProgress, "no strictly expansive motion found at step " + std::to_string(result_.steps) +
                                                    " (smallest weighted strut rate " + std::to_string(field.t) + ")"};
      return false;
    }
    carried_.clear();
    for (const auto& [a, b] : field.binding) carried_.emplace_back(chain_.key(a), chain_.key(b));
    return true;
  }

  // CarriedField: the joint speeds of the last step's field on the current (merged) chain, the
  // joints merged since dropped, bar 0 fixed as in the LP, checked on all pairs and mended locally
  // where some pair's weighted rate fell below carry_rate (detail::carried_velocity). False when
  // that fails: the global LP decides.
  bool carry_field(detail::ExpansiveVelocity& field) {
    if (options_.method != CarpenterPlanarMethod::CarriedField || closed_ || carried_speed_.empty()) return false;
    const int m = chain_.vertices();
    std::vector<double> speed(static_cast<std::size_t>(m), 0.0);
    std::vector<int> dropped;  // merged bars that hold a joint of the carried field
    for (int a = 0; a < m; ++a) {
      if (chain_.is_joint(a)) speed[a] = carried_speed_[chain_.key(a)];
      for (int i = chain_.key(a) + 1; a + 1 < m && i < chain_.key(a + 1); ++i)
        if (carried_speed_[i] != 0.0) {
          dropped.push_back(a);
          break;
        }
    }
    const int max_window = std::max(kMinWindow, static_cast<int>(options_.repair_window * m));
    detail::CarriedVelocity carried = detail::carried_velocity(chain_.q(), std::move(speed), dropped, options_.carry_rate, max_window);
    result_.lp_solves += carried.lp_solves;
    result_.window_lp_solves += carried.lp_solves;
    if (!carried.solved) return false;
    result_.max_struts = std::max(result_.max_struts, carried.struts);
    field.v = std::move(carried.v);
    field.t = carried.t;
    field.solved = true;
    ++result_.carried_steps;
    return true;
  }

  // The joint speeds of this step's field by input vertex, for carried_velocity() next step.
  void remember_speeds(const std::vector<double>& omega) {
    if (options_.method != CarpenterPlanarMethod::CarriedField || closed_) return;
    if (held_) {  // a held field leaves pairs at their distance, which the carried check refuses
      carried_speed_.clear();
      return;
    }
    carried_speed_.assign(input_.points.size(), 0.0);
    for (int a = 0; a < chain_.vertices(); ++a)
      if (chain_.is_joint(a)) carried_speed_[chain_.key(a)] = joint_rate(chain_, omega, a);
  }

  // The turn budget grows while steps pass at once and is halved per failed try.
  void adapt_budget(int halvings) {
    turn_budget_ = halvings == 0 ? std::min(turn_budget_ * 1.5, options_.max_turn) : turn_budget_ * std::pow(0.5, halvings);
  }

  // No step length keeps every distance growing: the run ends here (false, status set).
  bool stalled() {
    result_.status = {StatusCode::NoProgress, "no step keeps every distance growing at step " + std::to_string(result_.steps)};
    return false;
  }

  // An accepted step's positions become the chain's (its merges and frame follow).
  void take(const Frame2& next) {
    chain_.set_q(next);
    ++result_.steps;
    if (options_.progress) options_.progress({static_cast<double>(result_.steps), 0.0, "steps", -1.0});
  }

  // One LP step: solve for the velocity, size the step, take it, merge what it straightened.
  // False (with the status set) when the run cannot go on.
  bool lp_step() {
    detail::ExpansiveVelocity field;
    const bool carried = carry_field(field);
    if (!carried && !solve_velocity(field)) return false;
    const double budget = turn_budget_;
    // The step turns the fastest joint by about `turn_budget` radians: far vertices may sweep a
    // long way when a large part of the chain turns almost rigidly, which angle coordinates
    // integrate exactly. The budget grows while steps pass at once and shrinks when halved.
    const std::vector<double> omega = bar_rates(chain_, field.v);
    remember_speeds(omega);
    double h = turn_budget_ / fastest_joint(chain_, omega);
    const std::vector<double> theta0 = joint_angles(chain_);
    const int free_halvings = look_ahead(chain_, field.v, theta0, h);
    const StepOutcome step = try_steps(chain_, field.v, omega, theta0, h);
    const int halvings = std::max(0, step.attempts - 1 - free_halvings);
    adapt_budget(halvings);
    if (!step.accepted && carried) {
      // A carried field that no step can follow is no verdict: the global LP takes this step.
      carried_speed_.clear();
      turn_budget_ = budget;
      return true;
    }
    if (!step.accepted) return stalled();
    const int m = chain_.vertices();
    take(step.next);
    if (held_) ++result_.held_steps;
    merge_after_step(step.next, step.event_joint, m);
    record_step();
    return true;
  }

  bool pseudo() const { return options_.method == CarpenterPlanarMethod::PseudoTriangulation; }

  // One step of Streinu's mechanism (carpenter_pseudo.hpp): the PPT brought up to date, its
  // velocity, a step to the next event at most, then the flip or the merge of that event.
  bool pseudo_step() {
    if (mechanism_.counts.unflips > unflips_seen_) {
      // The last flip's edge crossed once the new mechanism moved (it took the vertex back):
      // flipping again would cycle, so one global LP step moves the chain off that configuration.
      unflips_seen_ = mechanism_.counts.unflips;
      mechanism_.reset();
      ++result_.pseudo_lp_steps;
      return lp_step();
    }
    Frame2 v;
    bool ok = mechanism_.sync(chain_) && mechanism_.velocity(chain_, v);
    if (!ok) {  // a PPT that went wrong (not pointed, singular) is built again from the bars
      mechanism_.reset();
      ++mechanism_.counts.rebuilds;
      ok = mechanism_.sync(chain_) && mechanism_.velocity(chain_, v);
    }
    const std::vector<double> omega = ok ? bar_rates(chain_, v) : std::vector<double>{};
    const double fastest = ok ? fastest_joint(chain_, omega) : 0.0;
    if (!(fastest > 0.0) || !std::isfinite(fastest)) {
      // No PPT at these positions (a vertex left within rounding of an event, where no edge
      // across it is valid yet): one global LP step moves off the degeneracy, and the next step
      // builds the PPT again.
      mechanism_.reset();
      ++result_.pseudo_lp_steps;
      return lp_step();
    }
    const pseudo_detail::PseudoStep step = mechanism_.step(chain_, v, turn_budget_ / fastest);
    const int halvings = step.attempts - 1;
    adapt_budget(halvings);
    if (!step.accepted) return stalled();
    const int m = chain_.vertices();
    take(step.next);
    int merged = -1;
    if (step.event_vertex >= 0) {
      const bool closed = chain_.closed();
      if (pseudo_detail::is_bar(step.event_vertex, step.aligned.first, m, closed) &&
          pseudo_detail::is_bar(step.event_vertex, step.aligned.second, m, closed)) {
        merged = step.event_vertex;
        ++mechanism_.counts.straightenings;
      } else {
        mechanism_.flip(chain_, step.event_vertex, step.aligned);
      }
    }
    mechanism_.settle(chain_);
    merge_after_step(step.next, merged, m);
    record_step();
    return true;
  }

  // Merges the event joint and any other joint the step left straight to within rounding.
  void merge_after_step(const Frame2& next, int event_joint, int m) {
    std::vector<int> straight;
    for (int a = 0; a < m; ++a) {
      if (!chain_.is_joint(a)) continue;
      const double t = chain_.theta(next, a);
      const double reach = std::min(chain_.length()[(a + m - 1) % m], chain_.length()[a % chain_.bars()]);
      if (a == event_joint || std::abs(t) * reach <= 1e-13 * mean_bar_) straight.push_back(a);
    }
    if (!straight.empty()) chain_.merge(straight);
  }

  const PlanarChain& input_;
  const CarpenterPlanarOptions& options_;
  const bool closed_;
  MergedChain chain_;
  const double mean_bar_;  // of the input's bars
  const std::size_t stride_;
  double turn_budget_;
  CarpenterPlanarResult result_;
  double min_growth_ = std::numeric_limits<double>::infinity();
  Frame2 last_recorded_;
  Frame2 pending_;                            // the last unrecorded frame (frame_stride > 1)
  pseudo_detail::PseudoMechanism mechanism_;  // method pseudo: the PPT between steps
  std::size_t unflips_seen_ = 0;              // mechanism_.counts.unflips at the last LP step
  detail::BasisMemo basis_memo_;              // the last LP's optimal basis: the next starts there
  std::vector<std::pair<int, int>> carried_;  // binding struts of the last step, as input vertices
  std::vector<double> carried_speed_;         // last field's joint speeds by input vertex (CarriedField)
  bool monotone_failed_ = false;              // the closed-form straightening was tried and a check failed
  bool held_ = false;                         // this step's field holds an end rigid (HeldEnds)
  HeldEnds hold_;  // an end of an open chain held rigid (spirals)
};

// The options' ranges (carpenter_planar's @throws); a NaN fails every test, so each is written so.
void check_options(const CarpenterPlanarOptions& o) {
  if (!(o.max_turn > 0.0 && o.max_turn <= M_PI)) throw std::invalid_argument("carpenter: max_turn must lie in (0, pi]");
  if (!(o.near_radius > 0.0) || !std::isfinite(o.near_radius))
    throw std::invalid_argument("carpenter: near_radius must be positive and finite");
  if (!(o.carry_rate > 0.0 && o.carry_rate <= 1.0)) throw std::invalid_argument("carpenter: carry_rate must lie in (0, 1]");
  if (!(o.repair_window >= 0.0 && o.repair_window <= 1.0))
    throw std::invalid_argument("carpenter: repair_window must lie in [0, 1]");
}

}  // namespace

CarpenterPlanarResult carpenter_planar(const PlanarChain& input, const CarpenterPlanarOptions& options) {
  check_options(options);
  check_simple_chain(input);
  const auto start = std::chrono::steady_clock::now();
  CarpenterPlanarResult result = PlanarRun(input, options).run();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace foldkit::folding
