#include "motoflex/sim/resolved_parameters.hpp"

#include <cmath>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex::detail {
namespace {

class Reader {
 public:
  Reader(const ParameterSet& values, ServoKind servo) : values_(values), servo_(servo) {}
  double operator()(const std::string& name) const {
    const auto index = values_.registry().find(name);
    if (!index) {
      throw ModelError("parameter '" + name + "' is needed by servo '" + to_string(servo_) +
                       "' but the robot does not declare it");
    }
    return values_.get(*index);
  }

 private:
  const ParameterSet& values_;
  ServoKind servo_;
};

JointFrictionParams read_friction(const Reader& get, const std::string& joint) {
  JointFrictionParams friction;
  friction.coulomb_nm = get(joint + "friction_nm");
  friction.viscous_nm_s_per_rad = get(joint + "viscous_nm_s_per_rad");
  friction.stribeck_nm = get(joint + "stribeck_nm");
  friction.stribeck_velocity_rad_s = get(joint + "stribeck_velocity_rad_s");
  friction.load_coefficient = get(joint + "load_friction");
  if (friction.coulomb_nm < 0.0 || friction.viscous_nm_s_per_rad < 0.0 ||
      friction.stribeck_nm < 0.0 || !(friction.stribeck_velocity_rad_s > 0.0) ||
      friction.load_coefficient < 0.0) {
    throw ModelError("friction parameters of " + joint + "* must not be negative (" + joint +
                     "stribeck_velocity_rad_s > 0)");
  }
  return friction;
}

bool has_flex_joints(const RobotModel& model) {
  for (const auto& j : model.joints) {
    if (j.kind == JointKind::kFlex) return true;
  }
  return false;
}

}  // namespace

ResolvedParameters resolve_parameters(const RobotModel& model, const ParameterSet& values,
                                      ServoKind servo) {
  const Reader get(values, servo);
  ResolvedParameters out;
  out.actuators.resize(model.actuators.size());
  for (std::size_t i = 0; i < model.actuators.size(); ++i) {
    const ActuatorSpec& spec = model.actuators[i];
    ActuatorParameters& a = out.actuators[i];
    const std::string joint = "joint." + spec.name + ".";
    switch (servo) {
      case ServoKind::kMotoflex: {
        a.pid = {get("pid.kp_v_per_rad"), get("pid.ki_v_per_rad_s"), get("pid.kd_v_s_per_rad")};
        a.motor.supply_v = get("motor.supply_v");
        a.motor.resistance_ohm = get("motor.R_ohm");
        a.motor.inductance_h = get("motor.L_h");
        a.motor.torque_constant_nm_per_a = get("motor.Kt_nm_per_a");
        a.motor.stiffness = get("motor.stiffness");
        const std::string gear = "gear." + spec.group + ".";
        a.motor.viscous_nm_s_per_rad = get(gear + "motor_viscous_nm_s_per_rad");
        a.gear.ratio = get(gear + "ratio");
        a.gear.backlash_rad = get(gear + "backlash_rad");
        a.gear.spring_nm_per_rad = get(gear + "spring_nm_per_rad");
        a.gear.mass_kg_m2 = get(gear + "mass_kg_m2");
        a.gear.viscous_nm_s_per_rad = get(gear + "viscous_nm_s_per_rad");
        a.friction = read_friction(get, joint);
        // Algorithm 1's B·ω_m reaches the joint as B·σ²·ω. Applied as an explicit torque it is
        // unstable at 1 ms on light links (B·σ²·dt/I > 2 at the Nao's ankles), so the rollout
        // integrates it implicitly: a zero-velocity motor row with unbounded force and
        // CFM = 1/(B·σ²), ODE's damper equivalence. The motor itself then sees no speed term.
        a.back_emf_damping_nm_s_per_rad =
            a.motor.viscous_nm_s_per_rad * a.gear.ratio * a.gear.ratio;
        a.motor.viscous_nm_s_per_rad = 0.0;
        break;
      }
      case ServoKind::kVelocity:
        a.velocity = {get(joint + "gain_per_s"), get(joint + "torque_max_nm")};
        break;
      case ServoKind::kIdeal:
        break;
      case ServoKind::kBench:
        a.bench.kp = get("bench.kp");
        a.bench.error_gain = get("bench.error_gain");
        a.bench.max_duty = get("bench.max_duty");
        a.bench.supply_v = get("bench.supply_v");
        a.bench.torque_constant_nm_per_a = get("bench.Kt_nm_per_a");
        a.bench.resistance_ohm = get("bench.R_ohm");
        a.bench.torque_off_s = get("bench.torque_off_s");
        a.friction = read_friction(get, joint);
        break;
    }
    a.encoder_scale = get(joint + "encoder_scale");
    a.encoder_offset_rad = get(joint + "encoder_offset_rad");
  }
  if (servo == ServoKind::kIdeal) out.ideal.torque_max_nm = get("ideal.torque_max_nm");
  if (servo == ServoKind::kMotoflex || servo == ServoKind::kBench) {
    out.motor_resistance_drift_per_s = get("motor.R_drift_per_s");
    out.supply_sag_ohm = get("motor.supply_sag_ohm");
    if (out.supply_sag_ohm < 0.0) throw ModelError("motor.supply_sag_ohm must not be negative");
  }
  if (servo == ServoKind::kBench) {
    out.bench_load = {get("bench.mass_kg"), get("bench.length_m"), get("bench.armature_kg_m2")};
    if (!(out.bench_load.mass_kg > 0.0) || !(out.bench_load.length_m > 0.0) ||
        out.bench_load.armature_kg_m2 < 0.0) {
      throw ModelError("bench mass and length must be positive, armature not negative");
    }
  }
  if (has_flex_joints(model)) {
    out.flex = {get("flex.spring_nm_per_rad"), get("flex.damping_nm_s_per_rad"),
                get("flex.friction_nm")};
    if (!(out.flex.spring_nm_per_rad > 0.0) || out.flex.damping_nm_s_per_rad < 0.0 ||
        out.flex.friction_nm < 0.0) {
      throw ModelError("flex.spring_nm_per_rad must be positive, damping and friction >= 0");
    }
  }
  out.contact = {get("contact.mu"), get("contact.soft_erp"), get("contact.soft_cfm"),
                 get("contact.slip")};
  out.world_erp = get("world.erp");
  out.world_cfm = get("world.cfm");
  out.encoder.resolution_bits = static_cast<int>(std::lround(get("sensor.resolution_bits")));
  out.encoder.noise_rad = get("sensor.noise_rad");
  out.encoder.delay_s = get("sensor.delay_s");
  return out;
}

}  // namespace motoflex::detail
