// The commanded angles of a log are read by the 1 kHz physics through linear interpolation
// between the log's frames, whatever their spacing (recorders with jittery clocks).

#include "motoflex/motion/command_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace motoflex {
namespace {

TEST(CommandTrajectoryTest, LinearInterpolationBetweenIrregularFrames) {
  // Frames 3.5, 3.5, 7.1 and 0.7 ms apart; two joints.
  const std::vector<double> t = {0.0035, 0.0070, 0.0105, 0.0176, 0.0183};
  const std::vector<double> q = {0.0, 1.0, 0.1, 2.0, 0.3, 1.0, -0.4, 0.0, 0.0, 5.0};
  const CommandTrajectory trajectory(t, q, 2);
  std::size_t hint = 0;
  double out[2];
  // Sweeping forward at 1 kHz and jumping back (the hint only speeds the search up).
  for (const double time : {0.004, 0.008, 0.0105, 0.012, 0.018, 0.0179, 0.005}) {
    trajectory.sample(time, out, hint);
    std::size_t f = 0;
    while (f + 2 < t.size() && t[f + 1] < time) ++f;
    const double w = (time - t[f]) / (t[f + 1] - t[f]);
    for (int j = 0; j < 2; ++j) {
      const double expected = q[f * 2 + j] + w * (q[(f + 1) * 2 + j] - q[f * 2 + j]);
      EXPECT_NEAR(out[j], expected, 1e-15) << time << " joint " << j;
    }
  }
  // Before the first frame and after the last the ends hold.
  trajectory.sample(0.0, out, hint);
  EXPECT_EQ(out[0], 0.0);
  EXPECT_EQ(out[1], 1.0);
  trajectory.sample(1.0, out, hint);
  EXPECT_EQ(out[0], 0.0);
  EXPECT_EQ(out[1], 5.0);
}

// The logged supply is smoothed by a centred moving average over 0.1 s: a constant stays exact,
// a step becomes a ramp exactly 0.1 s wide centred on it, and the value at a frame is the mean of
// the frames within ±0.05 s of it.
TEST(CommandTrajectoryTest, LoggedSupplyIsACentredMovingAverage) {
  std::vector<double> t, q, constant, step;
  for (int k = 0; k <= 400; ++k) {  // 5 ms frames, 2 s
    t.push_back(0.005 * k);
    q.push_back(0.0);
    constant.push_back(7.4);
    step.push_back(k < 200 ? 6.0 : 8.0);  // steps between 0.995 s and 1.0 s
  }
  CommandTrajectory flat(t, q, 1);
  flat.set_supply_v(constant);
  for (const double v : flat.supply_v()) EXPECT_DOUBLE_EQ(v, 7.4);
  CommandTrajectory trajectory(t, q, 1);
  EXPECT_FALSE(trajectory.has_supply());
  std::size_t hint = 0;
  EXPECT_TRUE(std::isnan(trajectory.supply_v_at(0.5, hint)));
  trajectory.set_supply_v(step);
  ASSERT_TRUE(trajectory.has_supply());
  const std::vector<double>& smooth = trajectory.supply_v();
  for (std::size_t i = 0; i < t.size(); ++i) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (std::abs(t[k] - t[i]) <= 0.05 + 1e-9) {
        sum += step[k];
        ++count;
      }
    }
    EXPECT_NEAR(smooth[i], sum / count, 1e-12) << t[i];
  }
  EXPECT_EQ(smooth[189], 6.0);  // 0.945 s: the window ends at 0.995 s
  EXPECT_EQ(smooth[211], 8.0);  // 1.055 s: it starts at 1.005 s
  EXPECT_NEAR(trajectory.supply_v_at(0.9975, hint), 7.0, 0.05);  // half way up the ramp
  // Between frames linear; clamped beyond the ends.
  EXPECT_NEAR(trajectory.supply_v_at(0.9725, hint), 0.5 * (smooth[194] + smooth[195]), 1e-12);
  EXPECT_EQ(trajectory.supply_v_at(-1.0, hint), 6.0);
  EXPECT_EQ(trajectory.supply_v_at(5.0, hint), 8.0);
  EXPECT_THROW(trajectory.set_supply_v(std::vector<double>(3, 7.4)), std::invalid_argument);
  std::vector<double> negative = constant;
  negative[7] = -1.0;
  EXPECT_THROW(trajectory.set_smoothed_supply_v(negative), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
