#include "foldkit/planners/planner_factory.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <stdexcept>
#include <utility>

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/est/ProjEST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rlrt/BiRLRT.h>
#include <ompl/geometric/planners/rlrt/RLRT.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
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

struct Entry {
  const char* name;
  const char* alias;
  Make make;
};

const std::vector<Entry>& table() {
  static const std::vector<Entry> t = {
      {"RRTConnect", "", make<og::RRTConnect>()},  {"RRT", "", make<og::RRT>()},
      {"RRT*", "RRTstar", make<og::RRTstar>()},     {"RRT#", "RRTsharp", make<og::RRTsharp>()},
      {"LazyRRT", "", make<og::LazyRRT>()},         {"TRRT", "", make<og::TRRT>()},
      {"BiTRRT", "", make<og::BiTRRT>()},           {"LBTRRT", "", make<og::LBTRRT>()},
      {"PRM", "", make<og::PRM>()},                 {"PRM*", "PRMstar", make<og::PRMstar>()},
      {"LazyPRM", "", make<og::LazyPRM>()},         {"LazyPRM*", "LazyPRMstar", make<og::LazyPRMstar>()},
      {"KPIECE1", "KPIECE", make<og::KPIECE1>()},   {"BKPIECE1", "BKPIECE", make<og::BKPIECE1>()},
      {"LBKPIECE1", "LBKPIECE", make<og::LBKPIECE1>()}, {"EST", "", make<og::EST>()},
      {"BiEST", "", make<og::BiEST>()},             {"ProjEST", "", make<og::ProjEST>()},
      {"SBL", "", make<og::SBL>()},                 {"STRIDE", "", make<og::STRIDE>()},
      {"PDST", "", make<og::PDST>()},               {"FMT", "FMT*", make<og::FMT>()},
      {"BFMT", "BFMT*", make<og::BFMT>()},          {"SST", "", make<og::SST>()},
      {"RLRT", "", make<og::RLRT>()},               {"BiRLRT", "", make<og::BiRLRT>()},
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
  return find(name).make(si);
}

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

bool planner_is_threaded(const std::string& name) {
  const std::string n = find(name).name;
  return n == "PRM" || n == "PRM*";
}

}  // namespace foldkit::planners
