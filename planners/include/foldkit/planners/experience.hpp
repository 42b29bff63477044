#pragma once
/// @file
/// Planning from experience (issue 38, item 4): OMPL's Lightning and Thunder frameworks on
/// foldkit's spaces. A database keeps the paths of earlier plans on one pattern. Lightning recalls
/// the stored path whose ends are nearest to the query's own (OMPL's LightningDB, by the space's
/// distance, either direction) and repairs the stretches that are no longer valid with the
/// planner (og::LightningRetrieveRepair); Thunder adds every stored path to a sparse roadmap
/// (OMPL's SPARSdb inside a ThunderDB) and searches it from the query's start to its goal
/// (og::ThunderRetrieveRepair). Either plans from scratch only when recall fails. Unlike
/// ompl::tools::Lightning and ompl::tools::Thunder, recall and scratch run one after the other,
/// not racing in two threads, so that a plan stays a function of its seed.
///
/// The file is foldkit's own: a text header that names the space, the size of its states, a
/// fingerprint of the pattern and a CRC-32 of the records, then per path its number of states and
/// the states as the space serializes them; a database of another pattern or space, a damaged one,
/// or states that are not finite and within the space's bounds, are refused with the reason
/// (docs/PLANNING.md, "Planning from experience"). Both frameworks read the same file: it holds
/// paths, and (version 2) Thunder's roadmap as Thunder last wrote it, with the number of paths it
/// covers. Thunder reads that roadmap and adds to it only the paths written after it (all of them
/// when there is none: a version 1 file, or one only Lightning has written); Lightning checks the
/// section and writes it back unchanged. Rebuilding the roadmap checks every stored path's
/// motions again (3.4 s per `foldkit plan` at 37 paths on the Resch pattern); reading it does not.
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>

#include "foldkit/geometry/crease_pattern.hpp"

namespace ompl::tools {
class LightningDB;
class ThunderDB;
}  // namespace ompl::tools
namespace ompl::geometric {
class SPARSdb;
}  // namespace ompl::geometric

namespace foldkit::planners {

/// Which of OMPL's experience frameworks recalls: Lightning (stored paths, the nearest repaired)
/// or Thunder (a sparse roadmap of the stored paths, searched).
enum class ExperienceFramework { Lightning, Thunder };
/// The frameworks' names, in order: "lightning", "thunder" (--experience-framework, Python's
/// experience_framework=).
std::vector<std::string> experience_framework_names();
/// The framework named `name` (case-insensitive).
/// @throws std::invalid_argument naming the known frameworks for any other name
ExperienceFramework parse_experience_framework(const std::string& name);
/// The framework's name: "lightning" or "thunder".
std::string to_string(ExperienceFramework framework);

/// A database file that cannot be used: unreadable, damaged, or made for another pattern or
/// space. what() is "FILE: reason".
class ExperienceError : public std::runtime_error {
 public:
  /// @param name    the database file's name
  /// @param reason  what is wrong with it
  ExperienceError(const std::string& name, const std::string& reason) : std::runtime_error(name + ": " + reason), reason_(reason) {}
  /// What is wrong, without the file's name.
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

/// A fingerprint of a pattern's geometry and creases (FNV-1a over the vertex coordinates, the
/// joints' actors and the actors' vertex lists): equal for the same pattern read from any file
/// that holds the same numbers, different (up to hash collisions) otherwise.
std::uint64_t pattern_fingerprint(const geometry::CreasePattern& pattern);

/// The paths of earlier plans on one pattern in one space, loaded from and saved to foldkit's
/// database file, and held for recall by the framework's own database: OMPL's LightningDB, or a
/// ThunderDB whose SPARSdb roadmap every path is added to (Thunder's sparse-roadmap settings:
/// stretch factor 1.2, visibility range 0.05 of the space's extent), read back from the file
/// where it holds one. Not thread-safe.
class ExperienceDatabase {
 public:
  /// An empty database for the states of `si`'s space.
  /// @param si           the space information of the plan (its space serializes its states;
  ///                     Thunder's roadmap checks its motions with si's motion validator)
  /// @param space_name   the space's name (PlanSpace::name()), kept in the file
  /// @param fingerprint  pattern_fingerprint() of the pattern, kept in the file
  /// @param framework    which framework recalls
  ExperienceDatabase(const ompl::base::SpaceInformationPtr& si, std::string space_name, std::uint64_t fingerprint,
                     ExperienceFramework framework = ExperienceFramework::Lightning);
  ~ExperienceDatabase();
  ExperienceDatabase(const ExperienceDatabase&) = delete;
  ExperienceDatabase& operator=(const ExperienceDatabase&) = delete;

  /// Adds the paths of a database file's bytes (io::read_file's; the caller reads and writes the
  /// file, so that planners does no file I/O). Empty bytes add nothing: the first plan with a new
  /// database starts it. Thunder, into an empty database, reads the file's roadmap and adds only
  /// the paths it does not cover; Lightning keeps the roadmap's records to write them back.
  /// @param bytes  the file's content
  /// @param name   the file's name, for messages
  /// @throws ExperienceError ("NAME: reason") when the bytes are not a foldkit experience
  ///         database, are damaged (the CRCs, the lengths, a path of fewer than two states, a state
  ///         not finite or outside the space's bounds; for Thunder, a roadmap record that names no
  ///         guard type or vertex of it), or were written for another pattern or space; nothing of
  ///         refused bytes is kept
  void read(const std::string& bytes, const std::string& name);
  /// The database file's bytes: the header, then every path, then Thunder's roadmap (Lightning:
  /// the roadmap's records it read, unchanged; write them atomically: io::write_file_atomic).
  std::string bytes() const;
  /// Adds `path` (at least two states of the database's space); shorter paths are not kept.
  /// Thunder adds it to its roadmap too (SPARSdb::addPathToRoadmap: the path interpolated at the
  /// validity resolution, states kept where they add coverage, connectivity or a shorter way).
  void add(const ompl::geometric::PathGeometric& path);
  /// The number of paths kept.
  std::size_t paths() const;
  /// Lightning: the number of states over all paths; Thunder: the roadmap's vertices (SPARSdb's
  /// count, its query vertex included).
  std::size_t states() const;
  /// Thunder: the roadmap's edges; Lightning: 0.
  std::size_t edges() const;
  /// Thunder: how many of the paths the last read() took from the file's roadmap rather than
  /// adding them to the roadmap again (0 when the file had none); Lightning: 0.
  std::size_t paths_from_roadmap() const { return paths_from_roadmap_; }
  /// The framework that recalls.
  ExperienceFramework framework() const { return framework_; }
  /// The framework's recall planner on this database: og::LightningRetrieveRepair, or
  /// og::ThunderRetrieveRepair; `repair` re-plans what recall cannot use (OMPL 1.5.2's Thunder
  /// searches its roadmap lazily, checking each edge, and repairs nothing).
  ompl::base::PlannerPtr recall_planner(const ompl::base::SpaceInformationPtr& si, const ompl::base::PlannerPtr& repair) const;

 private:
  ompl::geometric::PathGeometric read_path(const char* data, std::size_t count, const std::string& which,
                                           const std::string& name) const;
  void read_roadmap_section(const std::string& records, std::size_t vertices, std::size_t edges, std::size_t paths,
                            const std::string& name);

  ompl::base::SpaceInformationPtr si_;
  std::string space_name_;
  std::uint64_t fingerprint_;
  ExperienceFramework framework_;
  std::vector<ompl::geometric::PathGeometric> paths_;  // as added: what the file holds
  std::shared_ptr<ompl::tools::LightningDB> lightning_;  // Lightning only
  std::shared_ptr<ompl::tools::ThunderDB> thunder_;      // Thunder only
  // Lightning only: the roadmap section of the file read, written back as it was.
  std::string roadmap_;
  std::size_t roadmap_paths_ = 0, roadmap_vertices_ = 0, roadmap_edges_ = 0;
  std::size_t paths_from_roadmap_ = 0;  // Thunder only: see paths_from_roadmap()
};

namespace detail {
/// Deserializes one state of `space` from `data` (getSerializationLength() bytes) into `state`.
/// @return whether it is a state the database may hold: finite, closed, within the space's bounds
bool read_state(const ompl::base::StateSpace& space, const char* data, ompl::base::State* state);
/// An empty SPARSdb roadmap on `si` whose graph roadmap_records() writes and read_roadmap() reads
/// back (experience_roadmap.cpp; SPARSdb keeps its graph to its subclasses).
std::shared_ptr<ompl::geometric::SPARSdb> make_roadmap(const ompl::base::SpaceInformationPtr& si);
/// The roadmap's vertices that hold states (SPARSdb's count less its query vertex).
std::size_t roadmap_vertices(const ompl::geometric::SPARSdb& roadmap);
/// The roadmap's records: its vertices (guard type, state), its edges, its interface data.
/// @throws std::logic_error when `roadmap` was not made by make_roadmap
std::string roadmap_records(const ompl::geometric::SPARSdb& roadmap);
/// Reads roadmap_records() of `vertices` vertices and `edges` edges into `roadmap`, empty and made
/// by make_roadmap, checking every index and state.
/// @return why the records are not such a roadmap, or empty when they are (then read)
/// @throws std::logic_error when `roadmap` is not empty or not made by make_roadmap
std::string read_roadmap(ompl::geometric::SPARSdb& roadmap, const std::string& records, std::size_t vertices, std::size_t edges);
}  // namespace detail

/// The share of a plan's time limit that recall and repair may take before the planner from
/// scratch gets the rest. A repair that cannot succeed (the recalled path runs on another branch,
/// or through a state that now collides) would otherwise spend all of it: measured on the Resch
/// pattern, where RRTConnect alone solves a query in about 10 ms, a failed repair ran out a 10 s
/// limit and left nothing for the search from scratch.
constexpr double kRecallShare = 0.1;

/// Recall, then scratch: the database's recall planner (ExperienceDatabase::recall_planner, its
/// repairs by `repair`) for at most `recall_time` seconds, and, when the database is empty or
/// recall finds no exact path, the `scratch` planner with the time left. The planner's name is
/// the scratch planner's followed by "+Lightning" or "+Thunder"; recalled() says which of the
/// two solved.
class ExperiencePlanner : public ompl::base::Planner {
 public:
  /// @param si           the plan's space information (validity checker and motion validator set)
  /// @param db           the database to recall from (must outlive the planner)
  /// @param scratch      the planner from scratch, made for `si`
  /// @param repair       the planner that repairs recalled paths, made for `si`
  /// @param recall_time  seconds recall and repair may take at most (positive)
  /// @throws std::invalid_argument when db, scratch or repair is null, or recall_time is not positive
  ExperiencePlanner(const ompl::base::SpaceInformationPtr& si, const ExperienceDatabase* db, ompl::base::PlannerPtr scratch,
                    ompl::base::PlannerPtr repair, double recall_time);
  /// Recall (when the database holds paths), then scratch; see the class comment.
  /// @return EXACT_SOLUTION from either, else the scratch planner's status
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  /// Clears both planners and the outcome.
  void clear() override;
  /// Sets up both planners on this planner's problem definition.
  void setup() override;
  /// Whether the last solve() solved by recall (false: from scratch, or not at all).
  bool recalled() const { return recalled_; }
  /// Seconds the last solve() spent recalling and repairing.
  double recall_seconds() const { return recall_seconds_; }

 private:
  bool ends_valid() const;

  const ExperienceDatabase* db_;
  ompl::base::PlannerPtr scratch_, recall_;
  double recall_time_;
  bool recalled_ = false;
  double recall_seconds_ = 0.0;
};

}  // namespace foldkit::planners
