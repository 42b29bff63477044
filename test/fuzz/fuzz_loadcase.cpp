// Any bytes: parse_load_case either throws ParseError or gives a load case whose numbers are all
// finite; applied to a flat three-tile strip (actors 1..3) it either is refused with a ParseError
// or solves (linear mode) to finite displacements or a stated failure — never a crash or a NaN.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "foldkit/analysis/load_case.hpp"
#include "foldkit/analysis/solver.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/parse_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foldkit;
  static const geometry::CreasePattern strip = geometry::build_or_throw(geometry::generators::strip(3));
  analysis::LoadCase lc;
  try {
    lc = analysis::parse_load_case(std::string(reinterpret_cast<const char*>(data), size), "fuzz.loadcase");
  } catch (const io::ParseError&) {
    return 0;
  }
  for (const auto& k : lc.stiffness)
    if (!k.allFinite()) std::abort();
  for (const auto& l : lc.loads)
    if (!l.force.allFinite() || (l.point && !l.point->allFinite())) std::abort();
  if (lc.fixed.empty()) std::abort();
  analysis::Problem problem;
  try {
    problem = analysis::make_problem(analysis::build_structure(strip, geometry::FoldState::flat(strip)), lc, "fuzz.loadcase");
  } catch (const io::ParseError&) {
    return 0;
  }
  analysis::SolveOptions o;
  o.linear = true;
  const analysis::SolveResult r = analysis::solve(problem, o);
  if (r.status.ok()) {
    if (!std::isfinite(r.max_displacement) || !std::isfinite(r.residual_norm)) std::abort();
    for (const auto& m : r.modules)
      if (!m.displacement.allFinite() || !m.rotation.allFinite()) std::abort();
  } else if (r.status.message.empty()) {
    std::abort();
  }
  return 0;
}
