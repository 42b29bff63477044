// Planning from experience (issue 38, item 4): the database file round-trips its paths, refuses
// what is not its own with the reason, and a stored path is recalled and repaired for a new query.
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <boost/crc.hpp>
#include <gtest/gtest.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/planners/experience.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "folded_state.hpp"
#include "spec_helpers.hpp"

namespace {

using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::ExperienceDatabase;
using foldkit::planners::ExperienceError;
using foldkit::planners::ExperiencePlanner;
using foldkit::planners::PlanOptions;
using foldkit::planners::PlanSetup;
namespace og = ompl::geometric;
namespace ob = ompl::base;
namespace gen = foldkit::geometry::generators;

CreasePattern miura(int n) { return foldkit::geometry::build_or_throw(gen::miura(n, n)); }

struct Solved {
  bool ok = false;
  bool recalled = false;
  std::vector<FoldState> states;  // the OMPL path's states, read as fold states
};

// One query on `setup`: the experience planner (recall from `db`, then RRTConnect) or, without a
// database, RRTConnect alone. Adds the path to `db` when one is given.
Solved solve(const PlanSetup& setup, ExperienceDatabase* db, unsigned seed, og::PathGeometric* out = nullptr) {
  ompl::RNG::setSeed(seed);
  og::SimpleSetup ss(setup.si);
  ob::PlannerPtr scratch = foldkit::planners::make_planner("RRTConnect", setup.si);
  std::shared_ptr<ExperiencePlanner> experience;
  if (db) {
    experience =
        std::make_shared<ExperiencePlanner>(setup.si, db, scratch, foldkit::planners::make_planner("RRTConnect", setup.si), 1.0);
    ss.setPlanner(experience);
  } else {
    ss.setPlanner(scratch);
  }
  foldkit::planners::set_start_and_goal(setup, ss, setup.goal);
  ss.setup();
  Solved s;
  s.ok = foldkit::planners::run_planner(setup, ss, 10.0) == ob::PlannerStatus::EXACT_SOLUTION;
  if (!s.ok) return s;
  s.recalled = experience && experience->recalled();
  og::PathGeometric& path = ss.getSolutionPath();
  for (const ob::State* st : path.getStates()) {
    FoldState f;
    EXPECT_TRUE(setup.reader(st, f));
    s.states.push_back(f);
  }
  if (db) db->add(path);
  if (out) *out = path;
  return s;
}

PlanSetup setup_for(const CreasePattern& p, double fraction) {
  PlanOptions o;
  o.quiet = true;
  return foldkit::planners::make_plan_setup(p, foldkit::test::folded_along_assignment(p, fraction), o);
}

// A recalled or repaired path: valid by the space's own checks, from the setup's start to its goal.
void expect_valid_path(const PlanSetup& setup, const og::PathGeometric& path, const Solved& solved) {
  for (unsigned int i = 0; i + 1 < static_cast<unsigned int>(path.getStateCount()); ++i)
    EXPECT_TRUE(setup.si->checkMotion(path.getState(i), path.getState(i + 1)));
  EXPECT_LT((solved.states.front().angles - setup.prefix.back().angles).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((solved.states.back().angles - setup.goal.angles).cwiseAbs().maxCoeff(), 1e-6);
}

ExperienceDatabase database_for(const PlanSetup& setup) {
  return ExperienceDatabase(setup.si, setup.plan_space->name(), foldkit::planners::pattern_fingerprint(*setup.pattern));
}

std::string message_of(ExperienceDatabase& db, const std::string& bytes) {
  try {
    db.read(bytes, "x.db");
  } catch (const ExperienceError& e) {
    return e.what();
  }
  return {};
}

TEST(Experience, DatabaseBytesRoundTripEveryState) {
  const CreasePattern p = miura(4);
  const PlanSetup setup = setup_for(p, 0.8);
  ExperienceDatabase db(setup.si, setup.plan_space->name(), foldkit::planners::pattern_fingerprint(p));
  const Solved first = solve(setup, &db, 1);
  ASSERT_TRUE(first.ok);
  ASSERT_EQ(db.paths(), 1u);
  const std::string bytes = db.bytes();
  EXPECT_EQ(bytes.rfind("foldkit-experience 1\nspace driving\n", 0), 0u) << bytes.substr(0, 80);

  ExperienceDatabase again(setup.si, setup.plan_space->name(), foldkit::planners::pattern_fingerprint(p));
  again.read(bytes, "x.db");
  ASSERT_EQ(again.paths(), 1u);
  EXPECT_EQ(again.states(), first.states.size());
  EXPECT_EQ(again.bytes(), bytes);  // the same records, the same header
  again.read("", "new.db");         // a new database: nothing added
  EXPECT_EQ(again.paths(), 1u);
}

TEST(Experience, ForeignOrDamagedDatabasesAreRefusedWithTheirReason) {
  const CreasePattern p = miura(4), q = miura(6);
  const PlanSetup setup = setup_for(p, 0.8);
  ExperienceDatabase db = database_for(setup);
  ASSERT_TRUE(solve(setup, &db, 1).ok);
  const std::string good = db.bytes();

  ExperienceDatabase fresh = database_for(setup);
  EXPECT_NE(message_of(fresh, "<CMML></CMML>").find("x.db: not a foldkit experience database"), std::string::npos);
  std::string version = good;
  version.replace(version.find(" 1\n"), 3, " 7\n");
  EXPECT_NE(message_of(fresh, version).find("version 7"), std::string::npos);
  EXPECT_NE(message_of(fresh, good.substr(0, good.size() - 5)).find("damaged"), std::string::npos);
  std::string flipped = good;
  flipped[flipped.size() - 9] = static_cast<char>(flipped[flipped.size() - 9] ^ 0x40);
  EXPECT_NE(message_of(fresh, flipped).find("CRC-32"), std::string::npos);
  EXPECT_EQ(fresh.paths(), 0u);  // nothing of a refused file is kept

  // Another pattern: the Miura 6x6's setup reads states of another size; the same size with
  // another fingerprint is refused by the fingerprint.
  const PlanSetup other = setup_for(q, 0.8);
  ExperienceDatabase theirs = database_for(other);
  EXPECT_NE(message_of(theirs, good).find("another pattern"), std::string::npos);
  ExperienceDatabase same_size(setup.si, setup.plan_space->name(), 12345);
  EXPECT_NE(message_of(same_size, good).find("another pattern (its fingerprint"), std::string::npos);
  ExperienceDatabase other_space(setup.si, "projected", foldkit::planners::pattern_fingerprint(p));
  EXPECT_NE(message_of(other_space, good).find("written for the driving space"), std::string::npos);
}

// `good` with its records replaced by `body`, the header's byte count and CRC-32 made to match:
// a file made by hand, which only the records' own checks can refuse.
std::string with_records(const std::string& good, const std::string& body) {
  const std::size_t paths_at = good.find("\nbytes ");
  boost::crc_32_type crc;
  crc.process_bytes(body.data(), body.size());
  std::ostringstream out;
  out << good.substr(0, paths_at) << "\nbytes " << body.size() << "\ncrc " << std::hex << crc.checksum() << '\n' << body;
  return out.str();
}

TEST(Experience, HandMadeRecordsWithAValidCrcAreCheckedStateByState) {
  const CreasePattern p = miura(4);
  const PlanSetup setup = setup_for(p, 0.8);
  ExperienceDatabase db = database_for(setup);
  ASSERT_TRUE(solve(setup, &db, 1).ok);
  const std::string good = db.bytes();
  const std::string body = good.substr(good.find("\ncrc ") + 1);
  const std::string records = body.substr(body.find('\n') + 1);
  const std::size_t state_bytes = setup.space->getSerializationLength();
  ASSERT_EQ((records.size() - 8) % state_bytes, 0u);
  ExperienceDatabase fresh = database_for(setup);
  ASSERT_EQ(message_of(fresh, with_records(good, records)), "");  // the oracle: rebuilt, it reads
  std::string nan = records;
  const double not_a_number = std::nan("");
  std::memcpy(&nan[8 + state_bytes], &not_a_number, sizeof not_a_number);  // state 2's first angle
  ExperienceDatabase a = database_for(setup);
  EXPECT_NE(message_of(a, with_records(good, nan)).find("path 1, state 2 is not a closed state"), std::string::npos);
  std::string huge = records;
  const std::uint64_t many = std::uint64_t(1) << 60;
  std::memcpy(&huge[0], &many, sizeof many);
  ExperienceDatabase b = database_for(setup);
  EXPECT_NE(message_of(b, with_records(good, huge)).find("path 1 holds more states than its bytes"), std::string::npos);
  ExperienceDatabase c = database_for(setup);
  EXPECT_NE(message_of(c, with_records(good, records.substr(0, 5))).find("path 1 is cut short"), std::string::npos);
  ExperienceDatabase d = database_for(setup);
  EXPECT_NE(message_of(d, with_records(good, records + "x")).find("bytes after the last"), std::string::npos);
  EXPECT_EQ(a.paths() + b.paths() + c.paths() + d.paths(), 0u);
}

// The stored path of one query is recalled for a nearby one and repaired into a valid path to
// the new goal; without experience the same query is solved from scratch.
TEST(Experience, StoredPathIsRecalledForANewGoal) {
  const CreasePattern p = miura(4);
  const PlanSetup to_08 = setup_for(p, 0.8), to_07 = setup_for(p, 0.7);
  ExperienceDatabase db = database_for(to_08);
  const Solved first = solve(to_08, &db, 1);
  ASSERT_TRUE(first.ok);
  EXPECT_FALSE(first.recalled);  // an empty database: from scratch

  ExperienceDatabase loaded = database_for(to_07);
  loaded.read(db.bytes(), "x.db");
  og::PathGeometric path(to_07.si);
  const Solved second = solve(to_07, &loaded, 2, &path);
  ASSERT_TRUE(second.ok);
  EXPECT_TRUE(second.recalled);
  expect_valid_path(to_07, path, second);
  EXPECT_EQ(loaded.paths(), 2u);  // the repaired path is kept too
}

// Thunder (OMPL's SPARSdb roadmap of the stored paths) reads the file Lightning wrote, recalls
// through its roadmap, and writes the paths back for either framework.
TEST(Experience, ThunderRecallsThroughARoadmapOfTheSameFile) {
  const CreasePattern p = miura(4);
  const PlanSetup to_08 = setup_for(p, 0.8), to_07 = setup_for(p, 0.7);
  ExperienceDatabase lightning = database_for(to_08);
  ASSERT_TRUE(solve(to_08, &lightning, 1).ok);

  ExperienceDatabase thunder(to_07.si, to_07.plan_space->name(), foldkit::planners::pattern_fingerprint(p),
                             foldkit::planners::ExperienceFramework::Thunder);
  thunder.read(lightning.bytes(), "x.db");
  EXPECT_EQ(thunder.paths(), 1u);
  EXPECT_GE(thunder.states(), 2u);  // the roadmap's vertices: at least the path's ends
  og::PathGeometric path(to_07.si);
  const Solved second = solve(to_07, &thunder, 2, &path);
  ASSERT_TRUE(second.ok);
  EXPECT_TRUE(second.recalled);
  expect_valid_path(to_07, path, second);
  ExperienceDatabase back = database_for(to_07);
  back.read(thunder.bytes(), "x.db");
  EXPECT_EQ(back.paths(), 2u);  // the same file, the recalled path added

  EXPECT_EQ(foldkit::planners::parse_experience_framework("Thunder"), foldkit::planners::ExperienceFramework::Thunder);
  EXPECT_EQ(foldkit::planners::experience_framework_names(), (std::vector<std::string>{"lightning", "thunder"}));
  EXPECT_THROW(foldkit::planners::parse_experience_framework("storm"), std::invalid_argument);
}

TEST(Experience, SameSeedSamePath) {
  const CreasePattern p = miura(4);
  const PlanSetup setup = setup_for(p, 0.7);
  std::vector<std::vector<FoldState>> runs;
  for (int run = 0; run < 2; ++run) {
    ExperienceDatabase db = database_for(setup);
    const PlanSetup to_08 = setup_for(p, 0.8);
    ExperienceDatabase first = database_for(to_08);
    ASSERT_TRUE(solve(to_08, &first, 1).ok);
    db.read(first.bytes(), "x.db");
    const Solved s = solve(setup, &db, 5);
    ASSERT_TRUE(s.ok);
    runs.push_back(s.states);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  for (std::size_t i = 0; i < runs[0].size(); ++i) EXPECT_EQ(runs[0][i].angles, runs[1][i].angles);
}

}  // namespace
