// `servo: motoflex` — seed 001's actuator pipeline with physical semantics: voltage PID →
// DC motor (supply clamp, RL lag, K_t, stiffness) → gear train (ratio, backlash hull, spring,
// gear mass, viscous term; sub-stepped) → joint torque, dry friction as a zero-velocity motor
// row, and the motor's B·ω_m as an implicit joint damper B·σ².

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/actuator/dc_motor.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/gear_train.hpp"
#include "motoflex/sim/actuator/pid.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

struct MotoflexServoParams {
  PidGains pid;
  DcMotorParams motor;
  GearParams gear;
  FrictionParams friction;
  double armature_kg_m2 = 0.0;                 // reflected rotor inertia, the rollout's inertia row
  double back_emf_damping_nm_s_per_rad = 0.0;  // B·σ², applied by the rollout's damper row
  // Robot-wide motor effects: R(t) = R·(1 + drift·t) as the windings heat up, and a battery
  // with internal resistance: U_bat(t) = U_bat − R_int·Σ|I| over all motors.
  double resistance_drift_per_s = 0.0;
  double supply_sag_ohm = 0.0;
};

class MotoflexServoLaw final : public ServoLaw {
 public:
  MotoflexServoLaw(const MotoflexServoParams& p, double dt_s, int gear_substeps)
      : params_(p),
        pid_(p.pid, dt_s),
        motor_(p.motor, dt_s),
        gear_(p.gear, dt_s, gear_substeps),
        operating_point_varies_(p.resistance_drift_per_s != 0.0 || p.supply_sag_ohm != 0.0) {}

  ServoOutput step(const ServoInput& in) override {
    if (operating_point_varies_) {
      const double supply_now_v =
          std::max(0.0, params_.motor.supply_v - params_.supply_sag_ohm * in.total_current_a);
      const double resistance_scale =
          std::max(1e-3, 1.0 + params_.resistance_drift_per_s * in.elapsed_s);
      motor_.set_operating_point(supply_now_v, params_.motor.resistance_ohm * resistance_scale);
    }
    // seed 001, Algorithm 1 (PID → clamp → RL → K_t) then Algorithm 2 (gear).
    const double volts = pid_.update(in.command_rad - in.angle_rad);
    const double motor_torque_nm = motor_.update(volts, in.rate_rad_s * params_.gear.ratio);
    ServoOutput out;
    out.torque_nm = gear_.update(motor_torque_nm);
    out.row = joint_friction(params_.friction, in.rate_rad_s, out.torque_nm);
    return out;
  }
  double damping_row_nm_s_per_rad() const override { return params_.back_emf_damping_nm_s_per_rad; }
  double current_a() const override { return motor_.current_a(); }
  double armature() const override { return params_.armature_kg_m2; }

 private:
  MotoflexServoParams params_;
  Pid pid_;
  DcMotor motor_;
  GearTrain gear_;
  bool operating_point_varies_;
};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  const ActuatorSpec& spec = model.actuators[actuator];
  std::vector<std::string> out = motoflex_pipeline_parameter_names(spec);
  out.push_back(armature_parameter_name(spec));
  out.emplace_back("motor.R_drift_per_s");
  out.emplace_back("motor.supply_sag_ohm");
  return out;
}

MotoflexServoParams read_params(const ServoLawSetup& setup) {
  const ParameterReader& get = setup.get;
  const ActuatorSpec& spec = setup.model.actuators[setup.actuator];
  MotoflexServoParams p;
  p.pid = {get("pid.kp_v_per_rad"), get("pid.ki_v_per_rad_s"), get("pid.kd_v_s_per_rad")};
  p.motor.supply_v = get("motor.supply_v");
  p.motor.resistance_ohm = get("motor.R_ohm");
  p.motor.inductance_h = get("motor.L_h");
  p.motor.torque_constant_nm_per_a = get("motor.Kt_nm_per_a");
  p.motor.stiffness = get("motor.stiffness");
  const std::string gear = "gear." + spec.group + ".";
  const double motor_viscous = get(gear + "motor_viscous_nm_s_per_rad");
  p.gear.ratio = get(gear + "ratio");
  p.gear.backlash_rad = get(gear + "backlash_rad");
  p.gear.spring_nm_per_rad = get(gear + "spring_nm_per_rad");
  p.gear.mass_kg_m2 = get(gear + "mass_kg_m2");
  p.gear.viscous_nm_s_per_rad = get(gear + "viscous_nm_s_per_rad");
  p.friction = read_friction(get, spec.name, FrictionTerms::kMotorLoad);
  p.armature_kg_m2 = read_armature(get, spec);
  // Algorithm 1's B·ω_m reaches the joint as B·σ²·ω. Applied as an explicit torque it is
  // unstable at 1 ms on light links (B·σ²·dt/I > 2 at the Nao's ankles), so the rollout
  // integrates it implicitly: a zero-velocity motor row with unbounded force and
  // CFM = 1/(B·σ²), ODE's damper equivalence. The motor itself then sees no speed term.
  if (motor_viscous < 0.0) throw ModelError(gear + "motor_viscous_nm_s_per_rad must be >= 0");
  p.back_emf_damping_nm_s_per_rad = motor_viscous * p.gear.ratio * p.gear.ratio;
  p.motor.viscous_nm_s_per_rad = 0.0;
  p.resistance_drift_per_s = get("motor.R_drift_per_s");
  p.supply_sag_ohm = get("motor.supply_sag_ohm");
  if (p.supply_sag_ohm < 0.0) throw ModelError("motor.supply_sag_ohm must not be negative");
  return p;
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const MotoflexServoParams params = read_params(setup);
  try {
    return std::make_unique<MotoflexServoLaw>(params, setup.dt_s, setup.gear_substeps);
  } catch (const std::invalid_argument& error) {
    // The stages reject values they cannot simulate (R <= 0, a negative backlash, ...); in a
    // fit that is a bad candidate, not a crash.
    throw ModelError(setup.model.actuators[setup.actuator].name + ": " + error.what());
  }
}

// The Nao's values (scenarios/robots/nao, MoToFlex's RE-Max 24 and its pitch gear B).
std::vector<ParameterDefault> defaults(const RobotModel& model, std::size_t actuator,
                                       const JointHints&) {
  const std::string gear = "gear." + model.actuators[actuator].group + ".";
  const std::string nao = "Nao (scenarios/robots/nao)";
  return {{"pid.kp_v_per_rad", 319.47, 30.0, 3000.0, nao},
          {"pid.ki_v_per_rad_s", 14.19, 0.1, 1000.0, nao},
          {"pid.kd_v_s_per_rad", 0.1636, 0.001, 2.0, nao},
          {"motor.supply_v", 21.6, 18.0, 25.2, nao},
          {"motor.R_ohm", 6.44, 2.0, 20.0, nao},
          {"motor.L_h", 3.09e-4, 3.0e-5, 3.0e-3, nao},
          {"motor.Kt_nm_per_a", 0.0195, 0.008, 0.05, nao},
          {"motor.stiffness", 0.7, 0.1, 1.0, nao},
          {gear + "ratio", 130.85, 10.0, 1000.0, nao + ", gear B"},
          {gear + "motor_viscous_nm_s_per_rad", 2.9675e-4, 2.9675e-5, 2.9675e-3, nao + ", gear B"},
          {gear + "backlash_rad", 1.051e-5, 1.0e-7, 0.05, nao + ", gear B"},
          {gear + "spring_nm_per_rad", 1.7995e+7, 1.0e+4, 1.7995e+8, nao + ", gear B"},
          {gear + "mass_kg_m2", 1.1037e-3, 1.0e-4, 1.0e-2, nao + ", gear B"},
          {gear + "viscous_nm_s_per_rad", 0.10897, 1.0e-3, 1000.0, nao + ", gear B"}};
}

}  // namespace

ServoLawInfo motoflex_servo_law_info() {
  ServoLawInfo info{"motoflex",
                    "seed 001: PID -> DC motor -> gear train (backlash, spring) -> joint, dry "
                    "friction",
                    names, create};
  info.init_defaults = defaults;
  return info;
}

}  // namespace motoflex
