#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "test_paths.hpp"

namespace foldkit::io {
namespace {

using geometry::Assignment;
using geometry::CreasePattern;
using geometry::Vec2;
using json = nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

double total_area(const CreasePattern& p) {
  double area = 0.0;
  for (const auto& actor : p.actors())
    for (const auto& t : actor.triangles) {
      const Vec2 a = p.vertices()[t.v[0]], b = p.vertices()[t.v[1]], c = p.vertices()[t.v[2]];
      const Vec2 u = b - a, w = c - a;
      area += 0.5 * (u.x() * w.y() - u.y() * w.x());
    }
  return area;
}

// Joint angles keyed by the joint's end coordinates, which survive export and re-import
// although joint IDs do not.
std::map<std::array<double, 4>, double> angles_by_segment(const CreasePattern& p, const geometry::FoldState& s) {
  std::map<std::array<double, 4>, double> out;
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    Vec2 a = p.vertices()[p.joints()[j].v[0]], b = p.vertices()[p.joints()[j].v[1]];
    if (std::make_pair(b.x(), b.y()) < std::make_pair(a.x(), a.y())) std::swap(a, b);
    out[{a.x(), a.y(), b.x(), b.y()}] = s.angles[static_cast<Eigen::Index>(j)];
  }
  return out;
}

const geometry::Joint& joint(const CreasePattern& p, int id) {
  const auto index = p.joint_index(id);
  EXPECT_TRUE(index.has_value()) << "no joint " << id;
  return p.joints().at(static_cast<std::size_t>(index.value_or(0)));
}

double angle(const FoldImport& fold, int joint_id) {
  EXPECT_TRUE(fold.state.has_value());
  const auto index = fold.pattern.joint_index(joint_id);
  EXPECT_TRUE(index.has_value()) << "no joint " << joint_id;
  return fold.state->angles[*index];
}

FoldImport fixture(const std::string& name) { return read_fold(test::fixture_path("fold/" + name)); }

void expect_same_model(const FoldImport& a, const FoldImport& b, const std::string& what) {
  EXPECT_EQ(a.pattern.actors().size(), b.pattern.actors().size()) << what;
  EXPECT_EQ(a.pattern.joints().size(), b.pattern.joints().size()) << what;
  EXPECT_EQ(a.pattern.vertices().size(), b.pattern.vertices().size()) << what;
  EXPECT_NEAR(total_area(a.pattern), total_area(b.pattern), 1e-12 * std::max(1.0, total_area(a.pattern))) << what;
  ASSERT_EQ(a.state.has_value(), b.state.has_value()) << what;
  if (a.state) {
    const auto sa = angles_by_segment(a.pattern, *a.state);
    const auto sb = angles_by_segment(b.pattern, *b.state);
    ASSERT_EQ(sa.size(), sb.size()) << what;
    for (auto i = sa.begin(), k = sb.begin(); i != sa.end(); ++i, ++k) {
      EXPECT_EQ(i->first, k->first) << what;
      EXPECT_NEAR(i->second, k->second, 1e-9) << what;
    }
  }
  ASSERT_EQ(a.frames.size(), b.frames.size()) << what;
}

TEST(FoldFixtures, EveryFileImportsExportsAndReimports) {
  if (!test::fixtures_available()) GTEST_SKIP() << "shared fixtures not present";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::fixture_path("fold"))) {
    if (entry.path().extension() != ".fold") continue;
    ++files;
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    FoldImport first = [&] {
      try {
        return read_fold(path);
      } catch (const ParseError& e) {
        ADD_FAILURE() << e.what();
        throw;
      }
    }();
    EXPECT_GT(first.pattern.actors().size(), 0U);
    EXPECT_GT(total_area(first.pattern), 0.0);
    if (first.state) {
      EXPECT_TRUE(first.state->angles.allFinite());
    }

    const std::string text = write_fold(first.pattern, FoldExport{first.state, first.frames, {}});
    const FoldImport second = parse_fold(text, path + " (exported)");
    expect_same_model(first, second, path);
    // Exporting the re-import reproduces the export exactly.
    EXPECT_EQ(write_fold(second.pattern, FoldExport{second.state, second.frames, {}}), text);
  }
  EXPECT_GE(files, 13);
}

TEST(FoldFixtures, DiagonalCreasePatternIsOneValleyAt180) {
  if (!test::fixtures_available()) GTEST_SKIP();
  const FoldImport fold = fixture("edemaine_fold__diagonal-cp.fold");
  ASSERT_EQ(fold.pattern.actors().size(), 2U);
  ASSERT_EQ(fold.pattern.joints().size(), 1U);
  // Edge 4 ([3,1], "V", foldAngle +180: FOLD counts valleys positive) is joint 5.
  EXPECT_EQ(joint(fold.pattern, 5).assignment, Assignment::Valley);
  EXPECT_DOUBLE_EQ(angle(fold, 5), -kPi);  // ours: mountain positive
  EXPECT_NEAR(total_area(fold.pattern), 1.0, 1e-15);
  EXPECT_TRUE(fold.warnings.empty());

  const json out = json::parse(write_fold(fold.pattern, FoldExport{fold.state, {}, {}}));
  bool found = false;
  for (std::size_t e = 0; e < out["edges_vertices"].size(); ++e)
    if (out["edges_assignment"][e] == "V") {
      EXPECT_EQ(out["edges_foldAngle"][e].get<double>(), 180.0);
      found = true;
    }
  EXPECT_TRUE(found);
}

TEST(FoldFixtures, DiagonalFoldedFormUsesItsFlatUnfoldCoords) {
  if (!test::fixtures_available()) GTEST_SKIP();
  const FoldImport fold = fixture("edemaine_fold__diagonal-folded.fold");
  ASSERT_EQ(fold.pattern.actors().size(), 2U);
  ASSERT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_DOUBLE_EQ(angle(fold, 5), -kPi);
  EXPECT_NEAR(total_area(fold.pattern), 1.0, 1e-15);
}

TEST(FoldFixtures, FlatFoldedFormUnfoldsWithoutHelp) {
  if (!test::fixtures_available()) GTEST_SKIP();
  json doc = json::parse(read_file(test::fixture_path("fold/edemaine_fold__diagonal-folded.fold")));
  doc.erase("vertices_flatUnfoldCoords");
  FoldImport fold = parse_fold(doc.dump(1), "folded.fold");
  EXPECT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_NEAR(total_area(fold.pattern), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(angle(fold, 5), -kPi);
  // Without a fold angle the ±180° sign comes from the V assignment.
  doc.erase("edges_foldAngle");
  fold = parse_fold(doc.dump(1), "folded.fold");
  EXPECT_DOUBLE_EQ(angle(fold, 5), -kPi);
}

TEST(FoldFixtures, SquareTwistUnfoldsToASquare) {
  if (!test::fixtures_available()) GTEST_SKIP();
  const FoldImport fold = fixture("edemaine_fold__squaretwist.fold");
  EXPECT_EQ(fold.pattern.actors().size(), 9U);
  ASSERT_TRUE(fold.state.has_value());
  Eigen::AlignedBox2d box;
  for (const Vec2& v : fold.pattern.vertices()) box.extend(v);
  const Vec2 size = box.sizes();
  EXPECT_NEAR(size.x(), size.y(), 1e-4);
  EXPECT_NEAR(total_area(fold.pattern), size.x() * size.y(), 1e-4);  // the faces tile the square
  const json doc = json::parse(read_file(test::fixture_path("fold/edemaine_fold__squaretwist.fold")));
  std::size_t creases = 0;
  for (const auto& a : doc["edges_assignment"]) creases += a != "B";
  ASSERT_EQ(fold.pattern.joints().size(), creases);
  for (const auto& j : fold.pattern.joints()) {
    const double theta = fold.state->angles[*fold.pattern.joint_index(j.id)];
    EXPECT_GT(std::abs(theta), 0.05) << "joint " << j.id;
    // Thomas Hull's M/V labels agree with the dihedral signs (mountain positive).
    if (j.assignment == Assignment::Mountain) {
      EXPECT_GT(theta, 0.0) << "joint " << j.id;
    } else if (j.assignment == Assignment::Valley) {
      EXPECT_LT(theta, 0.0) << "joint " << j.id;
    }
  }
  EXPECT_TRUE(fold.warnings.empty()) << fold.warnings.front().message;
}

TEST(FoldFixtures, SimpleThreeFoldHasOneRightAngleValleyAndTwoFlatMountains) {
  if (!test::fixtures_available()) GTEST_SKIP();
  const FoldImport fold = fixture("edemaine_fold__simple.fold");
  ASSERT_EQ(fold.pattern.actors().size(), 4U);
  ASSERT_EQ(fold.pattern.joints().size(), 3U);
  EXPECT_NEAR(angle(fold, 1), -kPi / 2, 1e-12);  // edge 0, "V"
  EXPECT_NEAR(angle(fold, 2), kPi, 1e-12);       // edge 1, "M", folded flat
  EXPECT_NEAR(angle(fold, 3), kPi, 1e-12);       // edge 2, "M", folded flat
}

TEST(FoldFixtures, SingleVertexWithoutFacesGetsFourDerivedFaces) {
  if (!test::fixtures_available()) GTEST_SKIP();
  const FoldImport fold = fixture("FoldForge__single_vertex.fold");
  EXPECT_EQ(fold.pattern.actors().size(), 4U);
  ASSERT_EQ(fold.pattern.joints().size(), 4U);
  EXPECT_EQ(joint(fold.pattern, 1).assignment, Assignment::Mountain);
  EXPECT_EQ(joint(fold.pattern, 2).assignment, Assignment::Valley);
  EXPECT_EQ(joint(fold.pattern, 3).assignment, Assignment::Mountain);
  EXPECT_EQ(joint(fold.pattern, 4).assignment, Assignment::Mountain);
  EXPECT_NEAR(total_area(fold.pattern), std::sqrt(3.0), 1e-12);
  EXPECT_FALSE(fold.state.has_value());
}

TEST(FoldFixtures, BoxUnfolds) {
  if (!test::fixtures_available()) GTEST_SKIP();
  const FoldImport fold = fixture("edemaine_fold__box.fold");
  ASSERT_TRUE(fold.state.has_value());
  // Unfolding keeps every face's area: compare with the 3D faces.
  const json doc = json::parse(read_file(test::fixture_path("fold/edemaine_fold__box.fold")));
  double area3d = 0.0;
  for (const auto& face : doc["faces_vertices"]) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto& p = doc["vertices_coords"][face[i].get<std::size_t>()];
      const auto& q = doc["vertices_coords"][face[(i + 1) % face.size()].get<std::size_t>()];
      n += Eigen::Vector3d(p[0], p[1], p[2]).cross(Eigen::Vector3d(q[0], q[1], q[2]));
    }
    area3d += 0.5 * n.norm();
  }
  EXPECT_NEAR(total_area(fold.pattern), area3d, 1e-9);
  bool bent = false;
  for (Eigen::Index j = 0; j < fold.state->angles.size(); ++j) bent = bent || std::abs(fold.state->angles[j]) > 0.1;
  EXPECT_TRUE(bent);
}

TEST(FoldFixtures, OrigamiSimulatorFilesAreFlatWithTargetAngles) {
  if (!test::fixtures_available()) GTEST_SKIP();
  for (const char* name : {"osbo_rigid-origami__birdBase.fold", "osbo_rigid-origami__flappingBird.fold",
                           "osbo_rigid-origami__waterbombBase.fold"}) {
    SCOPED_TRACE(name);
    const FoldImport fold = fixture(name);
    const json doc = json::parse(read_file(test::fixture_path(std::string("fold/") + name)));
    EXPECT_NEAR(total_area(fold.pattern), 2.0, 1e-6);  // a unit-diagonal-√2… square of side √2
    ASSERT_TRUE(fold.state.has_value());
    for (const auto& j : fold.pattern.joints()) {
      const auto& given = doc["edges_foldAngle"][static_cast<std::size_t>(j.id - 1)];
      const double expected = given.is_null() ? 0.0 : -given.get<double>() * kPi / 180.0;
      EXPECT_NEAR(fold.state->angles[*fold.pattern.joint_index(j.id)], expected, 1e-12) << "joint " << j.id;
    }
  }
}

// ───────────────────────── hand-made inputs ─────────────────────────

// A unit square creased along its diagonal 0–2, the second face lifted by a quarter turn to the
// +z side (the side the counter-clockwise faces face): a valley. lift = -1 folds it down.
std::string diagonal_fold(double lift, const std::string& assignment = "U") {
  const double h = std::sqrt(0.5);
  json doc = {{"file_spec", 1.2},
              {"vertices_coords", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.5, lift * h}}},
              {"faces_vertices", {{0, 1, 2}, {0, 2, 3}}},
              {"edges_vertices", {{0, 1}, {1, 2}, {0, 2}, {2, 3}, {3, 0}}},
              {"edges_assignment", {"B", "B", assignment, "B", "B"}}};
  return doc.dump(2);
}

TEST(FoldSign, ValleyFoldedUpIsNegative) {
  const FoldImport fold = parse_fold(diagonal_fold(+1.0), "valley.fold");
  ASSERT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_NEAR(angle(fold, 3), -kPi / 2, 1e-12);
  EXPECT_NEAR(total_area(fold.pattern), 1.0, 1e-12);
  // The FOLD export gives the valley FOLD's sign: +90.
  const json out = json::parse(write_fold(fold.pattern, FoldExport{fold.state, {}, {}}));
  for (std::size_t e = 0; e < out["edges_vertices"].size(); ++e)
    if (out["edges_assignment"][e] != "B") {
      EXPECT_EQ(out["edges_assignment"][e], "V");
      EXPECT_NEAR(out["edges_foldAngle"][e].get<double>(), 90.0, 1e-12);
    }
}

TEST(FoldSign, MountainFoldedDownIsPositive) {
  const FoldImport fold = parse_fold(diagonal_fold(-1.0), "mountain.fold");
  EXPECT_NEAR(angle(fold, 3), kPi / 2, 1e-12);
  EXPECT_TRUE(fold.warnings.empty());
}

TEST(FoldSign, FoldAngleIsNegatedAndNullMeansFlat) {
  const std::string text = R"({
    "vertices_coords": [[0,0],[1,0],[1,1],[0,1]],
    "faces_vertices": [[0,1,2],[0,2,3]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],
    "edges_assignment": ["B","B","B","B","M"],
    "edges_foldAngle": [null,null,null,null,-45],
    "file_frames": [
      {"frame_inherit": true, "frame_parent": 0, "edges_foldAngle": [0,0,0,0,-90.5]},
      {"frame_inherit": true, "frame_parent": 1, "frame_title": "no angles of its own"},
      {"frame_inherit": true, "edges_foldAngle": [0,0,0,0,null]}
    ]
  })";
  const FoldImport fold = parse_fold(text, "angles.fold");
  EXPECT_NEAR(angle(fold, 5), kPi / 4, 1e-15);
  ASSERT_EQ(fold.frames.size(), 2U);
  EXPECT_NEAR(fold.frames[0].angles[0], 90.5 * kPi / 180, 1e-15);
  EXPECT_EQ(fold.frames[1].angles[0], 0.0);

  const FoldImport again = parse_fold(write_fold(fold.pattern, FoldExport{fold.state, fold.frames, {}}), "again.fold");
  ASSERT_EQ(again.frames.size(), 2U);
  EXPECT_EQ(again.state->angles[0], fold.state->angles[0]);  // bit for bit
  EXPECT_EQ(again.frames[0].angles[0], fold.frames[0].angles[0]);

  // A simulated trajectory's frame times go into each frame as "foldkit:time", which readers
  // (foldkit's own included) may ignore; they must be one finite time per frame.
  const std::string timed = write_fold(fold.pattern, FoldExport{fold.state, fold.frames, {0.0, 0.1 + 0.2}});
  const json frames = json::parse(timed)["file_frames"];
  ASSERT_EQ(frames.size(), 2U);
  EXPECT_EQ(frames[0]["foldkit:time"].get<double>(), 0.0);
  EXPECT_EQ(frames[1]["foldkit:time"].get<double>(), 0.1 + 0.2);  // shortest decimals that read back
  EXPECT_EQ(parse_fold(timed, "timed.fold").frames.size(), 2U);
  EXPECT_FALSE(json::parse(write_fold(fold.pattern, FoldExport{fold.state, fold.frames, {}}))["file_frames"][0].contains("foldkit:time"));
  EXPECT_THROW(write_fold(fold.pattern, FoldExport{fold.state, fold.frames, {0.0}}), std::invalid_argument);
  EXPECT_THROW(write_fold(fold.pattern, FoldExport{fold.state, fold.frames, {0.0, std::nan("")}}), std::invalid_argument);
}

// Three strips side by side: a mountain crease at x = 1 (joint 9), a valley at x = 2 (joint 10).
constexpr const char* kStrips = R"({
  "vertices_coords": [[0,0],[1,0],[2,0],[3,0],[3,1],[2,1],[1,1],[0,1]],
  "faces_vertices": [[0,1,6,7],[1,2,5,6],[2,3,4,5]],
  "edges_vertices": [[0,1],[1,2],[2,3],[3,4],[4,5],[5,6],[6,7],[7,0],[1,6],[2,5]],
  "edges_assignment": ["B","B","B","B","B","B","B","B","M","V"]
})";

// The letters and FOLD angles an export gives the creases, keyed by their x.
std::map<double, std::pair<std::string, double>> crease_letters(const std::string& text) {
  const json out = json::parse(text);
  std::map<double, std::pair<std::string, double>> letters;
  for (std::size_t e = 0; e < out["edges_vertices"].size(); ++e) {
    const std::string l = out["edges_assignment"][e].get<std::string>();
    if (l == "B" || l == "J") continue;
    const double x = out["vertices_coords"][out["edges_vertices"][e][0].get<std::size_t>()][0].get<double>();
    letters[x] = {l, out.contains("edges_foldAngle") ? out["edges_foldAngle"][e].get<double>() : 0.0};
  }
  return letters;
}

TEST(FoldWrite, JointAtAngleZeroKeepsItsOwnAssignment) {
  const FoldImport fold = parse_fold(kStrips, "strips.fold");
  ASSERT_EQ(fold.pattern.joints().size(), 2U);
  EXPECT_EQ(joint(fold.pattern, 9).assignment, Assignment::Mountain);
  EXPECT_EQ(joint(fold.pattern, 10).assignment, Assignment::Valley);

  // An all-flat state (say, the first frame of a sequence) keeps M and V rather than writing F.
  const std::string flat = write_fold(fold.pattern, FoldExport{geometry::FoldState::flat(fold.pattern), {}, {}});
  auto letters = crease_letters(flat);
  ASSERT_EQ(letters.size(), 2U);
  EXPECT_EQ(letters[1.0], std::make_pair(std::string("M"), 0.0));
  EXPECT_EQ(letters[2.0], std::make_pair(std::string("V"), 0.0));
  const FoldImport again = parse_fold(flat, "again.fold");
  std::map<double, Assignment> reread;
  for (const auto& j : again.pattern.joints()) reread[again.pattern.vertices()[j.v[0]].x()] = j.assignment;
  EXPECT_EQ(reread, (std::map<double, Assignment>{{1.0, Assignment::Mountain}, {2.0, Assignment::Valley}}));

  // A bent joint still takes its letter from the sign: the valley bent as a mountain is "M".
  geometry::FoldState bent = geometry::FoldState::flat(fold.pattern);
  bent.angles[*fold.pattern.joint_index(10)] = 0.5;
  letters = crease_letters(write_fold(fold.pattern, FoldExport{bent, {}, {}}));
  EXPECT_EQ(letters[1.0].first, "M");
  EXPECT_EQ(letters[2.0].first, "M");
  EXPECT_LT(letters[2.0].second, 0.0);  // FOLD counts mountains negative
}

TEST(FoldImport, JoinEdgesMakeOneActor) {
  const std::string text = R"({
    "vertices_coords": [[0,0],[1,0],[1,1],[0,1],[2,0],[2,1]],
    "faces_vertices": [[0,1,2],[0,2,3],[1,4,5,2]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2],[1,4],[4,5],[5,2]],
    "edges_assignment": ["B","V","B","B","J","B","B","B"]
  })";
  const FoldImport fold = parse_fold(text, "join.fold");
  ASSERT_EQ(fold.pattern.actors().size(), 2U);
  EXPECT_EQ(fold.pattern.actors()[0].triangles.size(), 2U);
  EXPECT_EQ(fold.pattern.actors()[1].triangles.size(), 2U);  // the quad, cut in two
  ASSERT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_EQ(joint(fold.pattern, 2).assignment, Assignment::Valley);
  EXPECT_FALSE(fold.state.has_value());

  const json out = json::parse(write_fold(fold.pattern));
  EXPECT_EQ(out["file_spec"], 1.2);
  EXPECT_EQ(out["faces_vertices"].size(), 4U);
  std::map<std::string, int> letters;
  for (const auto& a : out["edges_assignment"]) ++letters[a.get<std::string>()];
  EXPECT_EQ(letters["B"], 6);
  EXPECT_EQ(letters["V"], 1);
  EXPECT_EQ(letters["J"], 2);
  EXPECT_FALSE(out.contains("edges_foldAngle"));
}

TEST(FoldImport, ClockwiseFacesAreReversedAndMissingAssignmentIsUnassigned) {
  const std::string text = R"({
    "vertices_coords": [[0,0],[1,0],[1,1],[0,1]],
    "faces_vertices": [[0,2,1],[0,3,2]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]]
  })";
  const FoldImport fold = parse_fold(text, "cw.fold");
  ASSERT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_EQ(joint(fold.pattern, 5).assignment, Assignment::Unassigned);
  EXPECT_NEAR(total_area(fold.pattern), 1.0, 1e-15);
  EXPECT_EQ(fold.warnings.size(), 1U);
}

TEST(FoldImport, InconsistentlyListedFaceIsRepaired) {
  const std::string text = R"({
    "vertices_coords": [[0,0],[1,0],[1,1],[0,1],[2,0],[2,1]],
    "faces_vertices": [[0,1,2,3],[1,2,5,4]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[1,4],[4,5],[5,2]],
    "edges_assignment": ["B","M","B","B","B","B","B"]
  })";
  const FoldImport fold = parse_fold(text, "mixed.fold");
  EXPECT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_NEAR(total_area(fold.pattern), 2.0, 1e-15);
  ASSERT_EQ(fold.warnings.size(), 1U);
  EXPECT_NE(fold.warnings[0].message.find("reversed"), std::string::npos);
}

TEST(FoldImport, PlanarThreeDimensionalSheetIsProjected) {
  // The unit square standing in the x–z plane, seen from −y its faces run counter-clockwise.
  const std::string text = R"({
    "vertices_coords": [[0,0,0],[1,0,0],[1,0,1],[0,0,1]],
    "faces_vertices": [[0,1,2],[0,2,3]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],
    "edges_assignment": ["B","B","B","B","V"]
  })";
  const FoldImport fold = parse_fold(text, "standing.fold");
  EXPECT_NEAR(total_area(fold.pattern), 1.0, 1e-15);
  ASSERT_TRUE(fold.state.has_value());
  EXPECT_EQ(fold.state->angles[0], 0.0);
}

TEST(FoldImport, SharedSideWithoutEdgeRecordIsAnUnassignedJoint) {
  const std::string text = R"({
    "vertices_coords": [[0,0],[1,0],[1,1],[0,1]],
    "faces_vertices": [[0,1,2],[0,2,3]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0]],
    "edges_assignment": ["B","B","B","B"]
  })";
  const FoldImport fold = parse_fold(text, "unrecorded.fold");
  ASSERT_EQ(fold.pattern.joints().size(), 1U);
  EXPECT_EQ(joint(fold.pattern, 5).assignment, Assignment::Unassigned);  // after the 4 records
  EXPECT_EQ(fold.warnings.size(), 1U);
}

TEST(FoldImport, FrameWithItsOwnFoldedCoordinatesGivesDihedrals) {
  const double h = std::sqrt(0.5);
  const json doc = {{"vertices_coords", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                    {"faces_vertices", {{0, 1, 2}, {0, 2, 3}}},
                    {"edges_vertices", {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}},
                    {"edges_assignment", {"B", "B", "B", "B", "V"}},
                    {"file_frames", {{{"frame_inherit", true},
                                      {"frame_classes", {"foldedForm"}},
                                      {"vertices_coords", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.5, h}}}}}}};
  const FoldImport fold = parse_fold(doc.dump(2), "frames.fold");
  EXPECT_FALSE(fold.state.has_value());
  ASSERT_EQ(fold.frames.size(), 1U);
  EXPECT_NEAR(fold.frames[0].angles[0], -kPi / 2, 1e-12);
}

// ───────────────────────── bad inputs ─────────────────────────

// Every failure is a ParseError whose text starts "NAME:LINE: ".
int error_line(const std::string& text, const std::string& needle = "") {
  try {
    parse_fold(text, "bad.fold");
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(std::regex_search(what, std::regex("^bad\\.fold:[0-9]+: "))) << what;
    EXPECT_EQ(what.rfind("bad.fold:" + std::to_string(e.line()) + ": ", 0), 0U) << what;
    if (!needle.empty()) {
      EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
    return e.line();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a ParseError: " << e.what();
    return -1;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return -1;
}

const char* kSquareEdges = R"("edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]])";

TEST(FoldErrors, SyntaxErrorNamesItsLine) {
  EXPECT_EQ(error_line("{\n  \"vertices_coords\": [\n    [0, 0],,\n  ]\n}", "invalid JSON"), 3);
  EXPECT_EQ(error_line("{\n  \"a\": tru\n}"), 2);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0]]"), 1);
}

TEST(FoldErrors, EmptyAndBinaryInput) {
  EXPECT_EQ(error_line("", "empty"), 1);
  EXPECT_EQ(error_line(" \n\t\n"), 1);
  EXPECT_EQ(error_line(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)), 1);
  EXPECT_EQ(error_line("[1, 2, 3]", "FOLD object"), 1);
  EXPECT_EQ(error_line("{}", "vertices_coords"), 1);
}

TEST(FoldErrors, DeepNestingIsRefused) {
  EXPECT_EQ(error_line(std::string(20000, '[') + std::string(20000, ']'), "nested"), 1);
  EXPECT_EQ(error_line("{\n\"x\":\n" + std::string(20000, '{'), "nested"), 3);
}

TEST(FoldErrors, WrongTypes) {
  EXPECT_EQ(error_line("{\n\"vertices_coords\": [\n[0,0],\n[1,\"a\"]\n]\n}", "vertices_coords[1][1]: expected a number"), 4);
  EXPECT_EQ(error_line("{\"vertices_coords\": {\"x\": 1}}", "expected an array"), 1);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0,0,0]]}", "2 or 3 coordinates"), 1);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"faces_vertices\": [[0,1,\"2\"]]}", "expected an index"), 2);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"faces_vertices\": [[0,1.5,2]]}", "whole number"), 2);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"faces_vertices\": [[0,1]]}", "at least 3"), 2);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"faces_vertices\": [[0,1,2]],\n"
                       "\"edges_vertices\": [[0,1]], \"edges_assignment\": [\"X\"]}",
                       "edges_assignment[0]"),
            3);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"faces_vertices\": [[0,1,2]],\n"
                       "\"edges_vertices\": [[0,1]],\n\"edges_foldAngle\": [270]}",
                       "outside [-180, 180]"),
            4);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"faces_vertices\": [[0,1,2]],\n"
                       "\"edges_vertices\": [[0,1]],\n\"edges_assignment\": [\"B\", \"B\"]}",
                       "has 2 entries"),
            4);
}

TEST(FoldErrors, IndexOutOfRange) {
  const std::string text = "{\n\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1]],\n\"faces_vertices\": [[0,1,2],[0,2,3]],\n"
                           "\"edges_vertices\": [\n[0,1],\n[1,99]\n]\n}";
  EXPECT_EQ(error_line(text, "edges_vertices[1]: vertex index 99 out of range (4 vertices)"), 6);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1]],\n\"faces_vertices\": [[0,1,-1]]}", "vertex index -1"), 2);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1]],\n\"faces_vertices\": [[0,1,1]]}", "twice"), 2);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1]], \"faces_vertices\": [[0,1,2]],\n"
                       "\"file_frames\": [{\"frame_inherit\": true, \"frame_parent\": 3}]}",
                       "frame_parent"),
            2);
}

TEST(FoldErrors, FrameErrorsPointIntoTheFrame) {
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1]], \"faces_vertices\": [[0,1,2]],\n"
                       "\"edges_vertices\": [[0,1],[1,2],[2,0]],\n\"file_frames\": [\n{\"frame_inherit\": true,\n"
                       "\"edges_foldAngle\": [0, 0]}]}",
                       "file_frames[0].edges_foldAngle: has 2 entries but edges_vertices has 3"),
            5);
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1]], \"faces_vertices\": [[0,1,2]],\n"
                       "\"file_frames\": [\n{\"frame_inherit\": true,\n\"vertices_coords\": [[0,0],\n[1,0,\"z\"]]}]}",
                       "file_frames[0].vertices_coords[1][2]"),
            5);
}

TEST(FoldErrors, NonFiniteNumber) {
  EXPECT_EQ(error_line("{\n\"vertices_coords\": [[0,0],\n[1e999,0]]}", "out of range"), 3);
  EXPECT_EQ(error_line("{\n\"vertices_coords\": [[0,0],[1,0],[0,1]],\n\"note\": \"1e999\",\n \"x\": -1e999}"), 4);
}

TEST(FoldErrors, BoundaryAndCutEdgesMustNotJoinFaces) {
  const std::string square = "{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1]],\n\"faces_vertices\": [[0,1,2],[0,2,3]],\n" +
                             std::string(kSquareEdges) + ",\n\"edges_assignment\": [\"B\",\"B\",\"B\",\"B\",\n";
  EXPECT_EQ(error_line(square + "\"B\"]}", "edges_assignment[4]: boundary edge (B) shared by faces 0 and 1"), 5);
  EXPECT_EQ(error_line(square + "\"C\"]}", "cut edge (C)"), 5);
}

TEST(FoldErrors, BadSurfaces) {
  // Three faces on one side.
  EXPECT_NE(error_line("{\"vertices_coords\": [[0,0,0],[1,0,0],[0,1,0],[0,-1,0],[0,0,1]],\n"
                       "\"faces_vertices\": [[0,1,2],[1,0,3],[0,1,4]]}",
                       "more than two faces"),
            -1);
  // A cone: four faces around an apex whose angles sum to less than 360°.
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0,1],[1,0,0],[0,1,0],[-1,0,0],[0,-1,0]],\n"
                       "\"faces_vertices\": [[0,1,2],[0,2,3],[0,3,4],[0,4,1]]}",
                       "not developable"),
            2);
  // Faces listed with no faces_vertices, but the edges leave a dangling end.
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1],[0.5,0.5]],\n"
                       "\"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],\n[0,4]]}",
                       "edges_vertices[4]: dangling"),
            3);
  // Two squares joined by a lone edge: it has the same region on both sides.
  EXPECT_EQ(error_line("{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1],[2,0],[3,0],[3,1],[2,1]],\n"
                       "\"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,7],[7,4],\n[1,4]]}",
                       "edges_vertices[8]: is a bridge"),
            3);
  // Overlapping faces are found by build_pattern and reported as a ParseError.
  EXPECT_NE(error_line("{\"vertices_coords\": [[0,0],[1,0],[0,1],[0.1,0.1],[1.1,0.1],[0.1,1.1]],\n"
                       "\"faces_vertices\": [[0,1,2],[3,4,5]]}",
                       "crease pattern rejected"),
            -1);
  // A crease pattern (so declared) whose faces lie on each other is not unfolded.
  EXPECT_EQ(error_line("{\"frame_classes\": [\"creasePattern\"],\n\"vertices_coords\": [[0,0],[1,0],[1,1],[0.8,0.2]],\n"
                       "\"faces_vertices\": [[0,1,2],[0,2,3]]}",
                       "lie on each other"),
            3);
}

TEST(FoldIo, ReadFoldReportsMissingFile) {
  const std::string path = test::temp_dir() + "/missing.fold";
  EXPECT_THROW(read_fold(path), ParseError);
}

}  // namespace
}  // namespace foldkit::io
