#include "motoflex/sim/actuator/motoflex_2011_stages.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace motoflex {

std::vector<std::string> motoflex_2011_switch_names() {
  return {"motoflex_2011.velocity_phase_s",
          "motoflex_2011.velocity_kp_per_s",
          "motoflex_2011.velocity_fmax_nm",
          "motoflex_2011.voltage_pid_in_velocity_phase",
          "motoflex_2011.integral_gain_is_joint_index",
          "motoflex_2011.derivative_per_frame",
          "motoflex_2011.voltage_delay",
          "motoflex_2011.voltage_clamp_upper_only",
          "motoflex_2011.b_from_frozen_velocity",
          "motoflex_2011.friction_at_frozen_velocity",
          "motoflex_2011.gear_semi_implicit_euler"};
}

std::vector<ParameterSpec> motoflex_2011_switch_defaults() {
  const Motoflex2011Switches original;
  const std::vector<std::string> n = motoflex_2011_switch_names();
  const auto flag = [](const std::string& name) { return ParameterSpec{name, "1", 1.0, 0.0, 1.0}; };
  return {{n[0], "s", original.velocity_phase_s, 0.0, 5.0},
          {n[1], "1/s", original.velocity_kp_per_s, 0.1, 1000.0},
          {n[2], "N·m", original.velocity_fmax_nm, 0.0, 1000.0},
          flag(n[3]),
          flag(n[4]),
          flag(n[5]),
          flag(n[6]),
          flag(n[7]),
          flag(n[8]),
          flag(n[9]),
          flag(n[10])};
}

namespace {

// The original's frame (frameLen), the step its D term is per (§2.4).
constexpr double kOriginalFrame_s = 0.001;

double integral_gain(const Motoflex2011Switches& s, std::optional<std::size_t> column,
                     double physical) {
  if (!s.integral_gain_is_joint_index) return physical;
  if (!column) {
    throw std::invalid_argument(
        "not a joint of the 2011 program, so it has no index for the I gain (set "
        "motoflex_2011.integral_gain_is_joint_index to 0)");
  }
  return static_cast<double>(*column);
}

}  // namespace

PidGains motoflex_2011_voltage_gains(const PidGains& physical, const Motoflex2011Switches& s,
                                     std::optional<std::size_t> column, double dt_s) {
  PidGains gains = physical;
  gains.ki_v_per_rad_s = integral_gain(s, column, physical.ki_v_per_rad_s);
  if (s.derivative_per_frame) gains.kd_v_s_per_rad *= dt_s / kOriginalFrame_s;
  return gains;
}

PidGains motoflex_2011_velocity_gains(const Motoflex2011Switches& s,
                                      std::optional<std::size_t> column) {
  return {s.velocity_kp_per_s, integral_gain(s, column, 0.0), 0.0};
}

VoltageStage2011::VoltageStage2011(double supply_v, double resistance_ohm, double inductance_h,
                                   double dt_s, bool upper_clamp_only, bool delay)
    : supply_v_(supply_v), upper_clamp_only_(upper_clamp_only), delay_(delay) {
  // Written as !(x > 0) so that NaN is rejected too.
  if (!(dt_s > 0.0)) throw std::invalid_argument("VoltageStage2011: dt_s must be > 0");
  if (!(resistance_ohm > 0.0)) {
    throw std::invalid_argument("VoltageStage2011: resistance_ohm must be > 0");
  }
  if (!(inductance_h >= 0.0)) {
    throw std::invalid_argument("VoltageStage2011: inductance_h must be >= 0");
  }
  if (!(supply_v >= 0.0)) throw std::invalid_argument("VoltageStage2011: supply_v must be >= 0");
  lag_fraction_ = inductance_h == 0.0 ? 1.0 : -std::expm1(-dt_s * resistance_ohm / inductance_h);
}

double VoltageStage2011::update(double pid_v) {
  // §2.5 (MAX_VOLT in Motor::controllerStep): the original clips the upper side only.
  const double u_v = upper_clamp_only_ ? std::min(pid_v, supply_v_)
                                       : std::min(std::max(pid_v, -supply_v_), supply_v_);
  if (!delay_) {
    voltage_v_ += (u_v - voltage_v_) * lag_fraction_;
    return voltage_v_;
  }
  // §2.5 (IMPEDANCE): curVolt += dVolt; dVolt = (u − curVolt)(1 − e^{−dt·R/L}). The torque of
  // this frame uses curVolt, i.e. (for 1 − e^{−20.8} ≈ 1) the previous frame's voltage.
  voltage_v_ += pending_dv_v_;
  pending_dv_v_ = (u_v - voltage_v_) * lag_fraction_;
  return voltage_v_;
}

SemiImplicitGear::SemiImplicitGear(double backlash_rad, double spring_nm_per_rad, double mass_kg_m2,
                                   double viscous_nm_s_per_rad, double dt_s, int substeps)
    : backlash_rad_(backlash_rad),
      spring_nm_per_rad_(spring_nm_per_rad),
      mass_kg_m2_(mass_kg_m2),
      viscous_nm_s_per_rad_(viscous_nm_s_per_rad),
      substep_s_(dt_s / substeps),
      substeps_(substeps) {
  if (!(dt_s > 0.0)) throw std::invalid_argument("SemiImplicitGear: dt_s must be > 0");
  if (substeps < 1) throw std::invalid_argument("SemiImplicitGear: substeps must be >= 1");
  if (!(mass_kg_m2 > 0.0)) throw std::invalid_argument("SemiImplicitGear: mass must be > 0");
  if (!(backlash_rad >= 0.0) || !(spring_nm_per_rad >= 0.0) || !(viscous_nm_s_per_rad >= 0.0)) {
    throw std::invalid_argument(
        "SemiImplicitGear: backlash, spring and damping must not be negative");
  }
}

double SemiImplicitGear::update(double input_nm) {
  // motoflex_2011.md §2.8; seed 001 Algorithm 2 with the velocity updated before the position.
  double position_rad = position_rad_;
  double velocity_rad_s = velocity_rad_s_;
  double summed_spring_nm = 0.0;
  for (int i = 0; i < substeps_; ++i) {
    double compression_rad = 0.0;
    if (position_rad > backlash_rad_) {
      compression_rad = position_rad - backlash_rad_;
    } else if (position_rad < 0.0) {
      compression_rad = position_rad;
    }
    const double spring_nm = spring_nm_per_rad_ * compression_rad;
    velocity_rad_s +=
        (input_nm - spring_nm - viscous_nm_s_per_rad_ * velocity_rad_s) / mass_kg_m2_ * substep_s_;
    position_rad += velocity_rad_s * substep_s_;
    summed_spring_nm += spring_nm;
  }
  position_rad_ = position_rad;
  velocity_rad_s_ = velocity_rad_s;
  return summed_spring_nm / substeps_;
}

}  // namespace motoflex
