// Fig. 5b of the founding paper: a straight chain of cubes reconfigured into a wrench head.
//   fig5_wrench_head [--out DIR] [--check]
// A Hamiltonian path through the pixels of experiments/data/wrench_head.txt gives the chain's
// order; its cell centres are a unit-bar planar chain, which the planar Carpenter's rule
// straightens by strictly expansive motions; the frames replayed backwards take the straight
// chain to the wrench head (docs/CARPENTER.md). Writes frames.csv (straight → wrench) and
// summary.md; --check exits 1 when a figure below fails. Whether the cubes themselves (unit
// squares on the chain's vertices, turned along their bars) stay apart is measured and
// reported, not assumed.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "experiment_io.hpp"
#include "foldkit/folding/carpenter.hpp"
#include "foldkit/folding/hamiltonian.hpp"
#include "foldkit/io/chain_file.hpp"
#include "foldkit/io/shape_file.hpp"

namespace {

using namespace foldkit;
using namespace foldkit::folding;
using foldkit::geometry::StatusCode;
using Vec = Eigen::Vector2d;

// The unit square on vertex i, turned along the bar to its successor (the last along the bar
// before it).
struct Square {
  Vec centre, axis;  // axis: unit, along the bar
};

Square square_of(const Frame2& p, std::size_t i) {
  const Vec d = i + 1 < p.size() ? p[i + 1] - p[i] : p[i] - p[i - 1];
  return {p[i], d.normalized()};
}

// Depth by which two unit squares overlap (separating-axis test; ≤ 0 when apart or touching).
double overlap(const Square& a, const Square& b) {
  double depth = 1e300;
  for (const Vec& axis : {a.axis, Vec(-a.axis.y(), a.axis.x()), b.axis, Vec(-b.axis.y(), b.axis.x())}) {
    auto radius = [&](const Square& s) {
      const Vec n(-s.axis.y(), s.axis.x());
      return 0.5 * (std::abs(s.axis.dot(axis)) + std::abs(n.dot(axis)));
    };
    const double gap = std::abs((b.centre - a.centre).dot(axis)) - radius(a) - radius(b);
    depth = std::min(depth, -gap);
  }
  return depth;
}

}  // namespace

int main(int argc, char** argv) {
  const experiments::Args args = experiments::parse_args(
      argc, argv, "fig5-output", "usage: fig5_wrench_head [--out DIR] [--check]\n");
  const PixelShape shape = io::read_pixel_shape(FOLDKIT_EXPERIMENTS_DATA "/wrench_head.txt");
  const std::size_t pixels = shape.count();

  // The exact search settles small shapes; the linear-time 2× refinement is the fallback.
  HamiltonianResult path = exact_hamiltonian(shape);
  std::string method = "exact";
  if (path.status.code != StatusCode::Success) {
    path = refined_hamiltonian_cycle(shape);
    method = "2x refined cycle, opened";
  }
  if (path.status.code != StatusCode::Success) {
    std::cerr << "no Hamiltonian path: " << path.status.message << '\n';
    return 1;
  }
  // One cube per cell (of the refined grid when refined), unit bars between cell centres.
  Frame2 chain;
  for (const Cell& c : path.path) chain.emplace_back(c.x, -c.y);  // y up

  // Joints turn at most 0.01 rad between frames (default 0.2): the figure's frames, and the
  // overlap test below, which samples the motion at frames only, stay dense.
  CarpenterPlanarOptions options;
  options.max_turn = 0.01;
  const CarpenterPlanarResult r = carpenter_planar({chain, false}, options);
  const std::vector<Frame2> fold = reversed(r.frames);  // straight → wrench head

  // Cubes: consecutive ones share a hinge edge, so only pairs two or more apart must stay apart.
  double worst = -1e300;
  std::size_t frames_with_overlap = 0;
  for (const Frame2& p : fold) {
    double frame_worst = -1e300;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 2; j < p.size(); ++j) {
        const Square a = square_of(p, i), b = square_of(p, j);
        frame_worst = std::max(frame_worst, overlap(a, b));
      }
    worst = std::max(worst, frame_worst);
    frames_with_overlap += frame_worst > 1e-9 ? 1 : 0;
  }
  double end_error = 0.0;
  for (std::size_t i = 0; i < chain.size(); ++i) end_error = std::max(end_error, (fold.back()[i] - chain[i]).norm());

  experiments::write_output(args, "frames.csv", io::frames_csv(fold));
  std::string md = "# Fig. 5b: straight chain of cubes to a wrench head\n\n";
  md += "| figure | value |\n|---|---|\n";
  md += "| pixels in the shape | " + std::to_string(pixels) + " |\n";
  md += "| Hamiltonian path | " + std::to_string(path.path.size()) + " cells (" + method + ") |\n";
  md += "| Carpenter steps / frames | " + std::to_string(r.steps) + " / " + std::to_string(r.frames.size()) + " |\n";
  md += "| straightened | " + std::string(r.status.ok() ? "yes" : "no: " + r.status.message) + " |\n";
  md += "| max bar length error | " + experiments::num(r.max_length_error) + " |\n";
  md += "| min pairwise distance change between frames (unfolding) | " + experiments::num(r.min_distance_growth) + " |\n";
  md += "| last folding frame vs. the path (max distance) | " + experiments::num(end_error) + " |\n";
  md += "| frames where two non-consecutive cubes overlap | " + std::to_string(frames_with_overlap) + " of " +
        std::to_string(fold.size()) + " |\n";
  md += "| deepest such overlap (cube edges) | " + experiments::num(std::max(worst, 0.0)) + " |\n";
  md += "| time | " + experiments::num(r.seconds) + " s |\n";
  experiments::write_output(args, "summary.md", md);
  std::cerr << md;

  if (!args.check) return 0;
  bool ok = true;
  ok &= experiments::expect(path.path.size() == pixels * (method == "exact" ? 1 : 4), "path visits every pixel once");
  ok &= experiments::expect(r.status.ok(), "the chain straightens");
  ok &= experiments::expect(r.min_distance_growth >= -1e-12, "expansive: no pairwise distance shrinks (unfolding)");
  ok &= experiments::expect(r.max_length_error <= 1e-9, "bar lengths kept to 1e-9");
  ok &= experiments::expect(is_straight(fold.front()), "the folding starts straight");
  ok &= experiments::expect(end_error <= 1e-9, "the folding ends on the wrench head's path");
  return ok ? 0 : 1;
}
