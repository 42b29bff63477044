#pragma once
// Contacts of the ODE sheet (private to this library, like every file that sees ODE): each actor a
// thin convex prism of the sheet's thickness about its mid-surface (one per triangle where the
// actor is not convex), an optional ground plane z = DynamicOptions::ground, and the contact joints
// of one step. Built only when the options ask for contacts: a scene without them has no space.
#include <memory>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>
#include <ode/ode.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/dynamics/mass_properties.hpp"

namespace foldkit::dynamics::detail {

// Owners of ODE's objects: a constructor that throws half way frees what it made.
struct WorldDeleter {
  void operator()(dxWorld* w) const { dWorldDestroy(w); }
};
struct SpaceDeleter {
  void operator()(dxSpace* s) const { dSpaceDestroy(s); }  // and the geoms in it
};
struct JointGroupDeleter {
  void operator()(dxJointGroup* g) const { dJointGroupDestroy(g); }
};
using World = std::unique_ptr<dxWorld, WorldDeleter>;
using Space = std::unique_ptr<dxSpace, SpaceDeleter>;
using JointGroup = std::unique_ptr<dxJointGroup, JointGroupDeleter>;

// One contact point of one step.
struct ContactPoint {
  int a = 0;       // actor index
  int b = -1;      // actor index; −1: the ground
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // world, metres
  double depth = 0.0;  // overlap of the two prisms (or prism and ground) along the normal, metres
  // Unit, world: the direction the contact pushes actor a (actor b is pushed the opposite way).
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// The collision space of one sheet and the contact joints of the current step. Keeps pointers to
// the world and bodies it is given (owned by the OdeSheet that owns this, which outlives it).
class OdeContacts {
 public:
  // `bodies` per actor index; `fixed` the held actor's index (−1: none), whose contacts are made
  // with the static environment.
  OdeContacts(dWorldID world, const std::vector<dBodyID>& bodies, int fixed, const geometry::CreasePattern& pattern,
              const DynamicOptions& options, const std::vector<MassProperties>& mass);
  OdeContacts(const OdeContacts&) = delete;
  OdeContacts& operator=(const OdeContacts&) = delete;
  ~OdeContacts();

  // Makes the contact joints of the sheet's current poses (before a step); they hold for one step.
  // With `leave_out` (per actor index; a probe step, see OdeSheet::hold_torque_signed()) the
  // contacts of the actors it marks are not made, the others push no penetration apart (soft ERP
  // 0: a probe holding the sheet still must not fight them), and points() keeps the last real step's.
  void collide(const std::vector<char>* leave_out = nullptr);
  // Removes them (after the step).
  void clear();
  // The contact points of the last collide() (vertex-shared points left out), in world metres.
  const std::vector<ContactPoint>& points() const { return points_; }
  double thickness() const { return thickness_; }  // metres

 private:
  struct Pair;
  static void near(void* self, dGeomID o1, dGeomID o2);
  void touch(dGeomID o1, dGeomID o2);
  const Pair& pair(int a, int b);
  bool at_shared_vertex(const Pair& p, int a, const Eigen::Vector3d& point) const;
  void add_prism(int actor, const std::vector<Eigen::Vector2d>& polygon);

  dWorldID world_;
  std::vector<dBodyID> bodies_;
  int fixed_;
  const geometry::CreasePattern& pattern_;
  const DynamicOptions& options_;
  double thickness_ = 0.0;
  std::vector<Eigen::Vector3d> centroid_;  // per actor: its body's origin in the flat sheet, metres
  std::vector<std::vector<int>> hinged_;   // per actor: actors it shares a crease with (never touch)
  // Prism data ODE points into (it copies nothing): kept for the geoms' lifetime.
  std::vector<std::unique_ptr<double[]>> planes_, corners_;
  std::vector<std::unique_ptr<unsigned[]>> polygons_;
  std::unordered_map<long long, Pair> pairs_;  // facet pairs met so far, by a·actors + b
  JointGroup group_;
  Space space_;
  std::vector<ContactPoint> points_;
  const std::vector<char>* leave_out_ = nullptr;  // during a probe's collide() only
};

}  // namespace foldkit::dynamics::detail
