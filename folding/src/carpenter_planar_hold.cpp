#include "carpenter_planar_hold.hpp"

#include <algorithm>
#include <utility>

namespace foldkit::folding::planar_detail {
namespace {

// m − moving merged vertices held: at the start (where 0), the end (1) or half at each (2).
detail::RigidEnds placement(int m, int moving, int where) {
  detail::RigidEnds r;
  const int held = m - moving;
  if (where == 0) r.prefix = held;
  if (where == 1) r.suffix = held;
  if (where == 2) r.prefix = held / 2, r.suffix = held - held / 2;
  return r;
}

// The LP with `rigid` held (both callers make it a probe: Clp's "infeasible" is not checked by
// fresh solves, as another hold is tried instead); its solves and rows counted in `result`.
bool solve_with(const MergedChain& chain, const detail::RigidEnds& rigid, detail::ExpansiveVelocity& field,
                const std::vector<int>& keys, const std::vector<std::pair<int, int>>& seed, double radius,
                CarpenterPlanarResult& result, bool all_struts) {
  detail::ExpansiveVelocity held =
      detail::expansive_velocity(chain.q(), false, seed, radius, all_struts, &keys, nullptr, rigid);
  result.lp_solves += held.lp_solves;
  result.max_struts = std::max(result.max_struts, held.struts);
  if (!held.solved || !(held.t > 0.0)) return false;
  field = std::move(held);
  return true;
}

}  // namespace

bool HeldEnds::find(const MergedChain& chain, detail::ExpansiveVelocity& field, const std::vector<int>& keys,
                    const std::vector<std::pair<int, int>>& seed, double radius, bool whole_failed,
                    CarpenterPlanarResult& result, bool all_struts) {
  const int m = chain.vertices();
  // After a hold, from twice the part it let move, its placement first.
  const int first = active_ ? std::min(m / 2, 2 * moving_) : m / 2;
  const int order[3] = {where_, (where_ + 1) % 3, (where_ + 2) % 3};
  for (int moving = first; moving >= 3; moving /= 2)
    for (const int where : order) {
      detail::RigidEnds rigid = placement(m, moving, where);
      rigid.probe = true;
      if (!solve_with(chain, rigid, field, keys, seed, radius, result, all_struts)) continue;
      if (whole_failed) {  // the whole chain is tried again after twice as many held steps
        backoff_ = active_ ? std::min(2 * backoff_, 64) : 2;
        wait_ = backoff_;
      }
      active_ = true;
      where_ = where;
      prefix_key_ = rigid.prefix >= 3 ? chain.key(rigid.prefix - 1) : -1;
      suffix_key_ = rigid.suffix >= 3 ? chain.key(m - rigid.suffix) : -1;
      moving_ = moving;
      return true;
    }
  return false;
}

HeldEnds::Reuse HeldEnds::reuse(const MergedChain& chain, detail::ExpansiveVelocity& field,
                                const std::vector<int>& keys, const std::vector<std::pair<int, int>>& seed,
                                double radius, CarpenterPlanarResult& result, bool all_struts) {
  if (!active_ || wait_ <= 0) return Reuse::Expired;
  --wait_;
  const int m = chain.vertices();
  detail::RigidEnds rigid;
  for (int a = 0; a < m; ++a) {
    rigid.prefix += prefix_key_ >= 0 && chain.key(a) <= prefix_key_;
    rigid.suffix += suffix_key_ >= 0 && chain.key(a) >= suffix_key_;
  }
  const int moving = m - rigid.prefix - rigid.suffix;
  if (2 * moving <= moving_ || moving < 3) return Reuse::Shrunk;
  rigid.probe = true;
  return solve_with(chain, rigid, field, keys, seed, radius, result, all_struts) ? Reuse::Used : Reuse::Shrunk;
}

}  // namespace foldkit::folding::planar_detail
