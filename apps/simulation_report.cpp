#include "simulation_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/simulation/snapshot.hpp"

namespace foldkit::apps {

nlohmann::json report_json(const geometry::CreasePattern& pattern, const simulation::SimulationReport& r) {
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : r.events)
    events.push_back({{"number", e.number}, {"start", e.start}, {"end", e.end}, {"max_closure_error", e.max_closure_error},
                      {"reached", e.reached}});
  auto listed = [](const std::vector<simulation::CollisionEvent>& list) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& c : list) {
      nlohmann::json one = {{"actors", c.actors},
                            {"time", c.time},
                            {"event", c.event},
                            {"point", {c.point.x(), c.point.y(), c.point.z()}},
                            {"kind", simulation::to_string(c.kind)},
                            {"closure_error", c.closure_error}};
      if (c.kind == simulation::CrossingKind::Mesh) one["depth"] = c.depth;
      if (c.closed_depth >= 0.0) one["closed_depth"] = c.closed_depth;
      out.push_back(std::move(one));
    }
    return out;
  };
  nlohmann::json angles = nlohmann::json::array();
  for (std::size_t j = 0; j < pattern.joints().size(); ++j)
    angles.push_back({{"joint", pattern.joints()[j].id},
                      {"angle", r.final_state.angles[static_cast<Eigen::Index>(j)] * 180.0 / M_PI}});
  return {{"ok", r.status.ok()},  // deprecated: status
          {"status", geometry::to_string(r.status.code)},
          {"message", r.status.message},
          {"model", simulation::to_string(r.model)},
          {"time_step", r.time_step},
          {"duration", r.duration},
          {"steps", r.steps},
          {"checks", r.checks},
          {"max_closure_error", r.max_closure_error},
          {"closure_tolerance", r.closure_tolerance},
          {"events", events},
          {"collisions", listed(r.collisions)},
          {"collision_count", r.collision_count},
          {"numerical_collisions", listed(r.numerical)},
          {"numerical_collision_count", r.numerical_count},
          {"problems", r.problems},
          {"final_angles", angles}};
}

void print_summary(const std::string& name, const simulation::SimulationReport& r) {
  std::cerr << name << ": " << r.events.size() << " events, " << r.duration << " s (" << r.steps << " steps, " << r.checks
            << " checks, model " << simulation::to_string(r.model) << "), max closure error " << r.max_closure_error << " rad, "
            << r.collision_count << " collision" << (r.collision_count == 1 ? "" : "s");
  if (r.numerical_count > 0)
    std::cerr << " (and " << r.numerical_count << " numerical: gone once the state is projected onto closure)";
  std::cerr << ": " << (r.status.ok() ? "valid" : "INVALID") << '\n';
  for (const auto& p : r.problems) std::cerr << "  " << p << '\n';
}

std::string trajectory_fold(const geometry::CreasePattern& pattern, const simulation::SimulationReport& r,
                            std::size_t max_frames) {
  io::FoldExport out;
  out.state = r.final_state;
  const std::size_t n = r.frames.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + max_frames - 1) / std::max<std::size_t>(1, max_frames));
  for (std::size_t i = 0; i < n; i += stride) {
    out.frames.push_back(r.frames[i].state);
    out.frame_times.push_back(r.frames[i].time);
  }
  if (n > 0 && (n - 1) % stride != 0) {
    out.frames.push_back(r.frames.back().state);
    out.frame_times.push_back(r.frames.back().time);
  }
  return io::write_fold(pattern, out);
}

std::vector<std::string> write_snapshots(const geometry::CreasePattern& pattern, const simulation::SimulationReport& r,
                                         const std::string& dir, std::size_t max_collisions) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const geometry::KinematicTree tree = geometry::make_tree(pattern);
  std::vector<std::string> written;
  auto draw = [&](const std::string& file, const geometry::FoldState& state, simulation::SnapshotOptions o) {
    const std::string path = (fs::path(dir) / file).string();
    io::write_file_atomic(path, simulation::snapshot_svg(pattern, geometry::facet_poses(pattern, tree, state), o));
    written.push_back(path);
  };
  for (std::size_t e = 0; e < r.events.size(); ++e) {
    const int number = r.events[e].number;
    const auto last = std::find_if(r.frames.rbegin(), r.frames.rend(), [&](const auto& f) { return f.event == number; });
    if (last == r.frames.rend()) continue;
    simulation::SnapshotOptions o;
    for (const auto& c : r.collisions)
      if (c.event == number)
        for (int id : c.actors) o.marked.push_back(*pattern.actor_index(id));
    o.caption = pattern.title() + " — event " + std::to_string(number) + ", t = " + std::to_string(last->time) + " s" +
                (o.marked.empty() ? "" : " (collisions in red)");
    draw("event-" + std::to_string(number) + ".svg", last->state, o);
  }
  for (std::size_t k = 0; k < r.collisions.size() && k < max_collisions; ++k) {
    const auto& c = r.collisions[k];
    simulation::SnapshotOptions o;
    for (int id : c.actors) o.marked.push_back(*pattern.actor_index(id));
    o.caption = "collision " + std::to_string(k + 1) + ": actors " + std::to_string(c.actors[0]) + " and " +
                std::to_string(c.actors[1]) + ", event " + std::to_string(c.event) + ", t = " + std::to_string(c.time) + " s";
    draw("collision-" + std::to_string(k + 1) + ".svg", c.state, o);
  }
  return written;
}

nlohmann::json dynamic_report_json(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& r,
                                   const dynamics::DynamicOptions& given) {
  // The settings the run had: density, gravity and the held actor from the pattern's file where
  // the options left them to it.
  const dynamics::DynamicOptions o = dynamics::resolve_options(pattern, given);
  constexpr double deg = 180.0 / M_PI;
  nlohmann::json events = nlohmann::json::array(), stalls = nlohmann::json::array(), joints = nlohmann::json::array();
  for (const auto& e : r.events)
    events.push_back({{"number", e.number}, {"start", e.start}, {"end", e.end}, {"reached", e.reached},
                      {"max_closure_error", e.max_closure_error}, {"energy", e.energy}});
  for (const auto& s : r.stalls)
    stalls.push_back({{"joint", s.joint}, {"event", s.event}, {"time", s.time}, {"angle", s.angle * deg},
                      {"target", s.target * deg}, {"needed_torque", s.needed_torque}, {"available_torque", s.available_torque},
                      {"blocked_by", s.blocked_by}});
  for (const auto& j : r.joints) joints.push_back({{"joint", j.id}, {"peak_torque", j.peak_torque}, {"angle", j.angle * deg}});
  nlohmann::json contacts = nlohmann::json::array();
  for (const auto& c : r.contacts)
    contacts.push_back({{"actors", c.actors}, {"ground", c.ground}, {"event", c.event}, {"time", c.time},
                        {"point", {c.point.x(), c.point.y(), c.point.z()}}, {"max_penetration", c.max_penetration}});
  nlohmann::json angles = nlohmann::json::array();
  for (std::size_t j = 0; j < pattern.joints().size(); ++j)
    angles.push_back({{"joint", pattern.joints()[j].id},
                      {"angle", r.final_state.angles[static_cast<Eigen::Index>(j)] * deg}});
  // The held actor's ID, or "none".
  const nlohmann::json fixed = !o.hold_fixed ? nlohmann::json("none")
                               : o.fixed_actor ? nlohmann::json(*o.fixed_actor)
                                               : nlohmann::json(nullptr);
  const bool touching = o.contacts || o.ground;  // friction acts only then
  return {{"ok", r.status.ok()},  // deprecated: status
          {"status", geometry::to_string(r.status.code)},
          {"message", r.status.message},
          {"model", dynamics::kModelName},
          {"drive", dynamics::to_string(o.drive)},
          {"gravity", {o.gravity->x(), o.gravity->y(), o.gravity->z()}},
          {"density", *o.density},
          {"max_torque", o.max_torque},
          {"scale", o.scale},
          {"fixed", fixed},
          {"ground", o.ground ? nlohmann::json(*o.ground) : nlohmann::json(nullptr)},
          {"facet_contacts", o.contacts},  // "contacts" lists the pairs that touched
          {"friction", touching ? nlohmann::json(o.friction.value_or(dynamics::kDefaultFriction)) : nlohmann::json(nullptr)},
          {"solver", dynamics::to_string(o.solver)},
          {"iterations", o.iterations},
          {"projection_interval", o.projection_interval},
          {"time_step", r.time_step},
          {"duration", r.duration},
          {"seconds", r.seconds},
          {"real_time_factor", r.seconds > 0.0 ? r.duration / r.seconds : 0.0},
          {"steps", r.steps},
          {"max_closure_error", r.max_closure_error},
          {"max_corrected_error", r.max_corrected_error},
          {"failed_corrections", r.failed_corrections},
          {"closure_tolerance", r.closure_tolerance},
          {"events", events},
          {"stalls", stalls},
          {"contacts", contacts},
          {"max_penetration", r.max_penetration},
          {"thickness", r.thickness > 0.0 ? nlohmann::json(r.thickness) : nlohmann::json(nullptr)},
          {"joints", joints},
          {"energy", {{"kinetic", r.kinetic_energy}, {"potential", r.potential_energy}, {"spring", r.spring_energy},
                      {"peak_kinetic", r.peak_kinetic_energy}}},
          {"problems", r.problems},
          {"final_angles", angles}};
}

void print_dynamic_summary(const std::string& name, const dynamics::DynamicReport& r) {
  std::size_t reached = 0;
  for (const auto& e : r.events) reached += e.reached ? 1 : 0;
  std::cerr << name << ": " << reached << " of " << r.events.size() << " events reached, " << r.duration << " s simulated in "
            << r.seconds << " s (" << r.steps << " steps, model dynamic), closure drift " << r.max_closure_error
            << " rad, energy " << r.kinetic_energy + r.potential_energy + r.spring_energy << " J: "
            << (r.status.ok() ? "valid" : "INVALID") << '\n';
  for (const auto& p : r.problems) std::cerr << "  " << p << '\n';
}

std::string dynamic_series_csv(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& r) {
  std::ostringstream out;
  out.precision(10);
  out << "time,event";
  for (const auto& j : pattern.joints()) out << ",angle_" << j.id;
  for (const auto& j : pattern.joints()) out << ",torque_" << j.id;
  out << '\n';
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const auto& f = r.frames[k];
    out << f.time << ',' << f.event;
    for (Eigen::Index j = 0; j < f.state.angles.size(); ++j) out << ',' << f.state.angles[j] * 180.0 / M_PI;
    for (Eigen::Index j = 0; j < r.frame_torques[k].size(); ++j) out << ',' << r.frame_torques[k][j];
    out << '\n';
  }
  return out.str();
}

nlohmann::json dynamic_series_json(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& r) {
  nlohmann::json time = nlohmann::json::array(), event = nlohmann::json::array(), joints = nlohmann::json::array();
  for (const auto& f : r.frames) {
    time.push_back(f.time);
    event.push_back(f.event);
  }
  for (std::size_t j = 0; j < pattern.joints().size(); ++j) {
    const auto at = static_cast<Eigen::Index>(j);
    nlohmann::json angle = nlohmann::json::array(), torque = nlohmann::json::array();
    for (std::size_t k = 0; k < r.frames.size(); ++k) {
      angle.push_back(r.frames[k].state.angles[at] * 180.0 / M_PI);
      torque.push_back(r.frame_torques[k][at]);
    }
    joints.push_back({{"joint", pattern.joints()[j].id}, {"angle", std::move(angle)}, {"torque", std::move(torque)}});
  }
  return {{"time", std::move(time)}, {"event", std::move(event)}, {"joints", std::move(joints)}};
}

bool is_series_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".csv" || ext == ".json";
}

std::string dynamic_series(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& r, const std::string& path) {
  if (std::filesystem::path(path).extension() == ".json") return dynamic_series_json(pattern, r).dump() + "\n";
  return dynamic_series_csv(pattern, r);
}

simulation::SimulationReport frames_view(const dynamics::DynamicReport& r) {
  simulation::SimulationReport view;
  view.status = r.status;
  view.duration = r.duration;
  view.max_closure_error = r.max_closure_error;
  for (const auto& e : r.events) view.events.push_back({e.number, e.start, e.end, e.max_closure_error, e.reached});
  view.frames = r.frames;
  view.final_state = r.final_state;
  return view;
}

}  // namespace foldkit::apps
