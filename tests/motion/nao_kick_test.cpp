#include "motoflex/motion/nao_kick.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/nao_leg_kinematics.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

const RobotModel& rigid_nao() {
  static const RobotModel model =
      load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao", {});
  return model;
}

NaoLegAngles leg_at(const CommandTrajectory& commands, std::size_t frame, const char* prefix) {
  NaoLegAngles q;
  for (int j = 0; j < 5; ++j) {
    q[j] = commands.angle_rad(
        frame, *rigid_nao().actuator_index(std::string(prefix) + nao_leg::kJointNames[j]));
  }
  return q;
}

// The kick lifts the kicking foot, swings it behind and then in front of the support foot, and
// the rigid Nao on ideal servos stays up the whole time, for either leg.
TEST(NaoKick, RigidNaoKicksWithEitherLegAndStaysUp) {
  const RobotModel& model = rigid_nao();
  const ParameterSet parameters(model.parameters);
  RolloutOptions options;
  options.servo = "ideal";
  options.settle_s = 0.5;
  for (const bool left : {false, true}) {
    NaoKickParams p;
    p.kick_left = left;
    const CommandTrajectory commands = nao_kick_trajectory(model, p);
    EXPECT_NEAR(commands.duration_s(), 5.6, 1e-9);
    // Foot path relative to the support foot (torso-frame difference of the two soles).
    double lowest_x = 1.0, highest_x = -1.0, highest_z = 0.0;
    for (std::size_t f = 0; f < commands.frames(); ++f) {
      const NaoFootPose kick = nao_leg_forward(left ? LegSide::kLeft : LegSide::kRight,
                                               leg_at(commands, f, left ? "L" : "R"));
      const NaoFootPose support = nao_leg_forward(left ? LegSide::kRight : LegSide::kLeft,
                                                  leg_at(commands, f, left ? "R" : "L"));
      const Eigen::Vector3d d = kick.position_m - support.position_m;
      lowest_x = std::min(lowest_x, d.x());
      highest_x = std::max(highest_x, d.x());
      highest_z = std::max(highest_z, d.z());
      EXPECT_NEAR(kick.pitch_rad, 0.0, 1e-9);
      EXPECT_NEAR(support.roll_rad, 0.0, 1e-9);
    }
    EXPECT_NEAR(lowest_x, -p.backswing_m, 1e-6);
    EXPECT_NEAR(highest_x, p.reach_m, 1e-6);
    EXPECT_NEAR(highest_z, p.lift_height_m, 1e-6);

    const RolloutResult result = run_rollout(model, parameters, commands, options);
    EXPECT_EQ(result.end, RolloutEnd::kCompleted) << result.end_detail;
    EXPECT_EQ(result.frames_completed, commands.frames());
    for (std::size_t f = 0; f < result.frames_completed; ++f) {
      EXPECT_LT(std::abs(result.imu_pitch_rad[f]), 0.05);
      EXPECT_LT(std::abs(result.imu_roll_rad[f]), 0.05);
    }
  }
}

std::string error_of(const NaoKickParams& p) {
  try {
    nao_kick_trajectory(rigid_nao(), p);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(NaoKick, InvalidParametersNameTheParameter) {
  NaoKickParams p;
  p.kick_s = 0;
  EXPECT_EQ(error_of(p).rfind("kick_s = 0: must be positive", 0), 0u);
  p = {};
  p.support_com_x_m = 0.2;
  EXPECT_EQ(error_of(p).rfind("support_com_x_m = 0.2", 0), 0u);
  p = {};
  p.reach_m = 0.3;  // beyond the leg
  const std::string reach = error_of(p);
  EXPECT_EQ(reach.rfind("kick phase 'kick'", 0), 0u) << reach;
  EXPECT_NE(reach.find("reach_m"), std::string::npos) << reach;
}

}  // namespace
}  // namespace motoflex
