#pragma once
/// @file
/// OMPL's geometric planners by name.
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>

namespace foldkit::planners {

/// A planner that cannot plan on the space asked for, with the reason (what it needs that the
/// space does not give it).
class PlannerRefused : public std::invalid_argument {
 public:
  /// "planner PLANNER cannot plan here: REASON".
  PlannerRefused(const std::string& planner, const std::string& reason);
};

/// An OMPL geometric planner by name, case-insensitive, with OMPL's default settings: every one
/// OMPL 1.5.2 ships (planner_names(); docs/PLANNING.md lists them with their status on each
/// space). Aliases: RRTstar, RRTsharp, PRMstar, LazyPRMstar, KPIECE, BKPIECE, LBKPIECE, FMT*,
/// BFMT*, BITstar, ABITstar, AITstar, InformedRRTstar, SORRTstar, APS.
/// @throws std::invalid_argument for an unknown name (the message lists the known ones)
/// @throws PlannerRefused for a planner that cannot plan on a crease pattern (planner_refusal()),
///         and for SORRT* on a space without a direct informed sampler (every space but the joint
///         box of a sheet without loops)
ompl::base::PlannerPtr make_planner(const std::string& name, const ompl::base::SpaceInformationPtr& si);
/// Sets the planner's parameters by name through OMPL's ParamSet (planner.params()), in order.
/// @param planner  the planner (made by make_planner())
/// @param name     its name, for messages
/// @param params   (parameter, value) pairs, e.g. ("range", "0.3")
/// @throws std::invalid_argument for a parameter the planner does not have (the message lists
///         the ones it has) or a value it refuses
void set_planner_params(ompl::base::Planner& planner, const std::string& name,
                        const std::vector<std::pair<std::string, std::string>>& params);
/// Parses "NAME=VALUE" into its two parts.
/// @throws std::invalid_argument when there is no '=' or the name is empty
std::pair<std::string, std::string> parse_planner_param(const std::string& text);
/// Checks parameters against the planner's ParamSet before there is a problem to plan (a planner
/// made on a one-dimensional box): for command lines that answer a bad parameter as a usage error.
/// @throws std::invalid_argument as set_planner_params() does
void check_planner_params(const std::string& planner, const std::vector<std::pair<std::string, std::string>>& params);
/// The canonical names of every planner make_planner() knows, those it refuses included.
std::vector<std::string> planner_names();
/// Why make_planner() refuses the planner (what it needs that a crease pattern does not give it);
/// empty for a planner it makes.
/// @throws std::invalid_argument for an unknown planner
std::string planner_refusal(const std::string& name);
/// The canonical name of a planner.
/// @throws std::invalid_argument for an unknown one
std::string canonical_planner(const std::string& name);
/// The objective a plan with this planner sets on its problem: for the planners that draw from the
/// objective's informed sampler (BIT*, ABIT*, AIT*, InformedRRT*, SORRT*, CForest), path length
/// with an informed sampler that works on foldkit's spaces (OMPL's direct one throws on the
/// single-vertex and driving spaces; docs/PLANNING.md, "Planners"); null for every other planner,
/// which then picks its own default as OMPL does (PRM stops at its first path, TRRT weighs
/// mechanical work).
/// @param name  the planner
/// @param si    the plan's space information
/// @param stop  once true, the informed sampler stops drawing by rejection (planners::sampling_stop()
///              of the plan's setup: its time is up); empty: never
/// @throws std::invalid_argument for an unknown planner
ompl::base::OptimizationObjectivePtr informed_objective(const std::string& name, const ompl::base::SpaceInformationPtr& si,
                                                        std::function<bool()> stop = {});
/// Whether the planner draws from its objective's informed sampler (BIT*, ABIT*, AIT*,
/// InformedRRT*, SORRT*, CForest): it needs an objective that has one (objective_refusal()).
/// @throws std::invalid_argument for an unknown planner
bool planner_samples_informed(const std::string& name);
/// Whether the planner fills ordered batches from the informed sampler without looking at the
/// time limit (SORRT*): it needs a direct informed sampler, not a rejection one.
/// @throws std::invalid_argument for an unknown planner
bool planner_orders_informed_batches(const std::string& name);
/// Whether the planner runs threads of its own (PRM, PRM*, pRRT, pSBL, CForest,
/// AnytimePathShortening: their plans are not reproducible from the seed).
/// @throws std::invalid_argument for an unknown planner
bool planner_is_threaded(const std::string& name);

}  // namespace foldkit::planners
