// The paper's Fig. 10: 48 tiles folded into a 2×4 cube beam under a 40 N transverse load.
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

namespace {

using namespace foldkit;
using analysis::ConnectionKind;
using Eigen::Vector3d;

constexpr double kTile = 0.01;   // m: Fig. 10c spans about 0.05 m along the beam
constexpr double kLoad = 40.0;   // N
constexpr int kCubes = 8, kAlong = 4;

// Cube centres of the 8-net sheet of Fig. 8a for every choice of the 7 hinges between nets
// (0°, ±90°, 180°), nets folded to cubes; how many give 8 distinct cubes in a 2×4 block.
int reachable_beams() {
  const auto p = geometry::build_or_throw(geometry::generators::cube_sheet(kCubes, 1.0));
  const auto tree = geometry::make_tree(p);
  const double choices[] = {-M_PI / 2, M_PI / 2, M_PI, 0.0};
  int found = 0;
  for (int code = 0; code < (1 << 14); ++code) {
    geometry::FoldState s = geometry::FoldState::flat(p);
    for (int n = 0; n < kCubes; ++n)
      for (int j = 0; j < 5; ++j) s.angles[6 * n + j] = -M_PI / 2;
    for (int n = 0, c = code; n < kCubes - 1; ++n, c >>= 2) s.angles[6 * n + 5] = choices[c & 3];
    const auto poses = geometry::facet_poses(p, tree, s);
    std::set<std::array<long, 3>> cells;
    Vector3d lo = Vector3d::Constant(1e9), hi = -lo;
    for (int n = 0; n < kCubes; ++n) {
      Vector3d centre = Vector3d::Zero();
      for (int k = 0; k < 6; ++k) {
        const auto& t = p.actors()[6 * n + k].triangles.front();
        const auto& v = p.vertices();  // first corner seeds the box
        // A square tile's centre: the middle of its bounding box.
        Vector3d a = poses[6 * n + k] * Vector3d(v[t.v[0]].x(), v[t.v[0]].y(), 0);
        Vector3d b = a;
        for (const auto& tri : p.actors()[6 * n + k].triangles)
          for (int q : tri.v) {
            const Vector3d x = poses[6 * n + k] * Vector3d(v[q].x(), v[q].y(), 0);
            a = a.cwiseMin(x), b = b.cwiseMax(x);
          }
        centre += (a + b) / 12.0;
      }
      cells.insert({std::lround(2 * centre.x()), std::lround(2 * centre.y()), std::lround(2 * centre.z())});
      lo = lo.cwiseMin(centre), hi = hi.cwiseMax(centre);
    }
    std::array<double, 3> ext{hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z()};
    std::sort(ext.begin(), ext.end());
    if (cells.size() == kCubes && std::abs(ext[0]) < 1e-9 && std::abs(ext[1] - 1) < 1e-9 && std::abs(ext[2] - 3) < 1e-9) ++found;
  }
  return found;
}

// 8 separate cube nets (tile kTile), each folded by its five valley creases and moved to its cell
// of the 2×4 block: cube c at x ∈ [i, i+1]·t, y ∈ [j, j+1]·t, z ∈ [0, t], i = c mod 4, j = c div 4.
analysis::Structure beam() {
  geometry::PatternSpec spec;
  spec.title = "2x4 cube beam";
  const auto net = geometry::generators::cube_sheet(1, kTile);
  for (int c = 0; c < kCubes; ++c) {
    const geometry::Vec2 shift(5.0 * kTile * c, 0.0);
    for (auto a : net.actors) {
      a.id += 6 * c;
      for (auto& t : a.triangles)
        for (auto& p : t.corners) p += shift;
      spec.actors.push_back(a);
    }
    for (auto j : net.joints) {
      j.id += 5 * c;
      for (auto& id : j.actor_ids) id += 6 * c;
      for (auto& p : j.coords) p += shift;
      spec.joints.push_back(j);
    }
  }
  const auto pattern = geometry::build_or_throw(spec);
  geometry::FoldState s = geometry::FoldState::flat(pattern);
  for (auto& a : s.angles) a = -M_PI / 2;
  auto poses = geometry::facet_poses(pattern, geometry::make_tree(pattern), s);
  for (int c = 0; c < kCubes; ++c) {
    Vector3d lo = Vector3d::Constant(1e9);
    for (int k = 0; k < 6; ++k)
      for (const auto& t : pattern.actors()[6 * c + k].triangles)
        for (int v : t.v) lo = lo.cwiseMin(poses[6 * c + k] * Vector3d(pattern.vertices()[v].x(), pattern.vertices()[v].y(), 0));
    const Vector3d target(kTile * (c % kAlong), kTile * (c / kAlong), 0.0);
    for (int k = 0; k < 6; ++k) poses[6 * c + k].pretranslate(target - lo);
  }
  return analysis::build_structure(pattern, poses);
}

struct Case {
  std::string name;
  double face = 1, edge = 1;
  bool inter_cube_edges = true;
};

struct Outcome {
  double tip = 0, max = 0, residual = 0, condition = 0;
  int iterations = 0;
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
  out.converged = r.converged;
  out.iterations = r.iterations;
  out.residual = r.residual_norm;
  out.condition = r.condition_estimate;
  out.max = r.max_displacement;
  for (int i : loaded) out.tip += -r.modules[i].displacement.z() / static_cast<double>(loaded.size());
  return out;
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
  const int reachable = reachable_beams();
  const analysis::Structure b = beam();
  int counts[3] = {0, 0, 0};
  for (const auto& c : b.connections) ++counts[static_cast<int>(c.kind)];
  const std::vector<Case> cases = {{"Eq. 6", 1, 1, true}, {"face ×4", 4, 1, true}, {"edge ×4", 1, 4, true},
                                   {"Eq. 6, edges within cubes only", 1, 1, false},
                                   {"face ×4, edges within cubes only", 4, 1, false},
                                   {"edge ×4, edges within cubes only", 1, 4, false}};
  const double paper[] = {3.2, 1.7, 2.3, 3.2, 1.7, 2.3};
  std::ostringstream md, csv;
  md << "# Fig. 10 beam: 48 tiles, 2×4 cubes, 40 N\n\n"
     << "8-net sheet of Fig. 8a: " << reachable << " of 16384 choices of the inter-net hinges (0°, ±90°, 180°) fold it "
     << "into a 2×4 block of cubes, so the beam is built from 8 separate nets (see docs/STIFFNESS.md).\n\n"
     << "Connections detected: " << counts[0] << " hinged, " << counts[1] << " face, " << counts[2] << " edge. Tile "
     << kTile * 1000 << " mm; fixed: the 2 end tiles at x = 0; load: 40 N along −z on the 2 end tiles at x = 4t.\n\n"
     << "| case | tip deflection (mm) | linear (mm) | ratio to Eq. 6 | paper (mm) | paper ratio | iterations | residual | condition |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  csv << "case,tip_mm,linear_tip_mm,ratio,paper_mm,paper_ratio,iterations,residual,condition\n";
  std::vector<Outcome> results;
  bool ok = reachable == 0 && counts[0] == 40 && counts[1] == 10;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Outcome o = run(b, cases[i], false), l = run(b, cases[i], true);
    ok = ok && o.converged && l.converged;
    results.push_back(o);
    const double base = results[i < 3 ? 0 : 3].tip;
    const double ratio = o.tip / base, paper_ratio = paper[i] / paper[i < 3 ? 0 : 3];
    md << "| " << cases[i].name << " | " << std::setprecision(4) << o.tip * 1000 << " | " << l.tip * 1000 << " | " << ratio
       << " | " << paper[i] << " | " << std::setprecision(3) << paper_ratio << " | " << o.iterations << " | "
       << std::setprecision(2) << o.residual << " | " << o.condition << " |\n";
    csv << '"' << cases[i].name << "\"," << std::setprecision(6) << o.tip * 1000 << ',' << l.tip * 1000 << ',' << ratio << ','
        << paper[i] << ',' << paper_ratio << ',' << o.iterations << ',' << o.residual << ',' << o.condition << '\n';
  }
  std::cout << md.str();
  std::filesystem::create_directories(dir);
  io::write_file_atomic(dir + "/fig10_beam.md", md.str());
  io::write_file_atomic(dir + "/fig10_beam.csv", csv.str());
  if (!check) return ok ? 0 : 1;
  // Bands (docs/STIFFNESS.md): regression guards on our own figures, and the paper's ordering.
  const auto within = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  const double tip = results[3].tip * 1000, r_face = results[4].tip / results[3].tip, r_edge = results[5].tip / results[3].tip;
  ok = ok && within(tip, 3.9, 4.1) && within(r_face, 0.46, 0.49) && within(r_edge, 0.86, 0.90) && r_face < r_edge &&
       within(results[0].tip * 1000, 0.50, 0.55);
  std::cerr << "check (edges within cubes): tip " << tip << " mm in [3.9, 4.1], face x4 ratio " << r_face
            << " in [0.46, 0.49], edge x4 ratio " << r_edge << " in [0.86, 0.90]; all edges: tip " << results[0].tip * 1000
            << " mm in [0.50, 0.55]: " << (ok ? "ok" : "FAILED") << '\n';
  return ok ? 0 : 1;
}
