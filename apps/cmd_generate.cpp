#include <cmath>
#include <filesystem>
#include <iostream>
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

CLI::App* kind(CLI::App* parent, const std::string& name, const std::string& what, const std::shared_ptr<Common>& common) {
  CLI::App* k = parent->add_subcommand(name, what);
  k->add_option("-o,--output", common->output, "Output file (.pmml, .fold or .svg)")->required();
  k->add_option("--title", common->title, "Title written into the file");
  k->add_option("--spring", common->joints.spring, "SpringConst of every joint")->capture_default_str();
  k->add_option("--damping", common->joints.damping, "DampConst of every joint")->capture_default_str();
  k->add_flag("--json", common->json, "Print one JSON object on stdout");
  return k;
}

}  // namespace

Command add_generate(CLI::App& root) {
  auto common = std::make_shared<Common>();
  auto make = std::make_shared<std::function<geometry::PatternSpec()>>();
  CLI::App* app = root.add_subcommand("generate", "Write a parametric crease pattern");
  app->require_subcommand(1);

  struct Params {
    std::string sectors;
    int degree = 0;
    unsigned seed = 0;
    int n = 4, rows = 4, cols = 4, rings = 3, spokes = 8, units = 3, cubes = 2;
    double width = 1, height = 1, cell = 1, ring_width = 1, a = 1, b = 1, angle = 60, radius = 1;
    double length = 4, half_width = 1, bow = 1, tile = 1, side = 1, twist = 60, pleat = 1;
    std::string chain_cmml;
  };
  auto p = std::make_shared<Params>();
  const auto positive = CLI::PositiveNumber;
  // Counts are bounded so that a typo cannot ask for more memory than the machine has.
  const auto count = CLI::Range(1, 100000);

  CLI::App* sv = kind(app, "single-vertex", "One interior vertex (paper Fig. 2)", common);
  sv->add_option("--sectors", p->sectors, "Sector angles in degrees, comma-separated, summing to 360");
  sv->add_option("--degree", p->degree, "Number of creases (equal sectors, or random with --seed)")->check(CLI::Range(3, 100000));
  auto* seed = sv->add_option("--seed", p->seed, "Seed for random sector angles with --degree");
  sv->add_option("--radius", p->radius, "Sheet radius")->check(positive)->capture_default_str();
  sv->callback([=] {
    *make = [=] {
      auto s = sectors_from(p->sectors, p->degree, seed->count() ? std::optional<unsigned>(p->seed) : std::nullopt);
      return gen::single_vertex(s, p->radius, common->joints);
    };
  });

  CLI::App* strip = kind(app, "strip", "Panels in a row joined by parallel creases", common);
  strip->add_option("--panels", p->n, "Number of panels")->check(count)->capture_default_str();
  strip->add_option("--width", p->width, "Panel width")->check(positive)->capture_default_str();
  strip->add_option("--height", p->height, "Panel height")->check(positive)->capture_default_str();
  strip->callback([=] { *make = [=] { return gen::strip(p->n, p->width, p->height, common->joints); }; });

  CLI::App* grid = kind(app, "grid", "Square lattice of cells", common);
  grid->add_option("--rows", p->rows, "Rows of cells")->check(count)->capture_default_str();
  grid->add_option("--cols", p->cols, "Columns of cells")->check(count)->capture_default_str();
  grid->add_option("--cell", p->cell, "Cell size")->check(positive)->capture_default_str();
  grid->callback([=] { *make = [=] { return gen::grid(p->rows, p->cols, p->cell, common->joints); }; });

  CLI::App* circ = kind(app, "circular", "Circular lattice: rings crossed by spokes", common);
  circ->add_option("--rings", p->rings, "Number of rings")->check(count)->capture_default_str();
  circ->add_option("--spokes", p->spokes, "Number of radial creases")->check(CLI::Range(3, 100000))->capture_default_str();
  circ->add_option("--ring-width", p->ring_width, "Width of each ring")->check(positive)->capture_default_str();
  circ->callback([=] { *make = [=] { return gen::circular_lattice(p->rings, p->spokes, p->ring_width, common->joints); }; });

  CLI::App* miura = kind(app, "miura", "Miura-ori of rows × cols parallelograms", common);
  miura->add_option("--rows", p->rows, "Rows")->check(count)->capture_default_str();
  miura->add_option("--cols", p->cols, "Columns")->check(count)->capture_default_str();
  miura->add_option("--a", p->a, "Column width")->check(positive)->capture_default_str();
  miura->add_option("--b", p->b, "Row height")->check(positive)->capture_default_str();
  miura->add_option("--angle", p->angle, "Parallelogram angle in degrees, (0, 90]")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  miura->callback([=] { *make = [=] { return gen::miura(p->rows, p->cols, p->a, p->b, radians(p->angle), common->joints); }; });

  CLI::App* wb = kind(app, "waterbomb", "Waterbomb tessellation", common);
  wb->add_option("--units", p->units, "Units across")->check(count)->capture_default_str();
  wb->add_option("--rows", p->rows, "Rows")->check(count)->capture_default_str();
  wb->callback([=] { *make = [=] { return gen::waterbomb(p->units, p->rows, common->joints); }; });

  CLI::App* boat = kind(app, "boat", "The boat of the paper's Fig. 3", common);
  boat->add_option("--length", p->length, "Sheet length")->check(positive)->capture_default_str();
  boat->add_option("--half-width", p->half_width, "Half the sheet width")->check(positive)->capture_default_str();
  boat->add_option("--bow", p->bow, "Distance from each end to its vertex")->check(positive)->capture_default_str();
  boat->callback([=] { *make = [=] { return gen::boat(p->length, p->half_width, p->bow, common->joints); }; });

  CLI::App* cubes = kind(app, "cube-sheet", "Cube nets in a row (paper Fig. 8a)", common);
  cubes->add_option("--cubes", p->cubes, "Number of cube nets")->check(count)->capture_default_str();
  cubes->add_option("--tile", p->tile, "Tile size")->check(positive)->capture_default_str();
  cubes->add_option("--chain-cmml", p->chain_cmml,
                    "Also write the CMML that folds the sheet into a straight line of cubes (docs/CARPENTER.md)");
  cubes->callback([=] { *make = [=] { return gen::cube_sheet(p->cubes, p->tile, common->joints); }; });

  CLI::App* twist = kind(app, "square-twist", "The classic square twist (not rigidly foldable)", common);
  twist->add_option("--side", p->side, "Side of the central square")->check(positive)->capture_default_str();
  twist->add_option("--twist", p->twist, "Twist angle in degrees, (0, 90)")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  twist->add_option("--pleat", p->pleat, "Pleat length")->check(positive)->capture_default_str();
  twist->callback([=] {
    *make = [=] {
      if (p->twist <= 0.0 || p->twist >= 90.0) throw UsageError("--twist must lie strictly between 0 and 90 degrees");
      return gen::square_twist(p->side, radians(p->twist), p->pleat, common->joints);
    };
  });

  return {app, [=] {
            // rows × cols style products: at most four million actors.
            const long long cells = static_cast<long long>(p->rows) * p->cols;
            const long long limit = 4'000'000;
            if ((grid->parsed() || miura->parsed()) && cells > limit)
              throw UsageError("rows × cols = " + std::to_string(cells) + " is more than 4,000,000 actors");
            if (wb->parsed() && static_cast<long long>(p->units) * p->rows * 8 > limit)
              throw UsageError("the waterbomb would have more than 4,000,000 actors");
            if (circ->parsed() && static_cast<long long>(p->rings) * p->spokes > limit)
              throw UsageError("rings × spokes is more than 4,000,000 actors");
            geometry::PatternSpec spec = (*make)();
            if (!common->title.empty()) spec.title = common->title;
            const geometry::CreasePattern pattern = geometry::build_or_throw(spec);
            // The folding is built before anything is written; if its file then cannot be written,
            // the sheet just written is removed again, so a failure leaves no half of the pair.
            std::string chain;
            std::size_t chain_events = 0;
            if (cubes->parsed() && !p->chain_cmml.empty()) {
              const geometry::FoldSequence folding = folding::fold_cube_chain(pattern, p->cubes);
              chain_events = folding.events.size();
              chain = io::write_cmml(folding);
            }
            save_pattern(common->output, pattern);
            std::cerr << common->output << ": " << pattern.actors().size() << " actors, " << pattern.joints().size()
                      << " joints\n";
            if (!chain.empty()) {
              try {
                io::write_file_atomic(p->chain_cmml, chain);
              } catch (...) {
                std::error_code ignored;
                std::filesystem::remove(common->output, ignored);
                throw;
              }
              std::cerr << p->chain_cmml << ": " << chain_events << " events folding " << p->cubes << " nets into a line of cubes\n";
            }
            nlohmann::json out{{"output", common->output}, {"actors", pattern.actors().size()}, {"joints", pattern.joints().size()}};
            if (!chain.empty()) out["chain_cmml"] = p->chain_cmml, out["chain_events"] = chain_events;
            if (common->json) print_json(out);
            return kOk;
          }};
}

}  // namespace foldkit::apps
