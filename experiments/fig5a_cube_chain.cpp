// The paper's Fig. 5a / Fig. 8a→8b: the sheet of 8 cube nets (48 tiles, as in Fig. 10a) folded
// into a straight chain of closed cubes by folding::fold_cube_chain, the CMML replayed by the
// simulator (FCL self-collision), and the end state checked cube by cube.
//
//   fig5a_cube_chain [--out DIR] [--check]
//
// Writes fig5a_cube_chain.{pmml,cmml,md} and snapshots fig5a_event_*.svg into DIR (default
// experiment-output/fig5a); --check exits 1 unless the replay is valid without a collision and
// the 8 nets end as 8 closed unit cubes in a straight line, neighbours face to face.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "experiment_io.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/folding/cube_chain.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "foldkit/simulation/snapshot.hpp"

#include "cube_tiles.hpp"

namespace {

using namespace foldkit;
using experiments::expect;
using experiments::num;
using Eigen::Vector3d;

constexpr int kCubes = 8;

struct CubeShape {
  std::vector<Vector3d> centres;
  double face_error = 0.0;  // largest |distance of a tile centre from its cube's centre − ½|
  bool six_faces = true;    // every cube's tiles on six different faces, upper sides inward
  double line_error = 0.0;  // largest distance of a cube centre from centre₀ + k·step
  double step = 0.0;        // |centre₁ − centre₀|
};

CubeShape cube_shape(const geometry::CreasePattern& p, const std::vector<Eigen::Isometry3d>& poses) {
  CubeShape s;
  const std::vector<Vector3d> tiles = experiments::tile_centres(p, poses);
  s.centres = experiments::cube_centres(tiles);
  for (int n = 0; n < kCubes; ++n) {
    std::array<bool, 6> seen{};
    for (int t = 0; t < 6; ++t) {
      const Vector3d d = tiles[static_cast<std::size_t>(6 * n + t)] - s.centres[static_cast<std::size_t>(n)];
      Eigen::Index axis = 0;
      d.cwiseAbs().maxCoeff(&axis);
      s.face_error = std::max(s.face_error, std::abs(d.norm() - 0.5));
      const std::size_t slot = static_cast<std::size_t>(2 * axis + (d[axis] > 0 ? 1 : 0));
      // Across the axis, its normal (upper side) toward the centre: the net's hinges are valleys.
      const double inward = poses[static_cast<std::size_t>(6 * n + t)].linear().col(2)[axis] * (d[axis] > 0 ? -1.0 : 1.0);
      s.six_faces &= !seen[slot] && std::abs(inward - 1.0) < 1e-9;
      seen[slot] = true;
    }
  }
  const Vector3d step = s.centres[1] - s.centres[0];
  s.step = step.norm();
  for (int n = 0; n < kCubes; ++n)
    s.line_error = std::max(s.line_error, (s.centres[static_cast<std::size_t>(n)] - s.centres[0] - n * step).norm());
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = experiments::parse_args(argc, argv, "experiment-output/fig5a",
                                            "usage: fig5a_cube_chain [--out DIR] [--check]\n"
                                            "  The Fig. 8a sheet of 8 cube nets folded into a line of cubes (Fig. 5a).\n");
  const geometry::CreasePattern sheet = geometry::build_or_throw(geometry::generators::cube_sheet(kCubes));
  const auto started = std::chrono::steady_clock::now();
  const std::string cmml = io::write_cmml(folding::fold_cube_chain(sheet, kCubes));
  // Replay the CMML as written, read back, as `foldkit simulate` would.
  const geometry::FoldSequence replayed = io::parse_cmml(cmml, "fig5a_cube_chain.cmml");
  const simulation::SimulationReport report = simulation::simulate(sheet, replayed);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const auto tree = geometry::make_tree(sheet);
  const CubeShape shape = cube_shape(sheet, geometry::facet_poses(sheet, tree, report.final_state));

  // Views after the first cube, half the chain and the whole of it (each event's end is a frame).
  for (int cube : {1, kCubes / 2, kCubes}) {
    const int event = 3 * cube;
    const auto frame = std::find_if(report.frames.rbegin(), report.frames.rend(), [&](const auto& f) { return f.event == event; });
    if (frame == report.frames.rend()) continue;
    simulation::SnapshotOptions so;
    so.size = 480;
    so.caption = "after event " + std::to_string(event) + ": " + std::to_string(cube) + " of " + std::to_string(kCubes) + " cubes";
    experiments::write_output(args, "fig5a_event_" + std::to_string(event) + ".svg",
                              simulation::snapshot_svg(sheet, geometry::facet_poses(sheet, tree, frame->state), so));
  }

  std::ostringstream md;
  md << "# Fig. 5a: the Fig. 8a sheet folded into a chain of cubes\n\n"
     << "generators::cube_sheet(" << kCubes << ") (" << sheet.actors().size() << " tiles, " << sheet.joints().size()
     << " hinges) folded by folding::fold_cube_chain; the CMML (fig5a_cube_chain.cmml) replayed by the simulator\n"
     << "(motor model, FCL self-collision).\n\n"
     << "| figure | value |\n|---|---|\n"
     << "| CMML events | " << replayed.events.size() << " |\n"
     << "| replay valid | " << (report.status.ok() ? "yes" : "no") << " |\n"
     << "| replay collisions | " << report.collision_count << " |\n"
     << "| replay, simulated time | " << num(report.duration) << " s (" << report.steps << " steps, " << report.checks
     << " states checked) |\n"
     << "| plan + replay, wall time | " << num(seconds, 2) << " s |\n"
     << "| tiles off their cube face (largest) | " << num(shape.face_error, 3) << " |\n"
     << "| every cube closed: six faces, upper sides inward | " << (shape.six_faces ? "yes" : "no") << " |\n"
     << "| step between neighbouring cube centres | " << num(shape.step, 10) << " tile |\n"
     << "| cube centres off the straight line (largest) | " << num(shape.line_error, 3) << " tile |\n";
  if (!report.problems.empty()) md << "\nReplay problems: " << report.problems.front() << '\n';

  experiments::write_output(args, "fig5a_cube_chain.pmml", io::write_pmml(sheet));
  experiments::write_output(args, "fig5a_cube_chain.cmml", cmml);
  experiments::write_output(args, "fig5a_cube_chain.md", md.str());
  std::cout << md.str();

  if (!args.check) return 0;
  bool ok = expect(report.status.ok() && report.collision_count == 0, "the CMML replays valid, without a collision");
  ok &= expect(shape.six_faces && shape.face_error < 1e-9, "every net ends as a closed unit cube");
  ok &= expect(std::abs(shape.step - 1.0) < 1e-9 && shape.line_error < 1e-9, "the cubes lie in a straight line, face to face");
  return ok ? 0 : 1;
}
