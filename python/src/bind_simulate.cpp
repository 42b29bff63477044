// foldkit.simulate: the kinematic replay of a fold sequence, with its report, frames and poses.
#include "bindings.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::python {
namespace {

using simulation::SimulationReport;

void bind_report_parts(py::module_& m) {
  py::class_<simulation::CollisionEvent>(m, "CollisionEvent", "The first time two facets crossed in an event.")
      .def_readonly("time", &simulation::CollisionEvent::time, "When, seconds from the start.")
      .def_readonly("event", &simulation::CollisionEvent::event, "EventNumber.")
      .def_readonly("actors", &simulation::CollisionEvent::actors, "Actor IDs (not indices).")
      .def_property_readonly("point", [](const simulation::CollisionEvent& c) { return c.point; }, "Where, world coordinates.")
      .def_property_readonly("kind", [](const simulation::CollisionEvent& c) { return std::string(simulation::to_string(c.kind)); },
                             "'mesh', 'stacked' or 'crease'.")
      .def_readonly("depth", &simulation::CollisionEvent::depth, "Mesh crossings: interpenetration, sheet units.")
      .def_readonly("closure_error", &simulation::CollisionEvent::closure_error, "Largest loop error then, radians.")
      .def_property_readonly("state", [](const simulation::CollisionEvent& c) { return c.state.angles; }, "The state then, radians.")
      .def("__repr__", [](const simulation::CollisionEvent& c) {
        return "CollisionEvent(event=" + std::to_string(c.event) + ", actors=(" + std::to_string(c.actors[0]) + ", " +
               std::to_string(c.actors[1]) + "), kind=" + simulation::to_string(c.kind) + ")";
      });
  py::class_<simulation::EventReport>(m, "EventReport", "One event of a simulated sequence.")
      .def_readonly("number", &simulation::EventReport::number, "EventNumber.")
      .def_readonly("start", &simulation::EventReport::start, "When it started, seconds.")
      .def_readonly("end", &simulation::EventReport::end, "When it ended, seconds.")
      .def_readonly("max_closure_error", &simulation::EventReport::max_closure_error, "Largest loop error in it, radians.")
      .def_readonly("reached", &simulation::EventReport::reached, "Whether every joint reached its angle.");
}

void bind_report(py::module_& m) {
  py::class_<SimulationReport>(m, "SimulationReport", py::dynamic_attr(),
                               "What the simulator found: valid or not (status), closure errors, collisions, and the "
                               "trajectory when frames were recorded (frames, frame_times, frame_events; poses).")
      .def_readonly("status", &SimulationReport::status, "'success' when valid; else 'collision' or 'closure-violated'.")
      .def_property_readonly("valid", [](const SimulationReport& r) { return r.status.ok(); }, "Whether the sequence is valid.")
      .def_property_readonly("model", [](const SimulationReport& r) { return std::string(simulation::to_string(r.model)); },
                             "The actuation model used.")
      .def_readonly("time_step", &SimulationReport::time_step, "Seconds per step.")
      .def_readonly("duration", &SimulationReport::duration, "Seconds the whole sequence took.")
      .def_readonly("max_closure_error", &SimulationReport::max_closure_error, "Largest loop error of every state checked, radians.")
      .def_readonly("closure_tolerance", &SimulationReport::closure_tolerance, "The tolerance used, radians.")
      .def_readonly("steps", &SimulationReport::steps, "Time steps.")
      .def_readonly("checks", &SimulationReport::checks, "States checked.")
      .def_readonly("events", &SimulationReport::events, "One EventReport per event.")
      .def_readonly("collisions", &SimulationReport::collisions, "CollisionEvents (the first few hundred).")
      .def_readonly("collision_count", &SimulationReport::collision_count, "All collisions counted.")
      .def_readonly("numerical", &SimulationReport::numerical, "Crossings explained by rounding, not counted as collisions.")
      .def_readonly("numerical_count", &SimulationReport::numerical_count, "All numerical crossings counted.")
      .def_readonly("problems", &SimulationReport::problems, "Why the sequence is invalid, in words; empty when valid.")
      .def_property_readonly(
          "frame_times", [](const SimulationReport& r) {
            std::vector<double> t;
            for (const auto& f : r.frames) t.push_back(f.time);
            return py::array(py::cast(t));
          },
          "Time of each recorded frame, seconds.")
      .def_property_readonly(
          "frame_events", [](const SimulationReport& r) {
            std::vector<int> e;
            for (const auto& f : r.frames) e.push_back(f.event);
            return py::array(py::cast(e));
          },
          "EventNumber of each recorded frame (−1 for the flat start).")
      .def_property_readonly(
          "frames", [](const SimulationReport& r) {
            std::vector<geometry::FoldState> s;
            for (const auto& f : r.frames) s.push_back(f.state);
            return states_array(s, r.final_state.angles.size());  // the width also when none
          },
          "Recorded states, shape (frames, joints), radians: every step, or with record_frames=False only each event's end.")
      .def_property_readonly("final_state", [](const SimulationReport& r) { return r.final_state.angles; }, "The state after the last event.")
      .def("__repr__", [](const SimulationReport& r) {
        return "SimulationReport(" + std::string(geometry::to_string(r.status.code)) + ", " + std::to_string(r.steps) + " steps, " +
               std::to_string(r.collision_count) + " collisions)";
      });
}

}  // namespace

void bind_simulate(py::module_& m) {
  bind_report_parts(m);
  bind_report(m);
  m.def(
      "simulate",
      [](const geometry::CreasePattern& p, const py::object& sequence_object, const std::string& model, double time_step,
         double closure_tolerance, bool collisions, bool record_frames, bool poses, double max_event_time) {
        const auto& sequence = sequence_object.cast<const geometry::FoldSequence&>();
        const std::string source = source_of(sequence_object);
        require_valid(p, sequence, source);
        require_positive(time_step, "time_step");
        require_positive(closure_tolerance, "closure_tolerance");
        require_positive(max_event_time, "max_event_time");
        simulation::SimulationOptions o;
        o.model = simulation::parse_actuation(model);
        o.time_step = time_step;
        o.closure_tolerance = closure_tolerance;
        o.collisions = collisions;
        o.record_frames = record_frames || poses;
        o.max_event_time = max_event_time;
        SimulationReport report;
        try {
          py::gil_scoped_release release;
          report = simulation::simulate(p, sequence, o);
        } catch (const simulation::SequenceError& e) {
          throw io::ParseError(source, e.line, e.what());
        }
        py::object pose_array = py::none();
        if (poses) {
          std::vector<geometry::FoldState> states;
          for (const auto& f : report.frames) states.push_back(f.state);
          pose_array = poses_array(p, states);
        }
        py::object out = py::cast(std::move(report));
        out.attr("poses") = pose_array;
        return out;
      },
      // SimulationOptions' defaults, but record_frames: the frames are what a notebook plots.
      py::arg("pattern"), py::arg("sequence"), py::arg("model") = std::string(simulation::to_string(simulation::SimulationOptions{}.model)),
      py::arg("time_step") = simulation::SimulationOptions{}.time_step,
      py::arg("closure_tolerance") = simulation::SimulationOptions{}.closure_tolerance,
      py::arg("collisions") = simulation::SimulationOptions{}.collisions, py::arg("record_frames") = true, py::arg("poses") = false,
      py::arg("max_event_time") = simulation::SimulationOptions{}.max_event_time,
      "Replays `sequence` on `pattern` as `foldkit simulate`: model 'motor' (CMML speeds), 'spring' or 'sync'. "
      "Returns a SimulationReport; with poses=True its `poses` holds each actor's 4×4 pose at every frame, shape "
      "(frames, actors, 4, 4). A sequence naming joints the pattern lacks raises ParseError at its line.");
}

}  // namespace foldkit::python
