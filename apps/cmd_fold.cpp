// foldkit fold: fold all creases together by projected velocities (Tachi), closure kept to 1e-10.
#include <cmath>
#include <iostream>

#include "cli_common.hpp"
#include "pending_output.hpp"
#include "progress_line.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/folding/projected_folding.hpp"

namespace foldkit::apps {
namespace {

// "ID:VALUE,ID:VALUE,…" over the assignment's signs: each named crease gets VALUE (any finite
// number; its sign says mountain or valley, its size how fast relative to the others).
Eigen::VectorXd parse_velocity(const geometry::CreasePattern& pattern, const std::string& text) {
  Eigen::VectorXd w = folding::assignment_velocity(pattern);
  for (const auto& [j, value] :
       parse_joint_values(pattern, text, "--velocity", "ID:VALUE", [](double v) { return std::isfinite(v); }, "a number"))
    w[j] = value;
  return w;
}

// The "stop" key predates the shared status and keeps its names ("reached", "step-limit"); the
// "status" key has the shared ones.
const char* stop_name(geometry::StatusCode code) {
  if (code == geometry::StatusCode::Success) return "reached";
  if (code == geometry::StatusCode::LimitReached) return "step-limit";
  return geometry::to_string(code);
}

// The fold angles of --toward: a CMML's end state, or the targets a pattern file carries (the
// same creases as the pattern folded: matched by index, checked by their ends).
Eigen::VectorXd target_angles(const geometry::CreasePattern& pattern, const std::string& path) {
  if (is_kind(path, FileKind::Cmml)) return state_from(pattern, path).angles;
  const LoadedPattern file = load_pattern(path);
  if (!file.state)
    throw io::ParseError(path, 0, "carries no fold angles to fold toward (an SVG's targets are its crease opacities, a FOLD "
                                  "file's its edges_foldAngle or folded frame)");
  const auto& mine = pattern.joints();
  const auto& theirs = file.pattern.joints();
  Eigen::AlignedBox2d box;
  for (const geometry::Vec2& v : pattern.vertices()) box.extend(v);
  const double tolerance = 1e-6 * box.diagonal().norm();
  const auto same_ends = [&](std::size_t j) {
    const geometry::Vec2 a0 = pattern.vertices()[mine[j].v[0]], a1 = pattern.vertices()[mine[j].v[1]];
    const geometry::Vec2 b0 = file.pattern.vertices()[theirs[j].v[0]], b1 = file.pattern.vertices()[theirs[j].v[1]];
    return std::max((a0 - b0).norm(), (a1 - b1).norm()) <= tolerance || std::max((a0 - b1).norm(), (a1 - b0).norm()) <= tolerance;
  };
  if (theirs.size() != mine.size())
    throw io::ParseError(path, 0, "has " + std::to_string(theirs.size()) + " creases, the pattern " + std::to_string(mine.size()));
  for (std::size_t j = 0; j < mine.size(); ++j)
    if (!same_ends(j))
      throw io::ParseError(path, theirs[j].line, "crease " + std::to_string(theirs[j].id) + " is not where the pattern's crease " +
                                                     std::to_string(mine[j].id) + " lies: not the same pattern");
  return file.state->angles;
}

struct FoldArgs {
  std::string pattern, output, velocity, toward;
  double fraction = folding::ProjectedFoldingOptions{}.target_fraction, step = folding::ProjectedFoldingOptions{}.max_step,
         chord_tolerance = folding::ProjectedFoldingOptions{}.chord_tolerance;
  int max_steps = folding::ProjectedFoldingOptions{}.max_steps;
  bool no_collision = false, partial = false, json = false;
};

void add_fold_options(CLI::App* app, FoldArgs& opt) {
  add_pattern(app, opt.pattern, " with a mountain/valley assignment, or --velocity or --toward");
  app->add_option("--fraction", opt.fraction,
                  "Stop when the largest fold angle reaches this fraction of 180 degrees (with --toward: of the targets' largest)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app->add_option("--step", opt.step, "Largest change of any crease per step, radians (every step's, with --chord-tolerance 0)")
      ->check(CLI::Range(1e-6, 0.5))
      ->capture_default_str();
  app->add_option("--chord-tolerance", opt.chord_tolerance,
                  "Size the steps so that the straight chord between consecutive states (what a replay follows) leaves "
                  "the closure manifold by at most this, radians; 0: fixed steps of --step")
      ->check(CLI::Range(0.0, 0.1))
      ->capture_default_str();
  positive(app->add_option("--max-steps", opt.max_steps, "Give up after this many steps"));
  app->add_option("--velocity", opt.velocity,
                  "Desired velocity as ID:VALUE,… over the assignment's signs (mountain +1, valley -1, others 0)");
  reads(app->add_option("--toward", opt.toward,
                  "Fold toward these fold angles: a CMML's end state, or a pattern file's own targets (SVG stroke opacities, "
                  "FOLD edges_foldAngle). They are the desired velocity, and --fraction is of their largest angle"))
      ->excludes(app->get_option("--velocity"));
  app->add_flag("--no-collision", opt.no_collision, "Closure only: no self-collision checks (folding or replay)");
  app->add_flag("--partial", opt.partial, "When the target is not reached, still write the path up to the stop");
  writes(app->add_option("-o,--output", opt.output, "Output CMML (.cmml; .cmml.gz: gzip-compressed)"))->required();
  add_json(app, opt.json);
}

folding::ProjectedFoldingResult fold(const FoldArgs& opt, const geometry::CreasePattern& pattern, PendingOutput& output) {
  folding::ProjectedFoldingOptions o;
  o.sequence_ready = output.starter();  // the CMML is written while the replay runs
  if (!opt.velocity.empty()) {
    o.velocity = parse_velocity(pattern, opt.velocity);
    if (!(o.velocity.cwiseAbs().maxCoeff() > 0.0)) throw UsageError("--velocity: the desired velocity is zero on every crease");
  }
  if (!opt.toward.empty()) o.toward = target_angles(pattern, opt.toward);
  o.target_fraction = opt.fraction;
  if (opt.chord_tolerance != 0.0 && !(opt.chord_tolerance > o.closure_tolerance))
    throw UsageError("--chord-tolerance: 0 (fixed steps) or above the closure tolerance of the states (1e-10 rad)");
  o.max_step = opt.step;
  o.chord_tolerance = opt.chord_tolerance;
  o.max_steps = opt.max_steps;
  o.collisions = !opt.no_collision;
  try {
    ProgressLine progress("fold");
    o.progress = progress.callback();
    return folding::fold_projected(pattern, o);
  } catch (const std::invalid_argument& e) {
    throw io::ParseError(opt.toward.empty() ? opt.pattern : opt.toward, 0, e.what());
  }
}

void print_summary(const folding::ProjectedFoldingResult& r) {
  std::cerr << stop_name(r.status.code) << ": " << r.status.message << " (fraction " << r.fraction << ", " << r.steps << " steps, "
            << r.newton_iterations << " Newton iterations, closure error " << r.max_closure_error << " rad, chord error " << r.max_chord_error << " rad, " << r.seconds << " s)\n";
  if (r.rank_decisions > 0)
    std::cerr << "rank " << r.rank << " (" << r.dof << " DOF) by " << r.rank_method << ", singular-value gap " << r.rank_gap
              << " (smallest over " << r.rank_decisions << " decisions " << r.min_rank_gap << ")\n";
}

nlohmann::json fold_json(const FoldArgs& opt, const folding::ProjectedFoldingResult& r, bool written) {
  const bool reached = r.status.code == geometry::StatusCode::Success;
  const bool replay_ok = r.replay && r.replay->status.ok();
  nlohmann::json j{{"stop", stop_name(r.status.code)},  // deprecated: status
                   {"reached", reached},  // deprecated: status
                   {"fraction", r.fraction},
                   {"target", opt.fraction},
                   {"steps", r.steps},
                   {"newton_iterations", r.newton_iterations},
                   {"max_closure_error", r.max_closure_error},
                   {"max_chord_error", r.max_chord_error},
                   {"rank", r.rank},
                   {"dof", r.dof},
                   {"min_pivot_ratio", r.min_pivot_ratio},
                   {"rank_method", r.rank_method},
                   {"rank_decisions", r.rank_decisions},
                   {"rank_gap", r.rank_gap},
                   {"min_rank_gap", r.rank_decisions ? nlohmann::json(r.min_rank_gap) : nlohmann::json(nullptr)},
                   {"seconds", r.seconds},
                   {"time", r.seconds},  // deprecated: the name of `seconds` before issue 37
                   {"replay_status", r.replay ? nlohmann::json(geometry::to_string(r.replay->status.code)) : nlohmann::json(nullptr)},
                   {"replay_ok", r.replay ? nlohmann::json(replay_ok) : nlohmann::json(nullptr)},  // deprecated: replay_status
                   {"message", r.status.message},
                   {"output", written ? nlohmann::json(opt.output) : nlohmann::json(nullptr)}};
  if (r.replay) j["replay_max_closure_error"] = r.replay->max_closure_error;
  j["toward"] = opt.toward.empty() ? nlohmann::json(nullptr) : nlohmann::json(opt.toward);
  j["target_distance"] = r.target_distance ? nlohmann::json(*r.target_distance) : nlohmann::json(nullptr);
  add_status(j, r.status);
  return j;
}

int run_fold(const FoldArgs& opt) {
  if (!is_kind(opt.output, FileKind::Cmml)) throw UsageError("-o needs a .cmml (or .cmml.gz) file name, not '" + opt.output + "'");
  if (!(opt.fraction > 0.0)) throw UsageError("--fraction must be greater than 0");
  const geometry::CreasePattern pattern = load_pattern(opt.pattern).pattern;
  PendingOutput output(opt.output);
  const folding::ProjectedFoldingResult r = fold(opt, pattern, output);
  const bool reached = r.status.code == geometry::StatusCode::Success;
  const bool replay_ok = r.replay && r.replay->status.ok();
  print_summary(r);
  const bool write = replay_ok && (reached || opt.partial);
  if (write) {
    output.commit(r.sequence);  // written during the replay, or now (streamed either way)
    std::cerr << "wrote " << opt.output << '\n';
  }
  if (opt.json) print_json(fold_json(opt, r, write));
  if (r.replay && !r.replay->status.ok()) return kInvalidSequence;
  return reached ? kOk : kNoPlan;
}

}  // namespace

Command add_fold(CLI::App& root) {
  auto opt = std::make_shared<FoldArgs>();
  CLI::App* app = root.add_subcommand(
      "fold", "Fold all creases together: desired velocity projected onto the closure constraint, Newton-corrected");
  add_fold_options(app, *opt);
  return {app, [opt] { return run_fold(*opt); }};
}

}  // namespace foldkit::apps
