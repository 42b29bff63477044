// The Hamiltonian cycle of a 2×-refined shape (Gabriely & Rimon's spanning-tree coverage, and its
// 3D analogue of NOTES.md): a Hamiltonian cycle on each coarse cell's block (the 4-cycle of a
// 2×2 block; a Gray-code 8-cycle of a 2×2×2 block, mirrored by block parity), merged along each
// edge of a spanning tree of the coarse cells by a 2-opt across the shared face. Each block face
// has its own reserved cycle edge, and mirroring makes the two reserved edges of a shared face
// translates of each other, so every merge removes two edges still on two different cycles and
// joins them into one. Linear time. Hand-written: no library builds these cycles.
#include <stdexcept>
#include <string>

#include "hamiltonian_graph.hpp"

namespace foldkit::folding::detail {
namespace {

struct Scheme {
  int dimension;
  std::vector<int> cycle;  // local codes (bit 0 x, bit 1 y, bit 2 z) of the block's cycle
  int reserved[3][2][2];   // [axis][side] → the cycle edge reserved on that face
};

const Scheme& scheme(int dimension) {
  static const Scheme kSquare{2, {0, 1, 3, 2}, {{{0, 2}, {1, 3}}, {{0, 1}, {2, 3}}, {{0, 0}, {0, 0}}}};
  static const Scheme kCube{3, {0, 1, 3, 2, 6, 7, 5, 4}, {{{2, 6}, {7, 5}}, {{4, 0}, {6, 7}}, {{0, 1}, {5, 4}}}};
  return dimension == 2 ? kSquare : kCube;
}

class Refinement {
 public:
  Refinement(const CellGraph& g, const std::vector<std::int32_t>& parent, int dimension)
      : g_(g), parent_(parent), d_(dimension), stride_(1u << dimension), mask_(g.vertex_count() * stride_, 0) {}

  std::vector<Cell> build() {
    const Scheme& s = scheme(d_);
    for (std::size_t v = 0; v < g_.vertex_count(); ++v) {
      const int r = reflection(v);
      for (std::size_t i = 0; i < s.cycle.size(); ++i) toggle(v, s.cycle[i] ^ r, v, s.cycle[(i + 1) % s.cycle.size()] ^ r);
    }
    for (std::size_t v = 0; v < g_.vertex_count(); ++v)
      if (parent_[v] >= 0) merge(v, static_cast<std::size_t>(parent_[v]));
    return walk();
  }

 private:
  int reflection(std::size_t v) const {
    const Cell& c = g_.cells[v];
    return (c.x & 1) | (c.y & 1) << 1 | (c.z & 1) << 2;
  }
  static int axis_of(int a, int b) { return (a ^ b) == 1 ? 0 : (a ^ b) == 2 ? 1 : 2; }

  std::uint8_t& mask(std::size_t v, int code) { return mask_[v * stride_ + static_cast<std::size_t>(code)]; }

  // Adds or removes the edge between fine cell (va, a) and the adjacent fine cell (vb, b).
  void toggle(std::size_t va, int a, std::size_t vb, int b) {
    int axis = 0;
    bool up = false;  // b lies on the + side of a
    if (va == vb) {
      axis = axis_of(a, b);
      up = (b >> axis & 1) != 0;
    } else {
      const Cell &ca = g_.cells[va], &cb = g_.cells[vb];
      axis = ca.x != cb.x ? 0 : ca.y != cb.y ? 1 : 2;
      up = (axis == 0 ? cb.x - ca.x : axis == 1 ? cb.y - ca.y : cb.z - ca.z) > 0;
    }
    mask(va, a) ^= static_cast<std::uint8_t>(1u << (2 * axis + (up ? 0 : 1)));
    mask(vb, b) ^= static_cast<std::uint8_t>(1u << (2 * axis + (up ? 1 : 0)));
  }

  bool has(std::size_t v, int a, int b) const {
    const int axis = axis_of(a, b);
    return (mask_[v * stride_ + static_cast<std::size_t>(a)] >> (2 * axis + ((b >> axis & 1) != 0 ? 0 : 1)) & 1) != 0;
  }

  // 2-opt across the face shared by two adjacent blocks.
  void merge(std::size_t u, std::size_t w) {
    const Cell &cu = g_.cells[u], &cw = g_.cells[w];
    const int axis = cu.x != cw.x ? 0 : cu.y != cw.y ? 1 : 2;
    const bool u_low = (axis == 0 ? cu.x < cw.x : axis == 1 ? cu.y < cw.y : cu.z < cw.z);
    const std::size_t lo = u_low ? u : w, hi = u_low ? w : u;
    const int r = reflection(lo);
    const int side = 1 ^ (r >> axis & 1);
    const int* e = scheme(d_).reserved[axis][side];
    const int a = e[0] ^ r, b = e[1] ^ r;  // on lo's + face
    const int a2 = a & ~(1 << axis), b2 = b & ~(1 << axis);
    if (!has(lo, a, b) || !has(hi, a2, b2)) throw std::logic_error("refinement: a reserved edge is missing");
    toggle(lo, a, lo, b);
    toggle(hi, a2, hi, b2);
    toggle(lo, a, hi, a2);
    toggle(lo, b, hi, b2);
  }

  std::vector<Cell> walk() const {
    std::vector<Cell> out;
    const std::size_t total = mask_.size();
    out.reserve(total);
    std::size_t v = 0;
    int code = 0, came_from = -1;  // direction bit back to the previous cell
    for (std::size_t step = 0; step < total; ++step) {
      const Cell& c = g_.cells[v];
      const Cell f{2 * c.x + (code & 1), 2 * c.y + (code >> 1 & 1), 2 * c.z + (code >> 2 & 1)};
      out.push_back(f);
      const std::uint8_t m = mask_[v * stride_ + static_cast<std::size_t>(code)];
      int dir = -1;
      for (int k = 0; k < 6; ++k)
        if ((m >> k & 1) != 0 && k != came_from) {
          dir = k;
          break;
        }
      if (dir < 0) throw std::logic_error("refinement: the cycle is broken");
      const int axis = dir / 2, delta = dir % 2 == 0 ? 1 : -1;
      int p[3] = {f.x, f.y, f.z};
      p[axis] += delta;
      const std::int32_t nv = g_.vertex_at(p[0] >> 1, p[1] >> 1, p[2] >> 1);
      if (p[axis] < 0 || nv < 0) throw std::logic_error("refinement: the cycle leaves the shape");
      v = static_cast<std::size_t>(nv);
      code = (p[0] & 1) | (p[1] & 1) << 1 | (p[2] & 1) << 2;
      came_from = dir ^ 1;
    }
    if (v != 0 || code != 0) throw std::logic_error("refinement: the cycle does not cover the refined shape");
    return out;
  }

  const CellGraph& g_;
  const std::vector<std::int32_t>& parent_;
  int d_;
  std::size_t stride_;
  std::vector<std::uint8_t> mask_;
};

}  // namespace

HamiltonianResult refine_cycle(const CellGraph& g, const SpanningTree& tree, int dimension) {
  HamiltonianResult r;
  r.status = {geometry::StatusCode::Success, "Hamiltonian cycle of the refined shape found"};
  r.cycle = true;
  r.path = Refinement(g, tree.parent, dimension).build();
  return r;
}

}  // namespace foldkit::folding::detail

namespace foldkit::folding {
namespace {

HamiltonianResult refined(const std::vector<std::uint8_t>& cells, int nx, int ny, int nz, int dimension) {
  HamiltonianResult r;
  std::size_t n = 0;
  for (const std::uint8_t c : cells) n += c != 0;
  if (n == 0) {
    r.status = {geometry::StatusCode::NoSolution, "the shape is empty"};
    return r;
  }
  if (n > kMaxRefineCells) {
    r.status = {geometry::StatusCode::LimitReached,
                "too large to refine (" + std::to_string(n) + " cells > " + std::to_string(kMaxRefineCells) + ")"};
    return r;
  }
  const detail::CellGraph g = detail::make_graph(cells, nx, ny, nz);
  const detail::SpanningTree tree = detail::spanning_tree(g);
  if (tree.components > 1) {
    r.status = {geometry::StatusCode::NoSolution, "the shape is not connected (" + std::to_string(tree.components) + " components)"};
    return r;
  }
  return detail::refine_cycle(g, tree, dimension);
}

}  // namespace

HamiltonianResult refined_hamiltonian_cycle(const PixelShape& shape) {
  return refined(shape.cells, shape.width, shape.height, 1, 2);
}

HamiltonianResult refined_hamiltonian_cycle(const VoxelShape& shape) {
  return refined(shape.cells, shape.nx, shape.ny, shape.nz, 3);
}

}  // namespace foldkit::folding
