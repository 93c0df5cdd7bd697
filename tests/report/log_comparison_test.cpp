// Measured vs simulated per channel: residual statistics, a simulation that ends early, logs
// on different time grids, thinning of long logs.

#include "motoflex/report/log_comparison.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "report_test_support.hpp"

namespace motoflex::report {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
using motoflex::testing::two_joint_log;

TEST(CompareLogs, ResidualRmsPerJointInDegrees) {
  const LogComparison c = compare_logs(two_joint_log(200), two_joint_log(200, -0.01), 2000);
  ASSERT_EQ(c.channels.size(), 2u);
  EXPECT_EQ(c.channels[0].name, "hip");
  EXPECT_NEAR(c.channels[0].rms_deg, 0.0, 1e-12);
  EXPECT_NEAR(c.channels[1].rms_deg, 0.01 * kDeg, 1e-9);
  EXPECT_NEAR(c.channels[1].max_abs_deg, 0.01 * kDeg, 1e-9);
  EXPECT_FALSE(c.thinned);
  EXPECT_TRUE(c.channels[1].frames.empty());
  EXPECT_EQ(c.channels[1].measured_deg.size(), 200u);
  EXPECT_NEAR(c.channels[1].measured_deg[100] - c.channels[1].simulated_deg[100], 0.01 * kDeg,
              1e-9);
}

TEST(CompareLogs, ASimulationThatEndsEarlyLeavesGapsAndScoresTheOverlapOnly) {
  JointLog simulated = two_joint_log(200, -0.02);
  JointLog measured = two_joint_log(500);
  const LogComparison c = compare_logs(measured, simulated, 2000);
  EXPECT_NEAR(c.simulated_end_s, 1.99, 1e-12);
  EXPECT_EQ(c.frames_simulated, 200u);
  EXPECT_TRUE(std::isnan(c.channels[1].simulated_deg[300]));
  EXPECT_FALSE(std::isnan(c.channels[1].simulated_deg[199]));
  EXPECT_NEAR(c.channels[1].rms_deg, 0.02 * kDeg, 1e-9);  // not diluted by the missing frames
  const nlohmann::json json = log_comparison_json(c);
  EXPECT_TRUE(json["channels"][1]["simulated"][300].is_null());
  EXPECT_FALSE(json["channels"][1].contains("t"));  // the log's own time grid
}

TEST(CompareLogs, ASimulationOnACoarserGridIsInterpolated) {
  // Measured at 100 Hz, simulated at 50 Hz; both a straight line, so interpolation is exact.
  JointLog measured, simulated;
  measured.joint_names = simulated.joint_names = {"hip"};
  for (int f = 0; f <= 100; ++f) {
    measured.time_s.push_back(0.01 * f);
    measured.measured_rad.push_back(0.5 * 0.01 * f);
  }
  for (int f = 0; f <= 50; ++f) {
    simulated.time_s.push_back(0.02 * f);
    simulated.measured_rad.push_back(0.5 * 0.02 * f - 0.001);
  }
  const LogComparison c = compare_logs(measured, simulated, 2000);
  ASSERT_EQ(c.channels.size(), 1u);
  EXPECT_NEAR(c.channels[0].rms_deg, 0.001 * kDeg, 1e-9);
  EXPECT_NEAR(c.channels[0].simulated_deg[51], (0.5 * 0.51 - 0.001) * kDeg, 1e-9);
}

TEST(CompareLogs, LongLogsAreThinnedKeepingThePeaksOfEveryTrace) {
  JointLog measured = two_joint_log(20000);
  JointLog simulated = two_joint_log(20000);
  measured.measured_rad[2 * 7777 + 1] = 3.0;     // a measured spike on the knee
  simulated.measured_rad[2 * 15000 + 1] = -3.0;  // a simulated one elsewhere
  const LogComparison c = compare_logs(measured, simulated, 300);
  EXPECT_TRUE(c.thinned);
  const ChannelComparison& knee = c.channels[1];
  EXPECT_LE(knee.frames.size(), 300u);
  EXPECT_EQ(knee.measured_deg.size(), knee.frames.size());
  EXPECT_EQ(*std::max_element(knee.measured_deg.begin(), knee.measured_deg.end()), 3.0 * kDeg);
  EXPECT_EQ(*std::min_element(knee.simulated_deg.begin(), knee.simulated_deg.end()), -3.0 * kDeg);
  EXPECT_NEAR(knee.max_abs_deg, (3.0 - std::sin(77.77)) * kDeg, 1e-6);  // from every frame
  const nlohmann::json json = log_comparison_json(c);
  EXPECT_EQ(json["channels"][1]["t"].size(), knee.frames.size());
  EXPECT_EQ(json["thinned"], true);
}

TEST(CompareLogs, ImuAnglesAreChannelsWhenBothLogsHaveThem) {
  JointLog measured = two_joint_log(50), simulated = two_joint_log(50);
  measured.imu_roll_rad.assign(50, 0.1);
  measured.imu_pitch_rad.assign(50, 0.0);
  simulated.imu_roll_rad.assign(50, 0.0);
  simulated.imu_pitch_rad.assign(50, 0.0);
  const LogComparison c = compare_logs(measured, simulated, 2000);
  ASSERT_EQ(c.channels.size(), 4u);
  EXPECT_EQ(c.channels[2].name, "imu.roll");
  EXPECT_NEAR(c.channels[2].rms_deg, 0.1 * kDeg, 1e-9);
  simulated.imu_roll_rad.clear();
  simulated.imu_pitch_rad.clear();
  EXPECT_EQ(compare_logs(measured, simulated, 2000).channels.size(), 2u);
}

TEST(CompareLogs, JointsWithACommandGetTheirFrequencyResponse) {
  // 20 s at 100 Hz of a two-sine command (1 and 3.1 Hz): the measured joint follows it exactly,
  // the simulated one 20 ms late (7.2° and 22.3° of phase there), at unit gain.
  const auto command = [](double t) {
    return std::sin(2.0 * std::numbers::pi * t) + 0.5 * std::sin(2.0 * std::numbers::pi * 3.1 * t);
  };
  JointLog measured, simulated;
  measured.joint_names = simulated.joint_names = {"hip"};
  for (int f = 0; f < 2000; ++f) {
    const double t = 0.01 * f;
    measured.time_s.push_back(t);
    simulated.time_s.push_back(t);
    measured.commanded_rad.push_back(command(t));
    simulated.commanded_rad.push_back(command(t));
    measured.measured_rad.push_back(command(t));
    simulated.measured_rad.push_back(command(t - 0.02));
    measured.imu_roll_rad.push_back(0.01);
    simulated.imu_roll_rad.push_back(0.02);
  }
  const LogComparison c = compare_logs(measured, simulated, 2000);
  ASSERT_EQ(c.channels.size(), 2u);
  ASSERT_TRUE(c.channels[0].frequency);
  EXPECT_FALSE(c.channels[1].frequency);  // imu.roll has no command
  const FrequencyComparison& f = *c.channels[0].frequency;
  ASSERT_GT(f.coherent_points, 0u);
  EXPECT_LT(f.gain_rms_db, 1.0);  // leakage between two lines mixes their delays a little
  EXPECT_GT(f.phase_rms_deg, 5.0);
  EXPECT_LT(f.phase_rms_deg, 25.0);
  const nlohmann::json json = log_comparison_json(c);
  EXPECT_TRUE(json["channels"][0].contains("frequency"));
  EXPECT_FALSE(json["channels"][1].contains("frequency"));
  // Without commands in the measured log there is nothing to compare against.
  measured.commanded_rad.clear();
  EXPECT_FALSE(compare_logs(measured, simulated, 2000).channels[0].frequency);
}

}  // namespace
}  // namespace motoflex::report
