// foldkit hamiltonian: a Hamiltonian path (chain of cubes) through a pixel or voxel shape.
#include <iostream>
#include <sstream>

#include "cli_common.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/shape_file.hpp"
#include "foldkit/folding/hamiltonian.hpp"

namespace foldkit::apps {
namespace {

std::string path_text(const folding::HamiltonianResult& r, bool three_d) {
  std::ostringstream out;
  for (const folding::Cell& c : r.path) {
    out << c.x << ' ' << c.y;
    if (three_d) out << ' ' << c.z;
    out << '\n';
  }
  return out.str();
}

// "X,Y" or "X,Y,Z" (Z only for voxels).
folding::Cell parse_start(const std::string& text, bool three_d) {
  folding::Cell c;
  char comma1 = 0, comma2 = 0, extra = 0;
  std::istringstream in(text);
  in >> c.x >> comma1 >> c.y;
  if (three_d) in >> comma2 >> c.z;
  if (!in || comma1 != ',' || (three_d && comma2 != ',') || (in >> extra))
    throw UsageError("--start " + text + ": expected " + (three_d ? "X,Y,Z" : "X,Y"));
  return c;
}

// The "verdict" key predates the shared status and keeps its names; "status" has the shared ones.
const char* verdict_name(geometry::StatusCode code) {
  if (code == geometry::StatusCode::Success) return "found";
  if (code == geometry::StatusCode::NoSolution) return "none";
  return "unknown";
}

}  // namespace

Command add_hamiltonian(CLI::App& root) {
  struct Options {
    std::string shape, output, start;
    bool refine = false, cycle = false, json = false;
    std::uint64_t budget = folding::ExactOptions{}.node_budget;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("hamiltonian", "Hamiltonian path (chain of cubes) through a pixel or voxel shape");
  reads(app->add_option("shape", opt->shape, "Shape: ASCII grid (.txt, .grid), PBM (.pbm) or voxel layers (.vox)"))->required();
  app->add_flag("--refine", opt->refine, "Refine each cell 2× (2×2 or 2×2×2) and build a Hamiltonian cycle in linear time");
  app->add_flag("--cycle", opt->cycle, "Exact search for a Hamiltonian cycle instead of a path");
  positive(app->add_option("--budget", opt->budget, "Node budget of the exact search"));
  app->add_option("--start", opt->start, "Exact path from this cell, X,Y (X,Y,Z for voxels)");
  writes(app->add_option("-o,--output", opt->output, "Write the path, one 'x y' or 'x y z' per line"));
  add_json(app, opt->json);
  return {app, [opt] {
            const std::string& path = opt->shape;
            const bool three_d = io::is_voxel_path(path);
            if (!three_d && !has_extension(path, ".txt") && !has_extension(path, ".grid") && !has_extension(path, ".pbm"))
              throw UsageError(path + ": unknown shape format (expected .txt, .grid, .pbm or .vox)");
            if (opt->refine && opt->cycle) throw UsageError("--refine always builds a cycle; --cycle is for the exact search");
            folding::ExactOptions exact;
            exact.node_budget = opt->budget;
            exact.cycle = opt->cycle;
    if (!opt->start.empty()) {
      if (opt->refine || opt->cycle) throw UsageError("--start is for the exact path search (not --refine or --cycle)");
      exact.start = parse_start(opt->start, three_d);
    }
            folding::HamiltonianResult r;
            std::size_t cells = 0;
            if (three_d) {
              const folding::VoxelShape s = io::read_voxel_shape(path);
              cells = s.count() * (opt->refine ? 8 : 1);
              r = opt->refine ? folding::refined_hamiltonian_cycle(s) : folding::exact_hamiltonian(s, exact);
            } else {
              const folding::PixelShape s = io::read_pixel_shape(path);
              cells = s.count() * (opt->refine ? 4 : 1);
              r = opt->refine ? folding::refined_hamiltonian_cycle(s) : folding::exact_hamiltonian(s, exact);
            }
            const bool found = r.status.ok();
            if (found && !opt->output.empty()) io::write_file_atomic(opt->output, path_text(r, three_d));
            const char* method = opt->refine ? "refined" : "exact";
            if (found)
              std::cerr << path << ": Hamiltonian " << (r.cycle ? "cycle" : "path") << " through " << r.path.size() << " cells ("
                        << method << ")\n";
            else
              std::cerr << path << ": " << (r.status.code == geometry::StatusCode::NoSolution ? "no Hamiltonian " : "undecided Hamiltonian ")
                        << (opt->cycle ? "cycle" : "path") << ": " << r.status.message << '\n';
            if (opt->json) {
              nlohmann::json j = {{"found", found},  // deprecated: status
                                  {"verdict", verdict_name(r.status.code)},  // deprecated: status
                                  {"method", method},
                                  {"dimension", three_d ? 3 : 2},
                                  {"cells", cells},
                                  {"length", r.path.size()},
                                  {"cycle", found && r.cycle},
                                  {"nodes", r.nodes}};
              if (!found) j["reason"] = r.status.message;
              add_status(j, r.status);
              print_json(j);
            } else if (found && opt->output.empty()) {
              std::cout << path_text(r, three_d);
            }
            return found ? kOk : kNoPlan;
          }};
}

}  // namespace foldkit::apps
