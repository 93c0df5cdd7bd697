// The metrics of seed 001's Section 5 on synthetic signals with known answers.

#include "motoflex/studies/seed001/walk_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace motoflex {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> times(double end_s, double dt_s) {
  std::vector<double> t;
  for (int i = 0; i * dt_s <= end_s + 1e-12; ++i) t.push_back(i * dt_s);
  return t;
}

TEST(WalkMetrics, SpeedIsTravelOverTimeWithInterpolation) {
  const std::vector<double> t = times(10.0, 0.01);
  std::vector<double> x;
  // 0.2 m/s plus a step-frequency wobble that cancels over whole periods.
  for (const double s : t) x.push_back(0.2 * s + 0.01 * std::sin(2.0 * kPi * s));
  EXPECT_NEAR(mean_speed_mm_s(t, x, 2.0, 8.0), 200.0, 1e-9);
  EXPECT_NEAR(mean_speed_mm_s(t, x, 2.005, 8.005), 200.0, 0.05);  // between samples
  EXPECT_TRUE(std::isnan(mean_speed_mm_s(t, x, 8.0, 2.0)));
  EXPECT_TRUE(std::isnan(mean_speed_mm_s(t, x, 2.0, 11.0)));
}

// A pitch oscillation with one period per step whose amplitude alternates 1, 2, 1, 2, ...
std::vector<double> alternating(const std::vector<double>& t, double period_s, double phase_s,
                                double a, double b) {
  std::vector<double> y;
  for (const double s : t) {
    const int k = static_cast<int>(std::floor((s - phase_s) / period_s));
    y.push_back((k % 2 == 0 ? a : b) * std::sin(2.0 * kPi * (s - phase_s) / period_s) + 0.05);
  }
  return y;
}

TEST(WalkMetrics, AlternatingAmplitudesOneTwoGiveRatioTwo) {
  const std::vector<double> t = times(12.0, 0.001);
  const std::vector<double> pitch = alternating(t, 0.5, 0.0, 1.0, 2.0);
  const std::vector<double> ranges = window_ranges(t, pitch, 1.0, 11.0, 0.5);
  ASSERT_EQ(ranges.size(), 20u);
  EXPECT_NEAR(ranges[0], 2.0, 1e-4);  // peak to peak of amplitude 1
  EXPECT_NEAR(ranges[1], 4.0, 1e-4);
  EXPECT_NEAR(alternation_ratio(ranges), 2.0, 1e-4);
  // The larger ones first: the same ratio.
  EXPECT_NEAR(
      alternation_ratio(window_ranges(t, alternating(t, 0.5, 0.0, 2.0, 1.0), 1.0, 11.0, 0.5)), 2.0,
      1e-4);
}

TEST(WalkMetrics, ASymmetricOscillationGivesOneAtAnyPhase) {
  const std::vector<double> t = times(12.0, 0.001);
  for (const double phase : {0.0, 0.1, 0.25, 0.37}) {
    const std::vector<double> pitch = alternating(t, 0.5, phase, 1.5, 1.5);
    EXPECT_NEAR(alternation_ratio(window_ranges(t, pitch, 1.0, 11.0, 0.5)), 1.0, 1e-4) << phase;
  }
}

TEST(WalkMetrics, WindowsEndAtTheLastWholeStepAndShortSignalsGiveNaN) {
  const std::vector<double> t = times(3.0, 0.01);
  const std::vector<double> pitch = alternating(t, 0.5, 0.0, 1.0, 2.0);
  EXPECT_EQ(window_ranges(t, pitch, 1.0, 2.99, 0.5).size(), 3u);  // 1–1.5, 1.5–2, 2–2.5
  EXPECT_EQ(window_ranges(t, pitch, 1.0, 3.0, 0.5).size(), 4u);
  EXPECT_TRUE(window_ranges(t, pitch, 1.0, 3.0, 0.0).empty());
  EXPECT_TRUE(std::isnan(alternation_ratio({1.0})));
  EXPECT_TRUE(std::isnan(alternation_ratio({})));
  EXPECT_TRUE(std::isnan(alternation_ratio({0.0, 0.0})));
}

TEST(WalkMetrics, FallDirectionFollowsTheLargerTilt) {
  EXPECT_EQ(fall_direction(0.1, 0.9), FallDirection::kForward);  // nose down
  EXPECT_EQ(fall_direction(0.1, -0.9), FallDirection::kBackward);
  EXPECT_EQ(fall_direction(0.9, 0.2), FallDirection::kRight);  // right side down
  EXPECT_EQ(fall_direction(-0.9, -0.2), FallDirection::kLeft);
  EXPECT_STREQ(to_string(FallDirection::kLeft), "left");
}

}  // namespace
}  // namespace motoflex
