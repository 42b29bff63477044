// Hamiltonian paths of pixel and voxel shapes, checked against oracles that share no code with
// the planners: a visit-every-cell-once checker, known facts, and brute force on tiny shapes.
#include "foldkit/folding/hamiltonian.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "foldkit/io/shape_file.hpp"

namespace {

using namespace foldkit::folding;
using foldkit::geometry::StatusCode;
using foldkit::io::parse_pixel_grid;
using foldkit::io::parse_voxel_layers;

using Key = std::tuple<int, int, int>;

std::set<Key> cells_of(const PixelShape& s) {
  std::set<Key> out;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      if (s.filled(x, y)) out.insert({x, y, 0});
  return out;
}

std::set<Key> cells_of(const VoxelShape& s) {
  std::set<Key> out;
  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x)
        if (s.filled(x, y, z)) out.insert({x, y, z});
  return out;
}

bool unit_step(const Cell& a, const Cell& b) {
  return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z) == 1;
}

// Empty when `path` visits every cell of `cells` exactly once with unit steps (and closes when
// `cycle`); otherwise what is wrong.
std::string check_path(const std::set<Key>& cells, const std::vector<Cell>& path, bool cycle) {
  if (path.size() != cells.size())
    return "path has " + std::to_string(path.size()) + " cells, shape " + std::to_string(cells.size());
  std::set<Key> seen;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Key k{path[i].x, path[i].y, path[i].z};
    if (!cells.count(k)) return "cell " + std::to_string(i) + " is outside the shape";
    if (!seen.insert(k).second) return "cell " + std::to_string(i) + " visited twice";
    if (i > 0 && !unit_step(path[i - 1], path[i])) return "step " + std::to_string(i) + " is not a unit step";
  }
  if (cycle && path.size() > 1 && !unit_step(path.back(), path.front())) return "the cycle does not close";
  return "";
}

PixelShape rectangle(int w, int h) {
  return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h), 1)};
}

PixelShape from_cells(const std::set<Key>& cells) {
  int minx = 1 << 30, miny = 1 << 30, maxx = -(1 << 30), maxy = -(1 << 30);
  for (const auto& [x, y, z] : cells) {
    minx = std::min(minx, x), miny = std::min(miny, y), maxx = std::max(maxx, x), maxy = std::max(maxy, y);
  }
  PixelShape s{maxx - minx + 1, maxy - miny + 1, {}};
  s.cells.assign(static_cast<std::size_t>(s.width * s.height), 0);
  for (const auto& [x, y, z] : cells) s.cells[static_cast<std::size_t>((y - miny) * s.width + (x - minx))] = 1;
  return s;
}

VoxelShape voxels_from_cells(const std::set<Key>& cells) {
  int lo[3] = {1 << 30, 1 << 30, 1 << 30}, hi[3] = {-(1 << 30), -(1 << 30), -(1 << 30)};
  for (const auto& [x, y, z] : cells) {
    const int p[3] = {x, y, z};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  VoxelShape s{hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1, {}};
  s.cells.assign(static_cast<std::size_t>(s.nx * s.ny * s.nz), 0);
  for (const auto& [x, y, z] : cells)
    s.cells[static_cast<std::size_t>(((z - lo[2]) * s.ny + (y - lo[1])) * s.nx + (x - lo[0]))] = 1;
  return s;
}

// A random connected polyomino (dims 2) or polycube (dims 3) of n cells, grown cell by cell.
std::set<Key> random_animal(std::mt19937& rng, std::size_t n, int dims) {
  static const int kSteps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Key> list = {{0, 0, 0}};
  std::set<Key> cells(list.begin(), list.end());
  while (cells.size() < n) {
    const auto& [x, y, z] = list[rng() % list.size()];
    const auto& s = kSteps[rng() % static_cast<unsigned>(2 * dims)];
    const Key k{x + s[0], y + s[1], z + s[2]};
    if (cells.insert(k).second) list.push_back(k);
  }
  return cells;
}

// Plain depth-first search over all orderings, no pruning: does a Hamiltonian path (cycle) exist?
bool brute_force(const std::set<Key>& cells, bool cycle) {
  const std::vector<Key> v(cells.begin(), cells.end());
  const std::size_t n = v.size();
  auto adj = [&](std::size_t a, std::size_t b) {
    return std::abs(std::get<0>(v[a]) - std::get<0>(v[b])) + std::abs(std::get<1>(v[a]) - std::get<1>(v[b])) +
               std::abs(std::get<2>(v[a]) - std::get<2>(v[b])) ==
           1;
  };
  std::vector<bool> used(n, false);
  std::size_t first = 0;
  auto dfs = [&](auto&& self, std::size_t at, std::size_t depth) -> bool {
    if (depth == n) return !cycle || (n >= 3 && adj(at, first));
    for (std::size_t w = 0; w < n; ++w)
      if (!used[w] && adj(at, w)) {
        used[w] = true;
        if (self(self, w, depth + 1)) return true;
        used[w] = false;
      }
    return false;
  };
  for (first = 0; first < (cycle ? std::min<std::size_t>(n, 1) : n); ++first) {
    used.assign(n, false);
    used[first] = true;
    if (dfs(dfs, first, 1)) return true;
  }
  return false;
}

TEST(HamiltonianExact, RectangleHasCycleIffBothSidesAtLeastTwoAndAreaEven) {
  for (int w = 1; w <= 6; ++w)
    for (int h = 1; h <= 6; ++h) {
      const PixelShape s = rectangle(w, h);
      ExactOptions o;
      o.cycle = true;
      const HamiltonianResult c = exact_hamiltonian(s, o);
      const bool expected = w >= 2 && h >= 2 && (w * h) % 2 == 0;
      ASSERT_NE(c.status.code, StatusCode::LimitReached) << w << "x" << h;
      EXPECT_EQ(c.status.code == StatusCode::Success, expected) << w << "x" << h << ": " << c.status.message;
      if (expected) {
        EXPECT_EQ(check_path(cells_of(s), c.path, true), "") << w << "x" << h;
      }
      const HamiltonianResult p = exact_hamiltonian(s);
      ASSERT_EQ(p.status.code, StatusCode::Success) << w << "x" << h << ": " << p.status.message;
      EXPECT_EQ(check_path(cells_of(s), p.path, false), "") << w << "x" << h;
    }
}

TEST(HamiltonianExact, ThreeByThreeStartsOnlyOnTheCornerAndCentreColour) {
  const PixelShape s = rectangle(3, 3);
  const HamiltonianResult any = exact_hamiltonian(s);
  ASSERT_EQ(any.status.code, StatusCode::Success);
  EXPECT_EQ((any.path.front().x + any.path.front().y) % 2, 0);
  EXPECT_EQ((any.path.back().x + any.path.back().y) % 2, 0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      ExactOptions o;
      o.start = Cell{x, y, 0};
      const HamiltonianResult r = exact_hamiltonian(s, o);
      if ((x + y) % 2 == 0) {
        ASSERT_EQ(r.status.code, StatusCode::Success) << x << "," << y;
        EXPECT_EQ(r.path.front(), (Cell{x, y, 0}));
        EXPECT_EQ(check_path(cells_of(s), r.path, false), "");
      } else {
        EXPECT_EQ(r.status.code, StatusCode::NoSolution);
        EXPECT_NE(r.status.message.find("parity"), std::string::npos) << r.status.message;
      }
    }
}

TEST(HamiltonianExact, PlusPentominoHasNoPathForItsFourLeaves) {
  const PixelShape plus = parse_pixel_grid(".#.\n###\n.#.\n", "plus.txt");
  const HamiltonianResult r = exact_hamiltonian(plus);
  EXPECT_EQ(r.status.code, StatusCode::NoSolution);
  EXPECT_NE(r.status.message.find("4 cells of degree 1"), std::string::npos) << r.status.message;
}

TEST(HamiltonianExact, ColourImbalanceIsReported) {
  // A comb of 8 cells: 5 even and 3 odd.
  const PixelShape s = parse_pixel_grid("#.#.#\n#####\n", "comb.txt");
  const HamiltonianResult r = exact_hamiltonian(s);
  EXPECT_EQ(r.status.code, StatusCode::NoSolution);
  EXPECT_NE(r.status.message.find("parity: 5 even and 3 odd"), std::string::npos) << r.status.message;
}

TEST(HamiltonianExact, AgreesWithBruteForceOnTinyShapes) {
  std::mt19937 rng(20240611);
  int with_path = 0, without = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int dims = trial % 4 == 0 ? 3 : 2;
    const std::size_t n = 1 + rng() % 12;
    const std::set<Key> cells = random_animal(rng, n, dims);
    for (const bool cycle : {false, true}) {
      ExactOptions o;
      o.cycle = cycle;
      const HamiltonianResult r =
          dims == 2 ? exact_hamiltonian(from_cells(cells), o) : exact_hamiltonian(voxels_from_cells(cells), o);
      ASSERT_NE(r.status.code, StatusCode::LimitReached) << r.status.message;
      const bool expected = brute_force(cells, cycle);
      ASSERT_EQ(r.status.code == StatusCode::Success, expected) << "trial " << trial << " cycle " << cycle << ": " << r.status.message;
      if (expected) {
        // Positions are relative to the bounding box; the checker runs in the same frame.
        const std::set<Key> framed = dims == 2 ? cells_of(from_cells(cells)) : cells_of(voxels_from_cells(cells));
        ASSERT_EQ(check_path(framed, r.path, cycle), "");
      }
      (expected ? with_path : without)++;
    }
  }
  EXPECT_GT(with_path, 50);
  EXPECT_GT(without, 50);
}

TEST(HamiltonianExact, BudgetAndSizeLimitsGiveUnknown) {
  ExactOptions o;
  o.node_budget = 3;
  EXPECT_EQ(exact_hamiltonian(rectangle(5, 5), o).status.code, StatusCode::LimitReached);
  const HamiltonianResult big = exact_hamiltonian(rectangle(40, 40));
  EXPECT_EQ(big.status.code, StatusCode::LimitReached);
  EXPECT_NE(big.status.message.find("too large"), std::string::npos);
}

TEST(HamiltonianExact, DisconnectedShapeIsNotConnected) {
  const PixelShape s = parse_pixel_grid("##.#\n", "two.txt");
  const HamiltonianResult r = exact_hamiltonian(s);
  EXPECT_EQ(r.status.code, StatusCode::NoSolution);
  EXPECT_NE(r.status.message.find("not connected (2 components)"), std::string::npos) << r.status.message;
  const HamiltonianResult f = refined_hamiltonian_cycle(s);
  EXPECT_EQ(f.status.code, StatusCode::NoSolution);
  EXPECT_NE(f.status.message.find("not connected"), std::string::npos) << f.status.message;
}

TEST(HamiltonianRefine, RandomPolyominoesRefinedAlwaysHaveACycle) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    const PixelShape s = from_cells(random_animal(rng, 1 + rng() % 300, 2));
    const HamiltonianResult r = refined_hamiltonian_cycle(s);
    ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
    EXPECT_TRUE(r.cycle);
    ASSERT_EQ(check_path(cells_of(refine(s)), r.path, true), "") << "trial " << trial;
  }
}

TEST(HamiltonianRefine, RandomPolycubesRefinedAlwaysHaveACycle) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const VoxelShape s = voxels_from_cells(random_animal(rng, 1 + rng() % 200, 3));
    const HamiltonianResult r = refined_hamiltonian_cycle(s);
    ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
    ASSERT_EQ(check_path(cells_of(refine(s)), r.path, true), "") << "trial " << trial;
  }
  const VoxelShape block = voxels_from_cells(random_animal(rng, 1, 3));
  EXPECT_EQ(refined_hamiltonian_cycle(block).path.size(), 8u);
}

TEST(HamiltonianRefine, FullBoxes) {
  for (const auto& [x, y, z] : {Key{1, 1, 1}, Key{3, 1, 1}, Key{4, 3, 2}, Key{5, 5, 5}}) {
    std::set<Key> cells;
    for (int k = 0; k < z; ++k)
      for (int j = 0; j < y; ++j)
        for (int i = 0; i < x; ++i) cells.insert({i, j, k});
    const VoxelShape s = voxels_from_cells(cells);
    const HamiltonianResult r = refined_hamiltonian_cycle(s);
    ASSERT_EQ(check_path(cells_of(refine(s)), r.path, true), "");
  }
  const PixelShape rect = rectangle(7, 3);
  EXPECT_EQ(check_path(cells_of(refine(rect)), refined_hamiltonian_cycle(rect).path, true), "");
}

TEST(HamiltonianExact, VoxelLayersHaveAPath) {
  const VoxelShape v = parse_voxel_layers("##\n#.\n\n.#\n..\n", "v.vox");
  const HamiltonianResult r = exact_hamiltonian(v);
  ASSERT_EQ(r.status.code, StatusCode::Success);
  EXPECT_EQ(check_path(cells_of(v), r.path, false), "");
}

}  // namespace
