#pragma once
// The stiffness benchmarks' structures, shared by bench_stiffness (ours against hybrd) and
// bench_stiffness_ceres (ours against Ceres): a clamped plate of tiles, and the cube beam of
// issue 20 (the Fig. 8a sheet folded into a straight line of cubes, the first cube clamped, a
// transverse load at the far end).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "foldkit/analysis/solver.hpp"
#include "foldkit/folding/cube_chain.hpp"
#include "foldkit/geometry/generators.hpp"

namespace foldkit::bench_stiffness {

/// About `modules` tiles in a flat grid, the first column fixed, a transverse corner load that
/// turns the free edge by about 0.1 rad.
inline analysis::Problem grid_problem(int modules) {
  const int rows = std::max(1, static_cast<int>(std::lround(std::sqrt(modules / 2.0))));
  const int cols = std::max(2, modules / rows);
  const auto pattern = geometry::build_or_throw(geometry::generators::grid(rows, cols, 0.01));
  analysis::Problem p;
  p.structure = analysis::build_structure(pattern, geometry::FoldState::flat(pattern));
  p.fixed.assign(p.structure.modules.size(), false);
  for (int j = 0; j < rows; ++j) p.fixed[static_cast<std::size_t>(j * cols)] = true;
  const int corner = rows * cols - 1;
  p.loads.push_back({corner, Eigen::Vector3d(0, 0, -10.0 / cols), p.structure.modules[static_cast<std::size_t>(corner)].centroid});
  return p;
}

/// A straight beam of modules / 6 cubes (at least 2; 10 mm tiles in metres, Eq. 6 stiffness):
/// cube_sheet folded by folding::fold_cube_chain, every touching face and edge a connection.
/// The first cube is clamped; one tile of the last cube carries a load across the beam, scaled
/// so that the linear solution turns some module by `rotation` radians, so every size bends
/// about as much (geometrically nonlinear for rotation ≳ 0.05).
inline analysis::Problem beam_problem(int modules, double rotation = 0.1) {
  const int cubes = std::max(2, modules / 6);
  const auto sheet = geometry::build_or_throw(geometry::generators::cube_sheet(cubes, 0.01));
  const auto state = geometry::end_state(sheet, folding::fold_cube_chain(sheet, cubes));
  analysis::Problem p;
  p.structure = analysis::build_structure(sheet, state);
  const auto& m = p.structure.modules;
  p.fixed.assign(m.size(), false);
  for (std::size_t t = 0; t < 6; ++t) p.fixed[t] = true;
  Eigen::Vector3d first = Eigen::Vector3d::Zero(), last = Eigen::Vector3d::Zero();
  for (std::size_t t = 0; t < 6; ++t) {
    first += m[t].centroid / 6.0;
    last += m[m.size() - 6 + t].centroid / 6.0;
  }
  const Eigen::Vector3d axis = (last - first).normalized();
  Eigen::Index k = 0;
  axis.cwiseAbs().minCoeff(&k);
  const Eigen::Vector3d across = axis.cross(Eigen::Vector3d::Unit(k)).normalized();
  const int tip = static_cast<int>(m.size()) - 1;
  p.loads.push_back({tip, across, m[static_cast<std::size_t>(tip)].centroid});
  analysis::SolveOptions linear;
  linear.linear = true;
  linear.estimate_condition = false;
  const auto unit = analysis::solve(p, linear);
  double turned = 0.0;
  for (const auto& r : unit.modules) turned = std::max(turned, r.rotation.norm());
  if (!unit.status.ok() || !(turned > 0.0)) throw std::runtime_error("beam_problem: the unit load does not bend the beam: " + unit.status.message);
  p.loads.front().force *= rotation / turned;
  return p;
}

}  // namespace foldkit::bench_stiffness
