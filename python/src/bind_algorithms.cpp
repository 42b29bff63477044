// The deterministic algorithms and the stiffness solver: projected folding, stiffness, planar
// and spherical Carpenter's rule, Hamiltonian paths of pixel/voxel shapes, the cube-chain fold.
#include "bindings.hpp"
#include "foldkit/analysis/solver.hpp"
#include "foldkit/analysis/structure.hpp"
#include "foldkit/folding/carpenter.hpp"
#include "foldkit/folding/carpenter_spherical.hpp"
#include "foldkit/folding/cube_chain.hpp"
#include "foldkit/folding/hamiltonian.hpp"
#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::python {
namespace {

using folding::Frame2;

void bind_fold(py::module_& m) {
  using R = folding::ProjectedFoldingResult;
  def_seconds(py::class_<R>(m, "FoldResult", "A projected-velocity fold: the closed states from flat, and how it stopped."),
              "Wall-clock seconds spent folding (not the replay).")
      .def_readonly("status", &R::status, "'success' when the target fraction was reached; else why it stopped.")
      .def_property_readonly("reached", [](const R& r) { return r.status.ok(); }, "Whether the target fraction was reached.")
      .def_property_readonly(
          "states", [](const R& r) { return states_array(r.states); },
          "Flat, then every accepted state, shape (steps + 1, joints), radians.")
      .def_readonly("fraction", &R::fraction, "Largest |fold angle| / π at the last state.")
      .def_readonly("target_distance", &R::target_distance,
                    "With `toward`: the largest |fold angle - target| at the last state, radians; else None.")
      .def_readonly("max_closure_error", &R::max_closure_error, "Largest loop error over the states, radians.")
      .def_readonly("max_chord_error", &R::max_chord_error,
                    "Largest loop error at the midpoint of the chord between consecutive states, radians.")
      .def_readonly("steps", &R::steps, "States after the flat one.")
      .def_readonly("newton_iterations", &R::newton_iterations, "Corrector iterations, all steps together.")
      .def_readonly("rank", &R::rank, "Rank of the closure Jacobian at the last decision.")
      .def_readonly("dof", &R::dof, "Creases − rank there.")
      .def_readonly("rank_gap", &R::rank_gap, "Singular-value gap of the last rank decision.")
      .def_readonly("rank_method", &R::rank_method, "How the rank was decided.")
      .def_readonly("rank_decisions", &R::rank_decisions, "Rank-revealing decisions made.")
      .def_property_readonly(
          "min_rank_gap", [](const R& r) { return r.rank_decisions ? py::object(py::float_(r.min_rank_gap)) : py::object(py::none()); },
          "Smallest singular-value gap over the rank decisions, or None when none was made.")
      .def_readonly("min_pivot_ratio", &R::min_pivot_ratio, "Smallest pivot ratio the rank screen saw.")
      .def_readonly("sequence", &R::sequence, "The CMML of the states (FoldSequence).")
      .def_readonly("replay", &R::replay,
                    "The simulator's SimulationReport of the sequence, or None. `status` stays 'success' when the target "
                    "was reached even if the replay is rejected: check `replay.valid` too (as the CLI's replay_ok).")
      .def("__repr__", [](const R& r) {
        return "FoldResult(" + std::string(geometry::to_string(r.status.code)) + ", fraction=" + py::repr(py::float_(r.fraction)).cast<std::string>() +
               ", steps=" + std::to_string(r.steps) + ")";
      });
  m.def(
      "fold",
      [](const geometry::CreasePattern& p, double fraction, const py::object& velocity, const py::object& toward, double max_step,
         double chord_tolerance, bool collisions, int max_steps, bool replay) {
        require(std::isfinite(fraction) && fraction > 0.0 && fraction <= 1.0, "fraction", "in (0, 1]", fraction);
        folding::ProjectedFoldingOptions o;
        if (!velocity.is_none() && !toward.is_none()) throw py::value_error("give velocity or toward, not both");
        if (!velocity.is_none()) {
          o.velocity = state_or_flat(p, velocity, "velocity").angles;
          if (!(o.velocity.cwiseAbs().maxCoeff() > 0.0)) throw py::value_error("velocity is zero on every crease");
        }
        if (!toward.is_none()) o.toward = state_or_flat(p, toward, "toward").angles;
        o.target_fraction = fraction;
        o.max_step = max_step;
        o.chord_tolerance = chord_tolerance;
        o.max_steps = max_steps;
        o.collisions = collisions;
        o.replay = replay;
        py::gil_scoped_release release;
        return folding::fold_projected(p, o);
      },
      py::arg("pattern"), py::arg("fraction") = folding::ProjectedFoldingOptions{}.target_fraction, py::arg("velocity") = py::none(),
      py::arg("toward") = py::none(), py::arg("max_step") = folding::ProjectedFoldingOptions{}.max_step,
      py::arg("chord_tolerance") = folding::ProjectedFoldingOptions{}.chord_tolerance,
      py::arg("collisions") = folding::ProjectedFoldingOptions{}.collisions, py::arg("max_steps") = folding::ProjectedFoldingOptions{}.max_steps,
      py::arg("replay") = folding::ProjectedFoldingOptions{}.replay,
      "Folds every crease at once along the closure manifold (Tachi's projected velocity), as `foldkit fold`, until the "
      "largest angle is `fraction` of π. `velocity` (one value per joint) defaults to the mountain/valley assignment. "
      "`toward` (a FoldState or one angle per joint, radians: e.g. read_pattern's `state` of an SVG) folds toward "
      "those angles instead: they are the velocity, and `fraction` is of their largest; `target_distance` says how "
      "far the fold ended from them. "
      "Steps are sized so that the chord between consecutive states leaves the closure manifold by at most "
      "`chord_tolerance` rad (0: fixed steps of `max_step`, otherwise the longest step). "
      "Bad options (e.g. max_step outside (0, 0.5]) raise ValueError.");
}

// One 3-vector of each module's result as the rows of a (modules, 3) array.
Eigen::MatrixX3d module_rows(const analysis::SolveResult& r, Eigen::Vector3d analysis::ModuleResult::*field) {
  Eigen::MatrixX3d rows(static_cast<Eigen::Index>(r.modules.size()), 3);
  for (std::size_t i = 0; i < r.modules.size(); ++i) rows.row(static_cast<Eigen::Index>(i)) = (r.modules[i].*field).transpose();
  return rows;
}

void bind_stiffness(py::module_& m) {
  using R = analysis::SolveResult;
  py::class_<R>(m, "StiffnessResult", "The lumped 6-DOF spring model's equilibrium under a load case.")
      .def_readonly("status", &R::status, "'success' when converged.")
      .def_readonly("iterations", &R::iterations, "Newton iterations.")
      .def_readonly("load_steps", &R::load_steps, "Load steps completed.")
      .def_readonly("residual_norm", &R::residual_norm, "Final residual norm.")
      .def_readonly("residual_floor", &R::residual_floor, "The residual rounding alone explains.")
      .def_readonly("condition_estimate", &R::condition_estimate, "Estimated condition number of the tangent stiffness.")
      .def_readonly("max_displacement", &R::max_displacement, "Largest centroid displacement, pattern units.")
      .def_property_readonly(
          "module_ids", [](const R& r) {
            std::vector<int> ids;
            for (const auto& mod : r.modules) ids.push_back(mod.id);
            return ids;
          },
          "Actor ID of each module, in the pattern's actor order.")
      .def_property_readonly(
          "fixed", [](const R& r) {
            std::vector<bool> f;
            for (const auto& mod : r.modules) f.push_back(mod.fixed);
            return f;
          },
          "Per module, whether it is held fixed.")
      .def_property_readonly(
          "displacements", [](const R& r) { return module_rows(r, &analysis::ModuleResult::displacement); },
          "Centroid displacement of each module, shape (modules, 3), pattern units.")
      .def_property_readonly(
          "rotations", [](const R& r) { return module_rows(r, &analysis::ModuleResult::rotation); },
          "Rotation vector of each module, shape (modules, 3), radians.")
      .def("__repr__", [](const R& r) {
        return "StiffnessResult(" + std::string(geometry::to_string(r.status.code)) + ", iterations=" + std::to_string(r.iterations) +
               ", max_displacement=" + py::repr(py::float_(r.max_displacement)).cast<std::string>() + ")";
      });
  m.def(
      "stiffness",
      [](const geometry::CreasePattern& p, const py::object& load_case, const py::object& state, bool linear, double detect_tolerance,
         int max_iterations) {
        require(max_iterations >= 1, "max_iterations", "at least 1", max_iterations);
        const analysis::Problem problem = stiffness_problem(p, load_case, state, detect_tolerance);
        analysis::SolveOptions so;
        so.linear = linear;
        so.max_total_iterations = max_iterations;
        py::gil_scoped_release release;
        return analysis::solve(problem, so);
      },
      py::arg("pattern"), py::arg("load_case"), py::arg("state") = py::none(), py::arg("linear") = false,
      py::arg("detect_tolerance") = analysis::DetectOptions{}.tolerance, py::arg("max_iterations") = analysis::SolveOptions{}.max_total_iterations,
      "Equilibrium of the folded `pattern` at `state` (default flat) under `load_case` (a path or a LoadCase), as "
      "`foldkit stiffness`: modules are the actors, springs the creases and the contacts found.");
}

py::array_t<double> frames_array(const std::vector<Frame2>& frames) {
  const std::size_t n = frames.empty() ? 0 : frames.front().size();
  py::array_t<double> out({static_cast<py::ssize_t>(frames.size()), static_cast<py::ssize_t>(n), py::ssize_t{2}});
  auto a = out.mutable_unchecked<3>();
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 2; ++k) a(static_cast<py::ssize_t>(f), static_cast<py::ssize_t>(i), k) = frames[f][i][k];
  return out;
}

// CarpenterPlanarResult unpacked member by member: a metric added to it stops this from compiling
// until it is bound in bind_carpenter() too, under its own name (`foldkit carpenter --json` has
// the same check; docs/CARPENTER.md, Metrics).
[[maybe_unused]] void every_carpenter_metric_is_bound(const folding::CarpenterPlanarResult& r) {
  [[maybe_unused]] const auto& [frames, closed, status, steps, lp_solves, carried_steps, window_lp_solves, held_steps, max_struts,
                                flips, straightenings, pseudo_lp_steps, certificate_seconds, seconds, max_length_error,
                                min_distance_growth] = r;
}

void bind_carpenter(py::module_& m) {
  using R = folding::CarpenterPlanarResult;
  py::class_<R>(m, "CarpenterResult", "Carpenter's rule on a planar chain: an expansive motion to straight (or convex).")
      .def_readonly("status", &R::status, "'success' when straight (open) or convex (closed).")
      .def_property_readonly("frames", [](const R& r) { return frames_array(r.frames); },
                             "The motion, shape (frames, points, 2); frames[0] is the input.")
      .def_readonly("closed", &R::closed, "Whether the chain is closed.")
      .def_readonly("steps", &R::steps, "Steps taken.")
      .def_readonly("lp_solves", &R::lp_solves, "LPs solved (window LPs included).")
      .def_readonly("window_lp_solves", &R::window_lp_solves, "Window LPs that mended a carried field (method 'carried').")
      .def_readonly("carried_steps", &R::carried_steps, "Steps on a carried, perhaps mended, field (method 'carried').")
      .def_readonly("held_steps", &R::held_steps, "Steps with part of an open chain held rigid (a spiral's slow ends; CARPENTER.md).")
      .def_readonly("max_struts", &R::max_struts, "Most strut rows any LP held.")
      .def_readonly("flips", &R::flips, "Flips of the pseudo-triangulation at events (method 'pseudo').")
      .def_readonly("straightenings", &R::straightenings, "Joints merged where two bars aligned (method 'pseudo').")
      .def_readonly("pseudo_lp_steps", &R::pseudo_lp_steps, "Steps the global LP took where no PPT could be built (method 'pseudo').")
      .def_readonly("certificate_seconds", &R::certificate_seconds,
                    "Wall-clock seconds of the all-pairs expansiveness check of the steps (method 'pseudo'; 0 otherwise).")
      .def_readonly("seconds", &R::seconds, "Wall-clock seconds of the run.")
      .def_readonly("max_length_error", &R::max_length_error, "Largest bar-length change over the frames.")
      .def_readonly("min_distance_growth", &R::min_distance_growth,
                    "Smallest change of any non-bar distance between frames (≥ 0: expansive).");
  m.def(
      "carpenter",
      [](const Eigen::MatrixX2d& points, bool closed, std::size_t max_steps, std::size_t frame_stride, const std::string& method) {
        require(frame_stride >= 1, "frame_stride", "at least 1", static_cast<double>(frame_stride));
        folding::PlanarChain chain;
        chain.closed = closed;
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
          require(points.row(i).allFinite(), "every point", "finite", points(i, 0));
          chain.points.push_back(points.row(i).transpose());
        }
        folding::check_simple_chain(chain);
        folding::CarpenterPlanarOptions o;
        o.max_steps = max_steps;
        o.frame_stride = frame_stride;
        o.method = folding::parse_carpenter_method(method);
        py::gil_scoped_release release;
        return folding::carpenter_planar(chain, o);
      },
      py::arg("points"), py::arg("closed") = false, py::arg("max_steps") = folding::CarpenterPlanarOptions{}.max_steps,
      py::arg("frame_stride") = 1, py::arg("method") = std::string(folding::to_string(folding::CarpenterPlanarOptions{}.method)),
      "Straightens an open planar chain (points: (n, 2) array) or convexifies a closed one, as `foldkit carpenter`; "
      "method 'carried' (the default), 'lp' or 'pseudo' as `--method` (docs/CARPENTER.md); ValueError when the chain is not simple "
      "or the method unknown.");

  using S = folding::CarpenterSphericalResult;
  py::class_<S>(m, "CarpenterVertexResult", "A single vertex flattened by the spherical Carpenter's rule.")
      .def_readonly("status", &S::status, "'success' when flat.")
      .def_property_readonly("frames", [](const S& r) { return states_array(r.frames); },
                             "Folded input … flat, shape (frames, joints), radians.")
      .def_readonly("steps", &S::steps, "LP steps taken.")
      .def_readonly("max_sector_error", &S::max_sector_error, "Largest sector-angle error, radians.")
      .def_readonly("min_distance_growth", &S::min_distance_growth, "Smallest change of a non-neighbour distance (≥ 0: expansive).")
      .def_readonly("max_closure_error", &S::max_closure_error, "Largest closure residual, radians.")
      .def_readonly("folding", &S::folding, "The CMML from flat to the input (the motion reversed).");
  m.def(
      "carpenter_vertex",
      [](const geometry::CreasePattern& p, const Eigen::VectorXd& state, int max_steps) {
        require(max_steps >= 1, "max_steps", "at least 1", max_steps);
        const geometry::FoldState folded = to_state(p, state, "state");
        folding::CarpenterSphericalOptions o;
        o.max_steps = max_steps;
        py::gil_scoped_release release;
        return folding::flatten_single_vertex(p, folded, o);
      },
      py::arg("pattern"), py::arg("state"), py::arg("max_steps") = folding::CarpenterSphericalOptions{}.max_steps,
      "Flattens a single-vertex pattern folded to `state` without self-intersection (`foldkit carpenter V.pmml --state`).");
}

// A Hamiltonian result with its path as an array of x, y[, z].
struct HamiltonianOut {
  geometry::Status status;
  py::array_t<int> path;
  bool cycle = false;
  std::uint64_t nodes = 0;
};

template <class Shape>
HamiltonianOut hamiltonian_of(const Shape& shape, bool refine, bool cycle, const py::object& start, std::uint64_t budget, int dims) {
  folding::ExactOptions o;
  o.cycle = cycle;
  o.node_budget = budget;
  if (!start.is_none()) {
    const auto c = start.cast<std::vector<int>>();
    if (static_cast<int>(c.size()) != dims) throw py::value_error("start must have " + std::to_string(dims) + " coordinates (x, y[, z])");
    o.start = folding::Cell{c[0], c[1], dims == 3 ? c[2] : 0};
  }
  folding::HamiltonianResult r;
  {
    py::gil_scoped_release release;
    r = refine ? folding::refined_hamiltonian_cycle(shape) : folding::exact_hamiltonian(shape, o);
  }
  py::array_t<int> path({static_cast<py::ssize_t>(r.path.size()), static_cast<py::ssize_t>(dims)});
  auto a = path.mutable_unchecked<2>();
  for (std::size_t i = 0; i < r.path.size(); ++i) {
    const auto row = static_cast<py::ssize_t>(i);
    a(row, 0) = r.path[i].x;
    a(row, 1) = r.path[i].y;
    if (dims == 3) a(row, 2) = r.path[i].z;
  }
  return {r.status, path, r.cycle, r.nodes};
}

void bind_hamiltonian(py::module_& m) {
  py::class_<HamiltonianOut>(m, "HamiltonianResult", "A Hamiltonian path or cycle through a shape's cells.")
      .def_readonly("status", &HamiltonianOut::status, "'success' when found, 'no-solution' when none exists, 'limit-reached' when undecided.")
      .def_readonly("path", &HamiltonianOut::path, "The cells in order, (cells, 2 or 3) int array of x, y[, z]; empty when none.")
      .def_readonly("cycle", &HamiltonianOut::cycle, "Whether the path is a cycle.")
      .def_readonly("nodes", &HamiltonianOut::nodes, "Search nodes expanded.");
  m.def(
      "hamiltonian",
      [](const py::array& cells, bool refine, bool cycle, const py::object& start, std::uint64_t budget) {
        const auto a = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(cells);
        if (!a || (a.ndim() != 2 && a.ndim() != 3)) throw py::value_error("shape must be a 2-D [y, x] or 3-D [z, y, x] array of cells");
        require(budget >= 1, "budget", "at least 1", static_cast<double>(budget));
        const bool* data = a.data();
        if (a.ndim() == 2) {
          geometry::PixelShape s;
          s.height = static_cast<int>(a.shape(0));
          s.width = static_cast<int>(a.shape(1));
          s.cells.assign(data, data + a.size());
          return hamiltonian_of(s, refine, cycle, start, budget, 2);
        }
        geometry::VoxelShape s;
        s.nz = static_cast<int>(a.shape(0));
        s.ny = static_cast<int>(a.shape(1));
        s.nx = static_cast<int>(a.shape(2));
        s.cells.assign(data, data + a.size());
        return hamiltonian_of(s, refine, cycle, start, budget, 3);
      },
      py::arg("shape"), py::arg("refine") = false, py::arg("cycle") = false, py::arg("start") = py::none(),
      py::arg("budget") = folding::ExactOptions{}.node_budget,
      "A Hamiltonian path (or cycle) through the filled cells of a pixel ([y, x]) or voxel ([z, y, x]) bool array, as "
      "`foldkit hamiltonian`: exact search within `budget` nodes, or with refine=True a cycle of the 2× refined shape in "
      "linear time. Returns a HamiltonianResult.");
  m.def(
      "fold_cube_chain",
      [](const geometry::CreasePattern& sheet, int cubes, double speed, const py::object& velocity) {
        speed = renamed(speed, 1.0, velocity, "velocity", "speed");
        require(cubes >= 1, "cubes", "at least 1", cubes);
        require_positive(speed, "speed");
        return folding::fold_cube_chain(sheet, cubes, speed);
      },
      py::arg("sheet"), py::arg("cubes"), py::arg("speed") = 1.0, py::arg("velocity") = py::none(),
      "The FoldSequence that folds generators.cube_sheet(cubes) into a chain of cubes, the hinges within a net at `speed` "
      "rad/s (`velocity`: its deprecated name).");
}

}  // namespace

void bind_algorithms(py::module_& m) {
  bind_fold(m);
  bind_stiffness(m);
  bind_carpenter(m);
  bind_hamiltonian(m);
}

}  // namespace foldkit::python
