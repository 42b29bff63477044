#include "facet_chain.hpp"

#include <algorithm>
#include <deque>
#include <unordered_map>

namespace foldkit::simulation::detail {

std::vector<int> chain_steps(const geometry::CreasePattern& pattern, int a, int b, std::size_t max_visited) {
  const geometry::FacetGraph& graph = pattern.facet_graph();
  const auto edge_index = boost::get(boost::edge_index, graph);
  std::unordered_map<int, int> via;  // actor → step that reached it
  via.emplace(a, kNoChain);
  std::deque<int> queue{a};
  while (!queue.empty() && !via.count(b) && via.size() < max_visited) {
    const int f = queue.front();
    queue.pop_front();
    for (auto [e, end] = boost::out_edges(f, graph); e != end; ++e) {
      const int j = edge_index[*e], g = static_cast<int>(boost::target(*e, graph));
      if (via.count(g)) continue;
      via.emplace(g, (j << 1) | (pattern.joints()[j].actors[0] == g ? 0 : 1));
      queue.push_back(g);
    }
  }
  if (!via.count(b)) return {kNoChain};
  std::vector<int> steps;
  for (int f = b; f != a;) {
    const int step = via.at(f);
    steps.push_back(step);
    const auto& joint = pattern.joints()[step >> 1];
    f = joint.actors[1 - (step & 1)];
  }
  std::reverse(steps.begin(), steps.end());
  return steps;
}

}  // namespace foldkit::simulation::detail
