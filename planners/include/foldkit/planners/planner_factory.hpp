#pragma once
/// @file
/// OMPL's geometric planners by name.
#include <string>
#include <utility>
#include <vector>

#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>

namespace foldkit::planners {

/// An OMPL geometric planner by name, case-insensitive: RRTConnect, RRT, RRT* (RRTstar), RRT#
/// (RRTsharp), LazyRRT, TRRT, BiTRRT, LBTRRT, PRM, PRM* (PRMstar), LazyPRM, LazyPRM* (LazyPRMstar),
/// KPIECE1, BKPIECE1, LBKPIECE1, EST, BiEST, ProjEST, SBL, STRIDE, PDST, FMT, BFMT, SST, RLRT, BiRLRT
/// (also KPIECE, BKPIECE, LBKPIECE, FMT*, BFMT*), with OMPL's default settings.
/// @throws std::invalid_argument for any other name (the message lists the known ones)
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
/// The canonical names above, in that order.
std::vector<std::string> planner_names();
/// The canonical name of a planner.
/// @throws std::invalid_argument for an unknown one
std::string canonical_planner(const std::string& name);
/// Whether the planner runs threads of its own (PRM and PRM*: their plans are not reproducible
/// from the seed).
/// @throws std::invalid_argument for an unknown planner
bool planner_is_threaded(const std::string& name);

}  // namespace foldkit::planners
