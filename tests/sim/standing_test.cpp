// Whole-robot integration: the legged robots stand still on their stand pose with each servo
// law, without falling and without sagging.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kStandDuration_s = 5.0;

std::string robot_dir(const std::string& name) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name;
}

struct Stand {
  RolloutResult result;
  double seconds = 0.0;  // wall-clock time of the rollout
};

// Holds the robot's stand pose for 5 s at 100 Hz (what the scenario `motion: stand` does).
Stand stand(const RobotModel& model, const RolloutOptions& options) {
  const std::vector<double> pose = model.stand_pose_vector();
  const CommandTrajectory commands =
      keyframe_trajectory({{0.0, pose}, {kStandDuration_s, pose}}, 100.0);
  const ParameterSet params(model.parameters);
  const auto start = std::chrono::steady_clock::now();
  Stand out;
  out.result = run_rollout(model, params, commands, options);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

double torso_z(const RolloutResult& r, std::size_t frame) {
  return r.torso_position_m[3 * frame + 2];
}

double max_height_change_m(const RolloutResult& r) {
  double worst = 0.0;
  for (std::size_t f = 0; f < r.frames_completed; ++f) {
    worst = std::max(worst, std::abs(torso_z(r, f) - torso_z(r, 0)));
  }
  return worst;
}

double max_tilt_rad(const RolloutResult& r) {
  double worst = 0.0;
  for (std::size_t f = 0; f < r.frames_completed; ++f) {
    worst = std::max({worst, std::abs(r.imu_roll_rad[f]), std::abs(r.imu_pitch_rad[f])});
  }
  return worst;
}

void expect_completed(const RolloutResult& r, const std::string& label) {
  EXPECT_EQ(r.end, RolloutEnd::kCompleted) << label << ": " << r.end_detail;
  EXPECT_EQ(r.frames_completed, r.frames_requested) << label;
  EXPECT_EQ(r.frames_requested, 501u) << label;
}

TEST(StandingTest, NaoStandsOnIdealServos) {
  const RobotModel nao = load_robot_model(robot_dir("nao"), {1, true});
  RolloutOptions options;
  options.servo = "ideal";
  const Stand s = stand(nao, options);
  expect_completed(s.result, "nao ideal");
  const double dz = max_height_change_m(s.result);
  std::printf(
      "[ stand   ] nao ideal: torso z0 %.4f m, max |Δz| %.2f mm, max tilt %.4f rad, "
      "%.2f s wall\n",
      torso_z(s.result, 0), 1e3 * dz, max_tilt_rad(s.result), s.seconds);
  // Measured: 1.02 mm (settling onto the soft contacts), 0.0001 rad.
  EXPECT_LT(dz, 0.003);
  EXPECT_LT(max_tilt_rad(s.result), 0.001);
}

TEST(StandingTest, NaoStandsWithTheFullMotoflexPipeline) {
  const RobotModel nao = load_robot_model(robot_dir("nao"), {2, true});
  RolloutOptions options;
  options.servo = "motoflex";
  options.gear_substeps = 100;
  const Stand s = stand(nao, options);
  expect_completed(s.result, "nao motoflex flex 2");
  const double dz = max_height_change_m(s.result);
  std::printf(
      "[ stand   ] nao motoflex flex 2: torso z0 %.4f m, max |Δz| %.2f mm, max tilt "
      "%.4f rad, %.2f s wall\n",
      torso_z(s.result, 0), 1e3 * dz, max_tilt_rad(s.result), s.seconds);
  // Measured: 1.05 mm, 0.0003 rad (the gear springs and flexible links barely give).
  EXPECT_LT(dz, 0.003);
  EXPECT_LT(max_tilt_rad(s.result), 0.002);
}

TEST(StandingTest, Titan8StandsOnItsVelocityServos) {
  const RobotModel titan = load_robot_model(robot_dir("titan8"), {});
  RolloutOptions options;
  options.servo = "velocity";
  const Stand s = stand(titan, options);
  const RolloutResult& r = s.result;
  expect_completed(r, "titan8 velocity");
  // Posture A puts the body origin (its CoM) 0.243 m above the soles (README); it starts 10 mm
  // higher (initial clearance) and drops onto its feet.
  const std::size_t last = r.frames_completed - 1;
  const double sag_m = 0.243 - torso_z(r, last);
  double spread_m = 0.0;  // over the last 3 s
  for (std::size_t f = 200; f <= last; ++f) {
    spread_m = std::max(spread_m, std::abs(torso_z(r, f) - torso_z(r, last)));
  }
  std::printf(
      "[ stand   ] titan8 velocity: start z %.4f m, final z %.5f m (sag %.2f mm), "
      "last-3-s spread %.3f mm, max tilt %.4f rad, %.2f s wall\n",
      torso_z(r, 0), torso_z(r, last), 1e3 * sag_m, 1e3 * spread_m, max_tilt_rad(r), s.seconds);
  EXPECT_NEAR(torso_z(r, 0), 0.243 + 0.01, 1e-9);
  // Measured: sag 0.01 mm, spread 0.001 mm, tilt below 1e-4 rad.
  EXPECT_LT(std::abs(sag_m), 1e-4);
  EXPECT_LT(spread_m, 1e-5);
  EXPECT_LT(max_tilt_rad(r), 0.001);
}

}  // namespace
}  // namespace motoflex
