// Sign conventions between the model (URDF: positive = child turns positively about the
// axis) and ODE (hinge angle of body1 relative to body2; universal angles measured on the
// parent side): a body placed by forward kinematics must read back the angles it was placed
// at, and a positive actuator torque or velocity command must turn the joint positively.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/rollout.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

std::string robot_dir(const std::string& name) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name;
}

struct Case {
  std::string robot;
  StructureOptions structure;
  std::string label() const {
    return robot + " flex " + std::to_string(structure.flex_sub_bodies) +
           (structure.universal_joints ? " universal" : " hinges");
  }
};
// Later tests pick cases by index: new ones go at the end.
const Case kCases[] = {{"nao", {1, true}},
                       {"nao", {1, false}},
                       {"nao", {2, true}},
                       {"nao", {2, false}},
                       {"titan8", {1, true}},
                       {"servo_pendulum", {1, true}},
                       {"nao_motoflex_2011", {2, true}}};

// A random pose inside the middle 80 % of every actuator's range (±1 rad if unlimited).
std::vector<double> random_pose(const RobotModel& model, std::mt19937_64& rng) {
  std::vector<double> pose;
  for (const ActuatorSpec& a : model.actuators) {
    const double lo = std::isfinite(a.lower_rad) ? a.lower_rad : -1.0;
    const double hi = std::isfinite(a.upper_rad) ? a.upper_rad : 1.0;
    const double margin = 0.1 * (hi - lo);
    pose.push_back(std::uniform_real_distribution<double>(lo + margin, hi - margin)(rng));
  }
  return pose;
}

Eigen::Vector3d vec(const dReal* v) {
  return {v[0], v[1], v[2]};
}

TEST(JointConventionsTest, PlacedBodiesReadBackTheirPose) {
  std::mt19937_64 rng(20240611);
  for (const Case& c : kCases) {
    const RobotModel model = load_robot_model(robot_dir(c.robot), c.structure);
    const ParameterSet params(model.parameters);
    RolloutOptions options;
    options.servo = model.default_servo;
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<double> pose =
          trial == 0 ? model.stand_pose_vector() : random_pose(model, rng);
      Rollout rollout(model, params, options, pose);
      for (std::size_t i = 0; i < model.actuators.size(); ++i) {
        EXPECT_NEAR(rollout.joint_angle_rad(i), pose[i], 1e-9)
            << c.label() << " " << model.actuators[i].name << " trial " << trial;
        EXPECT_EQ(rollout.encoder_rad(i), rollout.joint_angle_rad(i));
        EXPECT_EQ(rollout.joint_rate_rad_s(i), 0.0);
      }
      for (std::size_t j = 0; j < model.joints.size(); ++j) {
        const JointSpec& spec = model.joints[j];
        dJointID joint = RolloutOdeAccess::joint(rollout, j);
        dVector3 a1, a2;
        if (spec.kind == JointKind::kHinge) {
          dJointGetHingeAnchor(joint, a1);
          dJointGetHingeAnchor2(joint, a2);
        } else {
          dJointGetUniversalAnchor(joint, a1);
          dJointGetUniversalAnchor2(joint, a2);
        }
        // Both bodies agree where the joint is: the forward kinematics is consistent.
        EXPECT_LT((vec(a1) - vec(a2)).norm(), 1e-9) << c.label() << " " << spec.name;
        if (spec.kind == JointKind::kFlex) {
          // Flexible links are placed straight.
          EXPECT_NEAR(dJointGetUniversalAngle1(joint), 0.0, 1e-9) << c.label() << spec.name;
          EXPECT_NEAR(dJointGetUniversalAngle2(joint), 0.0, 1e-9) << c.label() << spec.name;
        }
      }
    }
  }
}

TEST(JointConventionsTest, NaoStandPoseHasTheLegGeometry) {
  // Hip −0.3, knee 0.6, ankle −0.3: both leg segments lean by 0.3 rad, the foot stays flat and
  // the torso upright. Torso origin above the ground = clearance + foot height + (thigh +
  // tibia)·cos 0.3 + HipOffsetZ (nao/README.md).
  const double expected_z = 0.001 + 0.04519 + (0.100 + 0.1029) * std::cos(0.3) + 0.085;
  for (const Case& c : {kCases[0], kCases[1], kCases[2], kCases[3]}) {
    const RobotModel model = load_robot_model(robot_dir(c.robot), c.structure);
    const ParameterSet params(model.parameters);
    RolloutOptions options;
    options.servo = model.default_servo;
    const Rollout rollout(model, params, options, model.stand_pose_vector());
    // The torso link is the root link, so its origin is the build frame's: −com_W0 in the
    // torso body's frame.
    const dBodyID torso = RolloutOdeAccess::body(rollout, model.torso_body);
    dVector3 origin;
    const Eigen::Vector3d com_W0 = model.bodies[model.torso_body].com_W0_m;
    dBodyGetRelPointPos(torso, -com_W0.x(), -com_W0.y(), -com_W0.z(), origin);
    EXPECT_NEAR(origin[2], expected_z, 1e-9) << c.label();
    double roll = 1.0, pitch = 1.0;
    rollout.imu_roll_pitch(roll, pitch);
    EXPECT_NEAR(roll, 0.0, 1e-12) << c.label();
    EXPECT_NEAR(pitch, 0.0, 1e-12) << c.label();
  }
}

// A weightless robot lifted 0.5 m clear of the ground (no contacts), for joint-level checks.
void lift_and_float(const RobotModel& model, Rollout& rollout) {
  dWorldSetGravity(RolloutOdeAccess::world(rollout), 0.0, 0.0, 0.0);
  if (model.fixed_base) return;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const dReal* p = dBodyGetPosition(RolloutOdeAccess::body(rollout, b));
    dBodySetPosition(RolloutOdeAccess::body(rollout, b), p[0], p[1], p[2] + 0.5);
  }
}

// From rest, without gravity and contacts, a command above the current angle must make that joint
// turn positively (and one below, negatively) for every servo law and joint kind.
void expect_positive_response(const Case& c, const std::string& servo, double step_rad, int steps) {
  const RobotModel model = load_robot_model(robot_dir(c.robot), c.structure);
  const ParameterSet params(model.parameters);
  RolloutOptions options;
  options.servo = servo;
  options.stop_on_fall = false;
  const std::vector<double> start = model.stand_pose_vector();
  for (std::size_t i = 0; i < model.actuators.size(); ++i) {
    for (const double sign : {1.0, -1.0}) {
      Rollout rollout(model, params, options, start);
      lift_and_float(model, rollout);
      std::vector<double> command = start;
      command[i] += sign * step_rad;
      for (int k = 0; k < steps; ++k) rollout.step(command.data(), command.data());
      const std::string where =
          c.label() + " " + servo + " " + model.actuators[i].name + (sign > 0 ? " +" : " -");
      EXPECT_GT(sign * rollout.joint_rate_rad_s(i), 0.0) << where;
      EXPECT_GT(sign * (rollout.joint_angle_rad(i) - start[i]), 0.0) << where;
      if (servo == "motoflex" || servo == "bench") {
        EXPECT_GT(sign * rollout.actuator_torque_nm(i), 0.0) << where;
      }
    }
  }
}

TEST(JointConventionsTest, JointStopsSitAtTheUrdfLimits) {
  // The Nao's roll and pitch ranges are asymmetric (LAnkleRoll −0.398 … +0.769), so a stop
  // mirrored by a wrong sign would show. Each joint is driven 0.3 rad past each limit by the
  // robot's position-type servo (ideal for the Nao; TITAN-VIII's velocity servo, made fast:
  // the ideal servo's 100 N·m would spin its 0.15 kg feet past the divergence check).
  for (const Case& c : {kCases[0], kCases[1], kCases[4]}) {
    const RobotModel model = load_robot_model(robot_dir(c.robot), c.structure);
    ParameterSet params(model.parameters);
    RolloutOptions options;
    options.servo = c.robot == "titan8" ? "velocity" : "ideal";
    options.stop_on_fall = false;
    if (options.servo == "velocity") {
      for (const ActuatorSpec& a : model.actuators) {
        params.set("joint." + a.name + ".gain_per_s", 20.0);
      }
    }
    const std::vector<double> start = model.stand_pose_vector();
    // TITAN-VIII: the front legs (a left and a right one) stand for all four.
    const std::size_t count = c.robot == "titan8" ? 8 : model.actuators.size();
    for (std::size_t i = 0; i < count; ++i) {
      const ActuatorSpec& a = model.actuators[i];
      for (const double limit : {a.lower_rad, a.upper_rad}) {
        ASSERT_TRUE(std::isfinite(limit));
        Rollout rollout(model, params, options, start);
        lift_and_float(model, rollout);
        std::vector<double> command = start;
        command[i] = limit + (limit > start[i] ? 0.3 : -0.3);
        for (int k = 0; k < 300; ++k) rollout.step(command.data(), command.data());
        EXPECT_EQ(rollout.end(), RolloutEnd::kCompleted) << c.label() << " " << a.name;
        EXPECT_NEAR(rollout.joint_angle_rad(i), limit, 1e-3) << c.label() << " " << a.name;
      }
    }
  }
}

TEST(JointConventionsTest, PositiveTorqueTurnsTheJointPositively) {
  // The motoflex pipeline applies its torque with dJointAdd*Torque(s): the sign mapping of
  // hinge and universal axes is exercised directly.
  for (const Case& c : {kCases[0], kCases[1], kCases[2]}) {
    expect_positive_response(c, "motoflex", 0.2, 10);
  }
  expect_positive_response(kCases[5], "bench", 0.5, 10);
}

TEST(JointConventionsTest, PositiveVelocityCommandTurnsTheJointPositively) {
  // Ideal and velocity servos drive ODE's joint motor rows (dParamVel) instead. The ideal servo
  // asks for the rate that reaches the target in one step (torque-limited) and then for rest, so
  // look right after that step.
  expect_positive_response(kCases[0], "ideal", 0.05, 1);
  expect_positive_response(kCases[1], "ideal", 0.05, 1);
  expect_positive_response(kCases[4], "velocity", 0.2, 10);
}

}  // namespace
}  // namespace motoflex
