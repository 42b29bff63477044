// foldkit.Status, foldkit.CreasePattern and the generators (foldkit.generators).
#include <cmath>
#include <random>

#include "bindings.hpp"
#include "foldkit/geometry/generators.hpp"

namespace foldkit::python {
namespace {

namespace gen = geometry::generators;

// Generators do not check their arguments (the CLI's parser does), so these do it here.
constexpr int kMaxCount = 100000;
void count(int n, const char* name) { require(n >= 1 && n <= kMaxCount, name, "an integer in [1, 100000]", n); }
gen::JointDefaults joints(double spring, double damping) {
  require(std::isfinite(spring) && spring >= 0.0, "spring", "finite and >= 0", spring);
  require(std::isfinite(damping) && damping >= 0.0, "damping", "finite and >= 0", damping);
  return {spring, damping};
}
geometry::CreasePattern built(geometry::PatternSpec spec, const std::string& title) {
  if (!title.empty()) spec.title = title;
  return geometry::build_or_throw(spec);
}
void cells(long long n, const char* what) {
  if (n > 4'000'000) throw py::value_error(std::string(what) + " would have more than 4,000,000 actors");
}

py::array_t<int> pairs(const std::vector<std::array<int, 2>>& rows) {
  py::array_t<int> out({static_cast<py::ssize_t>(rows.size()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    a(static_cast<py::ssize_t>(i), 0) = rows[i][0];
    a(static_cast<py::ssize_t>(i), 1) = rows[i][1];
  }
  return out;
}

template <class F>
py::array_t<double> per_joint(const geometry::CreasePattern& p, F value) {
  py::array_t<double> out(static_cast<py::ssize_t>(p.joints().size()));
  auto a = out.mutable_unchecked<1>();
  for (std::size_t j = 0; j < p.joints().size(); ++j) a(static_cast<py::ssize_t>(j)) = value(p.joints()[j]);
  return out;
}

void bind_status(py::module_& m) {
  py::class_<geometry::Status>(m, "Status", "How an algorithm ended: a code and a message in words.")
      .def_property_readonly(
          "code", [](const geometry::Status& s) { return std::string(geometry::to_string(s.code)); },
          "The code's name: 'success', 'invalid-input', 'collision', 'closure-violated', 'singular', "
          "'not-rigidly-foldable', 'no-solution', 'no-progress', 'limit-reached' or 'unknown' (as the CLI's JSON 'status').")
      .def_readonly("message", &geometry::Status::message, "Why, in words; a short summary on success.")
      .def_property_readonly("ok", &geometry::Status::ok, "Whether the code is 'success'.")
      .def("__bool__", &geometry::Status::ok, "Whether the code is 'success'.")
      .def("__repr__", [](const geometry::Status& s) {
        return "Status(" + std::string(geometry::to_string(s.code)) + ": " + s.message + ")";
      });
}

// The joints' facts: one entry per joint, in the order of a fold state's angles.
void bind_joints(py::class_<geometry::CreasePattern>& c) {
  using geometry::CreasePattern;
  c.def_property_readonly(
          "joint_ids", [](const CreasePattern& p) {
            std::vector<int> ids;
            for (const auto& j : p.joints()) ids.push_back(j.id);
            return ids;
          },
          "Joint (crease) IDs as in the file, in joint index order: the order of a fold state's angles.")
      .def_property_readonly(
          "joint_vertices", [](const CreasePattern& p) {
            std::vector<std::array<int, 2>> v;
            for (const auto& j : p.joints()) v.push_back(j.v);
            return pairs(v);
          },
          "Vertex indices of each joint's ends, shape (joints, 2).")
      .def_property_readonly(
          "joint_actors", [](const CreasePattern& p) {
            std::vector<std::array<int, 2>> v;
            for (const auto& j : p.joints()) v.push_back(j.actors);
            return pairs(v);
          },
          "Actor indices (not IDs) on either side of each joint, shape (joints, 2).")
      .def_property_readonly(
          "assignments", [](const CreasePattern& p) {
            std::vector<std::string> a;
            for (const auto& j : p.joints()) a.emplace_back(geometry::to_string(j.assignment));
            return a;
          },
          "Each joint's mountain/valley assignment: 'M' (folds to positive angles), 'V' (negative), 'F' (stays flat) or 'U'.")
      .def_property_readonly(
          "crease_directions", [](const CreasePattern& p) {
            Eigen::MatrixX2d d(static_cast<Eigen::Index>(p.joints().size()), 2);
            for (std::size_t j = 0; j < p.joints().size(); ++j) {
              const auto& jt = p.joints()[j];
              const geometry::Vec2 v = p.vertices()[static_cast<std::size_t>(jt.v[1])] - p.vertices()[static_cast<std::size_t>(jt.v[0])];
              d.row(static_cast<Eigen::Index>(j)) = v.normalized().transpose();
            }
            return d;
          },
          "Unit direction of each joint in the flat sheet, from its first vertex to its second (the rotation axis), shape (joints, 2).")
      .def_property_readonly(
          "springs", [](const CreasePattern& p) { return per_joint(p, [](const geometry::Joint& j) { return j.spring; }); },
          "Each joint's PMML SpringConst.")
      .def_property_readonly(
          "dampings", [](const CreasePattern& p) { return per_joint(p, [](const geometry::Joint& j) { return j.damping; }); },
          "Each joint's PMML DampConst.");
}

void bind_crease_pattern(py::module_& m) {
  using geometry::CreasePattern;
  py::class_<geometry::VertexStar>(m, "VertexStar", "An interior vertex and the creases around it.")
      .def_readonly("vertex", &geometry::VertexStar::vertex, "Vertex index.")
      .def_readonly("joints", &geometry::VertexStar::joints, "Joint indices around the vertex, counter-clockwise.")
      .def_readonly("directions", &geometry::VertexStar::directions, "Polar angle of each crease leaving the vertex, radians.")
      .def_readonly("sectors", &geometry::VertexStar::sectors, "Sector angles, radians, summing to 2π (one per crease).");

  py::class_<CreasePattern> c(m, "CreasePattern",
                            "An immutable crease pattern: facets (actors) of triangles joined by revolute creases (joints). "
                            "A fold state is a float array with one angle per joint, radians: 0 flat, positive mountain, "
                            "negative valley.");
  bind_joints(c);
  c.def_property_readonly("title", &CreasePattern::title, "The title (PMML Title).")
      .def_property_readonly(
          "vertices", [](const CreasePattern& p) {
            Eigen::MatrixX2d v(static_cast<Eigen::Index>(p.vertices().size()), 2);
            for (std::size_t i = 0; i < p.vertices().size(); ++i) v.row(static_cast<Eigen::Index>(i)) = p.vertices()[i].transpose();
            return v;
          },
          "Vertex coordinates in the flat sheet, shape (vertices, 2).")
      .def_property_readonly(
          "actor_ids", [](const CreasePattern& p) {
            std::vector<int> ids;
            for (const auto& a : p.actors()) ids.push_back(a.id);
            return ids;
          },
          "Actor (facet) IDs as in the file, in actor index order.")
      .def(
          "actor_triangles", [](const CreasePattern& p, int actor) {
            if (actor < 0 || static_cast<std::size_t>(actor) >= p.actors().size()) throw py::index_error("no actor index " + std::to_string(actor));
            const auto& tris = p.actors()[static_cast<std::size_t>(actor)].triangles;
            Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> t(static_cast<Eigen::Index>(tris.size()), 3);
            for (std::size_t i = 0; i < tris.size(); ++i)
              for (int k = 0; k < 3; ++k) t(static_cast<Eigen::Index>(i), k) = tris[i].v[static_cast<std::size_t>(k)];
            return t;
          },
          py::arg("actor"), "Vertex indices of the actor's triangles (counter-clockwise), shape (triangles, 3); `actor` is an index.")
      .def_property_readonly("interior_vertices", &CreasePattern::interior_vertices,
                             "The interior vertices, each a VertexStar (its creases counter-clockwise and its sector angles).")
      .def_property_readonly(
          "boundary_vertices", [](const CreasePattern& p) {
            py::array_t<bool> b(static_cast<py::ssize_t>(p.vertices().size()));
            auto a = b.mutable_unchecked<1>();
            for (py::ssize_t v = 0; v < a.shape(0); ++v) a(v) = p.is_boundary_vertex(static_cast<int>(v));
            return b;
          },
          "Per vertex, whether it lies on the sheet's boundary.")
      .def_property_readonly(
          "boundary_edges", [](const CreasePattern& p) { return pairs(p.boundary_edges()); }, "Vertex index pairs of the boundary edges, shape (edges, 2).")
      .def_property_readonly("diagonal", &CreasePattern::diagonal, "Length of the diagonal of the sheet's bounding box.")
      .def(
          "joint_index", [](const CreasePattern& p, int id) { return p.joint_index(id); }, py::arg("id"),
          "The index of the joint with this ID, or None.")
      .def(
          "actor_index", [](const CreasePattern& p, int id) { return p.actor_index(id); }, py::arg("id"),
          "The index of the actor with this ID, or None.")
      .def(
          "flat", [](const CreasePattern& p) { return Eigen::VectorXd(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(p.joints().size()))); },
          "The flat state: zeros, one per joint.")
      .def("__repr__", [](const CreasePattern& p) {
        return "<CreasePattern '" + p.title() + "': " + std::to_string(p.actors().size()) + " actors, " +
               std::to_string(p.joints().size()) + " joints, " + std::to_string(p.vertices().size()) + " vertices>";
      });
}

// The simple sheets: one vertex, strips, grids, circular lattices.
void bind_sheets(py::module_& g) {
  g.def(
      "single_vertex", [](const std::vector<double>& sectors, double radius, double spring, double damping, const std::string& title) {
        require(sectors.size() >= 3, "len(sectors)", "at least 3", static_cast<double>(sectors.size()));
        double sum = 0.0;
        for (double s : sectors) {
          require_positive(s, "every sector");
          sum += s;
        }
        // As the CLI: sectors typed by hand rarely sum to exactly 2π; tiny rounding is rescaled.
        require(std::abs(sum - 2.0 * M_PI) <= 1e-6, "sum(sectors)", "2π (within 1e-6)", sum);
        require_positive(radius, "radius");
        std::vector<double> scaled = sectors;
        for (double& s : scaled) s *= 2.0 * M_PI / sum;
        return built(gen::single_vertex(scaled, radius, joints(spring, damping)), title);
      },
      py::arg("sectors"), py::arg("radius") = 1.0, py::arg("spring") = 1.0, py::arg("damping") = 0.1, py::arg("title") = "",
      "One interior vertex with the given sector angles (radians, summing to 2π), counter-clockwise.");
  g.def(
      "random_sectors", [](int n, unsigned seed, double smallest) {
        require(n >= 3 && n <= kMaxCount, "n", "an integer in [3, 100000]", n);
        require(smallest > 0.0 && smallest * n < 2.0 * M_PI, "smallest", "positive and below 2π/n", smallest);
        std::mt19937 rng(seed);
        return gen::random_sectors(n, rng, smallest);
      },
      py::arg("n"), py::arg("seed") = 1, py::arg("smallest") = 0.05,
      "n random sector angles summing to 2π, none below `smallest` radians (the benchmark scenes' vertices); "
      "the same seed gives the same sectors.");
  g.def(
      "strip", [](int panels, double width, double height, double spring, double damping, const std::string& title) {
        count(panels, "panels");
        require_positive(width, "width");
        require_positive(height, "height");
        return built(gen::strip(panels, width, height, joints(spring, damping)), title);
      },
      py::arg("panels") = 4, py::arg("width") = 1.0, py::arg("height") = 1.0, py::arg("spring") = 1.0, py::arg("damping") = 0.1,
      py::arg("title") = "", "A row of rectangular panels joined by parallel creases (no interior vertex).");
  g.def(
      "grid", [](int rows, int cols, double cell, double spring, double damping, const std::string& title) {
        count(rows, "rows");
        count(cols, "cols");
        require_positive(cell, "cell");
        cells(static_cast<long long>(rows) * cols, "rows × cols");
        return built(gen::grid(rows, cols, cell, joints(spring, damping)), title);
      },
      py::arg("rows") = 4, py::arg("cols") = 4, py::arg("cell") = 1.0, py::arg("spring") = 1.0, py::arg("damping") = 0.1,
      py::arg("title") = "", "A square grid of cells, each cut into two triangles.");
  g.def(
      "circular_lattice", [](int rings, int spokes, double ring_width, double spring, double damping, const std::string& title) {
        count(rings, "rings");
        require(spokes >= 3 && spokes <= kMaxCount, "spokes", "an integer in [3, 100000]", spokes);
        require_positive(ring_width, "ring_width");
        cells(static_cast<long long>(rings) * spokes, "rings × spokes");
        return built(gen::circular_lattice(rings, spokes, ring_width, joints(spring, damping)), title);
      },
      py::arg("rings") = 3, py::arg("spokes") = 8, py::arg("ring_width") = 1.0, py::arg("spring") = 1.0, py::arg("damping") = 0.1,
      py::arg("title") = "", "Concentric rings crossed by radial creases.");
}

// The tessellations and the paper's examples.
void bind_tessellations(py::module_& g) {
  g.def(
      "miura", [](int rows, int cols, double a, double b, double angle, double spring, double damping, const std::string& title) {
        count(rows, "rows");
        count(cols, "cols");
        require_positive(a, "a");
        require_positive(b, "b");
        require(angle > 0.0 && angle <= M_PI / 2, "angle", "in (0, π/2] radians", angle);
        cells(static_cast<long long>(rows) * cols, "rows × cols");
        return built(gen::miura(rows, cols, a, b, angle, joints(spring, damping)), title);
      },
      py::arg("rows") = 4, py::arg("cols") = 4, py::arg("a") = 1.0, py::arg("b") = 1.0, py::arg("angle") = M_PI / 3,
      py::arg("spring") = 1.0, py::arg("damping") = 0.1, py::arg("title") = "",
      "A Miura-ori of rows × cols parallelograms (column width a, row height b, parallelogram angle in radians), "
      "mountain/valley assigned: 1 DOF once folded (the flat state is singular: foldkit.dof counts more there).");
  g.def(
      "waterbomb", [](int units, int rows, double spring, double damping, const std::string& title) {
        count(units, "units");
        count(rows, "rows");
        cells(static_cast<long long>(units) * rows * 8, "the waterbomb");
        return built(gen::waterbomb(units, rows, joints(spring, damping)), title);
      },
      py::arg("units") = 3, py::arg("rows") = 4, py::arg("spring") = 1.0, py::arg("damping") = 0.1, py::arg("title") = "",
      "A waterbomb tessellation of units × rows degree-6 bases, mountain/valley assigned.");
  g.def(
      "boat", [](double length, double half_width, double bow, double spring, double damping, const std::string& title) {
        require_positive(length, "length");
        require_positive(half_width, "half_width");
        require_positive(bow, "bow");
        return built(gen::boat(length, half_width, bow, joints(spring, damping)), title);
      },
      py::arg("length") = 4.0, py::arg("half_width") = 1.0, py::arg("bow") = 1.0, py::arg("spring") = 1.0,
      py::arg("damping") = 0.1, py::arg("title") = "", "The paper's boat: a sheet with two degree-4 vertices.");
  g.def(
      "square_twist", [](double side, double twist, double pleat, double spring, double damping, const std::string& title) {
        require_positive(side, "side");
        require_positive(pleat, "pleat");
        require(twist > 0.0 && twist < M_PI / 2, "twist", "strictly between 0 and π/2 radians", twist);
        return built(gen::square_twist(side, twist, pleat, joints(spring, damping)), title);
      },
      py::arg("side") = 1.0, py::arg("twist") = M_PI / 3, py::arg("pleat") = 1.0, py::arg("spring") = 1.0,
      py::arg("damping") = 0.1, py::arg("title") = "", "A square twist: a central square and four pleats (twist angle in radians).");
  g.def(
      "cube_sheet", [](int cubes, double tile, double spring, double damping, const std::string& title) {
        count(cubes, "cubes");
        require_positive(tile, "tile");
        return built(gen::cube_sheet(cubes, tile, joints(spring, damping)), title);
      },
      py::arg("cubes") = 2, py::arg("tile") = 1.0, py::arg("spring") = 1.0, py::arg("damping") = 0.1, py::arg("title") = "",
      "A row of cube nets that folds into a chain of cubes (foldkit.fold_cube_chain gives the sequence).");
}

}  // namespace

void bind_pattern(py::module_& m) {
  bind_status(m);
  bind_crease_pattern(m);
  py::module_ g = m.def_submodule("generators",
                                  "Crease-pattern generators, as `foldkit generate` (docs/GENERATORS.md). Lengths are in "
                                  "pattern units, angles in radians; every joint gets `spring` and `damping`.");
  bind_sheets(g);
  bind_tessellations(g);
}

}  // namespace foldkit::python
