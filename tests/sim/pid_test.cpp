#include "motoflex/sim/actuator/pid.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

constexpr double kDt = 1e-3;

TEST(PidTest, ProportionalOnlyIsGainTimesError) {
  Pid pid({.kp_v_per_rad = 12.5}, kDt);
  for (double error : {0.1, -0.3, 0.0, 2.0}) EXPECT_DOUBLE_EQ(pid.update(error), 12.5 * error);
}

TEST(PidTest, IntegralOnlyRampsExactlyUnderConstantError) {
  // u(t) = ki·∫e dt = ki·e·t at t = k·dt, the integral including the current step.
  const double ki = 40.0;
  const double error = 0.02;
  Pid pid({.ki_v_per_rad_s = ki}, kDt);
  for (int k = 1; k <= 1000; ++k) {
    const double t_s = k * kDt;
    ASSERT_NEAR(pid.update(error), ki * error * t_s, 1e-12) << "step " << k;
  }
  EXPECT_NEAR(pid.integral_rad_s(), error * 1.0, 1e-14);
}

TEST(PidTest, DerivativeOnlyOfRampIsGainTimesRateFromSecondStep) {
  const double kd = 0.3;
  const double rate_rad_s = 1.5;  // e = r·t
  Pid pid({.kd_v_s_per_rad = kd}, kDt);
  EXPECT_EQ(pid.update(rate_rad_s * kDt), 0.0);  // first update: no previous error, no kick
  for (int k = 2; k <= 100; ++k) {
    ASSERT_NEAR(pid.update(rate_rad_s * k * kDt), kd * rate_rad_s, 1e-10) << "step " << k;
  }
}

TEST(PidTest, ResetClearsIntegralAndDerivativeHistory) {
  Pid pid({.kp_v_per_rad = 1.0, .ki_v_per_rad_s = 10.0, .kd_v_s_per_rad = 0.5}, kDt);
  for (int k = 0; k < 50; ++k) pid.update(0.1 * k);
  pid.reset();
  EXPECT_EQ(pid.integral_rad_s(), 0.0);
  // As on a fresh controller: P plus one step of I, and no derivative of the jump from 4.9.
  Pid fresh({.kp_v_per_rad = 1.0, .ki_v_per_rad_s = 10.0, .kd_v_s_per_rad = 0.5}, kDt);
  EXPECT_EQ(pid.update(0.2), fresh.update(0.2));
  EXPECT_DOUBLE_EQ(fresh.update(0.2), 1.0 * 0.2 + 10.0 * 0.4 * kDt);
}

TEST(PidTest, PreloadedIntegralHoldsOutputAtZeroError) {
  Pid pid({.kp_v_per_rad = 5.0, .ki_v_per_rad_s = 20.0, .kd_v_s_per_rad = 0.1}, kDt);
  pid.preload_integral(3.7);
  EXPECT_DOUBLE_EQ(pid.integral_rad_s(), 3.7 / 20.0);
  for (int k = 0; k < 10; ++k) EXPECT_DOUBLE_EQ(pid.update(0.0), 3.7);
}

TEST(PidTest, PreloadWithoutIntegralGainIsAModelError) {
  Pid pid({.kp_v_per_rad = 5.0}, kDt);
  EXPECT_NO_THROW(pid.preload_integral(0.0));
  EXPECT_THROW(pid.preload_integral(1.0), ModelError);
}

TEST(PidTest, RejectsNonPositiveStep) {
  EXPECT_THROW(Pid({}, 0.0), std::invalid_argument);
  EXPECT_THROW(Pid({}, -1e-3), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
