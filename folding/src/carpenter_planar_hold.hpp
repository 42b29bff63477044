#pragma once
// Ends of an open chain held rigid when the LP over the whole chain fails (issue 36's spirals),
// private to carpenter_planar.cpp: which ends, for how many steps, and when the whole chain is
// tried again.
//
// On a spiral the expansive motions turn each joint faster than the one inside it by a fixed
// factor (≈ 1.5 per joint on an 18-gon-per-turn Archimedean spiral), so the speeds span more than
// the LP's 1e12 box and Clp's tolerances after about five turns, and the LP is called
// infeasible. The slow part then moves by less than a step resolves anyway: it is held rigid
// (its joints at speed 0, its inner pairs at their distance, the field rebuilt from the joint
// speeds), and the LP solves the rest, every pair with a moving joint between its ends still
// strictly expansive. Tried: m/2, m/4, … merged vertices moving, the rest held at the start, at
// the end, or half at each (a double spiral's two centres); the first that solves is used. The
// hold is kept (by the input vertices at its boundaries) for the next steps, and the whole chain
// is tried again after 2, 4, … 64 held steps; once half the part that moved has gone straight, a
// new hold is sought (failed LPs over the whole chain took most of the time: 150 s → 2–3 s on a
// 200-vertex spiral of ten turns).
#include <utility>
#include <vector>

#include "carpenter_planar_chain.hpp"
#include "carpenter_planar_velocity.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding::planar_detail {

// Keeps no reference to the chain or the result beyond a call.
class HeldEnds {
 public:
  // The arguments of every call below: the chain (open), the field to fill, the input vertex of
  // each merged vertex, the struts to seed the LP with, the LP's near radius (length units),
  // the result whose lp_solves and max_struts count the LPs solved here, and
  // CarpenterPlanarOptions::all_struts.

  // A field with an end held, sought as described above; false (field unchanged) when none
  // solves. `whole_failed`: the LP over the whole chain was tried for this step and failed.
  bool find(const MergedChain& chain, detail::ExpansiveVelocity& field, const std::vector<int>& keys,
            const std::vector<std::pair<int, int>>& seed, double radius, bool whole_failed,
            CarpenterPlanarResult& result, bool all_struts);

  // The last hold again, while it waits for the next try of the whole chain (Expired: no hold,
  // or its wait is over; Shrunk: half the part it let move has gone straight, or it failed: a
  // new hold is sought without trying the whole chain).
  enum class Reuse { Used, Shrunk, Expired };
  Reuse reuse(const MergedChain& chain, detail::ExpansiveVelocity& field, const std::vector<int>& keys,
              const std::vector<std::pair<int, int>>& seed, double radius, CarpenterPlanarResult& result,
              bool all_struts);

  bool active() const { return active_; }  // find() found one, and no whole-chain LP solved since
  void release() { active_ = false; }      // an LP over the whole chain solved

 private:
  bool active_ = false;
  int where_ = 0;        // placement(): held at the start, the end, both
  int prefix_key_ = -1;  // last input vertex of the body held at the start (-1: none)
  int suffix_key_ = -1;  // first input vertex of the body held at the end (-1: none)
  int moving_ = 0;       // merged vertices outside the body when it was found
  int wait_ = 0;         // held steps before the whole chain is tried again
  int backoff_ = 2;
};

}  // namespace foldkit::folding::planar_detail
