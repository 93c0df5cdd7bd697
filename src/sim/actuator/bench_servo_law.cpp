// `servo: bench` — the pendulum bench's voltage-controlled P servo (Dynamixel-style firmware,
// BAM eq. 12–13) with joint friction as a motor row, and the arm as a point mass (see
// ServoLawInfo::point_mass_arm).

#include <cmath>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/released_friction.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "motoflex/sim/actuator/winding_heating.hpp"

namespace motoflex {
namespace {

class BenchServoLaw final : public ServoLaw {
 public:
  BenchServoLaw(BenchServoParams params, FrictionParams friction, FrictionParams released,
                double drift_per_s, bool logged_supply, WindingTemperature winding, double dt_s)
      : params_(params),
        friction_(friction),
        released_friction_(released),
        resistance_drift_per_s_(drift_per_s),
        logged_supply_(logged_supply),
        external_(friction_reads_external_torque(friction)),
        winding_(winding),
        dt_s_(dt_s) {}

  ServoOutput step(const ServoInput& in) override {
    BenchServoParams bench = params_;
    bench.resistance_ohm *= 1.0 + resistance_drift_per_s_ * in.elapsed_s;
    // The supply the servo measured (a log's supply_v column) rather than the nominal one: a
    // 7.4 V pack reads 6.3-9.2 V over one XL330 log as the current swings.
    if (logged_supply_ && std::isfinite(in.logged_supply_v)) bench.supply_v = in.logged_supply_v;
    // A released H-bridge (BAM lift_and_drop): no drive and no back-EMF braking.
    const bool enabled = in.elapsed_s - in.settle_s < bench.torque_off_s;
    if (winding_.heats()) bench.resistance_ohm *= winding_.resistance_factor();
    ServoOutput out;
    // The goal's rate over this step, for a PD firmware's ė (only read when bench.derivative_s
    // is not 0; the rollout has checked dt_s > 0).
    const double command_rate_rad_s =
        bench.derivative_s != 0.0 ? (in.next_command_rad - in.command_rad) / dt_s_ : 0.0;
    const BenchServoOutput motor = bench_servo_output(bench, in.command_rad, in.angle_rad,
                                                      in.rate_rad_s, enabled, command_rate_rad_s);
    out.torque_nm = motor.torque_nm;
    // The winding heats with its current (none through a released bridge).
    winding_.advance(motor.current_a, bench.resistance_ohm);
    // A released joint's own Coulomb and viscous levels (released_friction.hpp).
    out.row = joint_friction(enabled ? friction_ : released_friction_, in.rate_rad_s, out.torque_nm,
                             in.external_torque_nm);
    return out;
  }
  // BAM's M3–M6 load terms read the gravity torque of the arm (τ_e); M1, M2 and the motor-load
  // term alone do not, and then the rollout does not compute it.
  bool needs_external_torque() const override { return external_; }

 private:
  BenchServoParams params_;
  FrictionParams friction_;
  FrictionParams released_friction_;  // the H-bridge off (released_friction.hpp)
  double resistance_drift_per_s_;
  bool logged_supply_;
  bool external_;
  WindingTemperature winding_;  // this rollout's winding
  double dt_s_;                 // the physics step
};

const char* const kBenchNames[] = {
    "bench.kp",          "bench.error_gain",   "bench.max_duty",       "bench.supply_v",
    "bench.Kt_nm_per_a", "bench.R_ohm",        "bench.armature_kg_m2", "bench.mass_kg",
    "bench.length_m",    "bench.torque_off_s", "bench.logged_supply"};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  std::vector<std::string> out(std::begin(kBenchNames), std::end(kBenchNames));
  // BAM's friction family M1–M6 (friction_family.hpp; at the defaults, friction_model 6 with the
  // external and quadratic coefficients 0, the Coulomb, viscous, Stribeck, K_m·|τ_m| budget the
  // bench always had, bit for bit); the arm's point mass carries the armature
  // (bench.armature_kg_m2), so joint.<J>.armature_kg_m2 is not read.
  for (auto& name :
       friction_parameter_names(model.actuators[actuator].name, FrictionTerms::kFamily)) {
    out.push_back(std::move(name));
  }
  for (auto& name : released_friction_parameter_names(model.actuators[actuator])) {
    out.push_back(std::move(name));
  }
  out.emplace_back("motor.R_drift_per_s");
  out.emplace_back("motor.current_limit_a");
  out.emplace_back("motor.torque_saturation_per_a");
  out.emplace_back("motor.winding_k_per_w");
  out.emplace_back("motor.winding_heat_j_per_k");
  out.emplace_back("motor.housing_temperature_c");
  out.emplace_back("motor.R_temperature_per_k");
  out.emplace_back("bench.derivative_s");
  return out;
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const ParameterReader& get = setup.get;
  BenchServoParams bench;
  bench.kp = get("bench.kp");
  bench.error_gain = get("bench.error_gain");
  bench.max_duty = get("bench.max_duty");
  bench.supply_v = get("bench.supply_v");
  bench.torque_constant_nm_per_a = get("bench.Kt_nm_per_a");
  bench.resistance_ohm = get("bench.R_ohm");
  bench.torque_off_s = get("bench.torque_off_s");
  bench.current_limit_a = get("motor.current_limit_a");
  if (!(bench.current_limit_a > 0.0)) throw ModelError("motor.current_limit_a must be positive");
  bench.saturation_per_a = read_torque_saturation_per_a(get);
  if (!(bench.resistance_ohm > 0.0)) throw ModelError("bench.R_ohm must be positive");
  // A log's housing temperature (its sidecar's motor.housing_temperature_c, the servo's own
  // reading) scales the winding's resistance from its value at kResistanceReferenceC:
  // R(T) = R_ref·(1 + α·(T − T_ref)), α = motor.R_temperature_per_k (copper's 0.00393 /K when
  // the reading is the winding's; 0, the default: bench.R_ohm whatever the temperature).
  const double r_per_k = get("motor.R_temperature_per_k");
  if (r_per_k != 0.0) {
    bench.resistance_ohm *=
        1.0 + r_per_k * (get("motor.housing_temperature_c") - kResistanceReferenceC);
    if (!(bench.resistance_ohm > 0.0)) {
      throw ModelError(
          "motor.R_temperature_per_k and motor.housing_temperature_c leave no positive winding "
          "resistance");
    }
  }
  if (bench.max_duty < 0.0) throw ModelError("bench.max_duty must not be negative");
  // A PD firmware's derivative time (the effect servo_derivative; 0, the default: P only).
  bench.derivative_s = get("bench.derivative_s");
  if (!(bench.derivative_s >= 0.0)) throw ModelError("bench.derivative_s must not be negative");
  const ActuatorSpec& joint = setup.model.actuators[setup.actuator];
  const FrictionParams friction = read_friction(get, joint.name, FrictionTerms::kFamily);
  const FrictionParams released = released_friction(friction, read_released_friction(get, joint));
  const double logged_supply = get("bench.logged_supply");
  if (logged_supply != 0.0 && logged_supply != 1.0) {
    throw ModelError("bench.logged_supply must be 0 (nominal bench.supply_v) or 1 (the log's)");
  }
  const WindingTemperature winding(
      {get("motor.winding_k_per_w"), get("motor.winding_heat_j_per_k")}, setup.dt_s);
  return std::make_unique<BenchServoLaw>(bench, friction, released, get("motor.R_drift_per_s"),
                                         logged_supply == 1.0, winding, setup.dt_s);
}

// The XL330 bench (scenarios/robots/servo_pendulum).
std::vector<ParameterDefault> defaults(const RobotModel&, std::size_t, const JointHints&) {
  const std::string xl330 = "XL330 bench (scenarios/robots/servo_pendulum)";
  return {{"bench.kp", 400.0, 1.0, 2000.0, xl330},
          {"bench.error_gain", 0.0028774, 0.00284, 0.00292, xl330},
          {"bench.max_duty", 1.0, 0.5, 1.0, xl330},
          {"bench.supply_v", 7.4, 5.0, 13.0, xl330},
          {"bench.Kt_nm_per_a", 0.6, 0.1, 3.0, xl330},
          {"bench.R_ohm", 2.6, 1.0, 6.0, xl330},
          {"bench.armature_kg_m2", 0.005, 1.0e-4, 0.05, xl330},
          {"bench.mass_kg", 0.49, 0.01, 5.0, xl330},
          {"bench.length_m", 0.1, 0.01, 0.5, xl330},
          {"bench.torque_off_s", 1.0e9, 0.0, 1.0e9, xl330},
          // 1: drive from the log's supply_v column when it has one; 0: bench.supply_v always.
          {"bench.logged_supply", 1.0, 0.0, 1.0, xl330}};
}

}  // namespace

ServoLawInfo bench_servo_law_info() {
  ServoLawInfo info{"bench", "the pendulum bench's voltage P servo (BAM eq. 12-13)", names, create};
  info.point_mass_arm = true;
  info.init_defaults = defaults;
  return info;
}

}  // namespace motoflex
