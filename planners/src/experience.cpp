#include "foldkit/planners/experience.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

#include <boost/crc.hpp>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/planners/experience/LightningRetrieveRepair.h>
#include <ompl/geometric/planners/experience/ThunderRetrieveRepair.h>
#include <ompl/tools/lightning/LightningDB.h>
#include <ompl/tools/thunder/SPARSdb.h>
#include <ompl/tools/thunder/ThunderDB.h>

namespace foldkit::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

constexpr const char* kMagic = "foldkit-experience";
// Version 2 adds Thunder's roadmap after the paths; version 1 files (paths only) still read.
constexpr int kVersion = 2;

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

// OMPL's databases warn, when they are destroyed, of paths their own save() did not write;
// foldkit's caller writes bytes() itself, so the count is cleared then.
class Database : public ompl::tools::LightningDB {
 public:
  using LightningDB::LightningDB;
  ~Database() override { numUnsavedPaths_ = 0; }
};
class Roadmaps : public ompl::tools::ThunderDB {
 public:
  using ThunderDB::ThunderDB;
  ~Roadmaps() override { numPathsInserted_ = 0; }
};

std::uint32_t crc32(const std::string& body) {
  boost::crc_32_type crc;
  crc.process_bytes(body.data(), body.size());
  return crc.checksum();
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << v;
  return s.str();
}

// The header: one "key value" line each, in this order; the records follow it.
struct Header {
  std::string space;
  std::size_t state_bytes = 0, paths = 0, bytes = 0;
  std::uint64_t pattern = 0;
  std::uint32_t crc = 0;
  // Version 2: the roadmap section (all 0 when there is none), its records after the paths'.
  std::size_t roadmap_paths = 0, roadmap_vertices = 0, roadmap_edges = 0, roadmap_bytes = 0;
  std::uint32_t roadmap_crc = 0;
};

// Reads the header off `in`; the reason it is not one, or empty.
std::string read_header(std::istream& in, Header& h) {
  std::string magic;
  int version = 0;
  if (!(in >> magic >> version) || magic != kMagic) return "not a foldkit experience database (it does not start with \"foldkit-experience\")";
  if (version != 1 && version != kVersion)
    return "experience database version " + std::to_string(version) + ", this foldkit reads versions 1 and " + std::to_string(kVersion);
  const auto field = [&](const char* key, auto& value, bool in_hex = false) {
    std::string k;
    if (!(in >> k) || k != key) return false;
    if (in_hex) in >> std::hex;
    in >> value;
    in >> std::dec;
    return static_cast<bool>(in);
  };
  if (!field("space", h.space) || !field("state-bytes", h.state_bytes) || !field("pattern", h.pattern, true) || !field("paths", h.paths) ||
      !field("bytes", h.bytes) || !field("crc", h.crc, true))
    return "damaged header (expected the lines space, state-bytes, pattern, paths, bytes, crc)";
  if (version >= 2 && (!field("roadmap-paths", h.roadmap_paths) || !field("roadmap-vertices", h.roadmap_vertices) ||
                       !field("roadmap-edges", h.roadmap_edges) || !field("roadmap-bytes", h.roadmap_bytes) ||
                       !field("roadmap-crc", h.roadmap_crc, true)))
    return "damaged header (expected the lines roadmap-paths, roadmap-vertices, roadmap-edges, roadmap-bytes, roadmap-crc)";
  if (in.get() != '\n') return "damaged header (no line break before the records)";
  return {};
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// SPARSdb's search asks its problem's goal whether a roadmap vertex near the query's start and one
// near its goal may pair (Goal::isStartGoalPairValid) and dereferences the goal unchecked; the
// roadmap serves every query, so any pair may.
class AnyPair : public ob::Goal {
 public:
  using ob::Goal::Goal;
  bool isSatisfied(const ob::State*) const override { return false; }
};

// A ThunderDB with its SPARSdb roadmap on `si` (its validity checker and motion validator), set
// up as ompl::tools::Thunder::setup() does: stretch factor 1.2, visibility range 0.05 of the
// space's maximum extent. SPARSdb is a planner and wants a problem definition: one whose goal
// pairs anything serves, as the roadmap is only built (addPathToRoadmap) and searched between
// the query's ends (getSimilarPaths).
std::shared_ptr<ompl::tools::ThunderDB> make_thunder(const ob::SpaceInformationPtr& si) {
  auto db = std::make_shared<Roadmaps>(si->getStateSpace());
  auto spars = detail::make_roadmap(si);
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setGoal(std::make_shared<AnyPair>(si));
  spars->setProblemDefinition(pdef);
  spars->setup();
  spars->setStretchFactor(1.2);
  spars->setSparseDeltaFraction(0.05);
  db->setSPARSdb(spars);
  return db;
}

}  // namespace

std::vector<std::string> experience_framework_names() { return {"lightning", "thunder"}; }

ExperienceFramework parse_experience_framework(const std::string& name) {
  if (lower(name) == "lightning") return ExperienceFramework::Lightning;
  if (lower(name) == "thunder") return ExperienceFramework::Thunder;
  throw std::invalid_argument("unknown experience framework '" + name + "' (known: lightning, thunder)");
}

std::string to_string(ExperienceFramework framework) {
  return framework == ExperienceFramework::Thunder ? "thunder" : "lightning";
}

std::uint64_t pattern_fingerprint(const geometry::CreasePattern& pattern) {
  Fnv f;
  f.value(pattern.vertices().size());
  for (const auto& v : pattern.vertices()) {
    f.value(v.x());
    f.value(v.y());
  }
  f.value(pattern.actors().size());
  for (const auto& a : pattern.actors())
    for (const auto& t : a.triangles)
      for (int v : t.v) f.value(v);
  f.value(pattern.joints().size());
  for (const auto& j : pattern.joints()) {
    f.value(j.actors[0]);
    f.value(j.actors[1]);
  }
  return f.h;
}

ExperienceDatabase::ExperienceDatabase(const ob::SpaceInformationPtr& si, std::string space_name, std::uint64_t fingerprint,
                                       ExperienceFramework framework)
    : si_(si), space_name_(std::move(space_name)), fingerprint_(fingerprint), framework_(framework) {
  if (framework_ == ExperienceFramework::Thunder)
    thunder_ = make_thunder(si);
  else
    lightning_ = std::make_shared<Database>(si->getStateSpace());
}

ExperienceDatabase::~ExperienceDatabase() = default;

void ExperienceDatabase::read(const std::string& bytes, const std::string& name) {
  if (bytes.empty()) return;
  const auto fail = [&](const std::string& why) { throw ExperienceError(name, why); };
  std::istringstream in(bytes);
  Header h;
  if (const std::string why = read_header(in, h); !why.empty()) fail(why);
  if (h.space != space_name_) fail("written for the " + h.space + " space, this plan searches the " + space_name_ + " space");
  const std::size_t state_bytes = si_->getStateSpace()->getSerializationLength();
  if (h.state_bytes != state_bytes)
    fail("written for states of " + std::to_string(h.state_bytes) + " bytes, this space's have " + std::to_string(state_bytes) +
         " (another pattern)");
  if (h.pattern != fingerprint_) fail("written for another pattern (its fingerprint " + hex(h.pattern) + ", this one's " + hex(fingerprint_) + ")");
  const auto at = static_cast<std::size_t>(in.tellg());
  // Compared without adding the two counts, which a hand-made header could make wrap around.
  if (h.bytes > bytes.size() - at || bytes.size() - at - h.bytes != h.roadmap_bytes)
    fail("damaged: " + std::to_string(bytes.size() - at) + " bytes of records where the header says " + std::to_string(h.bytes) +
         (h.roadmap_bytes ? " + " + std::to_string(h.roadmap_bytes) : std::string()));
  const std::string body = bytes.substr(at, h.bytes), roadmap = bytes.substr(at + h.bytes);
  if (crc32(body) != h.crc) fail("damaged: the records do not match their CRC-32");
  if (crc32(roadmap) != h.roadmap_crc) fail("damaged: the roadmap's records do not match their CRC-32");
  if (h.roadmap_paths > h.paths) fail("damaged: a roadmap of " + std::to_string(h.roadmap_paths) + " paths in a file of " + std::to_string(h.paths));
  if ((h.roadmap_vertices == 0) != (h.roadmap_paths == 0)) fail("damaged: a roadmap of " + std::to_string(h.roadmap_vertices) +
                                                                " vertices made from " + std::to_string(h.roadmap_paths) + " paths");
  std::vector<og::PathGeometric> loaded;
  std::size_t pos = 0;
  for (std::size_t i = 0; i < h.paths; ++i) {
    const std::string which = "path " + std::to_string(i + 1);
    std::uint64_t count = 0;
    if (body.size() - pos < sizeof count) fail("damaged: " + which + " is cut short");
    std::memcpy(&count, body.data() + pos, sizeof count);
    pos += sizeof count;
    if (count < 2) fail("damaged: " + which + " has fewer than two states");
    if (count > (body.size() - pos) / state_bytes) fail("damaged: " + which + " holds more states than its bytes");
    loaded.push_back(read_path(body.data() + pos, static_cast<std::size_t>(count), which, name));
    pos += static_cast<std::size_t>(count) * state_bytes;
  }
  if (pos != body.size()) fail("damaged: bytes after the last of its " + std::to_string(h.paths) + " paths");
  read_roadmap_section(roadmap, h.roadmap_vertices, h.roadmap_edges, h.roadmap_paths, name);
  // The paths the roadmap covers are kept (the file holds them) without being added to it again.
  const std::size_t covered = thunder_ ? paths_from_roadmap_ : 0;
  for (std::size_t i = 0; i < loaded.size(); ++i) {
    if (i < covered)
      paths_.push_back(loaded[i]);
    else
      add(loaded[i]);
  }
}

// Thunder reads the roadmap into a new one, taken only when all of it reads: a refused file
// leaves the database as it was. Lightning keeps the section, checked by its CRC, to write back.
void ExperienceDatabase::read_roadmap_section(const std::string& records, std::size_t vertices, std::size_t edges, std::size_t paths,
                                              const std::string& name) {
  paths_from_roadmap_ = 0;
  if (!thunder_) {
    roadmap_ = records;
    roadmap_paths_ = paths;
    roadmap_vertices_ = vertices;
    roadmap_edges_ = edges;
    return;
  }
  // A roadmap read into a database that already holds paths would not cover them.
  if (paths == 0 || !paths_.empty()) return;
  auto fresh = make_thunder(si_);
  if (const std::string why = detail::read_roadmap(*fresh->getSPARSdb(), records, vertices, edges); !why.empty())
    throw ExperienceError(name, "damaged roadmap: " + why);
  thunder_ = fresh;
  paths_from_roadmap_ = paths;
}

// Each path's states, as the space serializes them, checked: finite angles within the space's
// bounds (a record is read only after the header and the CRC agree, but a file can be made by hand).
og::PathGeometric ExperienceDatabase::read_path(const char* data, std::size_t count, const std::string& which,
                                                const std::string& name) const {
  const ob::StateSpacePtr& space = si_->getStateSpace();
  const std::size_t state_bytes = space->getSerializationLength();
  og::PathGeometric path(si_);
  ob::State* state = space->allocState();
  for (std::size_t k = 0; k < count; ++k) {
    if (!detail::read_state(*space, data + k * state_bytes, state)) {
      space->freeState(state);
      throw ExperienceError(name, "damaged: " + which + ", state " + std::to_string(k + 1) + " is not a closed state within the bounds");
    }
    path.append(state);
  }
  space->freeState(state);
  return path;
}

bool detail::read_state(const ob::StateSpace& space, const char* data, ob::State* state) {
  space.deserialize(state, data);
  std::vector<double> reals;
  space.copyToReals(reals, state);
  return std::all_of(reals.begin(), reals.end(), [](double v) { return std::isfinite(v); }) && space.satisfiesBounds(state);
}

// The records: per path its number of states (8 bytes, this machine's byte order), then the
// states as the space serializes them (getSerializationLength() bytes each). foldkit's own rather
// than OMPL's PlannerDataStorage, which trusts its Boost archive (a hand-made file could make it
// read past a state's buffer) and logs rather than reports what it cannot read.
std::string ExperienceDatabase::bytes() const {
  const ob::StateSpacePtr& space = si_->getStateSpace();
  std::string body, state(space->getSerializationLength(), '\0');
  for (const auto& path : paths_) {
    const std::uint64_t count = path.getStateCount();
    body.append(reinterpret_cast<const char*>(&count), sizeof count);
    for (unsigned int v = 0; v < path.getStateCount(); ++v) {
      space->serialize(state.data(), path.getState(v));
      body += state;
    }
  }
  // Thunder's roadmap covers every path it holds; Lightning's copy covers those it covered.
  const og::SPARSdb* spars = thunder_ ? thunder_->getSPARSdb().get() : nullptr;
  const std::string roadmap = spars ? detail::roadmap_records(*spars) : roadmap_;
  const std::size_t vertices = spars ? detail::roadmap_vertices(*spars) : roadmap_vertices_;
  const std::size_t edges = spars ? spars->getNumEdges() : roadmap_edges_;
  const std::size_t covered = spars ? (vertices > 0 ? paths_.size() : 0) : roadmap_paths_;
  std::ostringstream out;
  out << kMagic << ' ' << kVersion << "\nspace " << space_name_ << "\nstate-bytes " << space->getSerializationLength() << "\npattern "
      << std::hex << fingerprint_ << std::dec << "\npaths " << paths_.size() << "\nbytes " << body.size() << "\ncrc " << std::hex
      << crc32(body) << std::dec << "\nroadmap-paths " << covered << "\nroadmap-vertices " << vertices << "\nroadmap-edges " << edges
      << "\nroadmap-bytes " << roadmap.size() << "\nroadmap-crc " << std::hex << crc32(roadmap) << std::dec << '\n'
      << body << roadmap;
  return out.str();
}

void ExperienceDatabase::add(const og::PathGeometric& path) {
  if (path.getStateCount() < 2) return;
  paths_.push_back(path);
  og::PathGeometric copy(path);  // both databases may change it (Thunder interpolates it)
  double seconds = 0.0;
  if (thunder_)
    thunder_->addPath(copy, seconds);
  else
    lightning_->addPath(copy, seconds);
}

std::size_t ExperienceDatabase::paths() const { return paths_.size(); }

std::size_t ExperienceDatabase::edges() const { return thunder_ ? thunder_->getSPARSdb()->getNumEdges() : 0; }

std::size_t ExperienceDatabase::states() const {
  return thunder_ ? thunder_->getSPARSdb()->getNumVertices() : lightning_->getStatesCount();
}

ob::PlannerPtr ExperienceDatabase::recall_planner(const ob::SpaceInformationPtr& si, const ob::PlannerPtr& repair) const {
  if (thunder_) {
    auto recall = std::make_shared<og::ThunderRetrieveRepair>(si, thunder_);
    recall->setRepairPlanner(repair);
    return recall;
  }
  auto recall = std::make_shared<og::LightningRetrieveRepair>(si, lightning_);
  recall->setRepairPlanner(repair);
  return recall;
}

ExperiencePlanner::ExperiencePlanner(const ob::SpaceInformationPtr& si, const ExperienceDatabase* db, ob::PlannerPtr scratch,
                                     ob::PlannerPtr repair, double recall_time)
    : ob::Planner(si, "experience"), db_(db), scratch_(std::move(scratch)), recall_time_(recall_time) {
  if (!db_ || !scratch_ || !repair) throw std::invalid_argument("ExperiencePlanner: the database and both planners are required");
  if (!(recall_time_ > 0.0)) throw std::invalid_argument("ExperiencePlanner: the recall time must be positive");
  setName(scratch_->getName() + (db_->framework() == ExperienceFramework::Thunder ? "+Thunder" : "+Lightning"));
  recall_ = db_->recall_planner(si, repair);
  specs_ = scratch_->getSpecs();
  // The scratch planner's progress ("best cost", …) as this planner's, for what reads it: the
  // Carpenter fallback's share, bench logs, plan's cost history.
  for (const auto& [name, property] : scratch_->getPlannerProgressProperties()) addPlannerProgressProperty(name, property);
}

// OMPL 1.5.2's ThunderRetrieveRepair takes the query's ends from PlannerInputStates without
// looking: an end outside the space's bounds or invalid comes back null, and SPARSdb cloned it (a
// crash on a Resch goal outside the driving space's bounds). No recall can join such an end, so
// none is tried (the scratch planner reports it as before).
bool ExperiencePlanner::ends_valid() const {
  const auto ok = [this](const ob::State* s) { return si_->satisfiesBounds(s) && si_->isValid(s); };
  if (pdef_->getStartStateCount() == 0) return false;
  for (unsigned int i = 0; i < pdef_->getStartStateCount(); ++i)
    if (!ok(pdef_->getStartState(i))) return false;
  const auto* goal = dynamic_cast<const ob::GoalState*>(pdef_->getGoal().get());
  return goal == nullptr || ok(goal->getState());
}

void ExperiencePlanner::setup() {
  ob::Planner::setup();
  for (const auto& p : {scratch_, recall_}) {
    p->setProblemDefinition(pdef_);
    if (!p->isSetup()) p->setup();
  }
}

void ExperiencePlanner::clear() {
  ob::Planner::clear();
  scratch_->clear();
  recall_->clear();
  recalled_ = false;
  recall_seconds_ = 0.0;
}

ob::PlannerStatus ExperiencePlanner::solve(const ob::PlannerTerminationCondition& ptc) {
  recalled_ = false;
  recall_seconds_ = 0.0;
  if (db_->paths() > 0 && ends_valid()) {
    const auto t0 = std::chrono::steady_clock::now();
    const ob::PlannerStatus status =
        recall_->solve(ob::plannerOrTerminationCondition(ptc, ob::timedPlannerTerminationCondition(recall_time_)));
    recall_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (status == ob::PlannerStatus::EXACT_SOLUTION) {
      recalled_ = true;
      return status;
    }
    if (ptc()) return ob::PlannerStatus::TIMEOUT;
  }
  return scratch_->solve(ptc);
}

}  // namespace foldkit::planners
