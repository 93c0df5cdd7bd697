// The winding's Joule heating (winding_heating.hpp) against its closed forms:
//  * at constant current and resistance the rise relaxes exponentially to I²·R·R_th with time
//    constant R_th·C, step by step exactly;
//  * a bench arm driven at full duty against gravity settles where the hot motor's stall torque
//    K_t·U/(R₀·(1 + α·ΔT)) meets m·g·l·sin θ, with ΔT the root of ΔT·(1 + α·ΔT) = U²·R_th/R₀
//    (the stall current U/R heating the winding it flows through); a cold motor holds higher.

#include "motoflex/sim/actuator/winding_heating.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "bench_stall_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

TEST(WindingHeatingTest, RiseRelaxesExponentiallyToTheJouleHeatTimesTheThermalResistance) {
  const double r_th_k_per_w = 20.0;
  const double c_j_per_k = 0.25;
  const double dt_s = 0.001;
  WindingTemperature winding({r_th_k_per_w, c_j_per_k}, dt_s);
  const double current_a = 1.5;
  const double resistance_ohm = 3.0;
  const double settled_k = current_a * current_a * resistance_ohm * r_th_k_per_w;  // 135 K
  const double tau_s = r_th_k_per_w * c_j_per_k;
  for (int step = 1; step <= 20000; ++step) {
    winding.advance(current_a, resistance_ohm);
    if (step % 5000 == 0) {
      const double expected_k = settled_k * (1.0 - std::exp(-step * dt_s / tau_s));
      EXPECT_NEAR(winding.rise_k(), expected_k, 1e-9 * settled_k) << "after " << step << " steps";
    }
  }
  EXPECT_NEAR(winding.resistance_factor(), 1.0 + kCopperResistancePerK * winding.rise_k(), 1e-15);
  // Without current it cools back with the same time constant.
  const double hot_k = winding.rise_k();
  for (int step = 0; step < 5000; ++step) winding.advance(0.0, resistance_ohm);
  EXPECT_NEAR(winding.rise_k(), hot_k * std::exp(-5.0 / tau_s), 1e-9 * hot_k);
}

TEST(WindingHeatingTest, NoThermalResistanceIsNoHeatingAndBadValuesAreRejected) {
  WindingTemperature cold({0.0, 0.5}, 0.001);
  for (int step = 0; step < 100; ++step) cold.advance(10.0, 3.0);
  EXPECT_FALSE(cold.heats());
  EXPECT_EQ(cold.rise_k(), 0.0);
  EXPECT_EQ(cold.resistance_factor(), 1.0);
  EXPECT_THROW(WindingTemperature({-1.0, 0.5}, 0.001), ModelError);
  EXPECT_THROW(WindingTemperature({10.0, 0.0}, 0.001), ModelError);
  EXPECT_THROW(WindingTemperature({10.0, 0.5}, 0.0), ModelError);
}

TEST(WindingHeatingTest, ABenchArmAtFullDutySettlesWhereTheHotMotorsStallTorqueMeetsGravity) {
  const RobotModel bench = testing::load_servo_pendulum();
  ParameterSet v = testing::stall_bench_values(bench);
  const double goal_rad = testing::kBenchStallGoal_rad;
  const double mgl_nm = testing::bench_gravity_torque_nm(v);
  const double supply_v = v.get("bench.supply_v");
  const double kt = v.get("bench.Kt_nm_per_a");
  const double r0_ohm = v.get("bench.R_ohm");

  const double cold_rad = testing::held_angle(bench, v, goal_rad, 60.0);
  const double cold_expected_rad = std::asin(kt * supply_v / r0_ohm / mgl_nm);

  const double r_th_k_per_w = 20.0;
  v.set("motor.winding_k_per_w", r_th_k_per_w);
  v.set("motor.winding_heat_j_per_k", 0.25);  // τ = 5 s: 60 s is 12 time constants
  const double hot_rad = testing::held_angle(bench, v, goal_rad, 60.0);
  const double a = kCopperResistancePerK;
  const double heat_k = supply_v * supply_v * r_th_k_per_w / r0_ohm;
  const double rise_k = (std::sqrt(1.0 + 4.0 * a * heat_k) - 1.0) / (2.0 * a);
  const double hot_expected_rad = std::asin(kt * supply_v / (r0_ohm * (1.0 + a * rise_k)) / mgl_nm);
  std::printf(
      "[ stall ] cold %.6f rad (closed form %.6f), hot %.6f rad (closed form %.6f, "
      "winding +%.1f K)\n",
      cold_rad, cold_expected_rad, hot_rad, hot_expected_rad, rise_k);
  // Both holds saturate the duty, so the closed forms (full supply on the winding) apply.
  EXPECT_GT(v.get("bench.error_gain") * v.get("bench.kp") * (goal_rad - cold_rad), 1.0);
  EXPECT_NEAR(cold_rad, cold_expected_rad, 1e-4);
  EXPECT_NEAR(hot_rad, hot_expected_rad, 1e-4);
  EXPECT_LT(hot_rad, cold_rad - 0.3);  // the heated winding holds the arm far lower
}

}  // namespace
}  // namespace motoflex
