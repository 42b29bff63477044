// Every generator's output survives PMML and FOLD round trips unchanged.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using namespace foldkit;
namespace gen = geometry::generators;

struct Case {
  const char* name;
  std::function<geometry::PatternSpec()> make;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"single_vertex", [] { return gen::single_vertex({0.5, 1.2, 2.0, 2 * M_PI - 3.7}); }},
      {"single_vertex_64", [] { return gen::single_vertex(std::vector<double>(64, 2 * M_PI / 64)); }},
      {"strip", [] { return gen::strip(7, 0.3, 2.0); }},
      {"grid", [] { return gen::grid(3, 5, 0.7); }},
      {"circular", [] { return gen::circular_lattice(3, 7, 0.4); }},
      {"miura", [] { return gen::miura(5, 6, 1.0, 1.3, 1.1); }},
      {"waterbomb", [] { return gen::waterbomb(3, 4); }},
      {"boat", [] { return gen::boat(); }},
      {"cube_sheet", [] { return gen::cube_sheet(3, 2.0); }},
  };
  return all;
}

double area(const geometry::CreasePattern& p) {
  double sum = 0;
  for (const auto& a : p.actors())
    for (const auto& t : a.triangles) {
      const auto &u = p.vertices()[t.v[0]], &v = p.vertices()[t.v[1]], &w = p.vertices()[t.v[2]];
      sum += 0.5 * ((v - u).x() * (w - u).y() - (v - u).y() * (w - u).x());
    }
  return sum;
}

TEST(GeneratorRoundTrip, PmmlIsExact) {
  for (const Case& c : cases()) {
    const geometry::CreasePattern p = geometry::build_or_throw(c.make());
    const std::string text = io::write_pmml(p);
    const geometry::CreasePattern back = geometry::build_or_throw(io::parse_pmml(text, c.name));
    EXPECT_EQ(io::write_pmml(back), text) << c.name;
    EXPECT_EQ(back.vertices(), p.vertices()) << c.name;
    ASSERT_EQ(back.joints().size(), p.joints().size()) << c.name;
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      EXPECT_EQ(back.joints()[j].v, p.joints()[j].v) << c.name;
      EXPECT_EQ(back.joints()[j].assignment, p.joints()[j].assignment) << c.name;
    }
  }
}

TEST(GeneratorRoundTrip, FoldKeepsGeometryAndAngles) {
  for (const Case& c : cases()) {
    const geometry::CreasePattern p = geometry::build_or_throw(c.make());
    geometry::FoldState state = geometry::FoldState::flat(p);
    for (Eigen::Index j = 0; j < state.angles.size(); ++j) state.angles[j] = 0.01 * static_cast<double>(j % 7) - 0.03;
    const io::FoldImport back = io::parse_fold(io::write_fold(p, {state, {}, {}}), c.name);
    EXPECT_EQ(back.pattern.actors().size(), p.actors().size()) << c.name;
    EXPECT_EQ(back.pattern.joints().size(), p.joints().size()) << c.name;
    EXPECT_EQ(back.pattern.vertices().size(), p.vertices().size()) << c.name;
    EXPECT_NEAR(area(back.pattern), area(p), 1e-12 * area(p)) << c.name;
    ASSERT_TRUE(back.state) << c.name;
    // Joints are renumbered on import; match them by their segment.
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const auto& pj = p.joints()[j];
      const geometry::Vec2 mid = 0.5 * (p.vertices()[pj.v[0]] + p.vertices()[pj.v[1]]);
      bool found = false;
      for (std::size_t k = 0; k < back.pattern.joints().size() && !found; ++k) {
        const auto& bj = back.pattern.joints()[k];
        const geometry::Vec2 bmid = 0.5 * (back.pattern.vertices()[bj.v[0]] + back.pattern.vertices()[bj.v[1]]);
        if ((bmid - mid).norm() < 1e-12) {
          found = true;
          EXPECT_NEAR(back.state->angles[static_cast<Eigen::Index>(k)], state.angles[static_cast<Eigen::Index>(j)], 1e-15)
              << c.name << " joint " << pj.id;
        }
      }
      EXPECT_TRUE(found) << c.name << " joint " << pj.id;
    }
  }
}

}  // namespace
