#include "foldkit/folding/projected_folding.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/null_space.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/simulation/pipelined_replay.hpp"

#include "path_checker.hpp"
#include "projected_folding_options.hpp"

namespace foldkit::folding {

using geometry::FoldState;
using geometry::StatusCode;

Eigen::VectorXd assignment_velocity(const geometry::CreasePattern& pattern) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(pattern.joints().size()));
  for (std::size_t j = 0; j < pattern.joints().size(); ++j) {
    const auto a = pattern.joints()[j].assignment;
    w[static_cast<Eigen::Index>(j)] = a == geometry::Assignment::Mountain ? 1.0 : a == geometry::Assignment::Valley ? -1.0 : 0.0;
  }
  return w;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Corrected {
  FoldState state;
  bool ok = false;
  int iterations = 0;
  double error = 0.0;
};

class Folder {
 public:
  // `replay`, when set, gets every state accepted (its replay runs meanwhile).
  Folder(const geometry::CreasePattern& pattern, const ProjectedFoldingOptions& o, ProjectedFoldingResult& r,
         simulation::PipelinedReplay* replay)
      : pattern_(pattern), opt_(o), result_(r), replay_(replay), system_(pattern), solver_(o.rank_tolerance) {
    po_.tolerance = 0.1 * o.closure_tolerance;
    po_.max_iterations = 60;
    po_.keep_signs = true;
  }

  // Back to the manifold from `guess`. With the chord corrector (`step`: a step of the path, not
  // the lead-in): one Newton step on J(guess), factored once, then chord steps on that same
  // factorisation (two triangular solves each; the error shrinks about a hundredfold per
  // iteration that close to the solution), which the next step's tangent reuses too. If they
  // stall, or without the chord corrector: Newton with minimum-norm steps from `guess`,
  // refactored at every iterate; when that crosses a crease through flat or does not converge in
  // a few iterations, geometry::project (Levenberg–Marquardt, signs kept) from `guess`.
  Corrected correct(const FoldState& guess, bool step = false) {
    fresh_factor_ = false;
    if (step && opt_.chord_corrector) {
      const Corrected c = chord_correct(guess);
      if (c.ok) return c;
    }
    FoldState s = guess;
    Eigen::VectorXd r, delta;
    Eigen::SparseMatrix<double> J;
    for (int it = 0;; ++it) {
      const double error = system_.max_error(s);
      if (error <= po_.tolerance) return {s, true, it, error};
      if (it == 6) break;
      system_.evaluate(s, r, J);
      if (!solver_.min_norm_step(J, r, delta)) break;
      s.angles += delta;
      ++result_.newton_iterations;
      if (leaves_sign(s, guess)) break;
    }
    const geometry::ProjectionResult p = geometry::project(system_, guess, po_);
    result_.newton_iterations += p.iterations;
    return {p.state, p.status.ok() && p.error <= opt_.closure_tolerance, p.iterations, p.error};
  }

  // One Newton step from `guess` on J(guess), then chord steps on its factorisation; not ok when
  // the error stops shrinking tenfold, a crease crosses flat, or ten iterations do not converge.
  // Sets fresh_factor_ when it is ok after factoring J(guess).
  Corrected chord_correct(const FoldState& guess) {
    FoldState s = guess;
    Eigen::VectorXd r, delta;
    system_.evaluate(s, r, factored_jacobian_);
    double error = system_.residual_error(r);
    if (error <= po_.tolerance) return {s, true, 0, error};
    if (!solver_.min_norm_step(factored_jacobian_, r, delta, false)) return {s, false, 0, error};
    for (int it = 1; it <= 10; ++it) {
      s.angles += delta;
      ++result_.newton_iterations;
      if (leaves_sign(s, guess)) break;
      r = system_.residual(s);
      const double previous = error;
      error = system_.residual_error(r);
      if (error <= po_.tolerance) {
        fresh_factor_ = true;
        return {s, true, it, error};
      }
      if (!(error < 0.1 * previous) || !solver_.chord_step(factored_jacobian_, r, delta)) break;
    }
    return {s, false, 0, error};
  }

  // w projected onto null(J) at x: with the last step's factorisation when the chord corrector
  // left one (J at the prediction x was corrected from, a second-order distance away), else with
  // J(x) factored here.
  geometry::NullSpaceVelocity tangent(const FoldState& x, const Eigen::VectorXd& w) {
    if (fresh_factor_) return solver_.project_with_last_factor(w);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    system_.evaluate(x, r, J);
    return solver_.project_onto_null_space(J, w);
  }

  static bool leaves_sign(const FoldState& s, const FoldState& guess) {
    return (s.angles.array() * guess.angles.array() < 0.0).any() || s.angles.cwiseAbs().maxCoeff() > kPi;
  }

  void run(const Eigen::VectorXd& desired) {
    const Eigen::VectorXd w = desired / desired.cwiseAbs().maxCoeff();
    const double target = opt_.target_fraction;
    std::vector<FoldState>& states = result_.states;
    states.assign(1, FoldState::flat(pattern_));
    if (opt_.collisions) checker_.emplace(pattern_);
    if (checker_) checker_->crossing(states[0], states[0]);

    if (!lead_in(w)) return;
    if (fraction_of(states.back()) >= target - 1e-12) return finish(StatusCode::Success, "target reached");

    int reference_rank = -1;
    while (true) {
      const FoldState& x = states.back();
      const geometry::NullSpaceVelocity t = tangent(x, w);
      result_.min_pivot_ratio = std::min(result_.min_pivot_ratio, t.pivot_ratio);
      // The LDLᵀ pivots only screen: a change in their count, or collapsing pivots, calls for a
      // rank-revealing decision, at x itself, and only that decision stops the fold.
      const bool suspect = t.pivot_ratio < opt_.singular_ratio;
      if (t.rank != screened_rank_ || suspect) {
        screened_rank_ = t.rank;
        Eigen::VectorXd r;
        Eigen::SparseMatrix<double> J;
        system_.evaluate(x, r, J);
        decide(J);
      }
      std::ostringstream at;
      at << " at largest fold angle " << fraction_of(x) * 180.0 << " deg (step " << result_.steps << ")";
      if (reference_rank >= 0 && decision_.rank < reference_rank)
        return finish(StatusCode::Singular, "the closure Jacobian drops rank from " + std::to_string(reference_rank) + " to " +
                                              std::to_string(decision_.rank) + at.str() + " (" + evidence() + "): a bifurcation");
      reference_rank = std::max(reference_rank, decision_.rank);
      if (suspect && decision_.smallest_kept < opt_.singular_ratio * decision_.sigma_max) {
        std::ostringstream out;
        out << "the closure Jacobian is nearly singular (smallest kept singular value " << decision_.smallest_kept / decision_.sigma_max
            << " of the largest)" << at.str();
        return finish(StatusCode::Singular, out.str());
      }
      const double vnorm = t.velocity.norm();
      const double cosine = vnorm > 0.0 ? t.velocity.dot(w) / (vnorm * w.norm()) : 0.0;
      if (!(cosine > 1e-6))
        return finish(StatusCode::NoProgress, "the desired velocity has no component along the motions closure allows" + at.str());
      if (result_.steps >= opt_.max_steps)
        return finish(StatusCode::LimitReached, "stopped after " + std::to_string(opt_.max_steps) + " steps" + at.str());
      const Eigen::VectorXd v = t.velocity / t.velocity.cwiseAbs().maxCoeff();

      double h = toward_target(x, v, step_, target);
      std::string why;
      Corrected next = sized_step(x, v, h, why);
      if (!next.ok) return finish(StatusCode::Singular, why + at.str());
      bool reached = false;
      if (fraction_of(next.state) >= target - 1e-12) {
        next = land(x, v, h, next, target);
        check_chord(x, next, h);  // the shorter chord's error, for the record
        reached = true;
      }
      if (const std::string what = crossing(x, next.state); !what.empty()) {
        if (h <= lead_step_) return finish(StatusCode::Collision, "the next step collides: " + what);
        // Approach the contact again from x at the lead-in's step, so that the path stops as
        // close before it as with fixed steps; the world restarts at x, because it remembers
        // the motion it has checked.
        checker_->restart(x);
        step_ = cap_ = lead_step_;
        fresh_factor_ = false;
        continue;
      }
      accept(next);
      if (reached) return finish(StatusCode::Success, "target reached");
      if (last_v_.size() == v.size()) bend_ = (v - last_v_) / last_h_;
      last_v_ = v;
      last_h_ = h;
      resize_step(h);
    }
  }

 private:
  // Flat is singular (every vertex's crease axes lie in one plane, so the Jacobian drops rank and
  // first-order motions need not extend). The first states are the closed states nearest to the
  // desired direction at amplitudes s growing to lead_in, signs kept, until the Jacobian's rank and
  // pivots mean something; a pattern that folds rigidly along it keeps most of each amplitude, one
  // that does not (the square twist) collapses back to flat, where closure holds to second order
  // at angles of about √tolerance.
  bool lead_in(const Eigen::VectorXd& w) {
    const double amplitude = std::min(opt_.lead_in, 0.5 * opt_.target_fraction * kPi);
    const int parts = std::max(10, static_cast<int>(std::ceil(amplitude / opt_.max_step - 1e-9)));
    lead_step_ = amplitude / parts;
    step_ = opt_.chord_tolerance > 0.0 ? lead_step_ : opt_.max_step;
    cap_ = opt_.max_step;
    for (int k = 1; k <= parts; ++k) {
      const double s = amplitude * k / parts;
      const Corrected c = correct(FoldState{s * w});
      const double kept = c.state.angles.cwiseAbs().maxCoeff() / s;
      const double cosine = c.state.angles.dot(w) / (c.state.angles.norm() * w.norm() + 1e-300);
      if (!c.ok || kept < 0.25 || cosine < 0.2) {
        std::ostringstream out;
        out << "no closed state near flat follows the desired velocity: the closed state nearest to it at amplitude " << s
            << " rad (signs kept) keeps " << kept * 100.0 << "% of that amplitude (at least 25% needed";
        if (!c.ok) out << "; the projection did not converge, error " << c.error << " rad";
        out << "), so the sheet does not fold rigidly this way";
        finish(StatusCode::NotRigidlyFoldable, out.str());
        return false;
      }
      if ((c.state.angles - result_.states.back().angles).cwiseAbs().maxCoeff() > 2.0 * lead_step_) {
        finish(StatusCode::Singular, "the way out of the flat state jumps between branches at amplitude " + std::to_string(s) + " rad");
        return false;
      }
      check_chord(result_.states.back(), c, lead_step_);
      if (const std::string what = crossing(result_.states.back(), c.state); !what.empty()) {
        finish(StatusCode::Collision, "the next step collides: " + what);
        return false;
      }
      accept(c);
    }
    return true;
  }

  // The last accepted step's chord error, ∝ h² (a chord's midpoint is h²·κ/8 off a path of
  // curvature κ): the next step aims at 0.8 of the tolerance, so that steps are rarely refused,
  // growing at most twofold.
  void resize_step(double h) {
    if (opt_.chord_tolerance <= 0.0) return;
    const double grow = chord_ > 0.0 ? std::sqrt(0.8 * opt_.chord_tolerance / chord_) : 2.0;
    step_ = std::clamp(h * std::min(grow, 2.0), smallest_step(), cap_);
  }

  double smallest_step() const { return lead_step_ / 64; }

  // The predicted state h along the path from x: x + h·v, plus ½h²·a with the second-order
  // predictor, a = the change of the unit tangent over the last step, so that the prediction is
  // off the manifold by O(h³) instead of O(h²) and one Newton step usually corrects it.
  FoldState predict(const FoldState& x, const Eigen::VectorXd& v, double h) const {
    if (!opt_.second_order_predictor || bend_.size() != v.size()) return FoldState{x.angles + h * v};
    return FoldState{x.angles + h * v + (0.5 * h * h) * bend_};
  }

  // The step length h, or one that lands on the target: when the target is at most two steps
  // away (at the rate the largest angle grows along the prediction), one step that goes 10%
  // past it, which land() brings back, or half the way when that step would be longer than
  // allowed. Steps sized by the chord alone could leave a last state just short of the target,
  // where a singular end (a sheet folded flat) reads as singular.
  double toward_target(const FoldState& x, const Eigen::VectorXd& v, double h, double target) const {
    const double largest = x.angles.cwiseAbs().maxCoeff(), room = target * kPi - largest;
    const auto rate = [&](double step) { return (predict(x, v, step).angles.cwiseAbs().maxCoeff() - largest) / step; };
    if (!(rate(h) > 0.0) || room > 2.0 * h * rate(h)) return h;
    double landing = 1.1 * room / rate(h);
    if (rate(landing) > 0.0) landing = 1.1 * room / rate(landing);  // the rate along the longer or shorter prediction
    if (landing > cap_) landing = std::min(0.5 * landing, cap_);
    return std::max(landing, smallest_step());
  }

  // The step from x along v, starting at length h: refused and shortened while the correction
  // fails or jumps, a crease crosses flat, or the chord bends beyond the tolerance. Not ok (with
  // `why`) once it would be shorter than the smallest step; h is the length taken.
  Corrected sized_step(const FoldState& x, const Eigen::VectorXd& v, double& h, std::string& why) {
    while (true) {
      const FoldState predicted = predict(x, v, h);
      Corrected next = correct(predicted, true);
      why = check_step(x, predicted, next, h);
      bool bent = false;
      if (why.empty()) bent = !(why = check_chord(x, next, h)).empty();
      if (why.empty()) return next;
      h *= bent ? 0.9 * std::sqrt(opt_.chord_tolerance / chord_) : 0.5;
      if (h < smallest_step()) return {next.state, false, 0, next.error};
    }
  }

  // Empty when the chord from x to `next` stays within the chord tolerance at its midpoint (the
  // error is kept in chord_ either way).
  std::string check_chord(const FoldState& x, const Corrected& next, double h) {
    chord_ = system_.max_error(FoldState{0.5 * (x.angles + next.state.angles)});
    if (opt_.chord_tolerance <= 0.0 || chord_ <= opt_.chord_tolerance) return {};
    std::ostringstream out;
    out << "the path bends too sharply: the chord of a step of " << h << " rad leaves the closure manifold by " << chord_
        << " rad at its midpoint (chord tolerance " << opt_.chord_tolerance << ")";
    return out.str();
  }

  // Empty when `next` (corrected from `predicted`) is an acceptable step from `x`.
  std::string check_step(const FoldState& x, const FoldState& predicted, const Corrected& next, double h) const {
    if (!next.ok) {
      std::ostringstream out;
      out << "the Newton correction does not return to the closure manifold (error " << next.error << " rad)";
      return out.str();
    }
    if ((next.state.angles - predicted.angles).cwiseAbs().maxCoeff() > 0.5 * h)
      return "the Newton correction jumps away from the predicted step (another branch)";
    for (Eigen::Index j = 0; j < x.angles.size(); ++j)
      if (x.angles[j] * predicted.angles[j] < 0.0)
        return "crease " + std::to_string(pattern_.joints()[static_cast<std::size_t>(j)].id) +
               " returns to flat (it would change between mountain and valley)";
    return {};
  }

  // The step from x along v whose corrected state has its largest angle at target·π (regula falsi
  // on the step length; the fraction is nearly linear in it).
  Corrected land(const FoldState& x, const Eigen::VectorXd& v, double h, const Corrected& at_h, double target) {
    double lo = 0.0, flo = fraction_of(x) - target, hi = h;
    Corrected best = at_h;
    double fhi = fraction_of(best.state) - target;
    for (int it = 0; it < 40 && std::abs(fhi) > 1e-12; ++it) {
      const double mid = hi - fhi * (hi - lo) / (fhi - flo);
      const Corrected c = correct(predict(x, v, mid), true);
      if (!c.ok) break;
      const double fm = fraction_of(c.state) - target;
      if (fm >= 0.0) {
        hi = mid, fhi = fm, best = c;
      } else {
        lo = mid, flo = fm;
      }
    }
    return best;
  }

  // Empty when the straight motion from x to y crosses nothing (or collisions are off), else what
  // crosses.
  std::string crossing(const FoldState& x, const FoldState& y) { return checker_ ? checker_->crossing(x, y) : std::string(); }

  // Appends `next`, a checked step.
  void accept(const Corrected& next) {
    const double error = next.error;  // the corrector's, at next.state
    result_.max_closure_error = std::max(result_.max_closure_error, error);
    result_.max_chord_error = std::max(result_.max_chord_error, chord_);
    result_.states.push_back(next.state);
    if (replay_) replay_->push(next.state);
    result_.steps = static_cast<int>(result_.states.size()) - 1;
    if (opt_.progress) opt_.progress({static_cast<double>(result_.steps), 0.0, "steps", error});
  }

  // J's rank by singular values (geometry::LeastNormSolver::decide_rank), the fold's record of it;
  // σ_max floored at 1 as geometry::mobility does (closure Jacobians are dimensionless).
  void decide(const Eigen::SparseMatrix<double>& J) {
    decision_ = solver_.decide_rank(J, std::sqrt(opt_.rank_tolerance), 400, 1.0);
    ++result_.rank_decisions;
    result_.rank = decision_.rank;
    result_.dof = decision_.nullity;
    result_.rank_gap = decision_.gap();
    result_.rank_method = decision_.method;
    result_.min_rank_gap = std::min(result_.min_rank_gap, decision_.gap());
  }

  std::string evidence() const {
    std::ostringstream out;
    out << decision_.method << ": singular values <= " << decision_.tolerance << " count as 0; largest counted "
        << decision_.largest_zero << ", smallest kept " << decision_.smallest_kept << ", gap " << decision_.gap();
    return out.str();
  }

  void finish(StatusCode code, const std::string& message) { result_.status = {code, message}; }

  const geometry::CreasePattern& pattern_;
  const ProjectedFoldingOptions& opt_;
  ProjectedFoldingResult& result_;
  simulation::PipelinedReplay* replay_;  // null: no replay alongside
  geometry::ClosureSystem system_;
  geometry::LeastNormSolver solver_;  // keeps its ordering between the thousands of steps
  geometry::ProjectionOptions po_;
  std::optional<PathChecker> checker_;
  int screened_rank_ = -1;
  // The chord corrector's factorisation: J at the last step's prediction, left in the solver when
  // fresh_factor_; the next step's tangent is projected with it (O(h²) from the accepted state).
  Eigen::SparseMatrix<double> factored_jacobian_;
  bool fresh_factor_ = false;
  double lead_step_ = 0.0;  // the lead-in's step; 1/64 of it is the smallest step
  double step_ = 0.0;       // the next step's length
  Eigen::VectorXd bend_;    // the unit tangent's change per radian over the last step
  Eigen::VectorXd last_v_;  // the last step's unit tangent
  double last_h_ = 0.0;     // and its length
  double cap_ = 0.0;        // the longest step: max_step, or the lead-in's once a collision is near
  double chord_ = 0.0;      // the loop error at the midpoint of the last chord checked
  geometry::RankDecision decision_;
};

// The replay of the result's sequence: the pipeline's, when it replayed these events, else
// simulate() now (PipelinedReplay::report); `sequence_ready`'s reader runs meanwhile and is done
// before this returns (on every way out, exceptions included).
void replay(const ProjectedFoldingOptions& options, simulation::PipelinedReplay& pipeline, ProjectedFoldingResult& result) {
  simulation::ReaderWait wait;
  if (options.sequence_ready) wait.reading = options.sequence_ready(result.sequence);
  result.replay = pipeline.report(result.sequence);
  // The fold's own status stands (it says how far the folding got); the message adds the replay's verdict.
  if (!result.replay->status) result.status.message += "; the simulator rejects the CMML: " + result.replay->status.message;
}

}  // namespace

ProjectedFoldingResult fold_projected(const geometry::CreasePattern& pattern, const ProjectedFoldingOptions& options) {
  Eigen::VectorXd desired;
  ProjectedFoldingOptions o = detail::checked_options(pattern, options, desired);
  ProjectedFoldingResult result;
  // The folding's progress (this thread) and the replay's (its own) reach the caller one call at
  // a time.
  if (options.progress)
    o.progress = [mutex = std::make_shared<std::mutex>(), progress = options.progress](const geometry::Progress& p) {
      const std::lock_guard<std::mutex> lock(*mutex);
      progress(p);
    };
  simulation::SimulationOptions so;
  so.collisions = options.collisions;
  so.progress = o.progress;
  // Each accepted state is replayed on another thread while the next ones are folded (a Miura
  // 60×60: the replay was as long as the folding, after it); the report is simulate()'s.
  std::optional<simulation::PipelinedReplay> pipeline;
  if (options.replay) pipeline.emplace(pattern, so, options.speed);
  const auto t0 = std::chrono::steady_clock::now();
  Folder(pattern, o, result, pipeline && pipeline->active() ? &*pipeline : nullptr).run(desired);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.fraction = fraction_of(result.states.back());
  if (options.toward.size()) {
    // The stop is a fraction of the largest target; the targets themselves may lie on another
    // branch (a plus-shaped vertex folds one line at a time), so say how far they are.
    Eigen::Index worst = 0;
    result.target_distance = (result.states.back().angles - options.toward).cwiseAbs().maxCoeff(&worst);
    std::ostringstream out;
    out << "; " << *result.target_distance * 180.0 / kPi << " deg from the targets at crease "
        << pattern.joints()[static_cast<std::size_t>(worst)].id;
    result.status.message += out.str();
  }
  result.sequence = geometry::path_sequence(pattern, result.states, options.speed, pattern.title());
  if (pipeline && result.states.size() > 1) replay(options, *pipeline, result);
  return result;
}

}  // namespace foldkit::folding
