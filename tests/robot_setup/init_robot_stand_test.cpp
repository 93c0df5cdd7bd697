// A floating-base robot fresh from init-robot stands on init-robot's default law (pd_torque)
// with the stance gains derived from its mass and leg geometry (stance_gains.hpp): the
// third-party-style quadruped quad12 (10.1 kg, mesh feet, placeholder hip efforts), dropped
// from its initial clearance onto its feet, stays up for 5 s without sagging or tilting.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"
#include "motoflex/model/body_kinematics.hpp"
#include "motoflex/robot_setup/robot_init.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/actuator/stance_gains.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kStand_s = 5.0;

TEST(InitRobotStandTest, FreshQuadrupedStandsFiveSecondsOnDefaultPdTorque) {
  RobotInitOptions options;
  options.urdf_path = std::string(MOTOFLEX_SOURCE_DIR) +
                      "/tests/data/robots/third_party/quad12_description/urdf/quad12.urdf";
  options.out_dir = testing::fresh_dir("init_quad12_stand").string();
  const RobotInitResult init = init_robot(options);  // no --servo: the default law
  ASSERT_EQ(init.check.end, RolloutEnd::kCompleted) << init.check.end_detail;
  const RobotModel model = load_robot(options.out_dir, {});
  ASSERT_FALSE(model.fixed_base);
  ASSERT_EQ(actuator_servo_name(model, "", 0), "pd_torque");

  // The rule's numbers on the left front leg: d from the joint to the foot's centre.
  const auto knee = stance_gains(model, *model.actuator_index("lf_kfe"));
  ASSERT_TRUE(knee.has_value());
  EXPECT_NEAR(knee->lever_m, 0.15, 1e-9);  // the shank, 0.15 m to the foot's centre
  const double share_n = 10.12 * 9.81 / 4.0;
  EXPECT_NEAR(knee->hold_torque_nm, share_n * 0.15, 1e-9);
  // Rounded to three significant digits.
  EXPECT_NEAR(knee->kp_nm_per_rad, share_n * 0.15 / kStanceSag_rad, 0.5);
  EXPECT_EQ(knee->kp_nm_per_rad, 745.0);
  // The hip's placeholder effort (1000 N·m) is replaced by 4·τ_h; the knee keeps its 23.7 N·m.
  const ParameterSet defaults(model.parameters);
  const auto hip = stance_gains(model, *model.actuator_index("lf_haa"));
  ASSERT_TRUE(hip.has_value());
  EXPECT_NEAR(defaults.get("servo.lf_haa.torque_max_nm"), 4.0 * hip->hold_torque_nm, 0.05);
  EXPECT_EQ(defaults.get("servo.lf_kfe.torque_max_nm"), 23.7);

  // Not held: placed initial_clearance_m above the ground and dropped onto its feet.
  const std::vector<double> pose = model.stand_pose_vector();
  std::vector<double> angles = pose;
  angles.insert(angles.end(), pose.begin(), pose.end());
  RolloutOptions free;
  free.servo.clear();
  const RolloutResult r =
      run_rollout(model, defaults, CommandTrajectory({0.0, kStand_s}, angles, pose.size()), free);
  ASSERT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;

  // The trunk's height standing on rigid legs: its CoM above the feet's lowest points.
  const std::vector<Eigen::Isometry3d> poses = body_poses(model, pose);
  const double standing_z_m =
      poses[model.root_body].translation().z() - lowest_foot_point_z(model, poses);
  double lowest_z_m = INFINITY, tilt_rad = 0.0;
  for (std::size_t f = 0; f < r.frames_completed; ++f) {
    lowest_z_m = std::min(lowest_z_m, r.torso_position_m[3 * f + 2]);
    tilt_rad = std::max({tilt_rad, std::abs(r.imu_roll_rad[f]), std::abs(r.imu_pitch_rad[f])});
  }
  const double final_z_m = r.torso_position_m[3 * (r.frames_completed - 1) + 2];
  std::printf(
      "[ stand   ] quad12 pd_torque: standing z %.4f m, lowest %.4f m (sag %.2f mm), final sag "
      "%.2f mm, max tilt %.2e rad\n",
      standing_z_m, lowest_z_m, 1e3 * (standing_z_m - lowest_z_m), 1e3 * (standing_z_m - final_z_m),
      tilt_rad);
  // Measured: sag 0.84 mm (settled by 5 s, the soft contacts' sink included), tilt 4.6e-4 rad.
  // Before the stance rule (kp = effort / 0.1 rad, kd 0.5 explicit, hips' τ_max 5 N·m) the
  // hind shank touched the ground 0.12 s after the drop: a fall.
  EXPECT_LT(standing_z_m - lowest_z_m, 0.0025);
  EXPECT_LT(tilt_rad, 0.002);
}

}  // namespace
}  // namespace motoflex
