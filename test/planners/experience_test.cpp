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
  EXPECT_EQ(bytes.rfind("foldkit-experience 2\nspace driving\n", 0), 0u) << bytes.substr(0, 80);
  EXPECT_NE(bytes.find("\nroadmap-paths 0\nroadmap-vertices 0\nroadmap-edges 0\nroadmap-bytes 0\n"), std::string::npos);  // Lightning's: none

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
  version.replace(version.find(" 2\n"), 3, " 7\n");
  EXPECT_NE(message_of(fresh, version).find("version 7, this foldkit reads versions 1 and 2"), std::string::npos);
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

std::uint32_t crc_of(const std::string& s) {
  boost::crc_32_type crc;
  crc.process_bytes(s.data(), s.size());
  return crc.checksum();
}

// The number after "\nKEY " in a database's header.
std::size_t header_value(const std::string& bytes, const std::string& key) {
  const std::size_t at = bytes.find("\n" + key + " ");
  EXPECT_NE(at, std::string::npos) << key;
  return at == std::string::npos ? 0 : std::stoull(bytes.substr(at + key.size() + 2));
}

// A database's records after its header: the paths', then the roadmap's.
std::string records_of(const std::string& bytes) {
  const std::size_t line = bytes.find('\n', bytes.find("\nroadmap-crc ") + 1);
  return bytes.substr(line + 1);
}

// `good` with its path records replaced by `body` and its roadmap's by `roadmap` (counts as
// `vertices`, `edges`, `paths`), the header's byte counts and CRC-32s made to match: a file made by
// hand, which only the records' own checks can refuse.
std::string with_records(const std::string& good, const std::string& body, const std::string& roadmap = "", std::size_t vertices = 0,
                         std::size_t edges = 0, std::size_t paths = 0) {
  std::ostringstream out;
  out << good.substr(0, good.find("\nbytes ")) << "\nbytes " << body.size() << "\ncrc " << std::hex << crc_of(body) << std::dec
      << "\nroadmap-paths " << paths << "\nroadmap-vertices " << vertices << "\nroadmap-edges " << edges << "\nroadmap-bytes "
      << roadmap.size() << "\nroadmap-crc " << std::hex << crc_of(roadmap) << '\n'
      << body << roadmap;
  return out.str();
}

// `bytes` as foldkit wrote it before the roadmap section (version 1): its paths only.
std::string version_1(const std::string& bytes) {
  const std::string records = records_of(bytes).substr(0, header_value(bytes, "bytes"));
  std::string header = bytes.substr(0, bytes.find("\nroadmap-paths ") + 1);
  header.replace(0, header.find('\n'), "foldkit-experience 1");
  return header + records;
}

TEST(Experience, HandMadeRecordsWithAValidCrcAreCheckedStateByState) {
  const CreasePattern p = miura(4);
  const PlanSetup setup = setup_for(p, 0.8);
  ExperienceDatabase db = database_for(setup);
  ASSERT_TRUE(solve(setup, &db, 1).ok);
  const std::string good = db.bytes();
  const std::string records = records_of(good);
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

ExperienceDatabase thunder_for(const PlanSetup& setup) {
  return ExperienceDatabase(setup.si, setup.plan_space->name(), foldkit::planners::pattern_fingerprint(*setup.pattern),
                            foldkit::planners::ExperienceFramework::Thunder);
}

// Lightning's file, Thunder's file (with its roadmap) and Thunder's read back: the same seed
// gives the same plan from the same bytes, whichever way the roadmap came about.
TEST(Experience, SameSeedSamePath) {
  const CreasePattern p = miura(4);
  const PlanSetup setup = setup_for(p, 0.7);
  for (const auto framework : {foldkit::planners::ExperienceFramework::Lightning, foldkit::planners::ExperienceFramework::Thunder}) {
    std::vector<std::vector<FoldState>> runs;
    for (int run = 0; run < 2; ++run) {
      ExperienceDatabase db(setup.si, setup.plan_space->name(), foldkit::planners::pattern_fingerprint(p), framework);
      const PlanSetup to_08 = setup_for(p, 0.8);
      ExperienceDatabase first(to_08.si, to_08.plan_space->name(), foldkit::planners::pattern_fingerprint(p), framework);
      ASSERT_TRUE(solve(to_08, &first, 1).ok);
      db.read(first.bytes(), "x.db");
      const bool thunder = framework == foldkit::planners::ExperienceFramework::Thunder;
      EXPECT_EQ(db.paths_from_roadmap(), thunder ? 1u : 0u);
      const Solved s = solve(setup, &db, 5);
      ASSERT_TRUE(s.ok);
      runs.push_back(s.states);
    }
    ASSERT_EQ(runs[0].size(), runs[1].size());
    for (std::size_t i = 0; i < runs[0].size(); ++i) EXPECT_EQ(runs[0][i].angles, runs[1][i].angles);
  }
}

// Thunder writes its SPARSdb roadmap into the file and reads it back as it was (the same
// vertices, edges and interface data: the same bytes), instead of adding the paths to a new
// roadmap; a file without the section (version 1) rebuilds the same roadmap from its paths.
TEST(Experience, ThunderWritesItsRoadmapAndReadsItBackAsItWas) {
  const CreasePattern p = miura(4);
  const PlanSetup to_08 = setup_for(p, 0.8), to_07 = setup_for(p, 0.7), to_06 = setup_for(p, 0.6);
  ExperienceDatabase built = thunder_for(to_08);
  ASSERT_TRUE(solve(to_08, &built, 1).ok);
  const std::string first = built.bytes();
  EXPECT_EQ(header_value(first, "roadmap-paths"), 1u);
  EXPECT_EQ(header_value(first, "roadmap-vertices") + 1, built.states());  // SPARSdb counts its query vertex too
  EXPECT_EQ(header_value(first, "roadmap-edges"), built.edges());
  ASSERT_GE(built.edges(), 1u);

  ExperienceDatabase loaded = thunder_for(to_07);
  loaded.read(first, "x.db");
  EXPECT_EQ(loaded.paths_from_roadmap(), 1u);
  EXPECT_EQ(loaded.states(), built.states());
  EXPECT_EQ(loaded.edges(), built.edges());
  EXPECT_EQ(loaded.bytes(), first);

  ExperienceDatabase rebuilt = thunder_for(to_07);
  rebuilt.read(version_1(first), "old.db");
  EXPECT_EQ(rebuilt.paths_from_roadmap(), 0u);
  EXPECT_EQ(rebuilt.paths(), 1u);
  EXPECT_EQ(rebuilt.states(), built.states());
  EXPECT_EQ(rebuilt.edges(), built.edges());
  EXPECT_EQ(rebuilt.bytes(), first);  // rewritten with the section

  og::PathGeometric path(to_07.si);
  const Solved second = solve(to_07, &loaded, 2, &path);
  ASSERT_TRUE(second.ok);
  EXPECT_TRUE(second.recalled);
  expect_valid_path(to_07, path, second);
  const std::string two = loaded.bytes();
  EXPECT_EQ(header_value(two, "roadmap-paths"), 2u);
  ExperienceDatabase third = thunder_for(to_06);
  third.read(two, "x.db");
  EXPECT_EQ(third.paths_from_roadmap(), 2u);
  EXPECT_EQ(third.edges(), loaded.edges());
  og::PathGeometric path6(to_06.si);
  const Solved sixth = solve(to_06, &third, 3, &path6);
  ASSERT_TRUE(sixth.ok);
  EXPECT_TRUE(sixth.recalled);
  expect_valid_path(to_06, path6, sixth);

  // Lightning reads the old file as before and the new one past its roadmap.
  ExperienceDatabase lightning = database_for(to_07);
  lightning.read(version_1(first), "old.db");
  EXPECT_EQ(lightning.paths(), 1u);
  ExperienceDatabase lightning2 = database_for(to_07);
  lightning2.read(two, "x.db");
  EXPECT_EQ(lightning2.paths(), 2u);
}

// A damaged roadmap section is refused with the reason, whether its CRC-32 tells or only its
// records' own checks can (a file made by hand); Lightning carries a section it does not read
// back unchanged, and a later path after it is added by Thunder on the roadmap read.
TEST(Experience, DamagedRoadmapIsRefusedWithItsReason) {
  const CreasePattern p = miura(4);
  const PlanSetup setup = setup_for(p, 0.8), to_07 = setup_for(p, 0.7);
  ExperienceDatabase built = thunder_for(setup);
  ASSERT_TRUE(solve(setup, &built, 1).ok);
  const std::string good = built.bytes();
  const std::size_t path_bytes = header_value(good, "bytes"), vertices = header_value(good, "roadmap-vertices"),
                    edges = header_value(good, "roadmap-edges");
  const std::string paths = records_of(good).substr(0, path_bytes), roadmap = records_of(good).substr(path_bytes);
  const std::size_t state_bytes = setup.space->getSerializationLength();
  ASSERT_GE(roadmap.size(), vertices * (8 + state_bytes) + edges * 16);
  const auto refusal = [&](const std::string& bytes) {
    ExperienceDatabase db = thunder_for(setup);
    const std::string why = message_of(db, bytes);
    EXPECT_EQ(db.paths() + db.states() + db.edges(), 0u) << why;  // nothing of a refused file is kept
    return why;
  };
  ExperienceDatabase oracle = thunder_for(setup);  // rebuilt by with_records unchanged, it reads
  ASSERT_EQ(message_of(oracle, with_records(good, paths, roadmap, vertices, edges, 1)), "");
  EXPECT_EQ(oracle.paths_from_roadmap(), 1u);

  std::string flipped = good;
  flipped.back() = static_cast<char>(flipped.back() ^ 0x20);
  EXPECT_EQ(refusal(flipped), "x.db: damaged: the roadmap's records do not match their CRC-32");
  EXPECT_EQ(refusal(with_records(good, paths, roadmap, vertices, edges, 5)), "x.db: damaged: a roadmap of 5 paths in a file of 1");
  std::string type = roadmap;
  type[0] = 9;
  EXPECT_EQ(refusal(with_records(good, paths, type, vertices, edges, 1)), "x.db: damaged roadmap: vertex 1 has no guard type (9)");
  std::string nan = roadmap;
  const double not_a_number = std::nan("");
  std::memcpy(&nan[8], &not_a_number, sizeof not_a_number);  // vertex 1's first angle
  EXPECT_EQ(refusal(with_records(good, paths, nan, vertices, edges, 1)),
            "x.db: damaged roadmap: vertex 1: its state is not a closed state within the bounds");
  std::string edge = roadmap;
  const std::uint64_t far = vertices + 5;
  std::memcpy(&edge[vertices * (8 + state_bytes)], &far, sizeof far);  // edge 1's first vertex
  EXPECT_NE(refusal(with_records(good, paths, edge, vertices, edges, 1)).find("x.db: damaged roadmap: edge 1 joins vertices " + std::to_string(far)),
            std::string::npos);
  EXPECT_EQ(refusal(with_records(good, paths, roadmap.substr(0, 20), vertices, edges, 1)),
            "x.db: damaged roadmap: vertex 1: its state is cut short");
  EXPECT_EQ(refusal(with_records(good, paths, roadmap + "x", vertices, edges, 1)), "x.db: damaged roadmap: bytes after its last record");
  // Byte counts whose sum wraps around to the records' size: refused by the counts, not read.
  std::string wraps = good;
  const std::string counts = "\nbytes " + std::to_string(path_bytes) + "\n";
  wraps.replace(wraps.find(counts), counts.size(), "\nbytes 18446744073709551615\n");
  const std::string rb = "\nroadmap-bytes " + std::to_string(roadmap.size()) + "\n";
  wraps.replace(wraps.find(rb), rb.size(), "\nroadmap-bytes " + std::to_string(path_bytes + roadmap.size() + 1) + "\n");
  EXPECT_NE(refusal(wraps).find("bytes of records where the header says 18446744073709551615 + "), std::string::npos);

  // Lightning does not read the roadmap: it keeps the section as it is, and after its path is
  // added Thunder reads the roadmap and adds only that path to it.
  ExperienceDatabase lightning = database_for(to_07);
  lightning.read(with_records(good, paths, edge, vertices, edges, 1), "x.db");
  ASSERT_TRUE(solve(to_07, &lightning, 2).ok);
  const std::string carried = lightning.bytes();
  EXPECT_EQ(records_of(carried).substr(header_value(carried, "bytes")), edge);
  EXPECT_EQ(header_value(carried, "roadmap-paths"), 1u);
  ExperienceDatabase thunder = thunder_for(to_07);
  const std::string carried_paths = records_of(carried).substr(0, header_value(carried, "bytes"));
  thunder.read(with_records(carried, carried_paths, roadmap, vertices, edges, 1), "x.db");  // the undamaged roadmap
  EXPECT_EQ(thunder.paths(), 2u);
  EXPECT_EQ(thunder.paths_from_roadmap(), 1u);
  EXPECT_GE(thunder.edges(), built.edges());
}

}  // namespace
