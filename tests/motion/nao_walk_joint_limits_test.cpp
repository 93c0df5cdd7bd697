// The walk planner's joint limits (NaoWalkParams::joint_limits): by default every plan keeps to
// the URDF's ranges (the real Nao's); with `stops` only a robot that simulates them as stops is
// held to them. The 2011 MoToFlex box robot has none, like the original program, whose own
// 50 mm/s command file asks for AnkleRoll 0.46 rad (the Nao's range ends at 0.398): with `stops`
// a walk with the reference ZMP under the ankle plans for it and goes as far, and the commands
// still put the soles where the plan says.

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/nao_leg_kinematics.hpp"
#include "motoflex/motion/nao_stance.hpp"
#include "motoflex/motion/nao_walk.hpp"

namespace motoflex {
namespace {

RobotModel robot(const std::string& name) {
  return load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name, {});
}

// Seed 001's 50 mm/s walk with the reference ZMP under the ankle, ankles 0.11 m apart (the
// Dortmund engine's gait; scenarios/experiments/seed001/walk_50_2_dortmund.yaml has the rest).
NaoWalkParams zmp_under_the_ankle(NaoJointLimits limits) {
  NaoWalkParams p;
  p.speed_mm_s = 50.0;
  p.step_duration_s = 2.0;
  p.duration_s = 6.0;
  p.zmp_offset_y_m = 0.0;
  p.foot_spacing_m = 0.11;
  p.joint_limits = limits;
  return p;
}

std::string planning_error(const RobotModel& model, const NaoWalkParams& p) {
  try {
    plan_nao_walk(model, p);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(NaoWalkJointLimits, TheBoxRobotGoesBeyondTheUrdfRangesOnlyWithStops) {
  const RobotModel model = robot("nao_motoflex_2011");
  ASSERT_FALSE(model.joint_stops);
  const std::string refused = planning_error(model, zmp_under_the_ankle(NaoJointLimits::kUrdf));
  EXPECT_NE(refused.find("AnkleRoll"), std::string::npos) << refused;
  EXPECT_NE(refused.find("outside its URDF limits"), std::string::npos) << refused;
  EXPECT_NE(refused.find("joint_limits: stops"), std::string::npos) << refused;

  const NaoWalkPlan plan = plan_nao_walk(model, zmp_under_the_ankle(NaoJointLimits::kStops));
  const std::size_t left_roll = *model.actuator_index("LAnkleRoll");
  const std::size_t right_roll = *model.actuator_index("RAnkleRoll");
  // The Nao's AnkleRoll ranges, mirrored: right [-0.768992, 0.397761], left [-0.397761, ...].
  const double right_upper = model.actuators[right_roll].upper_rad;
  const double left_lower = model.actuators[left_roll].lower_rad;
  double beyond_rad = 0.0;
  for (std::size_t f = 0; f < plan.commands.frames(); ++f) {
    beyond_rad = std::max(beyond_rad, plan.commands.angle_rad(f, right_roll) - right_upper);
    beyond_rad = std::max(beyond_rad, left_lower - plan.commands.angle_rad(f, left_roll));
  }
  EXPECT_GT(beyond_rad, 0.005);  // the plan uses the range the robot has and the Nao does not

  // Beyond the URDF's range the commands still realise the planned feet (the box robot's leg).
  const NaoStance stance(model, NaoJointLimits::kStops);
  int checked = 0;
  for (std::size_t f = 0; f < plan.samples.size(); f += 5) {
    const NaoWalkSample& s = plan.samples[f];
    if (s.left_foot.pitch_rad != 0.0 || s.right_foot.pitch_rad != 0.0) continue;
    NaoLegAngles left{}, right{};
    for (int j = 0; j < 5; ++j) {
      left[j] = plan.commands.angle_rad(
          f, *model.actuator_index(std::string("L") + nao_leg::kJointNames[j]));
      right[j] = plan.commands.angle_rad(
          f, *model.actuator_index(std::string("R") + nao_leg::kJointNames[j]));
    }
    const NaoFootPose l = nao_leg_forward(LegSide::kLeft, left, stance.geometry());
    const NaoFootPose r = nao_leg_forward(LegSide::kRight, right, stance.geometry());
    EXPECT_NEAR((s.torso_m + l.position_m - s.left_sole_m).norm(), 0.0, 1e-9);
    EXPECT_NEAR((s.torso_m + r.position_m - s.right_sole_m).norm(), 0.0, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(NaoWalkJointLimits, ARobotWithStopsKeepsItsUrdfRanges) {
  const RobotModel model = robot("nao");
  ASSERT_TRUE(model.joint_stops);
  const std::string refused = planning_error(model, zmp_under_the_ankle(NaoJointLimits::kStops));
  EXPECT_NE(refused.find("outside its URDF limits"), std::string::npos) << refused;
  EXPECT_EQ(refused.find("joint_limits: stops"), std::string::npos) << refused;  // no such hint
}

TEST(NaoWalkJointLimits, APlanWithinTheRangesIsTheSameEitherWay) {
  const RobotModel model = robot("nao_motoflex_2011");
  NaoWalkParams p;
  p.speed_mm_s = 50.0;
  p.step_duration_s = 2.0;
  const CommandTrajectory urdf = plan_nao_walk(model, p).commands;
  p.joint_limits = NaoJointLimits::kStops;
  EXPECT_EQ(plan_nao_walk(model, p).commands.angles_rad(), urdf.angles_rad());
}

}  // namespace
}  // namespace motoflex
