#include "foldkit/planners/plan_space.hpp"

#include <stdexcept>
#include <string>

#include <ompl/base/SpaceInformation.h>

#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/statespaces/validity.hpp"
#include "spaces/space_common.hpp"

namespace foldkit::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

namespace {

// Every space kind: its name (parse_space, to_string, --space) and its implementation. A new
// space is a row here, its SpaceKind and its file under spaces/.
struct SpaceEntry {
  SpaceKind kind;
  const char* name;
  std::shared_ptr<PlanSpace> (*make)(const char* name);  // null for Auto, which plan() resolves
};
const SpaceEntry kSpaces[] = {
    {SpaceKind::Auto, "auto", nullptr},
    {SpaceKind::SingleVertex, "single-vertex", &spaces::single_vertex_plan_space},
    {SpaceKind::Driving, "driving", &spaces::driving_plan_space},
    {SpaceKind::Projected, "projected",
     [](const char* name) { return spaces::constrained_plan_space(name, statespaces::ConstrainedKind::Projected); }},
    {SpaceKind::Atlas, "atlas", [](const char* name) { return spaces::constrained_plan_space(name, statespaces::ConstrainedKind::Atlas); }},
    {SpaceKind::TangentBundle, "tangent-bundle",
     [](const char* name) { return spaces::constrained_plan_space(name, statespaces::ConstrainedKind::TangentBundle); }},
};

}  // namespace

std::vector<std::string> space_names() {
  std::vector<std::string> names;
  for (const SpaceEntry& e : kSpaces) names.emplace_back(e.name);
  return names;
}

SpaceKind parse_space(const std::string& name) {
  for (const SpaceEntry& e : kSpaces)
    if (name == e.name) return e.kind;
  std::string known;
  for (const auto& n : space_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown space '" + name + "' (" + known + ")");
}

const char* to_string(SpaceKind kind) {
  for (const SpaceEntry& e : kSpaces)
    if (e.kind == kind) return e.name;
  return "auto";
}

std::shared_ptr<PlanSpace> make_plan_space(SpaceKind kind) {
  for (const SpaceEntry& e : kSpaces)
    if (e.kind == kind && e.make) return e.make(e.name);
  throw std::invalid_argument(std::string("make_plan_space: no space of kind '") + to_string(kind) + "'");
}

void PlanSpace::anchor(ob::State*, ob::State*) const {}

std::vector<FoldState> PlanSpace::path_states(const PlanSetup& setup, og::PathGeometric path, double, const StateSink& sink,
                                              const Stop&) const {
  path.interpolate();
  std::vector<FoldState> states;
  for (unsigned int i = 0; i < static_cast<unsigned int>(path.getStateCount()); ++i) {
    FoldState f;
    setup.reader(path.getState(i), f);
    states.push_back(f);
  }
  if (sink)
    for (const FoldState& f : states) sink(f);
  return states;
}

Fallback PlanSpace::fallback() const { return Fallback::None; }
bool PlanSpace::straight_paths() const { return false; }

namespace spaces {

void use_space(PlanSetup& setup, const PlanOptions& options) {
  setup.si = std::make_shared<ob::SpaceInformation>(setup.space);
  setup.si->setMotionValidator(std::make_shared<statespaces::FoldMotionValidator>(setup.si, setup.validity, setup.reader,
                                                                                   options.resolution, 2.5 * options.resolution));
}

std::vector<FoldState> states_along(const PlanSetup& setup, const og::PathGeometric& path, double step, const Motion& motion,
                                    const PlanSpace::StateSink& sink) {
  std::vector<FoldState> states;
  const auto emit = [&](FoldState f) {
    if (sink) sink(f);
    states.push_back(std::move(f));
  };
  ob::State* tmp = setup.si->allocState();
  for (unsigned int i = 0; i < static_cast<unsigned int>(path.getStateCount()); ++i) {
    FoldState f;
    if (i > 0) motion(path.getState(i - 1), path.getState(i), step, tmp, emit);
    if (setup.reader(path.getState(i), f)) emit(std::move(f));
  }
  setup.si->freeState(tmp);
  return states;
}

}  // namespace spaces

}  // namespace foldkit::planners
