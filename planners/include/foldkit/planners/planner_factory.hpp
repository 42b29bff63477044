#pragma once
/// @file
/// OMPL's geometric planners by name.
#include <string>
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
