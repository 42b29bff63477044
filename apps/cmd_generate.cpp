#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <system_error>

#include "cli_common.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/folding/cube_chain.hpp"

namespace foldkit::apps {
namespace {

namespace gen = geometry::generators;

struct Common {
  std::string output;
  std::string title;
  gen::JointDefaults joints;
  bool json = false;
};

double radians(double degrees) { return degrees * M_PI / 180.0; }

// Sector angles from --sectors (degrees), or `degree` equal or seeded-random sectors.
std::vector<double> sectors_from(const std::string& list, int degree, std::optional<unsigned> seed) {
  std::vector<double> sectors;
  if (!list.empty()) {
    std::stringstream in(list);
    std::string token;
    while (std::getline(in, token, ',')) {
      try {
        std::size_t used = 0;
        const double v = std::stod(token, &used);
        if (used != token.size()) throw std::invalid_argument(token);
        sectors.push_back(radians(v));
      } catch (const std::exception&) {
        throw UsageError("--sectors: '" + token + "' is not a number (give degrees separated by commas)");
      }
    }
    // Degrees typed by hand rarely sum to exactly 2π in radians; rescale tiny rounding only.
    double sum = 0;
    for (double s : sectors) sum += s;
    if (std::abs(sum - 2 * M_PI) > 1e-6)
      throw UsageError("--sectors must sum to 360 degrees (they sum to " + std::to_string(sum * 180 / M_PI) + ")");
    for (double& s : sectors) s *= 2 * M_PI / sum;
    return sectors;
  }
  if (degree < 3) throw UsageError("give --sectors or --degree (at least 3)");
  if (!seed) return std::vector<double>(static_cast<std::size_t>(degree), 2 * M_PI / degree);
  std::mt19937 rng(*seed);
  std::uniform_real_distribution<double> u(0.2, 1.0);
  double sum = 0;
  for (int i = 0; i < degree; ++i) sum += sectors.emplace_back(u(rng));
  for (double& s : sectors) s *= 2 * M_PI / sum;
  return sectors;
}

// Every generator's parameters; each subcommand binds the ones it has.
struct Params {
  std::string sectors;
  int degree = 0;
  unsigned seed = 0;
  int n = 4, rows = 4, cols = 4, rings = 3, spokes = 8, units = 3, cubes = 2;
  double width = 1, height = 1, cell = 1, ring_width = 1, a = 1, b = 1, angle = 60, radius = 1;
  double length = 4, half_width = 1, bow = 1, tile = 1, side = 1, twist = 60, pleat = 1;
  std::string chain_cmml;
};

// What the subcommands share: their options, and the spec maker the chosen one's callback sets.
struct Context {
  std::shared_ptr<Common> common = std::make_shared<Common>();
  std::shared_ptr<Params> p = std::make_shared<Params>();
  std::shared_ptr<std::function<geometry::PatternSpec()>> make = std::make_shared<std::function<geometry::PatternSpec()>>();
};

// The subcommands the run step asks about: the ones whose size it bounds, and the cube sheet's
// extra output.
struct Kinds {
  CLI::App* grid = nullptr;
  CLI::App* circular = nullptr;
  CLI::App* miura = nullptr;
  CLI::App* waterbomb = nullptr;
  CLI::App* cube_sheet = nullptr;
};

// Counts are bounded so that a typo cannot ask for more memory than the machine has.
CLI::Range count_range() { return CLI::Range(1, 100000); }

CLI::App* kind(CLI::App* parent, const std::string& name, const std::string& what, const std::shared_ptr<Common>& common) {
  CLI::App* k = parent->add_subcommand(name, what);
  writes(k->add_option("-o,--output", common->output, "Output file (" + io::extensions(io::writes_patterns) + ")"))->required();
  k->add_option("--title", common->title, "Title written into the file");
  k->add_option("--spring", common->joints.spring, "SpringConst of every joint")->capture_default_str();
  k->add_option("--damping", common->joints.damping, "DampConst of every joint")->capture_default_str();
  add_json(k, common->json);
  return k;
}

// Sets what `generate` builds when this subcommand is chosen, from the options as parsed.
void on_chosen(CLI::App* sub, const Context& c, std::function<geometry::PatternSpec(const Params&, const Common&)> build) {
  sub->callback([p = c.p, common = c.common, make = c.make, build] {
    *make = [p, common, build] { return build(*p, *common); };
  });
}

void add_single_vertex(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* sv = kind(app, "single-vertex", "One interior vertex (paper Fig. 2)", c.common);
  sv->add_option("--sectors", opt.sectors, "Sector angles in degrees, comma-separated, summing to 360");
  sv->add_option("--degree", opt.degree, "Number of creases (equal sectors, or random with --seed)")->check(CLI::Range(3, 100000));
  auto* seed = sv->add_option("--seed", opt.seed, "Seed for random sector angles with --degree");
  positive(sv->add_option("--radius", opt.radius, "Sheet radius"));
  on_chosen(sv, c, [seed](const Params& p, const Common& common) {
    auto s = sectors_from(p.sectors, p.degree, seed->count() ? std::optional<unsigned>(p.seed) : std::nullopt);
    return gen::single_vertex(s, p.radius, common.joints);
  });
}

void add_strip(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* strip = kind(app, "strip", "Panels in a row joined by parallel creases", c.common);
  strip->add_option("--panels", opt.n, "Number of panels")->check(count_range())->capture_default_str();
  positive(strip->add_option("--width", opt.width, "Panel width"));
  positive(strip->add_option("--height", opt.height, "Panel height"));
  on_chosen(strip, c, [](const Params& p, const Common& common) { return gen::strip(p.n, p.width, p.height, common.joints); });
}

CLI::App* add_grid(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* grid = kind(app, "grid", "Square lattice of cells", c.common);
  grid->add_option("--rows", opt.rows, "Rows of cells")->check(count_range())->capture_default_str();
  grid->add_option("--cols", opt.cols, "Columns of cells")->check(count_range())->capture_default_str();
  positive(grid->add_option("--cell", opt.cell, "Cell size"));
  on_chosen(grid, c, [](const Params& p, const Common& common) { return gen::grid(p.rows, p.cols, p.cell, common.joints); });
  return grid;
}

CLI::App* add_circular(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* circ = kind(app, "circular", "Circular lattice: rings crossed by spokes", c.common);
  circ->add_option("--rings", opt.rings, "Number of rings")->check(count_range())->capture_default_str();
  circ->add_option("--spokes", opt.spokes, "Number of radial creases")->check(CLI::Range(3, 100000))->capture_default_str();
  positive(circ->add_option("--ring-width", opt.ring_width, "Width of each ring"));
  on_chosen(circ, c, [](const Params& p, const Common& common) {
    return gen::circular_lattice(p.rings, p.spokes, p.ring_width, common.joints);
  });
  return circ;
}

CLI::App* add_miura(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* miura = kind(app, "miura", "Miura-ori of rows × cols parallelograms", c.common);
  miura->add_option("--rows", opt.rows, "Rows")->check(count_range())->capture_default_str();
  miura->add_option("--cols", opt.cols, "Columns")->check(count_range())->capture_default_str();
  positive(miura->add_option("--a", opt.a, "Column width"));
  positive(miura->add_option("--b", opt.b, "Row height"));
  miura->add_option("--angle", opt.angle, "Parallelogram angle in degrees, (0, 90]")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  on_chosen(miura, c, [](const Params& p, const Common& common) {
    return gen::miura(p.rows, p.cols, p.a, p.b, radians(p.angle), common.joints);
  });
  return miura;
}

CLI::App* add_waterbomb(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* wb = kind(app, "waterbomb", "Waterbomb tessellation", c.common);
  wb->add_option("--units", opt.units, "Units across")->check(count_range())->capture_default_str();
  wb->add_option("--rows", opt.rows, "Rows")->check(count_range())->capture_default_str();
  on_chosen(wb, c, [](const Params& p, const Common& common) { return gen::waterbomb(p.units, p.rows, common.joints); });
  return wb;
}

void add_boat(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* boat = kind(app, "boat", "The boat of the paper's Fig. 3", c.common);
  positive(boat->add_option("--length", opt.length, "Sheet length"));
  positive(boat->add_option("--half-width", opt.half_width, "Half the sheet width"));
  positive(boat->add_option("--bow", opt.bow, "Distance from each end to its vertex"));
  on_chosen(boat, c, [](const Params& p, const Common& common) { return gen::boat(p.length, p.half_width, p.bow, common.joints); });
}

CLI::App* add_cube_sheet(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* cubes = kind(app, "cube-sheet", "Cube nets in a row (paper Fig. 8a)", c.common);
  cubes->add_option("--cubes", opt.cubes, "Number of cube nets")->check(count_range())->capture_default_str();
  positive(cubes->add_option("--tile", opt.tile, "Tile size"));
  writes(cubes->add_option("--chain-cmml", opt.chain_cmml,
                           "Also write the CMML that folds the sheet into a straight line of cubes (docs/CARPENTER.md)"));
  on_chosen(cubes, c, [](const Params& p, const Common& common) { return gen::cube_sheet(p.cubes, p.tile, common.joints); });
  return cubes;
}

void add_square_twist(CLI::App* app, const Context& c) {
  Params& opt = *c.p;
  CLI::App* twist = kind(app, "square-twist", "The classic square twist (not rigidly foldable)", c.common);
  positive(twist->add_option("--side", opt.side, "Side of the central square"));
  twist->add_option("--twist", opt.twist, "Twist angle in degrees, (0, 90)")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  positive(twist->add_option("--pleat", opt.pleat, "Pleat length"));
  on_chosen(twist, c, [](const Params& p, const Common& common) {
    if (p.twist <= 0.0 || p.twist >= 90.0) throw UsageError("--twist must lie strictly between 0 and 90 degrees");
    return gen::square_twist(p.side, radians(p.twist), p.pleat, common.joints);
  });
}

// rows × cols style products: at most four million actors.
void check_size(const Params& p, const Kinds& k) {
  const long long cells = static_cast<long long>(p.rows) * p.cols;
  const long long limit = 4'000'000;
  if ((k.grid->parsed() || k.miura->parsed()) && cells > limit)
    throw UsageError("rows × cols = " + std::to_string(cells) + " is more than 4,000,000 actors");
  if (k.waterbomb->parsed() && static_cast<long long>(p.units) * p.rows * 8 > limit)
    throw UsageError("the waterbomb would have more than 4,000,000 actors");
  if (k.circular->parsed() && static_cast<long long>(p.rings) * p.spokes > limit)
    throw UsageError("rings × spokes is more than 4,000,000 actors");
}

// Writes the sheet and, when asked, the CMML folding it into a line of cubes. The folding is
// built before anything is written; if its file then cannot be written, the sheet just written
// is removed again, so a failure leaves no half of the pair.
int run_generate(const Context& c, const Kinds& k) {
  const Common& common = *c.common;
  const Params& p = *c.p;
  check_size(p, k);
  geometry::PatternSpec spec = (*c.make)();
  if (!common.title.empty()) spec.title = common.title;
  const geometry::CreasePattern pattern = geometry::build_or_throw(spec);
  std::string chain;
  std::size_t chain_events = 0;
  if (k.cube_sheet->parsed() && !p.chain_cmml.empty()) {
    const geometry::FoldSequence folding = folding::fold_cube_chain(pattern, p.cubes);
    chain_events = folding.events.size();
    chain = io::write_cmml(folding);
  }
  save_pattern(common.output, pattern);
  std::cerr << common.output << ": " << pattern.actors().size() << " actors, " << pattern.joints().size() << " joints\n";
  if (!chain.empty()) {
    try {
      io::write_file_atomic(p.chain_cmml, chain);
    } catch (...) {
      std::error_code ignored;
      std::filesystem::remove(common.output, ignored);
      throw;
    }
    std::cerr << p.chain_cmml << ": " << chain_events << " events folding " << p.cubes << " nets into a line of cubes\n";
  }
  nlohmann::json out{{"output", common.output}, {"actors", pattern.actors().size()}, {"joints", pattern.joints().size()}};
  if (!chain.empty()) out["chain_cmml"] = p.chain_cmml, out["chain_events"] = chain_events;
  if (common.json) print_json(out);
  return kOk;
}

}  // namespace

Command add_generate(CLI::App& root) {
  const Context c;
  CLI::App* app = root.add_subcommand("generate", "Write a parametric crease pattern");
  app->require_subcommand(1);
  Kinds k;
  add_single_vertex(app, c);
  add_strip(app, c);
  k.grid = add_grid(app, c);
  k.circular = add_circular(app, c);
  k.miura = add_miura(app, c);
  k.waterbomb = add_waterbomb(app, c);
  add_boat(app, c);
  k.cube_sheet = add_cube_sheet(app, c);
  add_square_twist(app, c);
  return {app, [c, k] { return run_generate(c, k); }};
}

}  // namespace foldkit::apps
