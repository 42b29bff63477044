#pragma once
/// @file
/// What a plan optimises, by name (docs/PLANNING.md, "Objectives"): path length, total crease
/// rotation, clearance, and weighted sums of the additive ones; one table of names in
/// objectives.cpp.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <ompl/base/OptimizationObjective.h>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::planners {

struct PlanSetup;
struct PlanOptions;

/// One objective of the table with its weight in a sum.
struct ObjectiveTerm {
  std::string name;     ///< a name of objective_names()
  double weight = 1.0;  ///< positive and finite
};

/// An objective as parse_objective() reads it: one term, or a weighted sum of additive terms.
struct Objective {
  std::vector<ObjectiveTerm> terms;  ///< at least one; each name at most once
  /// The canonical spelling: "NAME" for a single term of weight 1, else "NAME:W,NAME:W" in the
  /// order given (weights written with up to 12 significant digits).
  std::string name() const;
  /// Whether it is the table's first objective, "length", alone with weight 1 (the default).
  bool is_default() const;
};

/// One row of the objective table, for listings and documentation.
struct ObjectiveInfo {
  std::string name,   ///< its name in --objective, Python's objective= and bench
      unit,           ///< the unit of its cost
      description;    ///< what it measures, in words
  bool additive = false;          ///< summed over a path's motions: may be part of a weighted sum
  bool informed_sampler = false;  ///< informed planners (BIT*, ABIT*, AIT*, InformedRRT*, CForest) may use it
};

/// The objective table, in order ("length" first: the default).
std::vector<ObjectiveInfo> objective_table();
/// The names of objective_table(), in order.
std::vector<std::string> objective_names();

/// Reads an objective: "NAME" or a weighted sum "NAME:WEIGHT,NAME:WEIGHT,…" (case-insensitive
/// names; a missing ":WEIGHT" is 1; weights positive and finite; each name at most once; only
/// additive objectives in a sum of more than one term).
/// @throws std::invalid_argument naming what is wrong and listing the known names
Objective parse_objective(const std::string& text);

/// Why `planner` cannot optimise `objective` (an informed planner with an objective that has no
/// informed sampler, SORRT* with one sampled by rejection), as planner_refusal() says for a
/// planner on its own; empty when it can.
/// @throws std::invalid_argument for an unknown planner
std::string objective_refusal(const std::string& planner, const Objective& objective);

/// The objective's cost of a path given as fold states (one angle per joint, radians), every
/// crease counted: length Σ‖Δθ‖₂ between neighbours (radians), rotation Σ‖Δθ‖₁ (radians),
/// clearance the smallest facet–facet distance over the states by simulation::min_clearance
/// (pattern units; +∞ when no two facets are apart); a sum, the weighted sum of its terms.
double path_cost(const Objective& objective, const geometry::CreasePattern& pattern,
                 const std::vector<geometry::FoldState>& states);

/// The objective as OMPL's, on the setup's space (states read through setup.reader): length in
/// the space's own metric (si->distance), rotation as Σ|Δθ| over every crease between a motion's
/// ends, clearance as the smallest simulation::min_clearance over a motion's interpolated states
/// (combined by min, larger better), a sum as OMPL adds its terms. `threshold`, when given, is its
/// cost threshold (OMPL's isSatisfied: cost below it; clearance: above it); else none is ever
/// satisfied. The setup must outlive the objective.
ompl::base::OptimizationObjectivePtr make_objective(const Objective& objective, const PlanSetup& setup,
                                                    std::optional<double> threshold);

/// The objective plan() sets on its problem: for the default ("length" without a cost
/// threshold) planners::informed_objective() of the planner (null for a planner that does not
/// sample informed, which keeps OMPL's own default), else make_objective() for every planner.
/// @throws std::invalid_argument for an objective that does not parse or a negative or NaN
///         threshold
ompl::base::OptimizationObjectivePtr plan_objective(const PlanSetup& setup, const PlanOptions& options);

/// When an informed sampler of the setup's objectives stops drawing by rejection: once the
/// plan's time is up (setup.validity's FoldValidity::expired(), under run_planner's TimeLimit).
/// OMPL 1.5.2's BIT* and AIT* fill their batches without looking at the time.
std::function<bool()> sampling_stop(const PlanSetup& setup);

/// Checks a cost threshold: finite and not negative.
/// @throws std::invalid_argument naming `what` otherwise
void check_cost_threshold(double threshold, const std::string& what);

}  // namespace foldkit::planners
