// The sensors of a rollout: joint encoders (delay) and the torso IMU.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/rollout.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

// The servos act on the true angle, so a delayed sensor reports exactly the undelayed log,
// shifted by the delay.
TEST(RolloutSensorsTest, DelayedLogIsTheUndelayedLogShifted) {
  const RobotModel bench = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum", StructureOptions{});
  // A swing the bench servo follows with a visible lag, logged at 100 Hz.
  const CommandTrajectory commands =
      keyframe_trajectory({{0.0, {0.0}}, {0.5, {0.8}}, {1.2, {-0.6}}, {2.0, {0.2}}}, 100.0);
  RolloutOptions options;
  options.servo = "bench";
  options.record_torques = true;

  ParameterSet exact(bench.parameters);
  ParameterSet delayed(bench.parameters);
  delayed.set("sensor.delay_s", 0.02);  // 2 frames at 100 Hz
  const RolloutResult a = run_rollout(bench, exact, commands, options);
  const RolloutResult b = run_rollout(bench, delayed, commands, options);
  ASSERT_EQ(a.end, RolloutEnd::kCompleted) << a.end_detail;
  ASSERT_EQ(b.end, RolloutEnd::kCompleted) << b.end_detail;
  ASSERT_EQ(a.frames_completed, commands.frames());
  ASSERT_EQ(b.frames_completed, commands.frames());

  const std::size_t shift = 2;
  double largest_motion = 0.0;
  for (std::size_t f = 0; f < commands.frames(); ++f) {
    // Before the delay has elapsed the sensor reports the resting start angle.
    const double expected = f >= shift ? a.measured_rad[f - shift] : a.measured_rad[0];
    EXPECT_NEAR(b.measured_rad[f], expected, 1e-9) << "frame " << f;
    if (f >= shift) {
      largest_motion =
          std::max(largest_motion, std::abs(a.measured_rad[f] - a.measured_rad[f - shift]));
    }
  }
  // The arm really moved between frames, so the shift is visible.
  EXPECT_GT(largest_motion, 0.01);
  // The delay does not touch the physics: the servo torques are the same.
  EXPECT_EQ(a.joint_torque_nm, b.joint_torque_nm);
}

TEST(RolloutSensorsTest, ImuReportsTorsoRollAndPitch) {
  // The IMU gives the Z-Y-X (yaw, pitch, roll) angles of the torso link; the Nao's torso link
  // has world axes in the build configuration, so turning its body by Rz·Ry·Rx must read back
  // (roll, pitch) whatever the yaw, and the tilt is the angle between the torso's z and world z.
  const RobotModel nao =
      load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao", {});
  const ParameterSet params(nao.parameters);
  RolloutOptions options;
  options.servo = "ideal";
  Rollout rollout(nao, params, options, nao.stand_pose_vector());
  const dBodyID torso = RolloutOdeAccess::body(rollout, nao.torso_body);
  for (const auto& [yaw, pitch, roll] :
       {std::tuple{0.0, 0.0, 0.3}, std::tuple{0.0, -0.2, 0.0}, std::tuple{1.0, 0.25, -0.4},
        std::tuple{-2.5, -0.6, 0.7}}) {
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    dMatrix3 ode_R;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) ode_R[4 * r + c] = R(r, c);
      ode_R[4 * r + 3] = 0.0;
    }
    dBodySetRotation(torso, ode_R);
    double measured_roll = 0.0, measured_pitch = 0.0;
    rollout.imu_roll_pitch(measured_roll, measured_pitch);
    EXPECT_NEAR(measured_roll, roll, 1e-12) << yaw << " " << pitch << " " << roll;
    EXPECT_NEAR(measured_pitch, pitch, 1e-12) << yaw << " " << pitch << " " << roll;
    EXPECT_NEAR(rollout.torso_tilt_rad(), std::acos(std::cos(pitch) * std::cos(roll)), 1e-12);
  }
}

}  // namespace
}  // namespace motoflex
