// init-robot on two URDFs of our own written the way real ones are: a 6-joint arm with a
// mimic gripper and placeholder limits, and a quadruped with mesh feet behind package:// paths.
// Each gives a robot folder that loads, whose assumptions are listed, and that simulates.

#include "motoflex/robot_setup/robot_init.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/robot_setup/robot_check.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"

namespace motoflex {
namespace {

std::string data(const std::string& path) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/tests/data/robots/" + path;
}

bool assumed(const RobotInitResult& result, const std::string& subject, const std::string& text) {
  return std::any_of(
      result.assumptions.begin(), result.assumptions.end(), [&](const Assumption& a) {
        return a.subject == subject && (a.choice + " " + a.reason).find(text) != std::string::npos;
      });
}

double default_of(const RobotModel& model, const std::string& name) {
  return model.parameters.spec(*model.parameters.find(name)).default_value;
}

TEST(InitRobotTest, ArmGetsEveryMovableJointAndItsAssumptionsListed) {
  RobotInitOptions options;
  options.urdf_path = data("arm6/arm6.urdf");
  options.out_dir = testing::fresh_dir("init_arm6").string();
  // The seed-001 pipeline reads joint friction; it drives revolute joints only, so the finger
  // gets a law for sliders of its own.
  options.servo = "motoflex";
  const RobotInitResult result = init_robot(options);
  EXPECT_EQ(result.check.end, RolloutEnd::kCompleted) << result.check.end_detail;

  const RobotModel model = load_robot(options.out_dir, {});
  const std::vector<std::string> expected = {"shoulder_pan",     "shoulder_lift", "elbow",
                                             "wrist_1",          "wrist_2",       "wrist_3",
                                             "finger_left_joint"};
  EXPECT_EQ(model.actuator_names(), expected);  // the URDF's order, the mimic finger left out
  EXPECT_TRUE(model.fixed_base);
  EXPECT_FALSE(model.ground);
  EXPECT_TRUE(model.actuators.back().prismatic);
  EXPECT_TRUE(assumed(result, "base", "fixed"));
  EXPECT_TRUE(assumed(result, "frame links", "world"));
  // The welded base is named after its first physical link, not the massless `world` root (a
  // body "world" made MuJoCo reject the MJCF export: MJCF and SDF reserve the name).
  EXPECT_EQ(model.bodies[model.root_body].name, "base_link");
  EXPECT_TRUE(assumed(result, "frame links", "tool0"));
  EXPECT_TRUE(assumed(result, "finger_right_joint", "mimic"));
  EXPECT_TRUE(assumed(result, "shoulder_pan effort", "placeholder"));  // 1000 N·m
  EXPECT_TRUE(assumed(result, "wrist_2 velocity", "placeholder"));     // 200 rad/s
  EXPECT_TRUE(assumed(result, "wrist_1 limits", "placeholder"));       // ±10 rad
  EXPECT_TRUE(assumed(result, "finger_left_joint servo", "prismatic"));
  EXPECT_EQ(actuator_servo_name(model, "", model.actuators.size() - 1), "velocity");
  // Placeholder limits replaced by ±π; real ones kept.
  const ActuatorSpec& wrist_1 = model.actuators[*model.actuator_index("wrist_1")];
  EXPECT_EQ(wrist_1.upper_rad, std::numbers::pi);
  EXPECT_EQ(model.actuators[*model.actuator_index("elbow")].upper_rad, 2.5);
  // The mimic finger is coupled, not actuated.
  const auto coupled = std::count_if(model.joints.begin(), model.joints.end(),
                                     [](const JointSpec& j) { return j.mimic.has_value(); });
  EXPECT_EQ(coupled, 1);
  // Friction and viscous terms from <dynamics>; none given: 0.
  EXPECT_EQ(default_of(model, "joint.shoulder_pan.friction_nm"), 0.05);
  EXPECT_EQ(default_of(model, "joint.shoulder_pan.viscous_nm_s_per_rad"), 0.1);
  EXPECT_EQ(default_of(model, "joint.elbow.viscous_nm_s_per_rad"), 0.05);
  EXPECT_EQ(default_of(model, "joint.shoulder_lift.friction_nm"), 0.0);
  EXPECT_EQ(default_of(model, "joint.finger_left_joint.friction_n"), 0.0);

  const RobotCheckReport check = check_robot_folder(options.out_dir);
  EXPECT_TRUE(check.problems.empty()) << check.problems.front().what();
}

TEST(InitRobotTest, QuadrupedStandsOnItsMeshFeet) {
  RobotInitOptions options;
  options.urdf_path = data("quadruped/urdf/quad.urdf");
  options.out_dir = testing::fresh_dir("init_quad").string();
  // init-robot's default law, pd_torque, with the stance gains of a floating base
  // (stance_gains.hpp; before them the hind calf capsule touched the ground 0.12 s after the
  // drop).
  const RobotInitResult result = init_robot(options);
  EXPECT_EQ(result.check.end, RolloutEnd::kCompleted) << result.check.end_detail;
  EXPECT_TRUE(assumed(result, "base", "floating"));

  const RobotModel model = load_robot(options.out_dir, {});
  EXPECT_FALSE(model.fixed_base);
  EXPECT_EQ(model.actuators.size(), 12u);
  EXPECT_EQ(model.bodies.size(), 13u);  // trunk (+ imu frame), 4 × hip, thigh, calf (+ foot)
  std::vector<std::string> feet;
  int hulls = 0, capsules = 0;
  for (const BodySpec& body : model.bodies) {
    for (const CollisionShape& shape : body.collisions) {
      if (shape.is_foot) feet.push_back(shape.link);
      hulls += shape.hull != nullptr;
      capsules += shape.kind == ShapeKind::kCapsule;
      if (shape.hull) {
        EXPECT_LE(shape.hull->vertex_count(), kMaxHullVertices);
      }
    }
  }
  std::sort(feet.begin(), feet.end());
  EXPECT_EQ(feet, (std::vector<std::string>{"FL_foot", "FR_foot", "HL_foot", "HR_foot"}));
  EXPECT_EQ(hulls, 4);
  EXPECT_EQ(capsules, 4);
  // 0 is outside the knees' limits [-2.5, -0.5]: they stand mid-range.
  EXPECT_EQ(model.stand_pose_rad.at("FL_calf_joint"), -1.5);

  // Not held: dropped onto its feet it stays up for half a second.
  const ParameterSet parameters(model.parameters);
  const std::vector<double> pose = model.stand_pose_vector();
  std::vector<double> angles = pose;
  angles.insert(angles.end(), pose.begin(), pose.end());
  RolloutOptions free;
  free.servo.clear();
  const RolloutResult stand =
      run_rollout(model, parameters, CommandTrajectory({0.0, 0.5}, angles, 12), free);
  EXPECT_EQ(stand.end, RolloutEnd::kCompleted) << stand.end_detail;
}

}  // namespace
}  // namespace motoflex
