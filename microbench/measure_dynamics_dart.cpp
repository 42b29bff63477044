// The dynamic-simulation spike's second engine (issue 33): the Miura-ori of measure_dynamics in
// DART 6.12: a skeleton of revolute joints along foldkit's spanning tree (generalised
// coordinates), each crease outside the tree closed by two ball-joint constraints at its ends,
// one SERVO motor. Prints the same closure drift, kinematic difference and real-time factor.
// Usage: measure_dynamics_dart [n=10] [time_step=1e-3] [speed=0.5]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <dart/constraint/BallJointConstraint.hpp>
#include <dart/constraint/BoxedLcpConstraintSolver.hpp>
#include <dart/constraint/PgsBoxedLcpSolver.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

#include "foldkit/dynamics/mass_properties.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "one_motor_miura.hpp"

using namespace foldkit;
using namespace dart::dynamics;

namespace {

struct Sheet {
  SkeletonPtr skeleton;
  std::vector<BodyNode*> body;       // per actor
  std::vector<RevoluteJoint*> hinge;  // per joint; null outside the tree
};

// The skeleton along foldkit's spanning tree, in the pose `start`; unit areal density.
Sheet build_sheet(const geometry::CreasePattern& p, const geometry::KinematicTree& tree, const geometry::FoldState& start) {
  Sheet s{Skeleton::create("sheet"), std::vector<BodyNode*>(p.actors().size(), nullptr),
          std::vector<RevoluteJoint*>(p.joints().size(), nullptr)};
  for (int a : tree.order) {
    const auto m = dynamics::mass_properties(p, a, 1.0);
    BodyNode* bn = nullptr;
    if (tree.parent[a] < 0) {
      bn = s.skeleton->createJointAndBodyNodePair<WeldJoint>(nullptr).second;
    } else {
      const int j = tree.parent_joint[a];
      const geometry::JointAxis ax = geometry::joint_axis(p, j);
      RevoluteJoint::Properties props;
      props.mAxis = tree.side[a] * ax.direction;  // child = parent · R(side·direction, angle)
      props.mT_ParentBodyToJoint = Eigen::Translation3d(ax.point) * Eigen::Isometry3d::Identity();
      props.mT_ChildBodyToJoint = props.mT_ParentBodyToJoint;
      props.mName = "crease" + std::to_string(j);
      auto pair = s.skeleton->createJointAndBodyNodePair<RevoluteJoint>(s.body[tree.parent[a]], props,
                                                                        BodyNode::AspectProperties("actor" + std::to_string(a)));
      bn = pair.second;
      s.hinge[j] = pair.first;
      s.hinge[j]->setPosition(0, start.angles[j]);
    }
    bn->setInertia(Inertia(m.mass, m.centroid, m.inertia));
    s.body[a] = bn;
  }
  return s;
}

// The hinges outside the tree, as two ball joints at the crease's ends (placed in the start pose).
void close_loops(dart::simulation::World& world, const geometry::CreasePattern& p, const geometry::KinematicTree& tree,
                 const Sheet& s) {
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    if (tree.in_tree[j]) continue;
    const auto& jt = p.joints()[j];
    const Eigen::Isometry3d T = s.body[jt.actors[0]]->getWorldTransform();
    for (int e = 0; e < 2; ++e) {
      const Eigen::Vector3d v(p.vertices()[jt.v[e]].x(), p.vertices()[jt.v[e]].y(), 0.0);
      world.getConstraintSolver()->addConstraint(
          std::make_shared<dart::constraint::BallJointConstraint>(s.body[jt.actors[0]], s.body[jt.actors[1]], T * v));
    }
  }
}

// Every crease's fold angle, read off the bodies' poses (as foldkit::dynamics reads ODE's).
geometry::FoldState angles_of(const geometry::CreasePattern& p, const Sheet& s) {
  geometry::FoldState out = geometry::FoldState::flat(p);
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    const auto& jt = p.joints()[j];
    const int right = geometry::side_of(p, static_cast<int>(j), jt.actors[0]) > 0 ? jt.actors[0] : jt.actors[1];
    const int left = right == jt.actors[0] ? jt.actors[1] : jt.actors[0];
    const Eigen::Quaterniond q(s.body[left]->getWorldTransform().linear().transpose() * s.body[right]->getWorldTransform().linear());
    out.angles[static_cast<Eigen::Index>(j)] =
        2.0 * std::atan2(q.vec().dot(geometry::joint_axis(p, static_cast<int>(j)).direction), q.w());
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  const double dt = argc > 2 ? std::atof(argv[2]) : 1e-3, speed = argc > 3 ? std::atof(argv[3]) : 0.5;
  const microbench::OneMotorMiura scene = microbench::one_motor_miura(n, speed);
  const geometry::CreasePattern& p = scene.pattern;
  const geometry::FoldState& K = scene.kinematic.states.back();
  const geometry::KinematicTree tree = geometry::make_tree(p, 0);
  const Sheet sheet = build_sheet(p, tree, geometry::FoldState{scene.start});
  auto world = dart::simulation::World::create();
  world->setGravity(Eigen::Vector3d::Zero());
  world->setTimeStep(dt);
  // DART's default boxed LCP solver (Dantzig) met the redundant rows of the closed loops with
  // NaN (the assertion in RevoluteJoint::updateRelativeTransform); PGS, like ODE's QuickStep, runs.
  if (std::getenv("DART_PGS"))
    world->setConstraintSolver(std::make_unique<dart::constraint::BoxedLcpConstraintSolver>(
        std::make_shared<dart::constraint::PgsBoxedLcpSolver>()));
  world->addSkeleton(sheet.skeleton);
  if (!std::getenv("DART_NO_LOOPS")) close_loops(*world, p, tree, sheet);
  // The motor: the fixed actor's most folded crease in the tree (DART drives tree joints only).
  int drive = -1;
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    if (tree.in_tree[j] && (p.joints()[j].actors[0] == 0 || p.joints()[j].actors[1] == 0) &&
        (drive < 0 || std::abs(K.angles[static_cast<Eigen::Index>(j)]) > std::abs(K.angles[drive])))
      drive = static_cast<int>(j);
  RevoluteJoint* motor = sheet.hinge[static_cast<std::size_t>(drive)];
  motor->setActuatorType(Joint::SERVO);
  motor->setForceUpperLimit(0, 1e6);
  motor->setForceLowerLimit(0, -1e6);
  const geometry::ClosureSystem closure(p, 0);
  double drift = 0.0, t = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int step = 0; t < 60.0; ++step) {
    const double error = K.angles[drive] - motor->getPosition(0);
    if (std::abs(error) <= 1e-4) break;
    motor->setCommand(0, std::clamp(error / 0.02, -speed, speed));
    world->step();
    t += dt;
    if (step % 10 == 0) drift = std::max(drift, closure.max_error(angles_of(p, sheet)));
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const geometry::FoldState end = angles_of(p, sheet);
  drift = std::max(drift, closure.max_error(end));
  std::printf("DART miura %dx%d joints %zu dt %g: %g s simulated in %g s (RTF %.3g), closure drift %.3g rad, "
              "max |angle - kinematic| %.3g rad\n",
              n, n, p.joints().size(), dt, t, wall, t / wall, drift, (end.angles - K.angles).cwiseAbs().maxCoeff());
  return 0;
}
