#include "foldkit/analysis/load_case.hpp"

#include <cstring>
#include <set>
#include <sstream>
#include <unordered_map>

#include <Eigen/Cholesky>

#include <tinyxml2.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/xml_reader.hpp"

namespace foldkit::analysis {
namespace {

using io::detail::XmlInput;
using tinyxml2::XMLElement;

Matrix6 stiffness(const XmlInput& in, const XMLElement& e) {
  const auto v = in.numbers(e);
  Matrix6 k = Matrix6::Zero();
  if (v.size() == 6) {
    for (int i = 0; i < 6; ++i) {
      if (!(v[static_cast<std::size_t>(i)] > 0)) in.fail(e, "<Stiffness>: diagonal values must be positive");
      k(i, i) = v[static_cast<std::size_t>(i)];
    }
    return k;
  }
  if (v.size() != 36) in.fail(e, "<Stiffness> needs 6 diagonal values or 36 (a 6×6 matrix by rows), found " + std::to_string(v.size()));
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) k(i, j) = v[static_cast<std::size_t>(6 * i + j)];
  if (!k.isApprox(k.transpose(), 1e-12)) in.fail(e, "<Stiffness>: the 6×6 matrix must be symmetric");
  if (k.llt().info() != Eigen::Success) in.fail(e, "<Stiffness>: the 6×6 matrix must be positive definite");
  return k;
}

// The children of `parent` named in `tags`, each at most once; anything else is an error.
template <std::size_t N>
std::array<const XMLElement*, N> fields(const XmlInput& in, const XMLElement& parent, const std::array<const char*, N>& tags) {
  std::array<const XMLElement*, N> found{};
  for (const XMLElement* c : in.children(parent)) {
    std::size_t k = 0;
    while (k < N && std::strcmp(c->Name(), tags[k]) != 0) ++k;
    if (k == N) in.fail(*c, std::string("unknown element <") + c->Name() + "> in <" + parent.Name() + ">");
    if (found[k]) in.fail(*c, std::string("<") + parent.Name() + "> has more than one <" + tags[k] + ">");
    found[k] = c;
  }
  return found;
}

Eigen::Vector3d vector3(const XmlInput& in, const XMLElement& e) {
  const auto v = in.numbers(e, 3);
  return {v[0], v[1], v[2]};
}

}  // namespace

LoadCase parse_load_case(const std::string& text, const std::string& name) {
  const XmlInput in(text, name);
  const XMLElement& root = in.root("LoadCase");
  LoadCase lc;
  lc.line = root.GetLineNum();
  bool titled = false;
  std::array<bool, 3> given{};
  std::set<int> fixed;
  for (const XMLElement* e : in.children(root)) {
    const std::string tag = e->Name();
    if (tag == "Title") {
      if (titled) in.fail(*e, "<LoadCase> has more than one <Title>");
      titled = true;
      lc.title = in.leaf_text(*e);
    } else if (tag == "Connection") {
      const auto [kind, stiff] = fields<2>(in, *e, {"Kind", "Stiffness"});
      if (!kind) in.fail(*e, "<Connection> has no <Kind>");
      if (!stiff) in.fail(*e, "<Connection> has no <Stiffness>");
      const std::string k = in.leaf_text(*kind);
      const auto ck = connection_kind(k);
      if (!ck) in.fail(*kind, "<Kind> must be hinged, face or edge, found '" + k.substr(0, 40) + "'");
      const auto idx = static_cast<std::size_t>(*ck);
      if (given[idx]) in.fail(*e, std::string("a second <Connection> of kind ") + to_string(*ck));
      given[idx] = true;
      lc.stiffness[idx] = stiffness(in, *stiff);
    } else if (tag == "Fixed") {
      std::istringstream tokens(in.leaf_text(*e));
      std::string token;
      while (tokens >> token) {
        const auto id = io::parse_int(token);
        if (!id) in.fail(*e, "<Fixed> must hold integer actor IDs, found '" + token.substr(0, 40) + "'");
        if (!fixed.insert(*id).second) in.fail(*e, "actor " + std::to_string(*id) + " is fixed twice");
        lc.fixed.push_back(*id);
        lc.fixed_lines.push_back(e->GetLineNum());
      }
    } else if (tag == "Load") {
      const auto [id, force, point] = fields<3>(in, *e, {"ActorID", "Force", "Point"});
      if (!id) in.fail(*e, "<Load> has no <ActorID>");
      if (!force) in.fail(*e, "<Load> has no <Force>");
      LoadSpec load;
      load.line = e->GetLineNum();
      load.actor = in.integer(*id, "an integer actor ID");
      load.force = vector3(in, *force);
      if (point) load.point = vector3(in, *point);
      lc.loads.push_back(load);
    } else {
      in.fail(*e, "unknown element <" + tag + "> in <LoadCase>");
    }
  }
  if (lc.fixed.empty()) in.fail(root, "<LoadCase> fixes no actor: add <Fixed>actor IDs</Fixed>");
  return lc;
}

LoadCase read_load_case(const std::string& path) { return parse_load_case(io::read_file(path), path); }

Problem make_problem(Structure structure, const LoadCase& lc, const std::string& name) {
  Problem p;
  std::unordered_map<int, int> index;
  for (std::size_t i = 0; i < structure.modules.size(); ++i) index[structure.modules[i].id] = static_cast<int>(i);
  const auto find = [&](int id, int line) {
    const auto it = index.find(id);
    if (it == index.end()) throw io::ParseError(name, line, "the pattern has no actor " + std::to_string(id));
    return it->second;
  };
  p.fixed.assign(structure.modules.size(), false);
  for (std::size_t i = 0; i < lc.fixed.size(); ++i) p.fixed[find(lc.fixed[i], lc.fixed_lines[i])] = true;
  for (const LoadSpec& l : lc.loads) {
    const int m = find(l.actor, l.line);
    p.loads.push_back({m, l.force, l.point ? *l.point : structure.modules[m].centroid});
  }
  p.stiffness = lc.stiffness;
  p.structure = std::move(structure);
  if (const int m = unrestrained_module(p); m >= 0)
    throw io::ParseError(name, lc.fixed_lines.front(),
                         "actor " + std::to_string(p.structure.modules[m].id) +
                             " is not tied to a fixed actor by any chain of connections");
  return p;
}

}  // namespace foldkit::analysis
