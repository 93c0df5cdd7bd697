// The dynamixel and feetech laws (position firmware → PWM → DC motor) on the one-joint
// turntable against closed forms: the saturated duty's stall torque N·K_t·U·d/R, the back-EMF's
// exponential approach to the no-load speed U·d/(K_t·N) with time constant I·R/(N·K_t)², the
// current limit's torque N·K_t·I_max, the dead band and integer ticks holding the arm still,
// and the H-bridge released at torque_off_s.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "motoflex/model/parameters.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

using testing::OneJointRobot;

constexpr double kDt_s = 1e-3;
// Copper's temperature coefficient (winding_heating.hpp's kCopperResistancePerK), written out.
constexpr double kCopperResistancePerKForTest = 0.00393;
// A heavy arm: the no-load speed is reached slowly enough to stay within ODE's ±π hinge angle.
// The arm's CoM on the axis (see pd_torque_law_test.cpp).
const OneJointRobot kTurntable{
    .mass_kg = 2.0, .length_m = 0.0, .com_inertia_kg_m2 = 0.18, .vertical_axis = true};

const RobotModel& turntable(const std::string& law) {
  static const RobotModel dynamixel =
      testing::make_one_joint_robot("firmware_dynamixel", kTurntable, "dynamixel");
  static const RobotModel feetech =
      testing::make_one_joint_robot("firmware_feetech", kTurntable, "feetech");
  return law == "feetech" ? feetech : dynamixel;
}

struct Motor {
  double kt = 0.6, r = 2.6, v = 7.4, ratio = 1.0;
};

ParameterSet values(const std::string& law, const Motor& m) {
  ParameterSet p(turntable(law).parameters);
  p.set("servo.hinge.Kt_nm_per_a", m.kt);
  p.set("servo.hinge.R_ohm", m.r);
  p.set("servo.hinge.supply_v", m.v);
  p.set("servo.hinge.gear_ratio", m.ratio);
  return p;
}

testing::StepTrace far_goal(const std::string& law, const ParameterSet& p, double duration_s) {
  return testing::run_steps(
      turntable(law), p, law, -2.5, [](double) { return 2.5; }, duration_s, kDt_s);
}

TEST(FirmwareLawTest, SaturatedDutyStallTorqueAndBackEmfSpeed) {
  const double inertia = axis_inertia_kg_m2(kTurntable);  // 0.18 kg·m²
  // The same joint-side motor twice: K_t 0.6 N·m/A direct, and 0.003 N·m/A through a 200:1 gear.
  for (const Motor& motor : {Motor{}, Motor{.kt = 0.003, .ratio = 200.0}}) {
    for (const char* law : {"dynamixel", "feetech"}) {
      ParameterSet p = values(law, motor);
      const double full_scale = p.get("servo.hinge.pwm_full_scale");
      p.set("servo.hinge.pwm_limit", 0.8 * full_scale);
      const double duty = 0.8;
      const double kt_joint = motor.kt * motor.ratio;
      const double stall_nm = kt_joint * motor.v * duty / motor.r;
      const double no_load_rad_s = motor.v * duty / kt_joint;
      const double tau_s = inertia * motor.r / (kt_joint * kt_joint);
      const auto trace = far_goal(law, p, 0.5);
      EXPECT_NEAR(trace.torque_nm.front(), stall_nm, 1e-12) << law;  // at rest: the stall torque
      double worst = 0.0;
      for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
        const double analytic = no_load_rad_s * (1.0 - std::exp(-trace.t_s[k] / tau_s));
        worst = std::max(worst, std::abs(trace.w_rad_s[k] - analytic));
      }
      std::printf(
          "[ firmware ] %-9s N %5.0f: stall %.4f N·m, no-load %.3f rad/s, τ %.3f s: "
          "max |ω − closed form| %.2e rad/s\n",
          law, motor.ratio, stall_nm, no_load_rad_s, tau_s, worst);
      // The back-EMF is explicit (from the step's start rate): first order in h/τ; measured
      // 9.9e-4 rad/s against ω(0.5 s) = 3.2 rad/s.
      EXPECT_LT(worst, 3e-3) << law;
    }
  }
}

TEST(FirmwareLawTest, CurrentLimitCapsTheStallTorque) {
  ParameterSet p = values("dynamixel", Motor{});
  p.set("servo.hinge.current_limit_a", 0.8);
  const auto trace = far_goal("dynamixel", p, 0.01);
  EXPECT_NEAR(trace.torque_nm.front(), 0.6 * 0.8, 1e-12);  // K_t·I_max (unlimited: 1.71 N·m)
}

// The motor's torque saturation (motor.torque_saturation_per_a, torque_saturation.hpp) in both
// firmware laws: the stall torque K_t·tanh(k·U·d/R)/k.
TEST(FirmwareLawTest, TorqueSaturationLowersTheStallTorque) {
  for (const char* law : {"dynamixel", "feetech"}) {
    ParameterSet p = values(law, Motor{});
    p.set("servo.hinge.pwm_limit", 0.8 * p.get("servo.hinge.pwm_full_scale"));
    p.set("motor.torque_saturation_per_a", 0.5);
    const double stall_a = 7.4 * 0.8 / 2.6;
    const auto trace = far_goal(law, p, 0.01);
    EXPECT_NEAR(trace.torque_nm.front(), 0.6 * std::tanh(0.5 * stall_a) / 0.5, 1e-12) << law;
  }
}

// The winding's Joule heating (winding_heating.hpp) in the firmware laws: a stalled servo at a
// held duty d heats its winding until ΔT·(1 + α·ΔT) = (U·d)²·R_th/R₀, and its torque falls to
// N·K_t·U·d/(R₀·(1 + α·ΔT)). The arm is a flywheel (1e5 kg·m²) so that it stays still: its
// back-EMF reaches 1.1e-5 of the drive after 8 s. With R_th = 0 the stall torque is the cold one.
TEST(FirmwareLawTest, WindingHeatingWeakensAStalledServoToTheHotStallTorque) {
  const OneJointRobot flywheel{
      .mass_kg = 2.0, .length_m = 0.0, .com_inertia_kg_m2 = 1.0e5, .vertical_axis = true};
  for (const char* law : {"dynamixel", "feetech"}) {
    const RobotModel model =
        testing::make_one_joint_robot(std::string("firmware_heating_") + law, flywheel, law);
    ParameterSet p(model.parameters);
    const Motor m;
    p.set("servo.hinge.Kt_nm_per_a", m.kt);
    p.set("servo.hinge.R_ohm", m.r);
    p.set("servo.hinge.supply_v", m.v);
    const double full_scale = p.get("servo.hinge.pwm_full_scale");
    p.set("servo.hinge.pwm_limit", 0.8 * full_scale);
    const double drive_v = m.v * 0.8;
    const double cold_nm = m.kt * drive_v / m.r;
    const auto stall = [&](const ParameterSet& values) {
      return testing::run_steps(
          model, values, law, -2.5, [](double) { return 2.5; }, 8.0, kDt_s);
    };
    const auto cold = stall(p);
    EXPECT_NEAR(cold.torque_nm.front(), cold_nm, 1e-12) << law;
    EXPECT_NEAR(cold.torque_nm.back(), cold_nm, 3e-5 * cold_nm) << law;
    const double r_th_k_per_w = 20.0;  // τ = R_th·C = 1 s: settled to e^-8 after 8 s
    p.set("motor.winding_k_per_w", r_th_k_per_w);
    p.set("motor.winding_heat_j_per_k", 0.05);
    const auto hot = stall(p);
    EXPECT_NEAR(hot.torque_nm.front(), cold_nm, 1e-12) << law;  // starts cold
    const double a = kCopperResistancePerKForTest;
    const double c = drive_v * drive_v * r_th_k_per_w / m.r;  // ΔT + a·ΔT² = c
    const double rise_k = (-1.0 + std::sqrt(1.0 + 4.0 * a * c)) / (2.0 * a);
    const double hot_nm = cold_nm / (1.0 + a * rise_k);
    std::printf(
        "[ firmware ] %-9s stall %.4f N·m cold, %.4f hot (winding +%.1f K), closed form "
        "%.4f\n",
        law, cold_nm, hot.torque_nm.back(), rise_k, hot_nm);
    EXPECT_NEAR(hot.torque_nm.back(), hot_nm, 1e-3 * hot_nm) << law;
    EXPECT_LT(hot.torque_nm.back(), 0.8 * cold_nm) << law;  // +150 K: a third weaker
  }
}

TEST(FirmwareLawTest, DeadBandAndIntegerTicksHoldTheArm) {
  const double tick_rad = 2.0 * std::acos(-1.0) / 4096.0;
  const auto hold = [&](double goal_ticks, double deadband, double integer) {
    ParameterSet p = values("dynamixel", Motor{});
    p.set("servo.hinge.deadband_ticks", deadband);
    p.set("servo.hinge.integer_ticks", integer);
    return testing::run_steps(
        turntable("dynamixel"), p, "dynamixel", 0.0, [&](double) { return goal_ticks * tick_rad; },
        0.2, kDt_s);
  };
  // 4 ticks inside a 5-tick dead band, 0.4 tick with integer positions: no torque, no motion.
  for (const auto& trace : {hold(4.0, 5.0, 0.0), hold(0.4, 0.0, 1.0)}) {
    EXPECT_EQ(trace.torque_nm.front(), 0.0);
    EXPECT_NEAR(trace.q_rad.back(), 0.0, 1e-12);
  }
  // Without them the same goals move the arm toward them.
  // (Back-EMF damping K_t²/R on 0.18 kg·m²: about 0.9 and 0.09 tick in 0.2 s.)
  EXPECT_GT(hold(4.0, 0.0, 0.0).q_rad.back(), 0.5 * tick_rad);
  EXPECT_GT(hold(0.4, 0.0, 0.0).q_rad.back(), 0.05 * tick_rad);
}

TEST(FirmwareLawTest, ReleasedBridgeAppliesNoTorque) {
  ParameterSet p = values("feetech", Motor{});
  p.set("servo.hinge.torque_off_s", 0.1);
  const auto trace = far_goal("feetech", p, 0.3);
  EXPECT_GT(trace.torque_nm[50], 1.0);
  const double coasting = trace.w_rad_s[150];
  EXPECT_EQ(trace.torque_nm[150], 0.0);
  EXPECT_NEAR(trace.w_rad_s.back(), coasting, 1e-12);  // no back-EMF braking either
}

// A wrist-sized link (I = 5e-5 kg·m², no armature) under the feetech defaults (K_t 1 N·m/A,
// R 2.5 Ω: back-EMF damping c = K_t²/R = 0.4 N·m·s/rad, c·h/I = 8): an explicit back-EMF torque
// diverges here (|1 − c·h/I| > 1); the implicit row gives the closed form of the massless limit,
// c·θ̇ = K_t·U·duty/R with duty = kp·e·(ticks/rad)/(kp_div·full_scale), i.e. a first-order
// approach at λ = U·kp·(ticks/rad)/(kp_div·full_scale·K_t) (7.8 /s), whose lag I/c = 0.13 ms is
// far below the 1 ms firmware cycle; with the duty held over each cycle, e_n = e₀·(1 − λh)ⁿ.
TEST(FirmwareLawTest, LightLinkFollowsTheMasslessFirstOrderApproach) {
  const OneJointRobot wrist{
      .mass_kg = 0.05, .length_m = 0.0, .com_inertia_kg_m2 = 5e-5, .vertical_axis = true};
  const RobotModel model = testing::make_one_joint_robot("firmware_wrist", wrist, "feetech");
  const ParameterSet p(model.parameters);
  ASSERT_EQ(p.get("joint.hinge.armature_kg_m2"), 0.0);
  const double ticks_per_rad = p.get("servo.hinge.ticks_per_rev") / (2.0 * std::numbers::pi);
  const double lambda_per_s =
      p.get("servo.hinge.supply_v") * p.get("servo.hinge.kp") * ticks_per_rad /
      (p.get("servo.hinge.kp_divisor") * p.get("servo.hinge.pwm_full_scale") *
       p.get("servo.hinge.Kt_nm_per_a"));
  const double e0_rad = 0.5;  // duty 0.33: the PWM never saturates
  const testing::StepTrace trace = testing::run_steps(
      model, p, "feetech", 0.0, [&](double) { return e0_rad; }, 0.6, kDt_s);
  ASSERT_EQ(trace.t_s.size(), 600U);  // no divergence
  for (const double t_s : {0.1, 0.3, 0.6}) {
    const auto k = static_cast<std::size_t>(std::lround(t_s / kDt_s)) - 1;
    const double error_rad = e0_rad - trace.q_rad[k];
    const double expected_rad = e0_rad * std::pow(1.0 - lambda_per_s * kDt_s, k + 1.0);
    // Measured within 0.4 % (the arm's 0.13 ms lag); allowed 1.5 %. The continuous e₀·e^(−λt)
    // is 2.2 % off at 0.6 s.
    EXPECT_NEAR(error_rad, expected_rad, 0.015 * expected_rad) << "t = " << t_s << " s";
  }
}

}  // namespace
}  // namespace motoflex
