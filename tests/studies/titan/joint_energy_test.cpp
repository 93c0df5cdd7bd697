// Eq. 8 bookkeeping and the settling time of §III-A on hand-made series.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "motoflex/studies/titan/joint_energy.hpp"
#include "motoflex/studies/titan/settling.hpp"

namespace motoflex {
namespace {

TEST(JointEnergyMeter, AveragedAbsolutePowerOfEquationEight) {
  // Two channels over 2 s: +3 W then −1 W on channel 0, constant −2 W on channel 1.
  JointEnergyMeter meter(2);
  for (int k = 0; k < 2000; ++k) {
    meter.add(0, k < 1000 ? 3.0 : -1.0, 0.001);
    meter.add(1, -2.0, 0.001);
    meter.advance(0.001);
  }
  EXPECT_NEAR(meter.duration_s(), 2.0, 1e-9);
  EXPECT_NEAR(meter.work_j(0), 2.0, 1e-9);
  EXPECT_NEAR(meter.absolute_work_j(0), 4.0, 1e-9);
  EXPECT_NEAR(meter.total_work_j(), -2.0, 1e-9);
  EXPECT_NEAR(meter.averaged_absolute_power_w(0), 2.0, 1e-9);
  EXPECT_NEAR(meter.averaged_absolute_power_w(), 4.0, 1e-9);  // (4 + 4) J / 2 s
}

TEST(Settling, TimeAfterWhichTheSeriesStaysInTheBand) {
  std::vector<double> t, v;
  for (int k = 0; k <= 100; ++k) {
    t.push_back(0.01 * k);
    v.push_back(k < 40 ? 1.0 : (k == 55 ? 0.2 : 0.01));  // a late excursion at 0.55 s
  }
  EXPECT_NEAR(settling_time_s(t, v, 0.0, 0.1, 0.0), 0.56, 1e-12);
  EXPECT_NEAR(settling_time_s(t, v, 0.0, 0.3, 0.0), 0.40, 1e-12);
  EXPECT_NEAR(settling_time_s(t, v, 0.0, 0.3, 0.7), 0.70, 1e-12);  // already settled at from_s
  v.back() = 5.0;
  EXPECT_EQ(settling_time_s(t, v, 0.0, 0.3, 0.0), std::numeric_limits<double>::infinity());
  EXPECT_NEAR(tail_mean(t, {t.begin(), t.end()}, 0.105), 0.95, 1e-12);  // mean of 0.9 … 1.0
  EXPECT_THROW(settling_time_s(t, {1.0}, 0.0, 0.1, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
