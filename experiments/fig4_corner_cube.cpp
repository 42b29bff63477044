// The paper's Fig. 4: a cube corner folded by Carpenter's rule — the degree-5 vertex (sectors 90°,
// 90°, 90°, 45°, 45°) unfolded from the corner by spherical expansive motions, the frames replayed
// backwards as CMML, and that CMML replayed by the simulator.
//
//   fig4_corner_cube [--out DIR] [--check]
//
// Writes fig4_corner_cube.{pmml,cmml,csv,md} into DIR (default experiment-output/fig4); --check
// exits 1 unless the unfolding reaches flat expansively and the replay of the folding CMML is
// valid (no collision, closure within tolerance) and ends at the corner.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "experiment_io.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/folding/carpenter_spherical.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace {

using namespace foldkit;
using experiments::expect;
using experiments::num;

constexpr double kDeg = 180.0 / M_PI;

// The corner 0.01 rad short of shut (as in test/planners/plan_test.cpp): the exact corner is
// singular — the flap's two halves lie on each other and creases 1 and 4 only fix their sum.
geometry::FoldState corner(const geometry::CreasePattern& p) {
  const double h = M_PI / 2;
  Eigen::VectorXd guess(5);
  guess << 0.778, -h + 0.01, -h + 0.01, 0.778, -M_PI + 0.02;
  geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  const auto r = geometry::project(geometry::ClosureSystem(p), geometry::FoldState{guess}, po);
  if (!r.status.ok()) {
    std::cerr << "fig4_corner_cube: the corner does not close: " << r.status.message << '\n';
    std::exit(1);
  }
  return r.state;
}

// Largest |cos| between the normals of the three quadrants (0 for a true cube corner), and the
// cosine between the flap's halves (−1 when they lie on each other).
std::pair<double, double> corner_shape(const geometry::CreasePattern& p, const geometry::FoldState& s) {
  const auto poses = geometry::facet_poses(p, geometry::make_tree(p), s);
  const auto normal = [&](int a) -> Eigen::Vector3d { return poses[static_cast<std::size_t>(a)].rotation().col(2); };
  const double square = std::max({std::abs(normal(0).dot(normal(1))), std::abs(normal(1).dot(normal(2))),
                                  std::abs(normal(0).dot(normal(2)))});
  return {square, normal(3).dot(normal(4))};
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = experiments::parse_args(argc, argv, "experiment-output/fig4",
                                            "usage: fig4_corner_cube [--out DIR] [--check]\n"
                                            "  The corner cube of Fig. 4 by spherical Carpenter's rule.\n");
  const double h = M_PI / 2, q = M_PI / 4;
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::single_vertex({h, h, h, q, q}));
  const geometry::FoldState goal = corner(p);

  const folding::CarpenterSphericalResult r = folding::flatten_single_vertex(p, goal);
  std::cerr << "fig4_corner_cube: " << r.status.message << ", " << r.frames.size() << " frames\n";

  // Replay the CMML as written, read back, as `foldkit simulate` would.
  const std::string cmml = io::write_cmml(r.folding);
  const geometry::FoldSequence replayed = io::parse_cmml(cmml, "fig4_corner_cube.cmml");
  const simulation::SimulationReport report = simulation::simulate(p, replayed);
  const double end_error = (report.final_state.angles - goal.angles).cwiseAbs().maxCoeff();
  const auto [square, flap] = corner_shape(p, report.final_state);

  // Smallest pairwise spherical distance (creases apart) per frame: it only grows while unfolding.
  std::ostringstream csv;
  csv << "frame";
  for (int j : r.joints) csv << ",joint" << p.joints()[static_cast<std::size_t>(j)].id << "_deg";
  csv << ",closest_creases_deg,closure_error_rad\n";
  const geometry::ClosureSystem closure(p);
  for (std::size_t f = 0; f < r.frames.size(); ++f) {
    const auto& s = r.frames[f];
    csv << f;
    for (int j : r.joints) csv << ',' << num(s.angles[j] * kDeg, 10);
    const auto u = folding::crease_directions(p, s);
    double closest = M_PI;
    for (std::size_t i = 0; i < u.size(); ++i)
      for (std::size_t k = i + 1; k < u.size(); ++k) closest = std::min(closest, std::atan2(u[i].cross(u[k]).norm(), u[i].dot(u[k])));
    csv << ',' << num(closest * kDeg, 10) << ',' << num(closure.max_error(s), 3) << '\n';
  }

  std::ostringstream md;
  md << "# Fig. 4: corner cube by spherical Carpenter's rule\n\n"
     << "Degree-5 vertex, sectors 90°, 90°, 90°, 45°, 45°; the corner 0.01 rad short of shut. Unfolded to flat by\n"
     << "expansive motions of its spherical polygon (folding::flatten_single_vertex), the frames replayed backwards as\n"
     << "CMML (fig4_corner_cube.cmml) and that CMML replayed by the simulator (motor model, FCL self-collision).\n\n"
     << "| figure | value |\n|---|---|\n"
     << "| unfolding | " << r.status.message << " |\n"
     << "| LP steps | " << r.steps << " |\n"
     << "| frames (CMML events) | " << r.frames.size() << " (" << r.folding.events.size() << ") |\n"
     << "| smallest LP rate t | " << num(r.min_rate) << " |\n"
     << "| smallest change of a pairwise distance between frames | " << num(r.min_distance_growth) << " rad |\n"
     << "| largest sector-angle error | " << num(r.max_sector_error) << " rad |\n"
     << "| largest closure residual of a frame | " << num(r.max_closure_error) << " rad |\n"
     << "| replay valid | " << (report.status.ok() ? "yes" : "no") << " |\n"
     << "| replay collisions | " << report.collision_count << " |\n"
     << "| replay closure error (largest) | " << num(report.max_closure_error) << " rad (tolerance "
     << num(report.closure_tolerance) << ") |\n"
     << "| replay duration | " << num(report.duration) << " s |\n"
     << "| replay end − corner (largest joint) | " << num(end_error) << " rad |\n"
     << "| quadrant normals, largest pairwise cosine | " << num(square) << " |\n"
     << "| flap halves, cosine of normals | " << num(flap) << " |\n";
  if (!report.problems.empty()) md << "\nReplay problems: " << report.problems.front() << '\n';

  experiments::write_output(args, "fig4_corner_cube.pmml", io::write_pmml(p));
  experiments::write_output(args, "fig4_corner_cube.cmml", cmml);
  experiments::write_output(args, "fig4_corner_cube.csv", csv.str());
  experiments::write_output(args, "fig4_corner_cube.md", md.str());
  std::cout << md.str();

  if (!args.check) return 0;
  bool ok = true;
  ok &= expect(r.status.ok(), "the corner unfolds to flat");
  ok &= expect(r.min_distance_growth > -1e-9, "no pairwise distance shrinks between frames");
  ok &= expect(r.max_sector_error < 1e-9 && r.max_closure_error < 1e-9, "every frame keeps its sectors and closes");
  ok &= expect(report.status.ok() && report.collision_count == 0, "the folding CMML replays valid, without a collision");
  ok &= expect(report.max_closure_error <= report.closure_tolerance, "the replay stays closed");
  ok &= expect(end_error < 1e-6, "the replay ends at the corner");
  ok &= expect(square < 0.02 && flap < -0.99, "the end is a cube corner with its flap shut");
  return ok ? 0 : 1;
}
