// The paper's Fig. 10: the 48 tiles of the Fig. 8a sheet folded into a 2×4 cube beam under a 40 N
// transverse load.
//
//   fig10_beam [--out DIR] [--check]
//
// Writes fig10_beam.md and fig10_beam.csv into DIR (default: experiment-output/fig10, created when
// missing); --check exits 1 when a figure leaves the band recorded in docs/STIFFNESS.md, so a
// regression shows in ctest.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "foldkit/analysis/solver.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/io/atomic_write.hpp"

#include "cube_tiles.hpp"

namespace {

using namespace foldkit;
using analysis::ConnectionKind;
using Eigen::Vector3d;
using experiments::cube_centres;
using experiments::tile_centres;

constexpr double kTile = 0.01;   // m: Fig. 10c spans about 0.05 m along the beam
constexpr double kLoad = 40.0;   // N
constexpr int kCubes = 8, kAlong = 4;

// The 8-net sheet of Fig. 8a (tile 1) with every net folded to its cube (five creases at −90°) and
// each of the 7 hinges between nets at 0°, ±90° or 180°: the states (of 16384) whose cubes are 8
// distinct cells of a 2×4×1 block, in the order of the search.
std::vector<geometry::FoldState> beam_foldings(const geometry::CreasePattern& p) {
  const auto tree = geometry::make_tree(p);
  const double choices[] = {-M_PI / 2, M_PI / 2, M_PI, 0.0};
  std::vector<geometry::FoldState> found;
  for (int code = 0; code < (1 << 14); ++code) {
    geometry::FoldState s = geometry::FoldState::flat(p);
    for (int n = 0; n < kCubes; ++n)
      for (int j = 0; j < 5; ++j) s.angles[6 * n + j] = -M_PI / 2;
    for (int n = 0, c = code; n < kCubes - 1; ++n, c >>= 2) s.angles[6 * n + 5] = choices[c & 3];
    const auto centres = cube_centres(tile_centres(p, geometry::facet_poses(p, tree, s)));
    std::set<std::array<long, 3>> cells;
    Vector3d lo = Vector3d::Constant(1e9), hi = -lo;
    for (const Vector3d& c : centres) {
      cells.insert({std::lround(2 * c.x()), std::lround(2 * c.y()), std::lround(2 * c.z())});
      lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    }
    std::array<double, 3> ext{hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z()};
    std::sort(ext.begin(), ext.end());
    if (cells.size() == kCubes && std::abs(ext[0]) < 1e-9 && std::abs(ext[1] - 1) < 1e-9 && std::abs(ext[2] - 3) < 1e-9)
      found.push_back(s);
  }
  return found;
}

// The sheet (tile kTile) in folding `s`, turned and moved so that the block is x ∈ [0, 4]·t
// (along the beam), y ∈ [0, 2]·t (across), z ∈ [0, 1]·t (its height).
analysis::Structure beam(const geometry::FoldState& s) {
  const auto pattern = geometry::build_or_throw(geometry::generators::cube_sheet(kCubes, kTile));
  auto poses = geometry::facet_poses(pattern, geometry::make_tree(pattern), s);
  const auto centres = cube_centres(tile_centres(pattern, poses));
  Vector3d lo = Vector3d::Constant(1e9), hi = -lo;
  for (const Vector3d& c : centres) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  // Axes of the world sorted by the block's extent: longest to x, next to y, the flat one to z.
  std::array<int, 3> axis{0, 1, 2};
  const Vector3d extent = hi - lo;
  std::sort(axis.begin(), axis.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  Eigen::Matrix3d turn = Eigen::Matrix3d::Zero();
  turn(0, axis[0]) = turn(1, axis[1]) = 1;
  turn.row(2) = turn.row(0).cross(turn.row(1));  // a rotation, not a mirror image
  Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
  place.linear() = turn;
  // The block's lowest corner: half a tile below the lowest turned cube centre on every axis.
  Vector3d low = Vector3d::Constant(1e9);
  for (const Vector3d& c : centres) low = low.cwiseMin(turn * c);
  place.pretranslate(-(low - Vector3d::Constant(kTile / 2)));
  for (auto& pose : poses) pose = place * pose;
  return analysis::build_structure(pattern, poses);
}

// The 7 inter-net hinge angles of a folding, in degrees.
std::string hinge_angles(const geometry::FoldState& s) {
  std::ostringstream o;
  for (int n = 0; n + 1 < kCubes; ++n) o << (n ? " " : "") << std::lround(s.angles[6 * n + 5] * 180 / M_PI);
  return o.str();
}

struct Case {
  std::string name;
  double face = 1, edge = 1;
  bool inter_cube_edges = true;
};

struct Outcome {
  double tip = 0, max = 0, residual = 0, condition = 0;
  int iterations = 0;
  int fixed = 0, loaded = 0;  // tiles held at x = 0 and loaded at x = 4t
  bool converged = false;
};

// Fixed: the two end tiles in the plane x = 0. Load: 40 N along −z shared by the two end tiles
// in the plane x = 4t, at their centroids.
Outcome run(const analysis::Structure& base, const Case& c, bool linear) {
  analysis::Problem p;
  p.structure = base;
  if (!c.inter_cube_edges) {
    const auto cube = [&](int module) { return (p.structure.modules[module].id - 1) / 6; };
    auto& k = p.structure.connections;
    k.erase(std::remove_if(k.begin(), k.end(),
                           [&](const analysis::Connection& x) { return x.kind == ConnectionKind::Edge && cube(x.a) != cube(x.b); }),
            k.end());
  }
  p.stiffness[static_cast<int>(ConnectionKind::Face)] *= c.face;
  p.stiffness[static_cast<int>(ConnectionKind::Edge)] *= c.edge;
  p.fixed.assign(p.structure.modules.size(), false);
  std::vector<int> loaded;
  for (std::size_t i = 0; i < p.structure.modules.size(); ++i) {
    const auto& m = p.structure.modules[i];
    if (std::abs(m.normal.x()) < 0.5) continue;
    if (std::abs(m.centroid.x()) < 1e-9) p.fixed[i] = true;
    if (std::abs(m.centroid.x() - kAlong * kTile) < 1e-9) loaded.push_back(static_cast<int>(i));
  }
  for (int i : loaded) p.loads.push_back({i, Vector3d(0, 0, -kLoad / static_cast<double>(loaded.size())), p.structure.modules[i].centroid});
  analysis::SolveOptions o;
  o.linear = linear;
  const auto r = analysis::solve(p, o);
  Outcome out;
  out.fixed = static_cast<int>(std::count(p.fixed.begin(), p.fixed.end(), true));
  out.loaded = static_cast<int>(loaded.size());
  out.converged = r.status.ok();
  out.iterations = r.iterations;
  out.residual = r.residual_norm;
  out.condition = r.condition_estimate;
  out.max = r.max_displacement;
  for (int i : loaded) out.tip += -r.modules[i].displacement.z() / static_cast<double>(loaded.size());
  return out;
}

// The six load cases, and the paper's tip deflection (mm) for each.
const std::vector<Case> kCases = {{"Eq. 6", 1, 1, true},
                                  {"face ×4", 4, 1, true},
                                  {"edge ×4", 1, 4, true},
                                  {"Eq. 6, edges within cubes only", 1, 1, false},
                                  {"face ×4, edges within cubes only", 4, 1, false},
                                  {"edge ×4, edges within cubes only", 1, 4, false}};
const double kPaper[] = {3.2, 1.7, 2.3, 3.2, 1.7, 2.3};

// Hinged, face and edge connections.
std::array<int, 3> connection_counts(const analysis::Structure& b) {
  std::array<int, 3> counts{0, 0, 0};
  for (const auto& c : b.connections) ++counts[static_cast<std::size_t>(c.kind)];
  return counts;
}

void header(std::ostream& md, int reachable, const geometry::FoldState& first, const std::array<int, 3>& counts) {
  md << "# Fig. 10 beam: 48 tiles, 2×4 cubes, 40 N\n\n"
     << "8-net sheet of Fig. 8a: " << reachable << " of 16384 choices of the inter-net hinges (0°, ±90°, 180°) fold it "
     << "into a 2×4 block of cubes; the beam is the first of them (inter-net hinges "
     << hinge_angles(first) << "), the others in the last table (see docs/STIFFNESS.md).\n\n"
     << "Connections detected: " << counts[0] << " hinged, " << counts[1] << " face, " << counts[2] << " edge. Tile "
     << kTile * 1000 << " mm; fixed: the 2 end tiles at x = 0; load: 40 N along −z on the 2 end tiles at x = 4t.\n\n"
     << "| case | tip deflection (mm) | linear (mm) | ratio to Eq. 6 | paper (mm) | paper ratio | iterations | residual | condition |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
}

// Every case on the beam b, nonlinear and linear: a row each in md and csv. Clears ok when a
// solve fails or the ends are not two tiles each.
std::vector<Outcome> case_table(const analysis::Structure& b, std::ostream& md, std::ostream& csv, bool& ok) {
  csv << "case,tip_mm,linear_tip_mm,ratio,paper_mm,paper_ratio,iterations,residual,condition\n";
  std::vector<Outcome> results;
  for (std::size_t i = 0; i < kCases.size(); ++i) {
    const Outcome o = run(b, kCases[i], false), l = run(b, kCases[i], true);
    ok = ok && o.converged && l.converged && o.fixed == 2 && o.loaded == 2;
    results.push_back(o);
    const double base = results[i < 3 ? 0 : 3].tip;
    const double ratio = o.tip / base, paper_ratio = kPaper[i] / kPaper[i < 3 ? 0 : 3];
    md << "| " << kCases[i].name << " | " << std::setprecision(4) << o.tip * 1000 << " | " << l.tip * 1000 << " | " << ratio
       << " | " << kPaper[i] << " | " << std::setprecision(3) << paper_ratio << " | " << o.iterations << " | "
       << std::setprecision(2) << o.residual << " | " << o.condition << " |\n";
    csv << '"' << kCases[i].name << "\"," << std::setprecision(6) << o.tip * 1000 << ',' << l.tip * 1000 << ',' << ratio << ','
        << kPaper[i] << ',' << paper_ratio << ',' << o.iterations << ',' << o.residual << ',' << o.condition << '\n';
  }
  return results;
}

// The same cases on every folding of the sheet into the block: which hinges join the cubes
// moves the figures. Clears ok when a solve fails.
void foldings_table(const std::vector<geometry::FoldState>& foldings, const std::vector<analysis::Structure>& beams,
                    std::ostream& md, bool& ok) {
  md << "\n| inter-net hinges (deg) | hinged / face / edge | Eq. 6, within cubes (mm) | face ×4 ratio | edge ×4 ratio | "
        "Eq. 6, all edges (mm) |\n|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < foldings.size(); ++i) {
    const analysis::Structure& bf = beams[i];
    const std::array<int, 3> k = connection_counts(bf);
    const Outcome e = run(bf, kCases[3], false), fx = run(bf, kCases[4], false), ex = run(bf, kCases[5], false),
                  all = run(bf, kCases[0], false);
    ok = ok && e.converged && fx.converged && ex.converged && all.converged;
    md << "| " << hinge_angles(foldings[i]) << " | " << k[0] << " / " << k[1] << " / " << k[2] << " | " << std::setprecision(4)
       << e.tip * 1000 << " | " << std::setprecision(3) << fx.tip / e.tip << " | " << ex.tip / e.tip << " | "
       << std::setprecision(4) << all.tip * 1000 << " |\n";
  }
}

// Bands (docs/STIFFNESS.md): regression guards on our own figures, and the paper's ordering.
bool within_bands(const std::vector<Outcome>& results, int reachable, bool ok) {
  const auto within = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  const double tip = results[3].tip * 1000, r_face = results[4].tip / results[3].tip, r_edge = results[5].tip / results[3].tip;
  ok = ok && within(tip, 2.35, 2.55) && within(r_face, 0.63, 0.68) && within(r_edge, 0.68, 0.72) && r_face < r_edge &&
       within(results[0].tip * 1000, 0.46, 0.50) && reachable == 9;
  std::cerr << "check (edges within cubes): tip " << tip << " mm in [2.35, 2.55], face x4 ratio " << r_face
            << " in [0.63, 0.68], edge x4 ratio " << r_edge << " in [0.68, 0.72]; all edges: tip " << results[0].tip * 1000
            << " mm in [0.46, 0.50]; " << reachable << " of 9 foldings into the block: " << (ok ? "ok" : "FAILED") << '\n';
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir = "experiment-output/fig10";
  bool check = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--check")) check = true;
    else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) dir = argv[++i];
    else {
      std::cerr << "usage: fig10_beam [--out DIR] [--check]\n";
      return 2;
    }
  }
  const auto sheet = geometry::build_or_throw(geometry::generators::cube_sheet(kCubes, 1.0));
  const std::vector<geometry::FoldState> foldings = beam_foldings(sheet);
  if (foldings.empty()) {
    std::cerr << "fig10_beam: no choice of the inter-net hinges folds the sheet into a 2x4 block\n";
    return 1;
  }
  const int reachable = static_cast<int>(foldings.size());
  std::vector<analysis::Structure> beams;
  for (const auto& f : foldings) beams.push_back(beam(f));
  const std::array<int, 3> counts = connection_counts(beams.front());
  std::ostringstream md, csv;
  header(md, reachable, foldings.front(), counts);
  bool ok = counts[0] == 47 && counts[1] == 10;
  const std::vector<Outcome> results = case_table(beams.front(), md, csv, ok);
  foldings_table(foldings, beams, md, ok);
  std::cout << md.str();
  std::filesystem::create_directories(dir);
  io::write_file_atomic(dir + "/fig10_beam.md", md.str());
  io::write_file_atomic(dir + "/fig10_beam.csv", csv.str());
  if (!check) return ok ? 0 : 1;
  return within_bands(results, reachable, ok) ? 0 : 1;
}
