// `servo: motoflex_2011` — seed 001's actuator pipeline with the 2011 program's semantics, item
// by item as ../shared/reference/motoflex_2011.md §2 measured them, each behind a switch of
// Motoflex2011Switches (motoflex_2011_stages.hpp) whose physical setting is what
// `servo: motoflex` does:
//   velocity phase (§2.3): ODE velocity motor, target from a PID on the angle, FMax 100 N·m;
//   torque mode: voltage PID (§2.4) → clamp and one-frame delay (§2.5) → current → K·I − B·ω
//   with ω the frozen velocity-mode target (§2.6) → ×σ → gear (§2.8) → joint torque; the motor
//   row holds the joint friction centred on the frozen velocity (§2.7).
// The original works in ODE's angles, which are minus ours for every joint (its joints' body1
// is the parent, §2.1); the law computes in those signs, so that the one-sided clamp and the
// frozen velocities read as in the reference, and turns its outputs back.

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/io/motoflex_command_file.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/gear_train.hpp"
#include "motoflex/sim/actuator/motoflex_2011_stages.hpp"
#include "motoflex/sim/actuator/pid.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

// Our angle = kOurSign · the original's ODE angle, for every joint (§2.1).
constexpr double kOurSign = -1.0;

struct Motoflex2011Params {
  Motoflex2011Switches switches;
  PidGains voltage_pid;  // V/rad, V/(rad·s), V·s/rad (as read; the law applies the switches)
  double supply_v = 21.6;
  double resistance_ohm = 6.44;
  double inductance_h = 3.09e-4;
  double torque_constant_nm_per_a = 0.0195;
  double stiffness = 1.0;
  double ratio = 1.0;                 // σ
  double b_joint_nm_s_per_rad = 0.0;  // B·σ at the joint per rad/s (= motor_viscous·σ²)
  GearParams gear;                    // joint side, ratio σ
  FrictionParams friction;
  std::optional<std::size_t> column;  // the joint's index in the original's order
};

class Motoflex2011ServoLaw final : public ServoLaw {
 public:
  Motoflex2011ServoLaw(const Motoflex2011Params& p, double dt_s, int gear_substeps)
      : params_(p),
        dt_s_(dt_s),
        voltage_pid_(motoflex_2011_voltage_gains(p.voltage_pid, p.switches, p.column, dt_s), dt_s),
        velocity_pid_(motoflex_2011_velocity_gains(p.switches, p.column), dt_s),
        voltage_(p.supply_v, p.resistance_ohm, p.inductance_h, dt_s,
                 p.switches.voltage_clamp_upper_only, p.switches.voltage_delay) {
    if (p.switches.gear_semi_implicit_euler) {
      semi_implicit_gear_.emplace(p.gear.backlash_rad, p.gear.spring_nm_per_rad, p.gear.mass_kg_m2,
                                  p.gear.viscous_nm_s_per_rad, dt_s, gear_substeps);
    } else {
      gear_train_.emplace(p.gear, dt_s, gear_substeps);
    }
  }

  ServoOutput step(const ServoInput& in) override {
    // The original's error and rate, in its (ODE's) signs.
    const double error_rad = (in.command_rad - in.angle_rad) / kOurSign;
    const bool velocity_mode = in.elapsed_s < params_.switches.velocity_phase_s - 0.5 * dt_s_;
    ServoOutput out;
    if (velocity_mode) {
      // §2.3: the velocity PID sets the AMotor's target; motor and gear stay at rest while the
      // voltage PID integrates all the same.
      frozen_velocity_rad_s_ = velocity_pid_.update(error_rad);
      if (params_.switches.voltage_pid_in_velocity_phase) voltage_pid_.update(error_rad);
      out.row = {kOurSign * frozen_velocity_rad_s_, params_.switches.velocity_fmax_nm};
      return out;  // the row's torque is not known here: torque_nm stays NaN
    }
    const double volts = voltage_.update(voltage_pid_.update(error_rad));
    // §2.5: I = V/R·stiffness; τ_m = K·I − B·ω with ω the AMotor's stored target (§2.6).
    const double motor_nm =
        params_.torque_constant_nm_per_a * volts / params_.resistance_ohm * params_.stiffness;
    const double bias_nm = params_.switches.b_from_frozen_velocity
                               ? params_.b_joint_nm_s_per_rad * frozen_velocity_rad_s_
                               : 0.0;
    const double joint_nm = semi_implicit_gear_
                                ? semi_implicit_gear_->update(motor_nm * params_.ratio - bias_nm)
                                : gear_train_->update(motor_nm - bias_nm / params_.ratio);
    out.torque_nm = kOurSign * joint_nm;
    // §2.7: FMax = jointFriction on the row whose target velocity is still the frozen one.
    out.row = joint_friction(params_.friction, in.rate_rad_s, out.torque_nm);
    if (params_.switches.friction_at_frozen_velocity) {
      out.row.velocity_rad_s = kOurSign * frozen_velocity_rad_s_;
    }
    return out;
  }

  double damping_row_nm_s_per_rad() const override {
    // Physical B (switch off): the implicit damper B·σ² of `servo: motoflex` on the true rate.
    return params_.switches.b_from_frozen_velocity ? 0.0 : params_.b_joint_nm_s_per_rad;
  }

 private:
  Motoflex2011Params params_;
  double dt_s_;
  Pid voltage_pid_;
  Pid velocity_pid_;
  VoltageStage2011 voltage_;
  std::optional<SemiImplicitGear> semi_implicit_gear_;
  std::optional<GearTrain> gear_train_;
  double frozen_velocity_rad_s_ = 0.0;  // ω of §2.6 (original's signs)
};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  const ActuatorSpec& spec = model.actuators[actuator];
  std::vector<std::string> out = motoflex_pipeline_parameter_names(spec);
  for (auto& name : motoflex_2011_switch_names()) out.push_back(std::move(name));
  return out;
}

bool read_flag(const ParameterReader& get, const std::string& name) {
  const double value = get(name);
  if (value != 0.0 && value != 1.0) throw ModelError(name + " must be 0 or 1");
  return value == 1.0;
}

Motoflex2011Switches read_switches(const ParameterReader& get) {
  const std::vector<std::string> n = motoflex_2011_switch_names();
  Motoflex2011Switches s;
  s.velocity_phase_s = get(n[0]);
  s.velocity_kp_per_s = get(n[1]);
  s.velocity_fmax_nm = get(n[2]);
  s.voltage_pid_in_velocity_phase = read_flag(get, n[3]);
  s.integral_gain_is_joint_index = read_flag(get, n[4]);
  s.derivative_per_frame = read_flag(get, n[5]);
  s.voltage_delay = read_flag(get, n[6]);
  s.voltage_clamp_upper_only = read_flag(get, n[7]);
  s.b_from_frozen_velocity = read_flag(get, n[8]);
  s.friction_at_frozen_velocity = read_flag(get, n[9]);
  s.gear_semi_implicit_euler = read_flag(get, n[10]);
  if (s.velocity_phase_s < 0.0 || s.velocity_fmax_nm < 0.0) {
    throw ModelError(n[0] + " and " + n[2] + " must not be negative");
  }
  return s;
}

Motoflex2011Params read_params(const ServoLawSetup& setup) {
  const ParameterReader& get = setup.get;
  const ActuatorSpec& spec = setup.model.actuators[setup.actuator];
  Motoflex2011Params p;
  p.switches = read_switches(get);
  p.voltage_pid = {get("pid.kp_v_per_rad"), get("pid.ki_v_per_rad_s"), get("pid.kd_v_s_per_rad")};
  p.supply_v = get("motor.supply_v");
  p.resistance_ohm = get("motor.R_ohm");
  p.inductance_h = get("motor.L_h");
  p.torque_constant_nm_per_a = get("motor.Kt_nm_per_a");
  p.stiffness = get("motor.stiffness");
  const std::string gear = "gear." + spec.group + ".";
  p.ratio = get(gear + "ratio");
  const double motor_viscous = get(gear + "motor_viscous_nm_s_per_rad");
  if (motor_viscous < 0.0) throw ModelError(gear + "motor_viscous_nm_s_per_rad must be >= 0");
  // The robot files hold B on the motor side (B/σ, scenarios/robots/nao/README.md); the
  // original's B·σ at the joint is then motor_viscous·σ² (10.76 and 5.08 N·m·s/rad, §2.6).
  p.b_joint_nm_s_per_rad = motor_viscous * p.ratio * p.ratio;
  p.gear.ratio = p.ratio;
  p.gear.backlash_rad = get(gear + "backlash_rad");
  p.gear.spring_nm_per_rad = get(gear + "spring_nm_per_rad");
  p.gear.mass_kg_m2 = get(gear + "mass_kg_m2");
  p.gear.viscous_nm_s_per_rad = get(gear + "viscous_nm_s_per_rad");
  p.friction = read_friction(get, spec.name, FrictionTerms::kMotorLoad);
  p.column = motoflex_2011_column(spec.name);
  return p;
}

std::vector<ParameterSpec> defaults(const RobotModel&, std::size_t) {
  return motoflex_2011_switch_defaults();
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const Motoflex2011Params params = read_params(setup);
  try {
    return std::make_unique<Motoflex2011ServoLaw>(params, setup.dt_s, setup.gear_substeps);
  } catch (const std::invalid_argument& error) {
    // A value the stages cannot simulate: in a fit a bad candidate, not a crash.
    throw ModelError(setup.model.actuators[setup.actuator].name + ": " + error.what());
  }
}

}  // namespace

ServoLawInfo motoflex_2011_servo_law_info() {
  ServoLawInfo info{"motoflex_2011",
                    "seed 001 as the 2011 program runs it: velocity start-up, B as a frozen bias, "
                    "friction at the frozen velocity (switches motoflex_2011.*)",
                    names, create};
  info.default_parameters = defaults;
  return info;
}

}  // namespace motoflex
