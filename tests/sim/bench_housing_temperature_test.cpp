// `servo: bench` scales its winding resistance to the log's housing temperature:
// R = R_25·(1 + α·(T − 25 °C)), α = motor.R_temperature_per_k, T = motor.housing_temperature_c
// (each BAM log's sidecar). Held against gravity at full duty with no dry friction, the arm
// settles where the stall torque K_t·U/R(T) equals m·g·l·sin q, so a warmer log holds lower,
// exactly as the resistance says; α = 0 ignores the temperature.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bench_stall_support.hpp"

namespace motoflex::testing {
namespace {

const RobotModel& bench() {
  static const RobotModel model = load_servo_pendulum();
  return model;
}

ParameterSet warm_bench(double r_per_k, double housing_c) {
  ParameterSet v = stall_bench_values(bench());
  v.set("motor.R_temperature_per_k", r_per_k);
  v.set("motor.housing_temperature_c", housing_c);
  return v;
}

TEST(BenchHousingTemperature, HoldAngleFollowsTheResistanceAtTheLoggedTemperature) {
  const double r_per_k = 0.02;
  for (const double housing_c : {25.0, 45.0, 65.0}) {
    const ParameterSet v = warm_bench(r_per_k, housing_c);
    const double r_ohm = v.get("bench.R_ohm") * (1.0 + r_per_k * (housing_c - 25.0));
    const double stall_nm = v.get("bench.Kt_nm_per_a") * v.get("bench.supply_v") / r_ohm;
    const double expected = std::asin(stall_nm / bench_gravity_torque_nm(v));
    EXPECT_NEAR(held_angle(bench(), v, kBenchStallGoal_rad, 10.0), expected, 2e-3)
        << housing_c << " C";
  }
  // α = 0 (the default): the temperature is ignored, bit for bit.
  const RolloutResult cold = hold_bench(bench(), warm_bench(0.0, 25.0), kBenchStallGoal_rad, 1.0);
  const RolloutResult hot = hold_bench(bench(), warm_bench(0.0, 80.0), kBenchStallGoal_rad, 1.0);
  EXPECT_EQ(cold.measured_rad, hot.measured_rad);
}

TEST(BenchHousingTemperature, ANonPositiveResistanceIsAModelError) {
  // 1 + 0.05·(−40 − 25) < 0.
  const RolloutResult r = hold_bench(bench(), warm_bench(0.05, -40.0), kBenchStallGoal_rad, 0.1);
  EXPECT_EQ(r.end, RolloutEnd::kModelError);
  EXPECT_NE(r.end_detail.find("motor.R_temperature_per_k"), std::string::npos) << r.end_detail;
}

}  // namespace
}  // namespace motoflex::testing
