// The fitness's optional IMU term (fitness.imu_weight): it adds w·Σ_t (roll² + pitch²) errors
// to each robot's joint sum before the division by T^m, needs IMU columns in every log, and
// leaves the identity of joint-only fits unchanged.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// The pendulum log of the truth with its IMU columns replaced (the bench's base is fixed, so
// the simulated IMU reads 0 and a measured constant is the whole IMU error).
void set_log_imu(const fs::path& csv, double roll_rad, double pitch_rad) {
  JointLog log = read_joint_log(csv.string(), JointLogRequirements{});
  log.imu_roll_rad.assign(log.frames(), roll_rad);
  log.imu_pitch_rad.assign(log.frames(), pitch_rad);
  write_joint_log(csv.string(), log);
}

FitConfig pendulum_config(const fs::path& dir, const std::string& fitness) {
  return load_fit_config(write_pendulum_fit(dir, dir / "data", "{kind: cma_es}",
                                            "{evaluations: 10}", "fitness: " + fitness + "\n"));
}

ParameterSet truth_of(const FitConfig& config) {
  ParameterSet truth = config.space->base();
  for (const auto& [name, value] : pendulum_truth()) truth.set(name, value);
  return truth;
}

TEST(FitnessImu, AddsTheWeightedTorsoErrorToEachRobotsSum) {
  const fs::path dir = fresh_dir("fitness_imu");
  record_pendulum_log(dir / "data", "sin_sin");
  const double roll_rad = 0.01, pitch_rad = -0.02, weight = 3.0;
  set_log_imu(dir / "data" / "sin_sin.csv", roll_rad, pitch_rad);

  const FitConfig joints_only = pendulum_config(dir, "{m: 2}");
  const FitConfig with_imu = pendulum_config(dir, "{m: 2, imu_weight: 3}");
  ASSERT_FALSE(joints_only.train->scores_imu());
  ASSERT_TRUE(with_imu.train->scores_imu());
  EXPECT_EQ(with_imu.train->channels(), joints_only.train->channels() + 2);
  EXPECT_EQ(with_imu.train->channel_name(with_imu.train->channels() - 1), "imu.pitch");

  std::vector<RolloutResult> rollouts;
  const FitnessBreakdown a = joints_only.train->evaluate(truth_of(joints_only));
  const FitnessBreakdown b = with_imu.train->evaluate(
      truth_of(with_imu), std::numeric_limits<double>::infinity(), &rollouts);
  ASSERT_EQ(a.cases.size(), 1u);
  // The fixed base does not tilt.
  for (std::size_t f = 0; f < rollouts[0].frames_completed; ++f) {
    ASSERT_EQ(rollouts[0].imu_roll_rad[f], 0.0);
    ASSERT_EQ(rollouts[0].imu_pitch_rad[f], 0.0);
  }
  // Every scored frame adds w·(roll² + pitch²); F = error / T², so F grows by w·(roll² +
  // pitch²)/T.
  const double t = static_cast<double>(b.cases[0].frames);
  EXPECT_EQ(b.cases[0].frames, a.cases[0].frames);
  const double expected = weight * (roll_rad * roll_rad + pitch_rad * pitch_rad) / t;
  EXPECT_NEAR(b.fitness - a.fitness, expected, 1e-12 * expected);
}

TEST(FitnessImu, ALogWithoutImuColumnsIsNamed) {
  const fs::path dir = fresh_dir("fitness_imu_missing");
  record_pendulum_log(dir / "data", "sin_sin");
  const fs::path csv = dir / "data" / "sin_sin.csv";
  JointLog log = read_joint_log(csv.string(), JointLogRequirements{});
  log.imu_roll_rad.clear();
  log.imu_pitch_rad.clear();
  write_joint_log(csv.string(), log);

  EXPECT_NO_THROW(pendulum_config(dir, "{m: 2}"));
  try {
    pendulum_config(dir, "{m: 2, imu_weight: 1}");
    FAIL() << "a fit that scores the IMU accepted a log without IMU columns";
  } catch (const InputError& error) {
    EXPECT_EQ(fs::path(error.file()), csv);
    EXPECT_EQ(error.field(), "imu.roll");
  }
  try {
    pendulum_config(dir, "{m: 2, imu_weight: -1}");
    FAIL() << "a negative IMU weight was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "fitness.imu_weight");
  }
}

TEST(FitnessImu, AJointOnlyFitKeepsItsIdentity) {
  const fs::path dir = fresh_dir("fitness_imu_hash");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string plain = pendulum_config(dir, "{m: 2}").hash;
  EXPECT_EQ(pendulum_config(dir, "{m: 2, imu_weight: 0}").hash, plain);
  EXPECT_NE(pendulum_config(dir, "{m: 2, imu_weight: 0.5}").hash, plain);
}

}  // namespace
}  // namespace motoflex::testing
