#pragma once

// The stages of `servo: motoflex_2011` that differ from the physical law's: the 2011 program's
// voltage stage and its gear integrator, as the original computes them
// (../shared/reference/motoflex_2011.md §2.5, §2.8), and the switches that choose between the
// original's behaviour and the physical one item by item (§2.3–§2.8). The law itself is
// src/sim/actuator/motoflex_2011_servo_law.cpp.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/sim/actuator/pid.hpp"

namespace motoflex {

// One named switch per quirk of the 2011 program, each read from a robot parameter
// `motoflex_2011.<name>` (robot.yaml of scenarios/robots/nao_motoflex_2011 declares them with
// the original's value as default). A flag is 1 (the original) or 0 (the physical alternative,
// i.e. what `servo: motoflex` does). The table of what each one does to the walks is in
// scenarios/robots/nao_motoflex_2011/README.md.
struct Motoflex2011Switches {
  // §2.3: for this long after the rollout starts every joint is an ODE velocity motor (target
  // velocity from a PID on the angle error, force limit velocity_fmax_nm; motor and gear off);
  // then torque mode. 0.82 s = behaviour frames 0–40. Physical: 0 (torque mode throughout).
  double velocity_phase_s = 0.82;
  double velocity_kp_per_s = 10.0;  // §2.3: the velocity PID's P (World::init)
  double velocity_fmax_nm = 100.0;  // §2.3: fMax of Normal.gnm
  // §2.3: the voltage PID integrates during the velocity phase too (Motor::controllerStep
  // updates both PIDs), so torque mode starts with its integral. Physical: 0 (it starts then).
  bool voltage_pid_in_velocity_phase = true;
  // §2.4: the I gain of both PIDs is the joint's column index in the original's order
  // (LHipRoll 0 … RAnkleRoll 9; a shadowed loop variable), not pid.ki_v_per_rad_s. Physical: 0
  // (voltage PID: pid.ki_v_per_rad_s; velocity PID: no I).
  bool integral_gain_is_joint_index = true;
  // §2.4: the D term is d·(e − e_prev) per frame, not divided by the step: kd_v_s_per_rad/1 ms
  // per step whatever the physics step (identical to the physical kd·Δe/dt at dt = 1 ms).
  bool derivative_per_frame = true;
  // §2.5: the impedance stage applies the previous frame's voltage (a one-frame delay, since
  // 1 − e^{−dt·R/L} ≈ 1). Physical: 0 (the RL lag of DcMotor, no delay).
  bool voltage_delay = true;
  // §2.5: the voltage is clamped at +supply_v only, in the original's signs (negative voltages
  // are unbounded). Physical: 0 (clamped to ±supply_v).
  bool voltage_clamp_upper_only = true;
  // §2.6: B multiplies the AMotor's stored target velocity, frozen at its last velocity-mode
  // value: a constant bias −B·σ·ω_frozen per joint. Physical: 0 (B·σ² as an implicit joint
  // damper on the true rate, as `servo: motoflex`).
  bool b_from_frozen_velocity = true;
  // §2.7: the joint-friction motor row keeps the frozen velocity as its target (friction
  // centred on ω_frozen). Physical: 0 (target 0).
  bool friction_at_frozen_velocity = true;
  // §2.8: the gear as the original integrates it (SemiImplicitGear). Physical: 0 (GearTrain:
  // implicit spring in contact).
  bool gear_semi_implicit_euler = true;
};

// The names of the switches as robot parameters (motoflex_2011.velocity_phase_s, ...), in the
// order of the struct.
std::vector<std::string> motoflex_2011_switch_names();

// The switches as robot parameters with the original's values as defaults (flags 0/1).
std::vector<ParameterSpec> motoflex_2011_switch_defaults();

// The gains of the voltage PID as the 2011 program applies them at physics step `dt_s`, from the
// robot's `physical` gains (pid.*): with integral_gain_is_joint_index the I gain is `column`
// (the joint's index in the original's order, §2.4; std::invalid_argument when it has none),
// and with derivative_per_frame kd acts per 1 ms frame of the original (kd·Δe per frame, so
// Pid's kd·Δe/dt needs kd·dt/1 ms).
PidGains motoflex_2011_voltage_gains(const PidGains& physical, const Motoflex2011Switches& s,
                                     std::optional<std::size_t> column, double dt_s);
// The velocity-phase PID (§2.3): P = velocity_kp_per_s, I = `column` with
// integral_gain_is_joint_index (else 0), no D. Output in rad/s per rad of error.
PidGains motoflex_2011_velocity_gains(const Motoflex2011Switches& s,
                                      std::optional<std::size_t> column);

// The original's voltage stage (motoflex_2011.md §2.5, `Motor::getTargetTorque`): the PID's
// output clamped (at +supply_v only, or to ±supply_v), then the RL impedance
// dV = (u − V)(1 − e^{−dt·R/L}). With `delay` the original's order: V += dV of the previous
// frame, then dV is computed from this frame's u, so V follows u one frame late; without it
// V += (u − V)(1 − e^{−dt·R/L}) at once (DcMotor's order). Signs are the original's (ODE's).
class VoltageStage2011 {
 public:
  // Throws std::invalid_argument for dt_s <= 0, R <= 0, L < 0 or supply_v < 0.
  VoltageStage2011(double supply_v, double resistance_ohm, double inductance_h, double dt_s,
                   bool upper_clamp_only, bool delay);
  // Returns the voltage across the windings this frame (V) for the PID output `pid_v`.
  double update(double pid_v);
  double voltage_v() const { return voltage_v_; }

 private:
  double supply_v_;
  double lag_fraction_;  // 1 − e^{−dt·R/L}
  bool upper_clamp_only_;
  bool delay_;
  double voltage_v_ = 0.0;     // curVolt
  double pending_dv_v_ = 0.0;  // dVolt, applied next frame (delay only)
};

// The original's gear (motoflex_2011.md §2.8, `FLEXIBLE_TOLERANCE_GEARS`; seed 001 Algorithm
// 2), integrated as the original does: `substeps` explicit semi-implicit-Euler sub-steps per
// frame, each
//   p_h = p − l_h if p > l_h;  p if p < 0;  else 0        (hull [0, l_h])
//   T_s = D_g·p_h
//   v ← v + (T_in − T_s − B_g·v)/m_g·Δt_g;   p ← p + v·Δt_g
// and the output is the mean of T_s over the sub-steps. Joint-side units (the input is the
// motor torque times the ratio). Stable for sqrt(D_g/m_g)·Δt_g < 2 and B_g·Δt_g/m_g < 2; with a
// backlash, contacts resolved by a few sub-steps make the mass rattle between the hull walls
// (GearTrain's header): that is the original's behaviour, kept here on purpose.
class SemiImplicitGear {
 public:
  // Throws std::invalid_argument for dt_s <= 0, substeps < 1, mass <= 0 or a negative backlash,
  // spring or damping.
  SemiImplicitGear(double backlash_rad, double spring_nm_per_rad, double mass_kg_m2,
                   double viscous_nm_s_per_rad, double dt_s, int substeps);
  // One frame with a constant joint-side input torque (N·m); returns the mean spring torque.
  double update(double input_nm);
  double position_rad() const { return position_rad_; }
  double velocity_rad_s() const { return velocity_rad_s_; }

 private:
  double backlash_rad_;
  double spring_nm_per_rad_;
  double mass_kg_m2_;
  double viscous_nm_s_per_rad_;
  double substep_s_;
  int substeps_;
  double position_rad_ = 0.0;  // at the lower hull wall, at rest (the original's zero state)
  double velocity_rad_s_ = 0.0;
};

}  // namespace motoflex
