// foldkit.simulate: the kinematic replay of a fold sequence, with its report, frames and poses;
// model="dynamic": the physical replay of foldkit::dynamics, with its DynamicReport.
#include <map>
#include <optional>

#include "bindings.hpp"
#include "foldkit/dynamics/dynamic_simulate.hpp"
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

// The dynamic report's parts: stalls, contacts, events, joints.
void bind_dynamic_report_parts(py::module_& m) {
  py::class_<dynamics::Stall>(m, "Stall", "A joint that did not reach its angle in the dynamic model.")
      .def_readonly("joint", &dynamics::Stall::joint, "Joint ID.")
      .def_readonly("event", &dynamics::Stall::event, "EventNumber.")
      .def_readonly("time", &dynamics::Stall::time, "When, seconds from the start.")
      .def_readonly("angle", &dynamics::Stall::angle, "Its angle then, radians.")
      .def_readonly("target", &dynamics::Stall::target, "The angle it was driven to, radians.")
      .def_readonly("needed_torque", &dynamics::Stall::needed_torque, "Torque to hold the sheet there at rest without the contacts of its moving side, N·m.")
      .def_readonly("available_torque", &dynamics::Stall::available_torque, "The motor's limit (a spring's k·|θ*−θ|), N·m.")
      .def_readonly("blocked_by", &dynamics::Stall::blocked_by,
                    "Actor IDs of the contact that blocks it (one: the ground); empty: its torque was too small.");
  py::class_<dynamics::Contact>(m, "Contact", "Two facets, or a facet and the ground, that touched in the dynamic model.")
      .def_readonly("actors", &dynamics::Contact::actors, "Actor IDs: two facets, or one for the ground.")
      .def_readonly("ground", &dynamics::Contact::ground, "Whether the other side is the ground plane.")
      .def_readonly("event", &dynamics::Contact::event, "EventNumber when they first touched.")
      .def_readonly("time", &dynamics::Contact::time, "When they first touched, seconds.")
      .def_property_readonly("point", [](const dynamics::Contact& c) { return c.point; }, "Where they first touched, world metres.")
      .def_readonly("max_penetration", &dynamics::Contact::max_penetration, "Deepest overlap over the run, metres.");
  py::class_<dynamics::DynamicEventReport>(m, "DynamicEventReport", "One event of a dynamic run.")
      .def_readonly("number", &dynamics::DynamicEventReport::number, "EventNumber.")
      .def_readonly("start", &dynamics::DynamicEventReport::start, "Seconds.")
      .def_readonly("end", &dynamics::DynamicEventReport::end, "Seconds.")
      .def_readonly("reached", &dynamics::DynamicEventReport::reached, "Whether every joint it names reached its angle.")
      .def_readonly("max_closure_error", &dynamics::DynamicEventReport::max_closure_error, "Radians.")
      .def_readonly("energy", &dynamics::DynamicEventReport::energy, "Kinetic + gravitational + spring energy at its end, J.");
  py::class_<dynamics::JointReport>(m, "JointReport", "One joint over a dynamic run.")
      .def_readonly("id", &dynamics::JointReport::id, "Joint ID.")
      .def_readonly("peak_torque", &dynamics::JointReport::peak_torque, "Largest |torque| of its motor or spring, N·m.")
      .def_readonly("angle", &dynamics::JointReport::angle, "Final angle, radians.");
}

void bind_dynamic_report(py::module_& m) {
  using dynamics::DynamicReport;
  bind_dynamic_report_parts(m);
  py::class_<DynamicReport>(m, "DynamicReport", py::dynamic_attr(),
                            "What simulate(model='dynamic') found: status, stalls, peak torques, closure drift, energy, frames.")
      .def_readonly("status", &DynamicReport::status,
                    "'success', or 'no-progress' (a stall), 'collision' (a blocked motor, facets passed through), "
                    "'limit-reached', 'closure-violated', 'singular'.")
      .def_property_readonly("valid", [](const DynamicReport& r) { return r.status.ok(); }, "Whether every event reached its angles.")
      .def_property_readonly("model", [](const DynamicReport&) { return std::string(dynamics::kModelName); }, "'dynamic'.")
      .def_readonly("time_step", &DynamicReport::time_step, "Seconds per engine step.")
      .def_readonly("duration", &DynamicReport::duration, "Simulated seconds.")
      .def_readonly("seconds", &DynamicReport::seconds, "Wall-clock seconds the engine ran.")
      .def_readonly("steps", &DynamicReport::steps, "Engine steps.")
      .def_readonly("max_closure_error", &DynamicReport::max_closure_error, "Closure drift of the engine's poses, radians.")
      .def_readonly("max_corrected_error", &DynamicReport::max_corrected_error,
                    "Loop error the engine's steps left before the post-stabilisations removed it, radians (0: none).")
      .def_readonly("failed_corrections", &DynamicReport::failed_corrections,
                    "Post-stabilisations that found no closed state near the engine's (0: every one closed).")
      .def_readonly("closure_tolerance", &DynamicReport::closure_tolerance, "Radians.")
      .def_readonly("events", &DynamicReport::events, "One DynamicEventReport per event run.")
      .def_readonly("stalls", &DynamicReport::stalls, "Stalls.")
      .def_readonly("joints", &DynamicReport::joints, "One JointReport per joint.")
      .def_readonly("contacts", &DynamicReport::contacts, "Every pair that touched (contacts=True, ground), in order.")
      .def_readonly("max_penetration", &DynamicReport::max_penetration, "Deepest overlap of any contact, metres.")
      .def_readonly("thickness", &DynamicReport::thickness, "The sheet's thickness for contacts, metres (0: none).")
      .def_readonly("kinetic_energy", &DynamicReport::kinetic_energy, "At the end, J.")
      .def_readonly("potential_energy", &DynamicReport::potential_energy, "Gravitational, relative to flat, at the end, J.")
      .def_readonly("spring_energy", &DynamicReport::spring_energy, "At the end, J.")
      .def_readonly("peak_kinetic_energy", &DynamicReport::peak_kinetic_energy, "J.")
      .def_readonly("problems", &DynamicReport::problems, "Why the run failed, in words.")
      .def_property_readonly(
          "frame_times", [](const DynamicReport& r) {
            std::vector<double> t;
            for (const auto& f : r.frames) t.push_back(f.time);
            return py::array(py::cast(t));
          },
          "Time of each recorded frame, seconds.")
      .def_property_readonly(
          "frames", [](const DynamicReport& r) {
            std::vector<geometry::FoldState> s;
            for (const auto& f : r.frames) s.push_back(f.state);
            return states_array(s, r.final_state.angles.size());
          },
          "Recorded states, shape (frames, joints), radians.")
      .def_property_readonly(
          "frame_torques", [](const DynamicReport& r) {
            std::vector<geometry::FoldState> t;
            for (const auto& v : r.frame_torques) t.push_back({v});
            return states_array(t, r.final_state.angles.size());
          },
          "Each joint's motor or spring torque at each frame, shape (frames, joints), N·m (0: free hinge).")
      .def_property_readonly("final_state", [](const DynamicReport& r) { return r.final_state.angles; }, "The engine's final angles.")
      .def("__repr__", [](const DynamicReport& r) {
        return "DynamicReport(" + std::string(geometry::to_string(r.status.code)) + ", " + std::to_string(r.steps) + " steps, " +
               std::to_string(r.stalls.size()) + " stalls)";
      });
}

// The physical options, each defaulting to dynamics::DynamicOptions' member (density, gravity,
// fixed: None, which leaves them to the pattern's PMML and then to that default).
struct PhysicsArgs {
  std::optional<Eigen::Vector3d> gravity;  // None: the pattern's <Gravity>, else none
  std::optional<double> density;           // None: the pattern's <Density>, else kDefaultDensity
  double max_torque, scale;
  py::object fixed;  // None: the pattern's <FixedActor>, else the first actor; an actor ID; "none": no actor held
  std::string drive;
  std::optional<double> ground;
  bool contacts;
  std::optional<double> friction;
  std::optional<double> thickness;
  std::optional<std::map<int, double>> joint_torque;
  py::object start;  // None: flat; angles (radians); or a FoldSequence, whose end state it starts from
  std::string solver;
  int iterations;
  double projection_interval;

  // Whether any differs from its default: they belong to the dynamic model only (as on the CLI).
  std::string given() const {
    const dynamics::DynamicOptions d;
    const std::pair<bool, const char*> named[] = {
        {gravity.has_value(), "gravity"}, {density.has_value(), "density"}, {max_torque != d.max_torque, "max_torque"},
        {scale != d.scale, "scale"}, {!fixed.is_none(), "fixed"}, {drive != dynamics::to_string(d.drive), "drive"},
        {ground.has_value(), "ground"}, {contacts != d.contacts, "contacts"}, {friction.has_value(), "friction"},
        {thickness.has_value(), "thickness"}, {joint_torque.has_value(), "joint_torque"}, {!start.is_none(), "start"},
        {solver != dynamics::to_string(d.solver), "solver"}, {iterations != d.iterations, "iterations"},
        {projection_interval != d.projection_interval, "projection_interval"}};
    for (const auto& [differs, name] : named)
      if (differs) return name;
    return {};
  }
};

// fixed=: None (the pattern's <FixedActor>, else the first actor), an actor ID of the pattern, or
// "none" (no actor held).
void set_fixed(dynamics::DynamicOptions& o, const geometry::CreasePattern& p, const py::object& fixed) {
  if (fixed.is_none()) return;
  if (py::isinstance<py::str>(fixed)) {
    if (fixed.cast<std::string>() != "none") throw py::value_error("fixed must be an actor ID, None or 'none'");
    o.hold_fixed = false;
    return;
  }
  const int id = fixed.cast<int>();
  require(p.actor_index(id).has_value(), "fixed", "an actor ID of the pattern", id);
  o.fixed_actor = id;
}

py::object simulate_dynamic(const geometry::CreasePattern& p, const geometry::FoldSequence& sequence, const std::string& source,
                            const PhysicsArgs& a, std::optional<double> time_step, std::optional<double> closure_tolerance,
                            std::optional<double> max_event_time, bool record_frames) {
  // density, gravity, fixed: given here, over the pattern's (PMML extensions), which
  // simulate_dynamic() takes where these stay empty.
  dynamics::DynamicOptions o;
  if (a.density) require_positive(*a.density, "density");
  require_positive(a.max_torque, "max_torque");
  require_positive(a.scale, "scale");
  o.density = a.density;
  o.max_torque = a.max_torque;
  o.scale = a.scale;
  o.gravity = a.gravity;
  if (a.gravity) require(a.gravity->allFinite(), "gravity", "finite", a.gravity->sum());
  set_fixed(o, p, a.fixed);
  o.drive = dynamics::parse_drive(a.drive);
  // The rest are checked by simulate_dynamic itself (std::invalid_argument: ValueError).
  o.ground = a.ground;
  o.contacts = a.contacts;
  o.friction = a.friction;
  o.thickness = a.thickness;
  if (a.joint_torque) o.joint_max_torque = *a.joint_torque;
  // As plan(start=…): a state, or a FoldSequence (its end state), as the CLI's --start CMML.
  if (!a.start.is_none())
    o.start = py::isinstance<geometry::FoldSequence>(a.start)
                  ? geometry::end_state(p, a.start.cast<const geometry::FoldSequence&>()).angles
                  : a.start.cast<Eigen::VectorXd>();
  o.solver = dynamics::parse_solver(a.solver);
  o.iterations = a.iterations;
  o.projection_interval = a.projection_interval;
  o.time_step = time_step.value_or(o.time_step);
  o.closure_tolerance = closure_tolerance.value_or(o.closure_tolerance);
  o.max_event_time = max_event_time.value_or(o.max_event_time);
  o.record_frames = record_frames;
  dynamics::DynamicReport report;
  try {
    py::gil_scoped_release release;
    report = dynamics::simulate_dynamic(p, sequence, o);
  } catch (const simulation::SequenceError& e) {
    throw io::ParseError(source, e.line, e.what());
  }
  return py::cast(std::move(report));
}

}  // namespace

void bind_simulate(py::module_& m) {
  bind_dynamic_report(m);
  bind_report_parts(m);
  bind_report(m);
  m.def(
      "simulate",
      [](const geometry::CreasePattern& p, const py::object& sequence_object, const std::string& model,
         std::optional<double> time_step, std::optional<double> closure_tolerance, bool collisions, bool record_frames, bool poses,
         std::optional<double> max_event_time, std::optional<Eigen::Vector3d> gravity, std::optional<double> density,
         double max_torque, const py::object& fixed, double scale, const std::string& drive, std::optional<double> ground, bool contacts,
         std::optional<double> friction, std::optional<double> thickness, std::optional<std::map<int, double>> joint_torque,
         const py::object& start, const std::string& solver, int iterations,
         double projection_interval) -> py::object {
        const auto& sequence = sequence_object.cast<const geometry::FoldSequence&>();
        const std::string source = source_of(sequence_object);
        require_valid(p, sequence, source);
        for (const auto& [value, name] : {std::pair{time_step, "time_step"}, {closure_tolerance, "closure_tolerance"},
                                          {max_event_time, "max_event_time"}})
          if (value) require_positive(*value, name);
        const PhysicsArgs physics{gravity, density, max_torque, scale, fixed, drive, ground, contacts, friction, thickness,
                                  joint_torque, start, solver, iterations, projection_interval};
        if (model == dynamics::kModelName)
          return simulate_dynamic(p, sequence, source, physics, time_step, closure_tolerance, max_event_time, record_frames);
        if (const std::string name = physics.given(); !name.empty())
          throw py::value_error(name + "= belongs to model='dynamic', not to model='" + model + "'");
        simulation::SimulationOptions o;
        o.model = simulation::parse_actuation(model);
        o.time_step = time_step.value_or(o.time_step);
        o.closure_tolerance = closure_tolerance.value_or(o.closure_tolerance);
        o.collisions = collisions;
        o.record_frames = record_frames || poses;
        o.max_event_time = max_event_time.value_or(o.max_event_time);
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
      // time_step, closure_tolerance, max_event_time: None takes the model's own default
      // (SimulationOptions' or DynamicOptions').
      py::arg("time_step") = py::none(), py::arg("closure_tolerance") = py::none(),
      py::arg("collisions") = simulation::SimulationOptions{}.collisions, py::arg("record_frames") = true, py::arg("poses") = false,
      py::arg("max_event_time") = py::none(), py::arg("gravity") = py::none(),
      py::arg("density") = py::none(), py::arg("max_torque") = dynamics::DynamicOptions{}.max_torque,
      py::arg("fixed") = py::none(), py::arg("scale") = dynamics::DynamicOptions{}.scale,
      py::arg("drive") = std::string(dynamics::to_string(dynamics::DynamicOptions{}.drive)), py::arg("ground") = py::none(),
      py::arg("contacts") = dynamics::DynamicOptions{}.contacts, py::arg("friction") = py::none(),
      py::arg("thickness") = py::none(), py::arg("joint_torque") = py::none(), py::arg("start") = py::none(),
      py::arg("solver") = std::string(dynamics::to_string(dynamics::DynamicOptions{}.solver)),
      py::arg("iterations") = dynamics::DynamicOptions{}.iterations,
      py::arg("projection_interval") = dynamics::DynamicOptions{}.projection_interval,
      "Replays `sequence` on `pattern` as `foldkit simulate`: model 'motor' (CMML speeds), 'spring', 'sync', or 'dynamic' "
      "(a physics engine: returns a DynamicReport; gravity (x, y, z) m/s², density kg/m² (None: the pattern's PMML "
      "<Gravity>, <Density>, else none, 1), max_torque N·m (joints without their own <MaxTorque>), joint_torque "
      "{joint ID: N·m}, fixed actor ID (None: the pattern's <FixedActor>, else the first; 'none': no actor held), "
      "scale metres per pattern unit, drive "
      "'motor' or 'spring', ground z of a ground plane (m), contacts=True for facet–facet contacts, friction μ (None: 0.5), "
      "thickness m, start (angles in radians, or a FoldSequence: its end state, as --start CMML) to start from, solver 'direct' or 'iterative' with iterations sweeps, "
      "projection_interval s between post-stabilisations (0: none); docs/SIMULATION.md; these are refused for the other models). "
      "time_step, closure_tolerance and max_event_time default to the model's own (None). "
      "Returns a SimulationReport; with poses=True its `poses` holds each actor's 4×4 pose at every frame, shape "
      "(frames, actors, 4, 4). A sequence naming joints the pattern lacks raises ParseError at its line.");
}

}  // namespace foldkit::python
