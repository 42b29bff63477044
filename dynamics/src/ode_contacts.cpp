#include "ode_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace foldkit::dynamics::detail {
namespace {

// A zero-thickness sheet has no stable contact: the facets are prisms of this share of the sheet's
// bounding-box diagonal unless DynamicOptions::thickness says otherwise.
constexpr double kDefaultThickness = 1e-3;
// Contacts this many thicknesses from a vertex two facets share are that vertex's (their prisms
// overlap there whenever the vertex is folded), not a collision: left out.
constexpr double kVertexRadius = 4.0;
constexpr int kMaxContacts = 8;  // per pair of geoms and step

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Counter-clockwise convex hull (Andrew's monotone chain).
std::vector<Eigen::Vector2d> hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

double area(const std::vector<Eigen::Vector2d>& polygon) {
  double a = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) a += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return a / 2.0;
}

int actor_of(dGeomID g) { return static_cast<int>(reinterpret_cast<std::intptr_t>(dGeomGetData(g))) - 1; }  // −1: ground

}  // namespace

// Two facets that met: the vertices they share (flat sheet, metres), whose neighbourhood is theirs.
struct OdeContacts::Pair {
  std::vector<Eigen::Vector3d> shared;
};

OdeContacts::OdeContacts(dWorldID world, const std::vector<dBodyID>& bodies, int fixed, const geometry::CreasePattern& pattern,
                         const DynamicOptions& options, const std::vector<MassProperties>& mass)
    : world_(world), bodies_(bodies), fixed_(fixed), pattern_(pattern), options_(options),
      hinged_(pattern.actors().size()), group_(dJointGroupCreate(0)), space_(dHashSpaceCreate(nullptr)) {
  thickness_ = options.thickness ? *options.thickness : kDefaultThickness * pattern.diagonal() * options.scale;
  for (const auto& m : mass) centroid_.push_back(m.centroid);
  for (const auto& j : pattern.joints()) {
    hinged_[j.actors[0]].push_back(j.actors[1]);
    hinged_[j.actors[1]].push_back(j.actors[0]);
  }
  const auto& V = pattern.vertices();
  {  // the facets' prisms (the ground alone needs them too)
    for (std::size_t a = 0; a < pattern.actors().size(); ++a) {
      std::vector<Eigen::Vector2d> corners;
      double triangles = 0.0;
      for (const auto& t : pattern.actors()[a].triangles) {
        std::vector<Eigen::Vector2d> tri;
        for (int v : t.v) tri.push_back(options.scale * Eigen::Vector2d(V[v].x(), V[v].y()));
        triangles += std::abs(area(tri));
        corners.insert(corners.end(), tri.begin(), tri.end());
      }
      // A convex facet is one prism (no seams inside it for another facet to catch on).
      const std::vector<Eigen::Vector2d> h = hull(corners);
      if (std::abs(area(h) - triangles) <= 1e-9 * triangles) {
        add_prism(static_cast<int>(a), h);
        continue;
      }
      for (const auto& t : pattern.actors()[a].triangles) {
        std::vector<Eigen::Vector2d> tri;
        for (int v : t.v) tri.push_back(options.scale * Eigen::Vector2d(V[v].x(), V[v].y()));
        add_prism(static_cast<int>(a), hull(tri));
      }
    }
  }
  if (options.ground) {
    dGeomID plane = dCreatePlane(space_.get(), 0, 0, 1, *options.ground);
    dGeomSetData(plane, nullptr);
  }
}

OdeContacts::~OdeContacts() = default;

void OdeContacts::add_prism(int actor, const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.size() < 3) return;  // a degenerate triangle has no inside to touch
  const auto n = static_cast<unsigned>(polygon.size());
  const double half = thickness_ / 2.0;
  const Eigen::Vector2d c(centroid_[actor].x(), centroid_[actor].y());  // the body's origin
  auto corners = std::make_unique<double[]>(6 * n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned side = 0; side < 2; ++side) {
      double* p = &corners[3 * (i + side * n)];
      p[0] = polygon[i].x() - c.x();
      p[1] = polygon[i].y() - c.y();
      p[2] = side == 0 ? -half : half;
    }
  // Planes n·x = d: top, bottom, then one per edge (outward, the polygon counter-clockwise).
  auto planes = std::make_unique<double[]>(4 * (n + 2));
  const double caps[8] = {0, 0, 1, half, 0, 0, -1, half};
  std::copy(caps, caps + 8, planes.get());
  // Faces: a count, then corner indices counter-clockwise seen from outside.
  auto polygons = std::make_unique<unsigned[]>(2 * (n + 1) + 5 * n);
  unsigned* f = polygons.get();
  *f++ = n;
  for (unsigned i = 0; i < n; ++i) *f++ = n + i;
  *f++ = n;
  for (unsigned i = n; i-- > 0;) *f++ = i;
  for (unsigned i = 0; i < n; ++i) {
    const Eigen::Vector2d a = polygon[i] - c, b = polygon[(i + 1) % n] - c, e = (b - a).normalized();
    const Eigen::Vector2d out(e.y(), -e.x());
    double* pl = &planes[4 * (i + 2)];
    pl[0] = out.x();
    pl[1] = out.y();
    pl[2] = 0.0;
    pl[3] = out.dot(a);
    const unsigned k = (i + 1) % n;
    *f++ = 4;
    *f++ = i;
    *f++ = k;
    *f++ = k + n;
    *f++ = i + n;
  }
  dGeomID g = dCreateConvex(space_.get(), planes.get(), n + 2, corners.get(), 2 * n, polygons.get());
  dGeomSetBody(g, bodies_[actor]);
  dGeomSetData(g, reinterpret_cast<void*>(static_cast<std::intptr_t>(actor + 1)));
  planes_.push_back(std::move(planes));
  corners_.push_back(std::move(corners));
  polygons_.push_back(std::move(polygons));
}

void OdeContacts::collide(const std::vector<char>* leave_out) {
  leave_out_ = leave_out;
  if (!leave_out) points_.clear();
  dSpaceCollide(space_.get(), this, &OdeContacts::near);
  leave_out_ = nullptr;
}

void OdeContacts::clear() { dJointGroupEmpty(group_.get()); }

void OdeContacts::near(void* self, dGeomID o1, dGeomID o2) { static_cast<OdeContacts*>(self)->touch(o1, o2); }

const OdeContacts::Pair& OdeContacts::pair(int a, int b) {
  const long long key = static_cast<long long>(a) * static_cast<long long>(bodies_.size()) + b;
  auto it = pairs_.find(key);
  if (it != pairs_.end()) return it->second;
  Pair p;
  std::vector<int> va, vb;
  for (const auto& t : pattern_.actors()[a].triangles) va.insert(va.end(), t.v.begin(), t.v.end());
  for (const auto& t : pattern_.actors()[b].triangles) vb.insert(vb.end(), t.v.begin(), t.v.end());
  std::sort(va.begin(), va.end());
  std::sort(vb.begin(), vb.end());
  std::vector<int> common;
  std::set_intersection(va.begin(), va.end(), vb.begin(), vb.end(), std::back_inserter(common));
  common.erase(std::unique(common.begin(), common.end()), common.end());
  for (int v : common) {
    const auto& x = pattern_.vertices()[v];
    p.shared.push_back(options_.scale * Eigen::Vector3d(x.x(), x.y(), 0.0));
  }
  return pairs_.emplace(key, std::move(p)).first->second;
}

bool OdeContacts::at_shared_vertex(const Pair& p, int a, const Eigen::Vector3d& point) const {
  if (p.shared.empty()) return false;
  const dReal* q = dBodyGetQuaternion(bodies_[a]);
  const dReal* c = dBodyGetPosition(bodies_[a]);
  const Eigen::Quaterniond R(q[0], q[1], q[2], q[3]);
  const Eigen::Vector3d origin(c[0], c[1], c[2]);
  for (const Eigen::Vector3d& v : p.shared)
    if ((origin + R * (v - centroid_[a]) - point).norm() <= kVertexRadius * thickness_) return true;
  return false;
}

void OdeContacts::touch(dGeomID o1, dGeomID o2) {
  int a = actor_of(o1), b = actor_of(o2);
  if (a < 0) {  // the ground second
    std::swap(o1, o2);
    std::swap(a, b);
  }
  if (a < 0 || a == b || (b < 0 && a == fixed_) || (a == fixed_ && b == fixed_)) return;
  if (b >= 0) {
    if (!options_.contacts) return;  // the ground only
    if (std::find(hinged_[a].begin(), hinged_[a].end(), b) != hinged_[a].end()) return;  // a crease joins them
    if (a > b) {
      std::swap(o1, o2);
      std::swap(a, b);
    }
  }
  if (leave_out_ && ((*leave_out_)[a] || (b >= 0 && (*leave_out_)[b]))) return;
  dContactGeom found[kMaxContacts];
  const int n = dCollide(o1, o2, kMaxContacts, found, sizeof(dContactGeom));
  if (n == 0) return;
  const Pair* shared = b >= 0 ? &pair(a, b) : nullptr;
  // The fixed actor and the ground do not move: their side of a contact is the static world.
  dBodyID b1 = a == fixed_ ? nullptr : bodies_[a];
  dBodyID b2 = b < 0 || b == fixed_ ? nullptr : bodies_[b];
  for (int i = 0; i < n; ++i) {
    const dContactGeom& g = found[i];
    const Eigen::Vector3d point(g.pos[0], g.pos[1], g.pos[2]);
    if (shared && at_shared_vertex(*shared, a, point)) continue;
    dContact c{};
    c.geom = g;
    c.surface.mode = dContactApprox1;
    c.surface.mu = options_.friction.value_or(kDefaultFriction);
    if (leave_out_) {
      c.surface.mode |= dContactSoftERP;
      c.surface.soft_erp = 0.0;
    }
    // Friction along the sliding direction, when sliding: Coulomb's cone there, not the pyramid of
    // two fixed axes ODE would take.
    dVector3 v1 = {0, 0, 0}, v2 = {0, 0, 0};
    if (b1) dBodyGetPointVel(b1, g.pos[0], g.pos[1], g.pos[2], v1);
    if (b2) dBodyGetPointVel(b2, g.pos[0], g.pos[1], g.pos[2], v2);
    const Eigen::Vector3d normal(g.normal[0], g.normal[1], g.normal[2]);
    Eigen::Vector3d slip = Eigen::Vector3d(v1[0] - v2[0], v1[1] - v2[1], v1[2] - v2[2]);
    slip -= slip.dot(normal) * normal;
    if (slip.norm() > 1e-9) {
      slip.normalize();
      c.surface.mode |= dContactFDir1;
      c.fdir1[0] = slip.x();
      c.fdir1[1] = slip.y();
      c.fdir1[2] = slip.z();
    }
    dJointID j = dJointCreateContact(world_, group_.get(), &c);
    dJointAttach(j, b1, b2);
    // ODE's normal points the way body 1 (actor a) is pushed.
    if (!leave_out_) points_.push_back({a, b, point, g.depth, normal});
  }
}

}  // namespace foldkit::dynamics::detail
