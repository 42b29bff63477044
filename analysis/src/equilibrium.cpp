#include "foldkit/analysis/equilibrium.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "so3.hpp"

namespace foldkit::analysis {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using detail::hat;
using Block = Eigen::Matrix<double, 3, 12>;

struct Pose {
  Matrix3d r = Matrix3d::Identity();
  Vector3d phi = Vector3d::Zero();
  Vector3d u = Vector3d::Zero();
};

// The connection graph's components that hold a fixed module.
std::vector<bool> held(const Problem& p) {
  const std::size_t n = p.structure.modules.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& c : p.structure.connections) parent[find(c.a)] = find(c.b);
  std::vector<bool> root_held(n, false), out(n);
  for (std::size_t i = 0; i < n; ++i)
    if (i < p.fixed.size() && p.fixed[i]) root_held[find(static_cast<int>(i))] = true;
  for (std::size_t i = 0; i < n; ++i) out[i] = root_held[find(static_cast<int>(i))];
  return out;
}

}  // namespace

int unrestrained_module(const Problem& problem) {
  const auto h = held(problem);
  for (std::size_t i = 0; i < h.size(); ++i)
    if (!h[i]) return static_cast<int>(i);
  return -1;
}

EquilibriumSystem::EquilibriumSystem(const Problem& problem) {
  const Structure& s = problem.structure;
  length_ = s.tile > 0 ? s.tile : 1.0;
  force_ = 0.0;
  for (const auto& l : problem.loads) force_ = std::max(force_, l.force.norm());
  if (!(force_ > 0)) force_ = 1.0;
  index_.assign(s.modules.size(), -1);
  for (std::size_t i = 0; i < s.modules.size(); ++i) {
    if (i < problem.fixed.size() && problem.fixed[i]) continue;
    index_[i] = static_cast<int>(free_.size());
    free_.push_back(static_cast<int>(i));
  }
  // K maps [Δp (length); θ] to [f; m]; in scaled units K̃ = diag(1/F₀, 1/(F₀L)) K diag(L, 1).
  Eigen::Matrix<double, 6, 1> in, out;
  in << length_, length_, length_, 1, 1, 1;
  out << 1 / force_, 1 / force_, 1 / force_, 1 / (force_ * length_), 1 / (force_ * length_), 1 / (force_ * length_);
  extent_ = 1.0;
  for (const auto& c : s.connections) {
    Spring sp;
    sp.a = c.a;
    sp.b = c.b;
    sp.q = c.axes;
    sp.ca = s.modules[c.a].centroid / length_;
    sp.cb = s.modules[c.b].centroid / length_;
    sp.ra = c.origin / length_ - sp.ca;
    sp.rb = c.origin / length_ - sp.cb;
    sp.k = out.asDiagonal() * problem.stiffness[static_cast<int>(c.kind)] * in.asDiagonal();
    stiffness_scale_ = std::max(stiffness_scale_, sp.k.cwiseAbs().maxCoeff());
    extent_ = std::max({extent_, sp.ra.norm(), sp.rb.norm()});
    springs_.push_back(sp);
  }
  for (const auto& l : problem.loads)
    loads_.push_back({l.module, l.force / force_, (l.point - s.modules[l.module].centroid) / length_});
  build_pattern();
}

void EquilibriumSystem::build_pattern() {
  const int n = static_cast<int>(free_.size());
  std::vector<std::vector<int>> block_rows(static_cast<std::size_t>(n));  // per block column, sorted
  for (int i = 0; i < n; ++i) block_rows[static_cast<std::size_t>(i)].push_back(i);
  for (const Spring& sp : springs_) {
    const int ia = index_[sp.a], ib = index_[sp.b];
    if (ia < 0 || ib < 0) continue;
    block_rows[static_cast<std::size_t>(ia)].push_back(ib);
    block_rows[static_cast<std::size_t>(ib)].push_back(ia);
  }
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    auto& rows = block_rows[static_cast<std::size_t>(j)];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int i : rows)
      for (int c = 0; c < 6; ++c)
        for (int r = 0; r < 6; ++r) t.emplace_back(6 * i + r, 6 * j + c, 0.0);
  }
  pattern_.resize(size(), size());
  pattern_.setFromTriplets(t.begin(), t.end());
  pattern_.makeCompressed();
  const auto slot = [&](int row, int col) {
    if (row < 0 || col < 0) return -1;
    const auto& rows = block_rows[static_cast<std::size_t>(col)];
    return static_cast<int>(std::lower_bound(rows.begin(), rows.end(), row) - rows.begin());
  };
  for (const Spring& sp : springs_) {
    const int ia = index_[sp.a], ib = index_[sp.b];
    spring_slots_.push_back({slot(ia, ia), slot(ia, ib), slot(ib, ia), slot(ib, ib)});
  }
  for (const Load& l : loads_) load_slots_.push_back(slot(index_[l.module], index_[l.module]));
}

double EquilibriumSystem::residual_floor(const Eigen::VectorXd& x) const {
  double u = 0.0;
  for (Eigen::Index i = 0; i < x.size(); i += 6) u = std::max(u, x.segment<3>(i).cwiseAbs().maxCoeff());
  // Spring forces are K times pose differences known to about ε·(lever + displacement).
  return 4.0 * std::numeric_limits<double>::epsilon() * stiffness_scale_ * (extent_ + u);
}

Eigen::VectorXd EquilibriumSystem::retract(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const {
  Eigen::VectorXd y = x;
  for (Eigen::Index i = 0; i < x.size(); i += 6) {
    // A screw motion rather than a straight line for the centroid: a module turning about a
    // hinge then keeps its spring closed, which a straight step would tear apart by (1 − cos)·lever.
    y.segment<3>(i) += detail::left_jacobian_times(dx.segment<3>(i + 3), dx.segment<3>(i));
    y.segment<3>(i + 3) =
        detail::log_so3(detail::exp_so3(dx.segment<3>(i + 3)) * detail::exp_so3(x.segment<3>(i + 3)));
  }
  return y;
}

namespace {

// One spring's pose error and its derivatives, at the poses of its two modules.
struct SpringState {
  Matrix3d a, jinv;
  Vector3d sa, sb, d, theta, f, m, fw, mw;
  Eigen::Matrix<double, 6, 12> dd;  // ∂[Δp; θ]/∂[δu_a, δφ_a, δu_b, δφ_b]
};

template <class S>
SpringState evaluate(const S& sp, const Pose& pa, const Pose& pb) {
  SpringState st;
  st.a = pa.r * sp.q;
  st.sa = pa.r * sp.ra;
  st.sb = pb.r * sp.rb;
  // Both axes' origins coincide unloaded, so d is a sum of small terms, each accurate to its
  // own size rather than to the size of the coordinates.
  st.d = (pb.u - pa.u) + detail::rotate_minus_identity(pb.phi, sp.rb) - detail::rotate_minus_identity(pa.phi, sp.ra);
  const Vector3d dp = st.a.transpose() * st.d;
  st.theta = detail::log_so3(st.a.transpose() * pb.r * sp.q);
  Eigen::Matrix<double, 6, 1> delta;
  delta << dp, st.theta;
  const Eigen::Matrix<double, 6, 1> w = sp.k * delta;
  st.f = w.head<3>();
  st.m = w.tail<3>();
  st.jinv = detail::inv_left_jacobian(st.theta);
  st.fw = st.a * st.f;
  st.mw = st.a * (st.jinv.transpose() * st.m);
  const Matrix3d at = st.a.transpose();
  st.dd.setZero();
  st.dd.block<3, 3>(0, 0) = -at;
  st.dd.block<3, 3>(0, 3) = at * (hat(st.sa) + hat(st.d));
  st.dd.block<3, 3>(0, 6) = at;
  st.dd.block<3, 3>(0, 9) = -at * hat(st.sb);
  st.dd.block<3, 3>(3, 3) = -st.jinv * at;
  st.dd.block<3, 3>(3, 9) = st.jinv * at;
  return st;
}

Pose pose_of(const Eigen::VectorXd& x, int index) {
  Pose p;
  if (index < 0) return p;
  p.u = x.segment<3>(6 * index);
  p.phi = x.segment<3>(6 * index + 3);
  p.r = detail::exp_so3(p.phi);
  return p;
}

// Adds block b at (block row, block column) = (·, col) in slot `slot` of m, whose pattern is
// EquilibriumSystem's: column 6·col + c holds the slot's six rows at 6·slot from its start.
void add_block(Eigen::SparseMatrix<double>& m, int col, int slot, const Eigen::Matrix<double, 6, 6>& b) {
  if (col < 0 || slot < 0) return;
  double* v = m.valuePtr();
  const int* outer = m.outerIndexPtr();
  for (int c = 0; c < 6; ++c) {
    double* out = v + outer[6 * col + c] + 6 * slot;
    for (int r = 0; r < 6; ++r) out[r] += b(r, c);
  }
}

}  // namespace

Eigen::VectorXd EquilibriumSystem::residual(const Eigen::VectorXd& x, double load_factor) const {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(size());
  for (const Spring& sp : springs_) {
    const int ia = index_[sp.a], ib = index_[sp.b];
    if (ia < 0 && ib < 0) continue;
    const SpringState st = evaluate(sp, pose_of(x, ia), pose_of(x, ib));
    if (ia >= 0) {
      r.segment<3>(6 * ia) -= st.fw;
      r.segment<3>(6 * ia + 3) -= (st.sa + st.d).cross(st.fw) + st.mw;
    }
    if (ib >= 0) {
      r.segment<3>(6 * ib) += st.fw;
      r.segment<3>(6 * ib + 3) += st.sb.cross(st.fw) + st.mw;
    }
  }
  for (const Load& l : loads_) {
    const int i = index_[l.module];
    if (i < 0) continue;
    const Pose p = pose_of(x, i);
    r.segment<3>(6 * i) -= load_factor * l.force;
    r.segment<3>(6 * i + 3) -= load_factor * (p.r * l.arm).cross(l.force);
  }
  return r;
}

Eigen::SparseMatrix<double> EquilibriumSystem::tangent(const Eigen::VectorXd& x, double load_factor, bool geometric) const {
  Eigen::SparseMatrix<double> m = pattern_;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(size());
  const Eigen::VectorXd& at = geometric ? x : zero;
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const Spring& sp = springs_[s];
    const auto& slots = spring_slots_[s];
    const int ia = index_[sp.a], ib = index_[sp.b];
    if (ia < 0 && ib < 0) continue;
    const SpringState st = evaluate(sp, pose_of(at, ia), pose_of(at, ib));
    Eigen::Matrix<double, 12, 12> h;
    if (!geometric) {
      h = st.dd.transpose() * sp.k * st.dd;
    } else {
      const Block dtheta = st.dd.bottomRows<3>();
      Block gf = st.a * sp.k.topRows<3>() * st.dd;
      gf.block<3, 3>(0, 3) -= hat(st.fw);
      Block gm = st.a * st.jinv.transpose() * sp.k.bottomRows<3>() * st.dd +
                 st.a * detail::d_inv_left_jacobian_t(st.theta, st.m) * dtheta;
      gm.block<3, 3>(0, 3) -= hat(st.mw);
      Block ea = Block::Zero(), eb = Block::Zero();
      ea.block<3, 3>(0, 0) = -Matrix3d::Identity();
      ea.block<3, 3>(0, 6) = Matrix3d::Identity();
      ea.block<3, 3>(0, 9) = -hat(st.sb);
      eb.block<3, 3>(0, 9) = -hat(st.sb);
      h.block<3, 12>(0, 0) = -gf;
      h.block<3, 12>(3, 0) = -hat(st.sa + st.d) * gf + hat(st.fw) * ea - gm;
      h.block<3, 12>(6, 0) = gf;
      h.block<3, 12>(9, 0) = hat(st.sb) * gf - hat(st.fw) * eb + gm;
    }
    add_block(m, ia, slots[0], h.block<6, 6>(0, 0));
    add_block(m, ib, slots[1], h.block<6, 6>(0, 6));
    add_block(m, ia, slots[2], h.block<6, 6>(6, 0));
    add_block(m, ib, slots[3], h.block<6, 6>(6, 6));
  }
  if (geometric) {
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      const Load& l = loads_[k];
      const int i = index_[l.module];
      if (i < 0) continue;
      Eigen::Matrix<double, 6, 6> kl = Eigen::Matrix<double, 6, 6>::Zero();
      kl.block<3, 3>(3, 3) = -load_factor * hat(l.force) * hat(pose_of(x, i).r * l.arm);
      add_block(m, i, load_slots_[k], kl);
    }
  }
  return m;
}

}  // namespace foldkit::analysis
