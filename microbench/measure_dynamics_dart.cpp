// The dynamic-simulation spike's second engine (issue 33): the Miura-ori of measure_dynamics in
// DART 6.12: a skeleton of revolute joints along foldkit's spanning tree (generalised
// coordinates), each crease outside the tree closed by two ball-joint constraints at its ends,
// one SERVO motor. Prints the same closure drift, kinematic difference and real-time factor.
// Usage: measure_dynamics_dart [n=10] [time_step=1e-3] [speed=0.5]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <dart/constraint/BallJointConstraint.hpp>
#include <dart/constraint/BoxedLcpConstraintSolver.hpp>
#include <dart/constraint/PgsBoxedLcpSolver.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

#include "foldkit/dynamics/mass_properties.hpp"
#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"

using namespace foldkit;
using namespace dart::dynamics;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  const double dt = argc > 2 ? std::atof(argv[2]) : 1e-3, speed = argc > 3 ? std::atof(argv[3]) : 0.5;
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::miura(n, n));
  folding::ProjectedFoldingOptions fo;
  fo.target_fraction = 0.5;
  fo.replay = false;
  fo.collisions = false;
  const auto kin = folding::fold_projected(p, fo);
  const geometry::FoldState& K = kin.states.back();
  geometry::FoldState start = K;
  for (const auto& s : kin.states)
    if (s.angles.cwiseAbs().maxCoeff() >= 0.2) { start = s; break; }
  const geometry::KinematicTree tree = geometry::make_tree(p, 0);
  const int actors = static_cast<int>(p.actors().size()), joints = static_cast<int>(p.joints().size());
  auto skel = Skeleton::create("sheet");
  std::vector<BodyNode*> body(actors, nullptr);
  std::vector<RevoluteJoint*> hinge(joints, nullptr);
  for (int a : tree.order) {
    const auto m = dynamics::mass_properties(p, a, 1.0);
    BodyNode* bn = nullptr;
    if (tree.parent[a] < 0) {
      bn = skel->createJointAndBodyNodePair<WeldJoint>(nullptr).second;
    } else {
      const int j = tree.parent_joint[a];
      const geometry::JointAxis ax = geometry::joint_axis(p, j);
      RevoluteJoint::Properties props;
      props.mAxis = tree.side[a] * ax.direction;  // child = parent · R(side·direction, angle)
      props.mT_ParentBodyToJoint = Eigen::Translation3d(ax.point) * Eigen::Isometry3d::Identity();
      props.mT_ChildBodyToJoint = props.mT_ParentBodyToJoint;
      props.mName = "crease" + std::to_string(j);
      auto pair = skel->createJointAndBodyNodePair<RevoluteJoint>(body[tree.parent[a]], props,
                                                                  BodyNode::AspectProperties("actor" + std::to_string(a)));
      bn = pair.second;
      hinge[j] = pair.first;
      hinge[j]->setPosition(0, start.angles[j]);
    }
    bn->setInertia(Inertia(m.mass, m.centroid, m.inertia));
    body[a] = bn;
  }
  const bool loops = !std::getenv("DART_NO_LOOPS");
  auto world = dart::simulation::World::create();
  world->setGravity(Eigen::Vector3d::Zero());
  world->setTimeStep(dt);
  // DART's default boxed LCP solver (Dantzig) met the redundant rows of the closed loops with
  // NaN (the assertion in RevoluteJoint::updateRelativeTransform); PGS, like ODE's QuickStep, runs.
  if (std::getenv("DART_PGS"))
    world->setConstraintSolver(std::make_unique<dart::constraint::BoxedLcpConstraintSolver>(
        std::make_shared<dart::constraint::PgsBoxedLcpSolver>()));
  world->addSkeleton(skel);
  // The hinges outside the tree, as two ball joints at the crease's ends (placed in the start pose).
  for (int j = 0; j < joints; ++j) {
    if (tree.in_tree[j] || !loops) continue;
    const auto& jt = p.joints()[j];
    const Eigen::Isometry3d T = body[jt.actors[0]]->getWorldTransform();
    for (int e = 0; e < 2; ++e) {
      const Eigen::Vector3d v(p.vertices()[jt.v[e]].x(), p.vertices()[jt.v[e]].y(), 0.0);
      world->getConstraintSolver()->addConstraint(
          std::make_shared<dart::constraint::BallJointConstraint>(body[jt.actors[0]], body[jt.actors[1]], T * v));
    }
  }
  int drive = -1;
  for (int j = 0; j < joints; ++j)
    if (tree.in_tree[j] && (p.joints()[j].actors[0] == 0 || p.joints()[j].actors[1] == 0) &&
        (drive < 0 || std::abs(K.angles[j]) > std::abs(K.angles[drive])))
      drive = j;
  hinge[drive]->setActuatorType(Joint::SERVO);
  hinge[drive]->setForceUpperLimit(0, 1e6);
  hinge[drive]->setForceLowerLimit(0, -1e6);
  auto angles = [&] {
    geometry::FoldState s = geometry::FoldState::flat(p);
    for (int j = 0; j < joints; ++j) {
      const auto& jt = p.joints()[j];
      const int right = geometry::side_of(p, j, jt.actors[0]) > 0 ? jt.actors[0] : jt.actors[1];
      const int left = right == jt.actors[0] ? jt.actors[1] : jt.actors[0];
      const Eigen::Quaterniond q(body[left]->getWorldTransform().linear().transpose() * body[right]->getWorldTransform().linear());
      s.angles[j] = 2.0 * std::atan2(q.vec().dot(geometry::joint_axis(p, j).direction), q.w());
    }
    return s;
  };
  const geometry::ClosureSystem closure(p, 0);
  double drift = 0.0, t = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int step = 0; t < 60.0; ++step) {
    const double error = K.angles[drive] - hinge[drive]->getPosition(0);
    if (std::abs(error) <= 1e-4) break;
    hinge[drive]->setCommand(0, std::clamp(error / 0.02, -speed, speed));
    world->step();
    t += dt;
    if (step % 10 == 0) drift = std::max(drift, closure.max_error(angles()));
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const geometry::FoldState end = angles();
  drift = std::max(drift, closure.max_error(end));
  std::printf("DART miura %dx%d joints %d dt %g: %g s simulated in %g s (RTF %.3g), closure drift %.3g rad, "
              "max |angle - kinematic| %.3g rad\n",
              n, n, joints, dt, t, wall, t / wall, drift, (end.angles - K.angles).cwiseAbs().maxCoeff());
  return 0;
}
