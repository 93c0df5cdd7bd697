// `servo: motoflex_2011`, switch by switch (motoflex_2011.md §2.3–§2.8): each test drives the
// law of one joint of the 2011 box robot through the ServoLaw interface with a constant angle
// error and checks the original's behaviour against the number it implies, then the switch's
// physical alternative. Signs: the law works in the original's ODE angles, minus ours (§2.1).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/actuator/motoflex_2011_stages.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

constexpr double kDt_s = 1e-3;
constexpr double kVelocityPhase_s = 0.82;  // the robot's default, the original's

const RobotModel& robot_2011() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao_motoflex_2011", {1, true});
  return model;
}

// One joint's law with the robot's defaults (Normal.gnm, every switch at the original's value)
// and `changes` on top.
struct LawUnderTest {
  ParameterSet values;
  std::unique_ptr<ServoLaw> law;
  double elapsed_s = 0.0;

  LawUnderTest(const std::string& joint,
               std::initializer_list<std::pair<const char*, double>> changes, double dt_s = kDt_s)
      : values(robot_2011().parameters) {
    for (const auto& [name, value] : changes) values.set(name, value);
    const ParameterReader reader(values, "motoflex_2011");
    const ServoLawSetup setup{robot_2011(), *robot_2011().actuator_index(joint), reader, dt_s, 100};
    law = servo_law("motoflex_2011").create(setup);
    dt = dt_s;
  }
  // One step with command − angle = `error_rad` (our signs), the joint at rest.
  ServoOutput step(double error_rad) {
    ServoInput in;
    in.command_rad = error_rad;
    in.elapsed_s = elapsed_s;
    elapsed_s += dt;
    return law->step(in);
  }
  ServoOutput run(double error_rad, double duration_s) {
    ServoOutput out;
    for (long k = 0; k < std::lround(duration_s / dt); ++k) out = step(error_rad);
    return out;
  }
  double get(const std::string& name) const { return values.get(name); }
  double dt = kDt_s;
};

// §2.3 + §2.4: for 820 frames the joint is an ODE velocity motor, target P·e + I·Σe·dt with
// P = 10/s and I = the joint's column (LKneePitch: 2), FMax 100 N·m, no explicit torque; then
// torque mode: an explicit torque and the friction row. A servo that changes mode mid-rollout.
TEST(Motoflex2011Law, VelocityPhaseThenTorqueMode) {
  LawUnderTest knee("LKneePitch", {});
  const double error_rad = 0.01;
  for (int frame = 1; frame <= 820; ++frame) {
    const ServoOutput out = knee.step(error_rad);
    ASSERT_TRUE(std::isnan(out.torque_nm)) << frame;
    EXPECT_EQ(out.row.fmax_nm, 100.0);
    // Our signs: the ODE error is −0.01, its target −(10·0.01 + 2·0.01·t), ours the opposite.
    const double expected = 10.0 * error_rad + 2.0 * error_rad * frame * kDt_s;
    ASSERT_NEAR(out.row.velocity_rad_s, expected, 1e-12) << frame;
  }
  const ServoOutput torque_mode = knee.step(error_rad);
  EXPECT_TRUE(std::isfinite(torque_mode.torque_nm));
  EXPECT_NEAR(torque_mode.row.fmax_nm, knee.get("joint.LKneePitch.friction_nm"), 1e-12);

  // Physical: torque mode from the first step.
  LawUnderTest physical("LKneePitch", {{"motoflex_2011.velocity_phase_s", 0.0}});
  EXPECT_TRUE(std::isfinite(physical.step(error_rad).torque_nm));
}

// §2.4: the I gain is the column index (LHipRoll 0 … RAnkleRoll 9); physical: no I in the
// velocity PID, pid.ki_v_per_rad_s in the voltage PID.
TEST(Motoflex2011Law, IntegralGainIsTheJointIndex) {
  const Motoflex2011Switches original;
  Motoflex2011Switches physical;
  physical.integral_gain_is_joint_index = false;
  const PidGains file{319.4724, 14.18586, 0.1635552};
  EXPECT_EQ(motoflex_2011_voltage_gains(file, original, 9, kDt_s).ki_v_per_rad_s, 9.0);
  EXPECT_EQ(motoflex_2011_velocity_gains(original, 4).ki_v_per_rad_s, 4.0);
  EXPECT_EQ(motoflex_2011_voltage_gains(file, physical, 9, kDt_s).ki_v_per_rad_s, 14.18586);
  EXPECT_EQ(motoflex_2011_velocity_gains(physical, 4).ki_v_per_rad_s, 0.0);
  EXPECT_THROW(motoflex_2011_velocity_gains(original, std::nullopt), std::invalid_argument);
  // Through the law: RAnkleRoll's velocity target after 100 frames of e = 0.01 (our signs).
  LawUnderTest ankle("RAnkleRoll", {});
  EXPECT_NEAR(ankle.run(0.01, 0.1).row.velocity_rad_s, 0.1 + 9.0 * 0.01 * 0.1, 1e-12);
  LawUnderTest no_index("RAnkleRoll", {{"motoflex_2011.integral_gain_is_joint_index", 0.0}});
  EXPECT_NEAR(no_index.run(0.01, 0.1).row.velocity_rad_s, 0.1, 1e-12);
}

// §2.4: d·(e − e_prev) per 1 ms frame whatever the step: at 0.5 ms kd/2 per Pid's kd·Δe/dt; at
// 1 ms the same as the physical kd·Δe/dt.
TEST(Motoflex2011Law, DerivativeActsPerFrame) {
  Motoflex2011Switches original;
  Motoflex2011Switches physical;
  physical.derivative_per_frame = false;
  const PidGains file{319.4724, 14.18586, 0.1635552};
  EXPECT_NEAR(motoflex_2011_voltage_gains(file, original, 0, 5e-4).kd_v_s_per_rad, 0.5 * 0.1635552,
              1e-15);
  EXPECT_EQ(motoflex_2011_voltage_gains(file, original, 0, 1e-3).kd_v_s_per_rad, 0.1635552);
  EXPECT_EQ(motoflex_2011_voltage_gains(file, physical, 0, 5e-4).kd_v_s_per_rad, 0.1635552);
}

// §2.5: clamp at +supply only, in the original's signs; the physical clamp is symmetric.
// Impedance with the delay: V follows u one frame late (1 − e^{−dt·R/L} = 1 − e^{−20.8}).
TEST(Motoflex2011Law, VoltageDelayAndUpperClamp) {
  VoltageStage2011 original(21.6, 6.44, 3.09e-4, kDt_s, true, true);
  EXPECT_EQ(original.update(5.0), 0.0);  // the first frame still has curVolt = 0
  const double lag = -std::expm1(-kDt_s * 6.44 / 3.09e-4);
  EXPECT_NEAR(original.update(-100.0), 5.0 * lag, 1e-12);
  EXPECT_NEAR(original.update(100.0), 5.0 * lag + (-100.0 - 5.0 * lag) * lag, 1e-9);  // ≈ −100
  EXPECT_LT(original.voltage_v(), -99.0);  // negative voltages are not clamped
  VoltageStage2011 physical(21.6, 6.44, 3.09e-4, kDt_s, false, false);
  EXPECT_NEAR(physical.update(5.0), 5.0 * lag, 1e-12);  // no delay
  EXPECT_NEAR(physical.update(-100.0), -21.6, 1e-6);    // symmetric clamp
  EXPECT_NEAR(physical.update(100.0), 21.6, 1e-6);
}

// §2.6: in torque mode with zero error the only torque is the bias −B·σ·ω_frozen (ODE signs),
// ω_frozen the velocity target of frame 819; B·σ = motor_viscous·σ² = 10.76 N·m·s/rad (roll)
// at Normal.gnm's B (set here: the robot's default is a nominal 1.9e-5).
// Physical: no bias, B·σ as the rollout's implicit damper row. The voltage PID is kept out of
// the velocity phase here so that zero error means zero voltage.
TEST(Motoflex2011Law, BIsABiasFromTheFrozenVelocity) {
  for (const double b_frozen : {1.0, 0.0}) {
    LawUnderTest hip("LHipRoll", {{"motoflex_2011.voltage_pid_in_velocity_phase", 0.0},
                                  {"motoflex_2011.b_from_frozen_velocity", b_frozen},
                                  {"gear.A.motor_viscous_nm_s_per_rad", 2.6558e-4}});
    const double b_sigma = hip.get("gear.A.motor_viscous_nm_s_per_rad") * 201.3 * 201.3;
    EXPECT_NEAR(b_sigma, 10.76, 0.01);
    hip.run(0.005, kVelocityPhase_s);  // LHipRoll: I = 0, frozen target 10·0.005 (ours)
    const ServoOutput out = hip.run(0.0, 0.3);
    // Ours: ω_frozen = −0.05 in ODE signs, bias +0.538 N·m there, −0.538 N·m here.
    const double expected = b_frozen == 1.0 ? -b_sigma * 0.05 : 0.0;
    std::printf("[ motoflex_2011 ] B switch %g: torque %.12f N·m (bias %.12f)\n", b_frozen,
                out.torque_nm, expected);
    EXPECT_NEAR(out.torque_nm, expected, 1e-9);  // measured: exact to 1e-15
    EXPECT_NEAR(hip.law->damping_row_nm_s_per_rad(), b_frozen == 1.0 ? 0.0 : b_sigma, 1e-12);
  }
}

// §2.7: the friction row keeps FMax = jointFriction and the frozen velocity as its target
// (Coulomb friction centred on ω_frozen); physical: target 0. jointFriction at Normal.gnm's
// value (set here: the robot's default is a nominal 1 N·m).
TEST(Motoflex2011Law, FrictionIsCentredOnTheFrozenVelocity) {
  for (const double centred : {1.0, 0.0}) {
    LawUnderTest knee("RKneePitch", {{"motoflex_2011.friction_at_frozen_velocity", centred},
                                     {"joint.RKneePitch.friction_nm", 0.7915588}});
    knee.run(0.002, kVelocityPhase_s);
    // RKneePitch: column 7, so the frozen target is 10·0.002 + 7·0.002·0.82 (ours).
    const double frozen = 10.0 * 0.002 + 7.0 * 0.002 * kVelocityPhase_s;
    const ServoOutput out = knee.step(0.002);
    EXPECT_NEAR(out.row.velocity_rad_s, centred == 1.0 ? frozen : 0.0, 1e-12);
    EXPECT_NEAR(out.row.fmax_nm, 0.7915588, 1e-12);
  }
}

// §2.3: the voltage PID integrates during the velocity phase, so torque mode starts with 820
// frames of integrated error: against a PID that starts at the switch, the voltage differs by
// I·Σe·dt = 4·e·0.82 s (LAnkleRoll, I = 4) for ever after, and in steady state so does the
// torque, by that voltage/R·stiffness·K·σ (every stage is linear below the clamp, and the roll
// joints' gear is well damped; the pitch joints' rattles in its hull, see the gear test).
TEST(Motoflex2011Law, VoltagePidIntegratesDuringTheVelocityPhase) {
  const double error_rad = -0.01;  // ODE error +0.01: positive voltages, below the clamp
  double torque_nm[2];
  for (const double integrates : {1.0, 0.0}) {
    LawUnderTest ankle("LAnkleRoll", {{"motoflex_2011.voltage_pid_in_velocity_phase", integrates}});
    torque_nm[integrates == 1.0 ? 0 : 1] = ankle.run(error_rad, kVelocityPhase_s + 0.3).torque_nm;
  }
  const double delta_v = 4.0 * 0.01 * kVelocityPhase_s;
  const double expected = -delta_v / 6.44 * 0.7 * 0.0195 * 201.3;  // ours = −ODE
  std::printf(
      "[ motoflex_2011 ] torque with / without the velocity-phase integral: %.12f / "
      "%.12f N·m\n",
      torque_nm[0], torque_nm[1]);
  EXPECT_NEAR(torque_nm[0] - torque_nm[1], expected, 1e-6 * std::abs(expected));
}

// §2.8: the original's gear: a free mass inside the hull (no output), then a spring; a constant
// input is transmitted exactly once the mass rests against the wall (the type 0 gear, damping
// ratio 0.52). The type 1 gear (damping ratio 0.0004, √(D/m)·Δt_g = 1.28) never comes to rest:
// its mass keeps bouncing off the hull walls, and its output scatters around the input.
TEST(Motoflex2011Law, SemiImplicitGearHasADeadZoneAndTransmitsSteadyTorque) {
  // Inside a 0.01 rad hull 1 N·m moves the 1e-3 kg·m² mass 0.5·1000·(1 ms)² = 5e-4 rad: no
  // spring torque at all.
  SemiImplicitGear wide(0.01, 1e5, 1e-3, 0.0, kDt_s, 100);
  EXPECT_EQ(wide.update(1.0), 0.0);
  EXPECT_NEAR(wide.position_rad(), 5e-4, 1e-5);  // the sum over 100 sub-steps: 5.05e-4
  // Normal.gnm's type 0 gear: the mean spring torque settles to the input.
  SemiImplicitGear type0(1.301046e-5, 6.130811e6, 1.080835e-3, 84.36548, kDt_s, 100);
  double out = 0.0;
  for (int frame = 0; frame < 100; ++frame) out = type0.update(-0.7);
  EXPECT_NEAR(out, -0.7, 1e-9);
  EXPECT_NEAR(type0.position_rad(), -0.7 / 6.130811e6, 1e-12);  // against the lower wall
  SemiImplicitGear type1(1.050896e-5, 1.799522e7, 1.103733e-3, 0.1089670, kDt_s, 100);
  double sum = 0.0, sum_sq = 0.0;
  for (int frame = 0; frame < 2000; ++frame) {
    out = type1.update(0.3);
    if (frame < 1000) continue;
    sum += out;
    sum_sq += out * out;
  }
  const double mean = sum / 1000.0, spread = std::sqrt(sum_sq / 1000.0 - mean * mean);
  std::printf("[ motoflex_2011 ] type 1 gear, 0.3 N·m in: mean %.6f, spread %.6f N·m\n", mean,
              spread);
  EXPECT_NEAR(mean, 0.3, 0.01);
  EXPECT_GT(spread, 0.01);
}

// The mode change inside a rollout (one-joint turntable, no gravity): during the velocity phase
// the joint follows the velocity motor's first-order lag, θ = θ_d·(1 − (1 − P·h)^k), and the
// rollout reports no actuator torque; after it, torque mode reports one.
TEST(Motoflex2011Law, RolloutChangesModeAtTheEndOfTheVelocityPhase) {
  const testing::OneJointRobot table{
      .mass_kg = 0.5, .length_m = 0.0, .com_inertia_kg_m2 = 0.005, .vertical_axis = true};
  const RobotModel model =
      testing::make_one_joint_robot("motoflex_2011_table", table, "motoflex_2011");
  ParameterSet values(model.parameters);
  values.set("motoflex_2011.integral_gain_is_joint_index", 0.0);  // `hinge` has no column
  values.set("motoflex_2011.velocity_phase_s", 0.2);
  values.set("pid.kp_v_per_rad", 100.0);
  values.set("pid.kd_v_s_per_rad", 1.0);  // damping ratio ≈ 0.4 in torque mode
  const auto trace = testing::run_steps(
      model, values, "motoflex_2011", 0.0, [](double) { return 0.1; }, 0.4);
  ASSERT_EQ(trace.t_s.size(), 400u);
  const double lag = 0.1 * (1.0 - std::pow(1.0 - 10.0 * kDt_s, 200.0));
  std::printf("[ motoflex_2011 ] θ(0.2 s) = %.12f rad, lag %.12f\n", trace.q_rad[199], lag);
  EXPECT_NEAR(trace.q_rad[199], lag, 1e-6);  // world CFM 1e-10 softens the row (measured 1e-9)
  EXPECT_TRUE(std::isnan(trace.torque_nm[199]));
  EXPECT_TRUE(std::isfinite(trace.torque_nm[200]));
  EXPECT_LT(std::abs(trace.q_rad.back() - 0.1), std::abs(trace.q_rad[199] - 0.1));
}

}  // namespace
}  // namespace motoflex
