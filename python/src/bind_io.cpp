// Fold sequences and every file foldkit reads or writes: PMML, CMML, FOLD, SVG, load cases,
// planar chains and pixel/voxel shapes. Writes go through a temporary file and a rename.
#include "bindings.hpp"
#include "foldkit/analysis/load_case.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/chain_file.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/file_name.hpp"
#include "foldkit/io/formats.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/io/shape_file.hpp"
#include "foldkit/io/svg.hpp"

namespace foldkit::python {
namespace {

using geometry::FoldSequence;

// A sequence read from a file remembers it, so that errors found later (simulate) name it.
py::object with_source(FoldSequence seq, const std::string& source) {
  py::object out = py::cast(std::move(seq));
  out.attr("source") = source;
  return out;
}

// FOLD's key frame and frames, as read.
struct FoldFile {
  geometry::CreasePattern pattern;
  py::object state;
  py::array_t<double> frames;
  std::vector<std::string> warnings;
};

geometry::BuildOptions build_options(double merge_tolerance, bool auto_joints) {
  require(merge_tolerance > 0.0 && merge_tolerance < 1e-2, "merge_tolerance", "in (0, 0.01)", merge_tolerance);
  geometry::BuildOptions o;
  o.merge_tolerance = merge_tolerance;
  o.auto_joints = auto_joints;
  return o;
}

// The key frame and frames write_fold adds, from Python arguments (None: left out).
io::FoldExport fold_export(const geometry::CreasePattern& p, const py::object& state, const py::object& frames) {
  io::FoldExport e;
  if (!state.is_none()) e.state = state_or_flat(p, state, "state");
  if (!frames.is_none()) e.frames = states_from_array(p, frames, "frames");
  return e;
}

FoldFile fold_file(io::FoldImport f, const std::string& name) {
  const auto joints = static_cast<Eigen::Index>(f.pattern.joints().size());
  std::vector<std::string> warnings;
  for (const auto& w : f.warnings) warnings.push_back(geometry::format(w, name));
  py::object state = f.state ? py::cast(f.state->angles) : py::none();
  return {std::move(f.pattern), state, states_array(f.frames, joints), std::move(warnings)};
}

void bind_fold_command(py::module_& m) {
  py::class_<geometry::FoldCommand>(m, "FoldCommand", "One joint's fold in an event: towards `angle` at `speed`.")
      .def(py::init([](int joint_id, double angle, double speed, const py::object& velocity) {
             speed = renamed(speed, 1.0, velocity, "velocity", "speed");
             require(std::isfinite(angle), "angle", "finite", angle);
             require_positive(speed, "speed");
             return geometry::FoldCommand{joint_id, angle, speed, 0};
           }),
           py::arg("joint_id"), py::arg("angle"), py::arg("speed") = 1.0, py::arg("velocity") = py::none(),
           "A fold of the joint with ID `joint_id` to `angle` radians at `speed` radians per second (the CMML's "
           "<Velocity>; `velocity` is the deprecated name of `speed`).")
      .def_readonly("joint_id", &geometry::FoldCommand::joint_id, "The joint's ID (not its index).")
      .def_readonly("angle", &geometry::FoldCommand::angle, "Target fold angle, radians.")
      .def_readonly("speed", &geometry::FoldCommand::speed, "How fast it turns towards it, radians per second (the CMML's <Velocity>).")
      .def_property_readonly(
          "velocity",
          [](const geometry::FoldCommand& c) {
            deprecated("FoldCommand.velocity is deprecated: use speed");
            return c.speed;
          },
          "Deprecated name of `speed`.")
      .def_readonly("line", &geometry::FoldCommand::line, "Source line in the CMML; 0 when not read from a file.")
      .def("__repr__", [](const geometry::FoldCommand& c) {
        return "FoldCommand(joint_id=" + std::to_string(c.joint_id) + ", angle=" + py::repr(py::float_(c.angle)).cast<std::string>() +
               ", speed=" + py::repr(py::float_(c.speed)).cast<std::string>() + ")";
      });
}

void bind_sequence(py::module_& m) {
  bind_fold_command(m);
  py::class_<geometry::FoldEvent>(m, "FoldEvent", "A CMML event: folds that run at the same time.")
      .def(py::init([](int number, std::vector<geometry::FoldCommand> folds) { return geometry::FoldEvent{number, std::move(folds)}; }),
           py::arg("number"), py::arg("folds"), "An event with its EventNumber and its folds.")
      .def_readonly("number", &geometry::FoldEvent::number, "The CMML EventNumber.")
      .def_readonly("folds", &geometry::FoldEvent::folds, "Its folds, in file order.");
  py::class_<FoldSequence>(m, "FoldSequence", py::dynamic_attr(),
                           "A fold sequence (CMML): events in order; a joint an event does not name keeps its angle. "
                           "`source` names the file it was read from, if any.")
      .def(py::init([](std::vector<geometry::FoldEvent> events, std::string title) {
             for (std::size_t i = 1; i < events.size(); ++i)
               if (events[i].number <= events[i - 1].number) throw py::value_error("event numbers must increase");
             return FoldSequence{std::move(title), std::move(events)};
           }),
           py::arg("events"), py::arg("title") = "", "A sequence of events (numbers increasing).")
      .def_readonly("title", &FoldSequence::title, "Free text (CMML Title).")
      .def_readonly("events", &FoldSequence::events, "The events, in increasing number.")
      .def(
          "check", [](const FoldSequence& s, const geometry::CreasePattern& p) {
            std::vector<std::string> out;
            for (const auto& d : geometry::check_sequence(p, s)) out.push_back(geometry::format(d, s.title.empty() ? "sequence" : s.title));
            return out;
          },
          py::arg("pattern"), "Problems with this sequence on `pattern` (unknown joints, a joint twice in an event), as messages.")
      .def(
          "end_state", [](const FoldSequence& s, const geometry::CreasePattern& p) { return geometry::end_state(p, s).angles; },
          py::arg("pattern"), "The state after the last event, from flat (angles carried through), radians.")
      .def(
          "event_states", [](const FoldSequence& s, const geometry::CreasePattern& p) {
            return states_array(geometry::event_states(p, s), static_cast<Eigen::Index>(p.joints().size()));
          },
          py::arg("pattern"), "The state before the first event and after each event, shape (events + 1, joints).")
      .def("__len__", [](const FoldSequence& s) { return s.events.size(); }, "The number of events.")
      .def("__repr__", [](const FoldSequence& s) {
        return "<FoldSequence '" + s.title + "': " + std::to_string(s.events.size()) + " events>";
      });

  m.def(
      "sequence_to",
      [](const geometry::CreasePattern& p, const Eigen::VectorXd& state, double speed, const std::string& title, const py::object& velocity) {
        speed = renamed(speed, M_PI / 6, velocity, "velocity", "speed");
        require_positive(speed, "speed");
        return geometry::sequence_to(p, to_state(p, state, "state"), speed, title);
      },
      py::arg("pattern"), py::arg("state"), py::arg("speed") = M_PI / 6, py::arg("title") = "", py::arg("velocity") = py::none(),
      "One event from flat to `state`, every joint at `speed` rad/s (`velocity`: its deprecated name).");
  m.def(
      "path_sequence",
      [](const geometry::CreasePattern& p, const py::object& waypoints, double max_speed, const std::string& title,
         const py::object& max_velocity) {
        max_speed = renamed(max_speed, 1.0, max_velocity, "max_velocity", "max_speed");
        require_positive(max_speed, "max_speed");
        return geometry::path_sequence(p, states_from_array(p, waypoints, "waypoints"), max_speed, title);
      },
      py::arg("pattern"), py::arg("waypoints"), py::arg("max_speed") = 1.0, py::arg("title") = "", py::arg("max_velocity") = py::none(),
      "One event per waypoint (rows of a (waypoints, joints) array, the first being where the sequence starts), the "
      "fastest joint of each at `max_speed` rad/s (`max_velocity`: its deprecated name).");
}

void bind_pattern_files(py::module_& m) {
  m.def(
      "read_pmml", [](const std::string& path, double merge_tolerance, bool auto_joints) {
        return io::read_pmml(path, build_options(merge_tolerance, auto_joints));
      },
      py::arg("path"), py::arg("merge_tolerance") = geometry::BuildOptions{}.merge_tolerance, py::arg("auto_joints") = geometry::BuildOptions{}.auto_joints,
      "Reads a PMML crease pattern; ParseError ('FILE:LINE: message') on bad input.");
  m.def(
      "parse_pmml", [](const std::string& text, const std::string& name) { return geometry::build_or_throw(io::parse_pmml(text, name)); },
      py::arg("text"), py::arg("name") = "<string>", "A crease pattern from PMML text; `name` stands for the file in messages.");
  m.def(
      "pmml_text", [](const geometry::CreasePattern& p) { return io::write_pmml(p); }, py::arg("pattern"), "The pattern as PMML text.");
  m.def(
      "write_pmml", [](const std::string& path, const geometry::CreasePattern& p) { io::write_file_atomic(path, io::write_pmml(p)); },
      py::arg("path"), py::arg("pattern"), "Writes the pattern as PMML (atomically: a temporary file renamed).");

  py::class_<FoldFile>(m, "FoldFile", "What a FOLD file held.")
      .def_readonly("pattern", &FoldFile::pattern, "The crease pattern, flat.")
      .def_readonly("state", &FoldFile::state, "The key frame's fold angles (radians, foldkit's sign: positive = mountain), or None.")
      .def_readonly("frames", &FoldFile::frames, "file_frames' fold angles, shape (frames, joints); empty when none.")
      .def_readonly("warnings", &FoldFile::warnings, "What was accepted with a warning, as 'FILE:LINE: message'.");
  m.def(
      "read_fold", [](const std::string& path, double merge_tolerance) {
        return fold_file(io::read_fold(path, build_options(merge_tolerance, false)), path);
      },
      py::arg("path"), py::arg("merge_tolerance") = geometry::BuildOptions{}.merge_tolerance,
      "Reads a FOLD 1.2 file (its fold angles change sign: FOLD's positive is valley).");
  m.def(
      "parse_fold", [](const std::string& text, const std::string& name) { return fold_file(io::parse_fold(text, name), name); },
      py::arg("text"), py::arg("name") = "<string>", "A FOLD file from its text.");
  m.def(
      "fold_text", [](const geometry::CreasePattern& p, const py::object& state, const py::object& frames) {
        return io::write_fold(p, fold_export(p, state, frames));
      },
      py::arg("pattern"), py::arg("state") = py::none(), py::arg("frames") = py::none(),
      "The pattern as FOLD 1.2 text, with a key frame `state` and `frames` (rows) if given.");
  m.def(
      "write_fold", [](const std::string& path, const geometry::CreasePattern& p, const py::object& state, const py::object& frames) {
        io::write_file_atomic(path, io::write_fold(p, fold_export(p, state, frames)));
      },
      py::arg("path"), py::arg("pattern"), py::arg("state") = py::none(), py::arg("frames") = py::none(),
      "Writes FOLD 1.2 (atomically), with a key frame `state` and `frames` (rows) if given.");
  m.def(
      "write_svg", [](const std::string& path, const geometry::CreasePattern& p, const py::object& state, bool joint_ids) {
        io::SvgOptions o;
        o.joint_ids = joint_ids;
        std::optional<geometry::FoldState> s;
        if (!state.is_none()) s = state_or_flat(p, state, "state");
        o.state = s ? &*s : nullptr;
        io::write_file_atomic(path, io::write_svg(p, o));
      },
      py::arg("path"), py::arg("pattern"), py::arg("state") = py::none(), py::arg("joint_ids") = false,
      "Writes the crease pattern as SVG (mountain/valley styled; with `state`, creases coloured by their angle's sign).");
}

// Any format of io::file_formats(), by extension, as the CLI's PATTERN arguments.
void bind_any_pattern_file(py::module_& m) {
  m.def(
      "load_pattern", [](const std::string& path) {
        try {
          return std::move(io::read_pattern_file(path).pattern);
        } catch (const io::UnknownFormat& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("path"),
      "A crease pattern by the extension of `path`, as the CLI's PATTERN arguments (.pmml, .fold, .svg in Origami "
      "Simulator's convention, ORIPA .cp and .opx).");
  m.def(
      "read_pattern", [](const std::string& path) {
        try {
          io::PatternFile f = io::read_pattern_file(path);
          std::vector<std::string> warnings;
          for (const auto& w : f.warnings) warnings.push_back(geometry::format(w, path));
          py::object state = f.state ? py::cast(f.state->angles) : py::none();
          const auto joints = static_cast<Eigen::Index>(f.pattern.joints().size());
          return FoldFile{std::move(f.pattern), state, states_array({}, joints), std::move(warnings)};
        } catch (const io::UnknownFormat& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("path"),
      "A crease pattern by the extension of `path` with the fold angles the file carries (FOLD's key frame, an SVG's "
      "targets: stroke opacity × 180°) as `state` (radians, positive = mountain) or None, and the reader's warnings "
      "(FILE:LINE: …); `frames` is empty.");
}

void bind_cmml(py::module_& m) {
  m.def(
      "read_cmml", [](const std::string& path) { return with_source(io::read_cmml(path), path); }, py::arg("path"),
      "Reads a CMML fold sequence (angles become radians).");
  m.def(
      "parse_cmml", [](const std::string& text, const std::string& name) { return with_source(io::parse_cmml(text, name), name); },
      py::arg("text"), py::arg("name") = "<string>", "A fold sequence from CMML text.");
  m.def(
      "cmml_text", [](const FoldSequence& s) { return io::write_cmml(s); }, py::arg("sequence"), "The sequence as CMML text (degrees).");
  m.def(
      "write_cmml", [](const std::string& path, const FoldSequence& s) { io::write_cmml_file(path, s); },
      py::arg("path"), py::arg("sequence"), "Writes the sequence as CMML (atomically).");
  m.def(
      "read_state",
      [](const geometry::CreasePattern& p, const std::string& path) { return checked_end_state(p, io::read_cmml(path), path).angles; },
      py::arg("pattern"), py::arg("path"),
      "The state at the end of a CMML on `pattern` (the CLI's --state FILE); ParseError at the line of a joint the pattern lacks.");
}

void bind_other_files(py::module_& m) {
  py::class_<analysis::LoadCase>(m, "LoadCase", "A stiffness load case: fixed actors, point loads, stiffness per connection kind.")
      .def_readonly("title", &analysis::LoadCase::title, "Free text.")
      .def_readonly("fixed", &analysis::LoadCase::fixed, "Actor IDs held fixed.")
      .def_property_readonly(
          "loads", [](const analysis::LoadCase& lc) {
            py::list out;
            for (const auto& l : lc.loads)
              out.append(py::make_tuple(l.actor, l.force, l.point ? py::cast(*l.point) : py::none()));
            return out;
          },
          "The loads as (actor ID, force (N, 3 floats), point or None for the centroid).");
  m.def("read_load_case", &analysis::read_load_case, py::arg("path"), "Reads a load case (docs/STIFFNESS.md).");
  m.def(
      "parse_load_case", [](const std::string& text, const std::string& name) { return analysis::parse_load_case(text, name); },
      py::arg("text"), py::arg("name") = "<string>", "A load case from its XML text.");
  m.def(
      "read_chain", [](const std::string& path) {
        const io::Frame2 points = io::parse_chain_points(io::read_file(path), path);
        Eigen::MatrixX2d out(static_cast<Eigen::Index>(points.size()), 2);
        for (std::size_t i = 0; i < points.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
        return out;
      },
      py::arg("path"), "A planar chain file (one 'x y' point per line) as an (points, 2) array.");
  m.def(
      "read_shape", [](const std::string& path) -> py::array {
        if (io::is_voxel_path(path)) {
          const geometry::VoxelShape s = io::read_voxel_shape(path);
          py::array_t<bool> out({s.nz, s.ny, s.nx});
          auto a = out.mutable_unchecked<3>();
          for (int z = 0; z < s.nz; ++z)
            for (int y = 0; y < s.ny; ++y)
              for (int x = 0; x < s.nx; ++x) a(z, y, x) = s.filled(x, y, z);
          return out;
        }
        const geometry::PixelShape s = io::read_pixel_shape(path);
        py::array_t<bool> out({s.height, s.width});
        auto a = out.mutable_unchecked<2>();
        for (int y = 0; y < s.height; ++y)
          for (int x = 0; x < s.width; ++x) a(y, x) = s.filled(x, y);
        return out;
      },
      py::arg("path"),
      "A pixel shape (.pbm, or a text grid) as a bool array indexed [y, x], or a voxel shape as [z, y, x] (as `foldkit hamiltonian`).");
}

}  // namespace

void bind_io(py::module_& m) {
  bind_sequence(m);
  bind_pattern_files(m);
  bind_any_pattern_file(m);
  bind_cmml(m);
  bind_other_files(m);
}

}  // namespace foldkit::python
