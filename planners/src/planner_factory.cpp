#include "foldkit/planners/planner_factory.hpp"

#include "path_length.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/constraint/ConstrainedStateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/geometric/planners/AnytimePathShortening.h>
#include <ompl/geometric/planners/cforest/CForest.h>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/est/ProjEST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/prm/SPARS.h>
#include <ompl/geometric/planners/prm/SPARStwo.h>
#include <ompl/geometric/planners/rlrt/BiRLRT.h>
#include <ompl/geometric/planners/rlrt/RLRT.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LazyLBTRRT.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTXstatic.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/SORRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/rrt/pRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/sbl/pSBL.h>
#include <ompl/geometric/planners/sst/SST.h>
#include <ompl/geometric/planners/stride/STRIDE.h>

namespace foldkit::planners {

namespace og = ompl::geometric;
using Make = std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr&)>;

namespace {

template <class P>
Make make() {
  return [](const ompl::base::SpaceInformationPtr& si) { return std::make_shared<P>(si); };
}

// One row per geometric planner OMPL 1.5.2 ships (ompl/geometric/planners/), so that a name is
// answered with a planner or with why there is none: `refused` says what the planner needs that
// a crease pattern does not give it.
struct Entry {
  const char* name;
  const char* alias;
  Make make;
  bool threaded = false;  // runs threads of its own: not reproducible from the seed
  const char* refused = "";
  // Refused where the path-length objective's informed sampler is by rejection (detail::PathLength)
  bool needs_direct_informed = false;
  // foldkit's defaults where OMPL's do not fit a crease pattern (NAME=VALUE, space-separated),
  // set before the caller's parameters (docs/PLANNING.md, "Planners")
  const char* defaults = "";
  // Draws from the objective's informed sampler: needs informed_objective() on foldkit's spaces
  bool informed = false;
};

// SORRT* fills ordered batches from the informed sampler without looking at the time limit; by
// rejection (every space but the joint box), a batch may never fill: it ran past 60 s on a
// degree-6 vertex with --time 2.
constexpr const char* kOrderedBatches =
    "SORRT* draws ordered batches from an informed sampler without checking the time limit, and on this "
    "space that sampler works by rejection (there is no direct ellipsoidal sampler for it), so a batch may "
    "never fill: use InformedRRT* or BIT*";

// LBTRRT on the constrained spaces: measured (Miura 4x4, 2 s, seed 3), it aborted the process on
// each of them (Debian's OMPL keeps its assertions), where it solves on the others.
constexpr const char* kLbtrrtConstrained =
    "OMPL 1.5.2's LBTRRT aborts the process on the constrained spaces (projected, atlas, tangent-bundle): the "
    "assertion `distance_[w] + weight != distance_[w]` in its lower-bound graph's DynamicSSSP::addEdge fails (an "
    "edge that changes no distance); use LazyLBTRRT, or LBTRRT in the driving or single-vertex space";

const std::vector<Entry>& table() {
  static const std::vector<Entry> t = {
      {"RRTConnect", "", make<og::RRTConnect>()},  {"RRT", "", make<og::RRT>()},
      {"RRT*", "RRTstar", make<og::RRTstar>()},     {"RRT#", "RRTsharp", make<og::RRTsharp>()},
      {"LazyRRT", "", make<og::LazyRRT>()},         {"TRRT", "", make<og::TRRT>(), false, "", false, "frontier_node_ratio=1"},
      {"BiTRRT", "", make<og::BiTRRT>()},           {"LBTRRT", "", make<og::LBTRRT>()},
      {"PRM", "", make<og::PRM>(), true},           {"PRM*", "PRMstar", make<og::PRMstar>(), true},
      {"LazyPRM", "", make<og::LazyPRM>()},         {"LazyPRM*", "LazyPRMstar", make<og::LazyPRMstar>()},
      {"KPIECE1", "KPIECE", make<og::KPIECE1>()},   {"BKPIECE1", "BKPIECE", make<og::BKPIECE1>()},
      {"LBKPIECE1", "LBKPIECE", make<og::LBKPIECE1>()}, {"EST", "", make<og::EST>()},
      {"BiEST", "", make<og::BiEST>()},             {"ProjEST", "", make<og::ProjEST>()},
      {"SBL", "", make<og::SBL>()},                 {"STRIDE", "", make<og::STRIDE>()},
      {"PDST", "", make<og::PDST>()},               {"FMT", "FMT*", make<og::FMT>()},
      {"BFMT", "BFMT*", make<og::BFMT>()},          {"SST", "", make<og::SST>(), false, "", false, "selection_radius=0.3 pruning_radius=0.02"},
      {"RLRT", "", make<og::RLRT>()},               {"BiRLRT", "", make<og::BiRLRT>()},
      // Issue 38: the rest of OMPL 1.5.2's geometric planners.
      {"BIT*", "BITstar", make<og::BITstar>(), false, "", false, "", true},
      {"ABIT*", "ABITstar", make<og::ABITstar>(), false, "", false, "", true},
      {"AIT*", "AITstar", make<og::AITstar>(), false, "", false, "", true},
      {"InformedRRT*", "InformedRRTstar", make<og::InformedRRTstar>(), false, "", false, "", true},
      {"SORRT*", "SORRTstar", make<og::SORRTstar>(), false, "", true, "", true}, {"RRTXstatic", "", make<og::RRTXstatic>()},
      {"LazyLBTRRT", "", make<og::LazyLBTRRT>()},   {"SPARS", "", make<og::SPARS>(), false, "", false, "sparse_delta_fraction=0.5"},
      {"SPARStwo", "", make<og::SPARStwo>()},       {"QRRT", "", nullptr, false,
       "OMPL 1.5.2's multilevel planners leak: MultiQuotient allocates each level's planner and its "
       "nearest-neighbour structure and never frees them (LeakSanitizer), and foldkit's spaces offer "
       "no coarser levels, so on one level it would be RRT with extra steps"},
      {"pRRT", "", make<og::pRRT>(), true},         {"pSBL", "", make<og::pSBL>(), true},
      {"CForest", "", make<og::CForest>(), true, "", false, "", true},   {"AnytimePathShortening", "APS", make<og::AnytimePathShortening>(), true},
      {"TSRRT", "", nullptr, false,
       "TSRRT grows its tree in a task space that the caller defines (a TaskSpaceConfig: a projection of "
       "the state and its inverse); a crease pattern names no such task space"},
      {"VFRRT", "", nullptr, false,
       "VFRRT follows a vector field over the space, which the caller supplies; a crease pattern has none"},
      {"XXL", "", nullptr, false,
       "XXL needs a workspace decomposition of the robot's links (XXLDecomposition); foldkit's spaces "
       "offer none"},
      {"ThunderRetrieveRepair", "", nullptr, false,
       "ThunderRetrieveRepair searches a roadmap built from an experience database (OMPL's Thunder "
       "framework), which a planner on its own does not have: plan with --experience DB --experience-framework thunder "
       "(Python: experience=, experience_framework='thunder')"},
      {"LightningRetrieveRepair", "", nullptr, false,
       "LightningRetrieveRepair repairs paths recalled from an experience database (OMPL's Lightning "
       "framework), which a planner on its own does not have: plan with --experience DB (Python: experience=)"},
  };
  return t;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

const Entry& find(const std::string& name) {
  const std::string key = lower(name);
  for (const Entry& e : table())
    if (key == lower(e.name) || (*e.alias && key == lower(e.alias))) return e;
  std::string known;
  for (const Entry& e : table()) known += (known.empty() ? "" : ", ") + std::string(e.name);
  throw std::invalid_argument("unknown planner '" + name + "' (known: " + known + ")");
}

}  // namespace

ompl::base::PlannerPtr make_planner(const std::string& name, const ompl::base::SpaceInformationPtr& si) {
  const Entry& e = find(name);
  if (*e.refused) throw PlannerRefused(e.name, e.refused);
  if (e.needs_direct_informed && !detail::has_direct_informed_sampler(si)) throw PlannerRefused(e.name, kOrderedBatches);
  if (std::string(e.name) == "LBTRRT" && std::dynamic_pointer_cast<ompl::base::ConstrainedStateSpace>(si->getStateSpace()))
    throw PlannerRefused(e.name, kLbtrrtConstrained);
  ompl::base::PlannerPtr planner = e.make(si);
  std::istringstream defaults(e.defaults);
  std::vector<std::pair<std::string, std::string>> params;
  for (std::string word; defaults >> word;) params.push_back(parse_planner_param(word));
  set_planner_params(*planner, e.name, params);
  return planner;
}

std::string planner_refusal(const std::string& name) { return find(name).refused; }

PlannerRefused::PlannerRefused(const std::string& planner, const std::string& reason)
    : std::invalid_argument("planner " + planner + " cannot plan here: " + reason) {}

void set_planner_params(ompl::base::Planner& planner, const std::string& name,
                        const std::vector<std::pair<std::string, std::string>>& params) {
  ompl::base::ParamSet& set = planner.params();
  for (const auto& [key, value] : params) {
    if (!set.hasParam(key)) {
      std::vector<std::string> names;
      set.getParamNames(names);
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      throw std::invalid_argument("planner " + name + " has no parameter '" + key + "' (it has: " + (known.empty() ? "none" : known) + ")");
    }
    // ParamSet::setParam answers false for a value the setter refuses, and OMPL's conversion
    // throws for one it cannot parse as the parameter's type.
    bool accepted = false;
    try {
      accepted = set.setParam(key, value);
    } catch (const std::exception&) {
      accepted = false;
    }
    if (!accepted)
      throw std::invalid_argument("planner " + name + ": parameter '" + key + "' refuses the value '" + value + "'");
  }
}

std::pair<std::string, std::string> parse_planner_param(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("planner parameter '" + text + "' is not NAME=VALUE");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

void check_planner_params(const std::string& planner, const std::vector<std::pair<std::string, std::string>>& params) {
  if (params.empty()) return;
  // OMPL announces each parameter set at its debug level, on stdout: silent here, where nothing
  // is planned (a CLI's --json owns stdout).
  struct Quiet {
    ompl::msg::LogLevel before = ompl::msg::getLogLevel();
    Quiet() { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
    ~Quiet() { ompl::msg::setLogLevel(before); }
  } quiet;
  auto box = std::make_shared<ompl::base::RealVectorStateSpace>(1);
  box->setBounds(0.0, 1.0);
  auto si = std::make_shared<ompl::base::SpaceInformation>(box);
  set_planner_params(*make_planner(planner, si), planner, params);
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const Entry& e : table()) names.emplace_back(e.name);
  return names;
}

std::string canonical_planner(const std::string& name) { return find(name).name; }

bool planner_is_threaded(const std::string& name) { return find(name).threaded; }

bool planner_samples_informed(const std::string& name) { return find(name).informed; }

bool planner_orders_informed_batches(const std::string& name) { return find(name).needs_direct_informed; }

ompl::base::OptimizationObjectivePtr informed_objective(const std::string& name, const ompl::base::SpaceInformationPtr& si,
                                                        std::function<bool()> stop) {
  if (!find(name).informed) return nullptr;
  return std::make_shared<detail::PathLength>(si, std::move(stop));
}

}  // namespace foldkit::planners
