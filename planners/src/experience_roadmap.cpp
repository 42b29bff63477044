// Thunder's roadmap in foldkit's experience file (issue 38, item 4): SPARSdb's graph written and
// read back as it is, so that a process loading the database does not rebuild it from the stored
// paths. Rebuilding (SPARSdb::addPathToRoadmap) interpolates every path and checks its states and
// motions: the closure projections and collision checks that took 3.4 s per `foldkit plan` at 37
// paths (perf: ClosureSystem::evaluate_vertex, LeastNormSolver::factor, the broad phase), against
// which reading the graph only deserializes states.
#include <cstring>
#include <string>

#include <boost/range/adaptor/map.hpp>
#include <ompl/tools/thunder/SPARSdb.h>

#include "foldkit/planners/experience.hpp"

namespace foldkit::planners::detail {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// The records, in this machine's byte order: per vertex after SPARSdb's query vertex (vertex 0,
// which has no state) its guard type (8 bytes) and its state; per edge, in the graph's order, its
// two vertices (8 bytes each); per vertex its interface data (SPARSdb's record of the closest
// pairs of states seen between its neighbours, which decides later quality guards): the number of
// entries, then per entry its pair of vertices, a mask of the states it holds (point A, point B,
// sigma A, sigma B: bits 0–3) and those states. Edges are written without their lazy collision
// state: they are checked when a search first uses them, as in a rebuilt roadmap.
class Roadmap : public og::SPARSdb {
 public:
  using SPARSdb::SPARSdb;

  std::string records() const {
    const ob::StateSpace& space = *si_->getStateSpace();
    std::string out, state(space.getSerializationLength(), '\0');
    const auto put = [&](std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
    const auto put_state = [&](const ob::State* s) {
      space.serialize(state.data(), s);
      out += state;
    };
    const std::size_t n = boost::num_vertices(g_);
    for (Vertex v = 1; v < n; ++v) {
      put(static_cast<std::uint64_t>(colorProperty_[v]));
      put_state(stateProperty_[v]);
    }
    for (const Edge e : boost::make_iterator_range(boost::edges(g_))) {
      put(boost::source(e, g_));
      put(boost::target(e, g_));
    }
    for (Vertex v = 1; v < n; ++v) {
      const InterfaceHash& hash = interfaceDataProperty_[v].interfaceHash;
      put(hash.size());
      for (const auto& [pair, data] : hash) {
        put(pair.first);
        put(pair.second);
        const ob::State* states[4] = {data.pointA_, data.pointB_, data.sigmaA_, data.sigmaB_};
        std::uint64_t mask = 0;
        for (int i = 0; i < 4; ++i)
          if (states[i]) mask |= 1u << i;
        put(mask);
        for (const ob::State* s : states)
          if (s) put_state(s);
      }
    }
    return out;
  }

  // Reads records written by records() into this empty roadmap: the reason they are not such
  // records, or empty. Every state is checked as the paths' are (read_state).
  std::string read(const std::string& records, std::size_t vertices, std::size_t edges) {
    Reader in{records, *si_->getStateSpace()};
    checkQueryStateInitialization();  // vertex 0, as SPARSdb's own loading (setPlannerData) makes it
    for (std::size_t i = 1; i <= vertices; ++i) {
      std::uint64_t type = 0;
      if (!in.u64(type)) return "vertex " + std::to_string(i) + " is cut short";
      if (type > QUALITY) return "vertex " + std::to_string(i) + " has no guard type (" + std::to_string(type) + ")";
      ob::State* state = nullptr;
      if (const std::string why = in.state(state); !why.empty()) return "vertex " + std::to_string(i) + ": " + why;
      addGuard(state, static_cast<GuardType>(type));
    }
    for (std::size_t i = 1; i <= edges; ++i) {
      std::uint64_t a = 0, b = 0;
      if (!in.u64(a) || !in.u64(b)) return "edge " + std::to_string(i) + " is cut short";
      if (a < 1 || a > vertices || b < 1 || b > vertices || a == b)
        return "edge " + std::to_string(i) + " joins vertices " + std::to_string(a) + " and " + std::to_string(b) + " of " +
               std::to_string(vertices);
      connectGuards(a, b);
    }
    for (Vertex v = 1; v <= vertices; ++v)
      if (const std::string why = read_interfaces(in, v, vertices); !why.empty()) return "vertex " + std::to_string(v) + "'s " + why;
    if (!in.done()) return "bytes after its last record";
    return {};
  }

 private:
  struct Reader {
    const std::string& bytes;
    const ob::StateSpace& space;
    std::size_t pos = 0;

    bool u64(std::uint64_t& v) {
      if (bytes.size() - pos < sizeof v) return false;
      std::memcpy(&v, bytes.data() + pos, sizeof v);
      pos += sizeof v;
      return true;
    }
    // A new state read off the records (the caller owns it), or the reason there is none.
    std::string state(ob::State*& out) {
      const std::size_t n = space.getSerializationLength();
      if (bytes.size() - pos < n) return "its state is cut short";
      out = space.allocState();
      if (!read_state(space, bytes.data() + pos, out)) {
        space.freeState(out);
        out = nullptr;
        return "its state is not a closed state within the bounds";
      }
      pos += n;
      return {};
    }
    bool done() const { return pos == bytes.size(); }
  };

  // Vertex v's interface data, as records() writes it. Read after every vertex is in: adding a
  // guard clears the interface data of the vertices near it (SPARSdb::abandonLists).
  std::string read_interfaces(Reader& in, Vertex v, std::size_t vertices) {
    std::uint64_t count = 0;
    if (!in.u64(count)) return "interface data is cut short";
    if (count > (in.bytes.size() - in.pos) / (3 * sizeof count)) return "interface data holds more entries than its bytes";
    for (std::uint64_t k = 0; k < count; ++k) {
      std::uint64_t a = 0, b = 0, mask = 0;
      if (!in.u64(a) || !in.u64(b) || !in.u64(mask)) return "interface data is cut short";
      if (a < 1 || a > vertices || b < 1 || b > vertices || mask > 15)
        return "interface entry " + std::to_string(k + 1) + " is not a pair of its vertices";
      InterfaceData& data = interfaceDataProperty_[v].interfaceHash[VertexPair(a, b)];
      data.clear(si_);
      ob::State** states[4] = {&data.pointA_, &data.pointB_, &data.sigmaA_, &data.sigmaB_};
      for (int i = 0; i < 4; ++i)
        if (mask & (1u << i))
          if (const std::string why = in.state(*states[i]); !why.empty()) return "interface entry " + std::to_string(k + 1) + ": " + why;
      // As InterfaceData::setFirst/setSecond keep it: the distance between the points, once both are known.
      if (data.pointA_ && data.pointB_) data.d_ = si_->distance(data.pointA_, data.pointB_);
    }
    return {};
  }
};

}  // namespace

std::shared_ptr<og::SPARSdb> make_roadmap(const ob::SpaceInformationPtr& si) { return std::make_shared<Roadmap>(si); }

std::size_t roadmap_vertices(const og::SPARSdb& roadmap) {
  // Vertex 0 is SPARSdb's query vertex, there once anything was added: not a state of the roadmap.
  return roadmap.getNumVertices() > 0 ? roadmap.getNumVertices() - 1 : 0;
}

std::string roadmap_records(const og::SPARSdb& roadmap) {
  const auto* own = dynamic_cast<const Roadmap*>(&roadmap);
  if (!own) throw std::logic_error("roadmap_records: a roadmap not made by make_roadmap");
  return own->records();
}

std::string read_roadmap(og::SPARSdb& roadmap, const std::string& records, std::size_t vertices, std::size_t edges) {
  auto* own = dynamic_cast<Roadmap*>(&roadmap);
  if (!own || roadmap.getNumVertices() != 0) throw std::logic_error("read_roadmap: an empty roadmap made by make_roadmap is needed");
  return own->read(records, vertices, edges);
}

}  // namespace foldkit::planners::detail
