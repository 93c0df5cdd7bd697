// The commanded angles of a log are read by the 1 kHz physics through linear interpolation
// between the log's frames, whatever their spacing (recorders with jittery clocks).

#include "motoflex/motion/command_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace motoflex
