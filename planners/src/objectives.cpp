// The objectives by name: one table (kTable) of what each measures on fold states and on OMPL
// states; parsing of weighted sums; which planners can use which.
#include "foldkit/planners/objectives.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <ompl/base/goals/GoalState.h>
#include <ompl/base/objectives/MaximizeMinClearanceObjective.h>

#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "foldkit/simulation/clearance.hpp"
#include "path_length.hpp"

namespace foldkit::planners {

namespace ob = ompl::base;
using geometry::FoldState;

namespace {

// What an additive term needs to cost a motion of OMPL states.
struct MotionContext {
  ob::SpaceInformationPtr si;
  const statespaces::StateReader* reader;
};

double length_motion(const MotionContext& c, const ob::State* a, const ob::State* b) { return c.si->distance(a, b); }

// Buffers per thread: PRM and PRM* cost motions from several threads.
double rotation_motion(const MotionContext& c, const ob::State* a, const ob::State* b) {
  thread_local FoldState fa, fb;
  if (!(*c.reader)(a, fa) || !(*c.reader)(b, fb)) return std::numeric_limits<double>::infinity();
  return (fb.angles - fa.angles).lpNorm<1>();
}

double length_path(const geometry::CreasePattern&, const std::vector<FoldState>& states) {
  double sum = 0.0;
  for (std::size_t i = 1; i < states.size(); ++i) sum += (states[i].angles - states[i - 1].angles).norm();
  return sum;
}

double rotation_path(const geometry::CreasePattern&, const std::vector<FoldState>& states) {
  double sum = 0.0;
  for (std::size_t i = 1; i < states.size(); ++i) sum += (states[i].angles - states[i - 1].angles).lpNorm<1>();
  return sum;
}

double clearance_path(const geometry::CreasePattern& pattern, const std::vector<FoldState>& states) {
  return simulation::min_clearance(pattern, states);
}

// One row per objective. `motion`: an additive term's cost of a motion between two OMPL states,
// null for clearance (a maximin, with its own OMPL objective). An additive term's motion cost is
// also its heuristic: it is a lower bound of any path's cost between the two states (the space's
// metric; Σ|Δθ| between the ends, by the triangle inequality), so OMPL's rejection informed
// sampler keeps only states that may lie on a better path. `path`: the cost of a path of fold
// states, every crease counted.
struct Entry {
  const char* name;
  const char* unit;
  const char* description;
  double (*motion)(const MotionContext&, const ob::State*, const ob::State*);
  double (*path)(const geometry::CreasePattern&, const std::vector<FoldState>&);
};

const Entry kTable[] = {
    {"length", "rad", "path length in the space's own metric (the driving angles' Euclidean distance in the driving space)",
     length_motion, length_path},
    {"rotation", "rad", "total crease rotation, Σ|Δθ| over every crease along the path: the actuators' travel",
     rotation_motion, rotation_path},
    {"clearance", "pattern units",
     "the smallest facet-facet distance along the path (simulation::min_clearance), maximised", nullptr, clearance_path},
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string known_list() {
  std::string known;
  for (const Entry& e : kTable) known += (known.empty() ? "" : ", ") + std::string(e.name);
  return known + "; a weighted sum as NAME:WEIGHT,NAME:WEIGHT";
}

const Entry& entry(const std::string& name) {
  for (const Entry& e : kTable)
    if (lower(name) == e.name) return e;
  throw std::invalid_argument("unknown objective '" + name + "' (known: " + known_list() + ")");
}

// A weighted sum of additive terms (length, rotation) as one OMPL objective: motion costs add,
// states cost nothing, and the heuristics are the motion costs themselves (each a lower bound of
// its term along any path), so OMPL's rejection sampler serves the informed planners.
class WeightedSum : public ob::OptimizationObjective {
 public:
  WeightedSum(const ob::SpaceInformationPtr& si, const statespaces::StateReader& reader,
              std::vector<std::pair<const Entry*, double>> terms, std::string name, std::function<bool()> stop)
      : ob::OptimizationObjective(si), context_{si, &reader}, terms_(std::move(terms)), stop_(std::move(stop)) {
    description_ = std::move(name);
    setCostToGoHeuristic([this](const ob::State* s, const ob::Goal* goal) {
      const auto* g = dynamic_cast<const ob::GoalState*>(goal);
      return g ? motionCostHeuristic(s, g->getState()) : identityCost();
    });
  }
  ob::Cost stateCost(const ob::State*) const override { return identityCost(); }
  ob::Cost motionCost(const ob::State* a, const ob::State* b) const override {
    double sum = 0.0;
    for (const auto& [e, w] : terms_) sum += w * e->motion(context_, a, b);
    return ob::Cost(sum);
  }
  ob::Cost motionCostHeuristic(const ob::State* a, const ob::State* b) const override { return motionCost(a, b); }
  ob::InformedSamplerPtr allocInformedStateSampler(const ob::ProblemDefinitionPtr& pdef, unsigned int calls) const override {
    return detail::rejection_sampler(pdef, calls, stop_);  // bounded draws: path_length.hpp
  }

 private:
  MotionContext context_;
  std::vector<std::pair<const Entry*, double>> terms_;
  std::function<bool()> stop_;
};

// OMPL's MaximizeMinClearanceObjective with the simulator's clearance: a state's cost is the
// smallest distance between facets that share no vertex, a motion's the smallest over its ends
// and the space's interpolated states at the validity resolution (each costed once), combined by
// min, larger better.
class Clearance : public ob::MaximizeMinClearanceObjective {
 public:
  Clearance(const ob::SpaceInformationPtr& si, const PlanSetup& setup)
      : ob::MaximizeMinClearanceObjective(si), pattern_(*setup.pattern), reader_(setup.reader) {
    description_ = "clearance";
  }
  ob::Cost stateCost(const ob::State* s) const override {
    thread_local FoldState f;
    if (!reader_(s, f)) return ob::Cost(0.0);
    return ob::Cost(simulation::min_clearance(pattern_, {f}));
  }
  ob::Cost motionCost(const ob::State* a, const ob::State* b) const override {
    ob::Cost worst = combineCosts(stateCost(a), stateCost(b));
    const unsigned int n = si_->getStateSpace()->validSegmentCount(a, b);
    if (n > 1) {
      ob::State* s = si_->allocState();
      for (unsigned int j = 1; j < n; ++j) {
        si_->getStateSpace()->interpolate(a, b, static_cast<double>(j) / n, s);
        worst = combineCosts(worst, stateCost(s));
      }
      si_->freeState(s);
    }
    return worst;
  }

 private:
  const geometry::CreasePattern& pattern_;
  statespaces::StateReader reader_;
};

std::string weight_text(double w) {
  std::ostringstream s;
  s.precision(12);
  s << w;
  return s.str();
}

// "NAME" or "NAME:WEIGHT" → the term (checked).
ObjectiveTerm parse_term(const std::string& item, const std::string& text) {
  const auto colon = item.find(':');
  ObjectiveTerm t{lower(item.substr(0, colon)), 1.0};
  entry(t.name);  // throws for an unknown name
  if (colon != std::string::npos) {
    const std::string w = item.substr(colon + 1);
    char* end = nullptr;
    t.weight = std::strtod(w.c_str(), &end);
    if (w.empty() || *end != '\0' || !(t.weight > 0.0) || !std::isfinite(t.weight))
      throw std::invalid_argument("objective '" + text + "': the weight '" + w + "' of " + t.name +
                                  " is not a positive number (known: " + known_list() + ")");
  }
  return t;
}

}  // namespace

std::function<bool()> sampling_stop(const PlanSetup& setup) {
  std::shared_ptr<const statespaces::FoldValidity> validity = setup.validity;
  return [validity] { return validity && validity->expired(); };
}

std::string Objective::name() const {
  if (terms.size() == 1 && terms[0].weight == 1.0) return terms[0].name;
  std::string out;
  for (const auto& t : terms) out += (out.empty() ? "" : ",") + t.name + ":" + weight_text(t.weight);
  return out;
}

bool Objective::is_default() const { return terms.size() == 1 && terms[0].name == kTable[0].name && terms[0].weight == 1.0; }

std::vector<ObjectiveInfo> objective_table() {
  std::vector<ObjectiveInfo> out;
  for (const Entry& e : kTable) out.push_back({e.name, e.unit, e.description, e.motion != nullptr, e.motion != nullptr});
  return out;
}

std::vector<std::string> objective_names() {
  std::vector<std::string> out;
  for (const Entry& e : kTable) out.emplace_back(e.name);
  return out;
}

Objective parse_objective(const std::string& text) {
  Objective o;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) throw std::invalid_argument("objective '" + text + "': an empty term (known: " + known_list() + ")");
    ObjectiveTerm t = parse_term(item, text);
    for (const auto& other : o.terms)
      if (other.name == t.name) throw std::invalid_argument("objective '" + text + "': " + t.name + " twice");
    o.terms.push_back(std::move(t));
  }
  if (o.terms.empty() || (!text.empty() && text.back() == ','))
    throw std::invalid_argument("objective '" + text + "': no objective named (known: " + known_list() + ")");
  if (o.terms.size() > 1)
    for (const auto& t : o.terms)
      if (!entry(t.name).motion)
        throw std::invalid_argument("objective '" + text + "': " + t.name +
                                    " is a maximin (the smallest value along the path), not a sum over its motions: "
                                    "it cannot be weighted with others; use it alone");
  return o;
}

std::string objective_refusal(const std::string& planner, const Objective& objective) {
  const std::string name = canonical_planner(planner);
  if (!planner_samples_informed(name)) return "";
  for (const auto& t : objective.terms)
    if (!entry(t.name).motion)
      return name + " samples from the objective's informed set, and the " + t.name +
             " objective has no informed sampler: a path's smallest clearance bounds neither the cost to come nor the "
             "cost to go of a state, so no state can be ruled out (use RRT*, RRT#, PRM* or FMT)";
  if (planner_orders_informed_batches(name) && !objective.is_default())
    return name + " draws ordered batches from an informed sampler without checking the time limit, and the " +
           objective.name() + " objective is sampled by rejection (no direct sampler exists for it), so a batch may "
           "never fill: use InformedRRT* or BIT*";
  return "";
}

double path_cost(const Objective& objective, const geometry::CreasePattern& pattern, const std::vector<FoldState>& states) {
  double sum = 0.0;
  for (const auto& t : objective.terms) sum += t.weight * entry(t.name).path(pattern, states);
  return sum;
}

ob::OptimizationObjectivePtr make_objective(const Objective& objective, const PlanSetup& setup, std::optional<double> threshold) {
  ob::OptimizationObjectivePtr out;
  if (objective.is_default()) {
    out = std::make_shared<detail::PathLength>(setup.si, sampling_stop(setup));
  } else if (!entry(objective.terms[0].name).motion) {
    out = std::make_shared<Clearance>(setup.si, setup);
  } else {
    std::vector<std::pair<const Entry*, double>> terms;
    for (const auto& t : objective.terms) terms.emplace_back(&entry(t.name), t.weight);
    out = std::make_shared<WeightedSum>(setup.si, setup.reader, std::move(terms), objective.name(), sampling_stop(setup));
  }
  // No threshold: none is ever satisfied (OMPL's path length has 0, which no path beats; the
  // clearance objective +∞), so optimising planners improve until their time runs out.
  if (threshold)
    out->setCostThreshold(ob::Cost(*threshold));
  else
    out->setCostThreshold(ob::Cost(entry(objective.terms[0].name).motion ? 0.0 : std::numeric_limits<double>::infinity()));
  return out;
}

void check_cost_threshold(double threshold, const std::string& what) {
  if (!(threshold >= 0.0) || !std::isfinite(threshold))
    throw std::invalid_argument(what + ": the cost threshold must be a finite number ≥ 0, not " + weight_text(threshold));
}

ob::OptimizationObjectivePtr plan_objective(const PlanSetup& setup, const PlanOptions& options) {
  const Objective objective = parse_objective(options.objective);
  if (options.cost_threshold) check_cost_threshold(*options.cost_threshold, "plan");
  if (objective.is_default() && !options.cost_threshold) return informed_objective(options.planner, setup.si, sampling_stop(setup));
  return make_objective(objective, setup, options.cost_threshold);
}

}  // namespace foldkit::planners
