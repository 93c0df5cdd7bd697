#include "firmware_servo_law.hpp"

#include <iterator>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/h_bridge_motor.hpp"
#include "motoflex/sim/actuator/position_firmware.hpp"
#include "motoflex/sim/actuator/released_friction.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "motoflex/sim/actuator/winding_heating.hpp"

namespace motoflex::detail {
namespace {

const char* const kLeaves[] = {"kp",
                               "ki",
                               "kd",
                               "kp_divisor",
                               "ki_divisor",
                               "kd_divisor",
                               "ticks_per_rev",
                               "integer_ticks",
                               "deadband_ticks",
                               "pwm_limit",
                               "pwm_full_scale",
                               "supply_v",
                               "Kt_nm_per_a",
                               "R_ohm",
                               "gear_ratio",
                               "current_limit_a",
                               "torque_off_s"};

struct FirmwareServoParams {
  PositionFirmwareParams firmware;
  HBridgeMotorParams motor;
  double torque_off_s = 1.0e9;  // log time from which the H-bridge is released
  FrictionParams friction;
  FrictionParams released_friction;  // the H-bridge off (released_friction.hpp)
  double armature_kg_m2 = 0.0;
  WindingHeatingParams winding;  // motor.winding_*: off at R_th = 0
};

class FirmwareServoLaw final : public ServoLaw {
 public:
  FirmwareServoLaw(const FirmwareServoParams& p, double dt_s)
      : params_(p),
        firmware_(p.firmware, dt_s),
        external_(friction_reads_external_torque(p.friction)),
        back_emf_damping_nm_s_per_rad_(p.motor.gear_ratio * p.motor.gear_ratio *
                                       p.motor.torque_constant_nm_per_a *
                                       p.motor.torque_constant_nm_per_a / p.motor.resistance_ohm),
        winding_(p.winding, dt_s) {}

  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    // A released H-bridge (BAM's torque_enable false) leaves the windings open: no drive, no
    // back-EMF braking (bam.md §2b); the firmware loop does not run.
    // The winding's resistance at its present temperature (winding_heating.hpp; exactly R₀
    // without heating), which then heats by this step's current.
    HBridgeMotorParams hot = params_.motor;
    if (winding_.heats()) hot.resistance_ohm *= winding_.resistance_factor();
    const bool enabled = in.elapsed_s - in.settle_s < params_.torque_off_s;
    if (enabled) {
      const double duty = firmware_.update(in.command_rad, in.angle_rad);
      const HBridgeMotorOutput motor = h_bridge_motor(hot, duty, in.rate_rad_s);
      out.torque_nm = motor.torque_nm;
      current_a_ = motor.current_a;
    } else {
      out.torque_nm = 0.0;
      current_a_ = 0.0;
    }
    winding_.advance(current_a_, hot.resistance_ohm);
    // A released joint's own Coulomb and viscous levels (released_friction.hpp).
    out.row = joint_friction(enabled ? params_.friction : params_.released_friction, in.rate_rad_s,
                             out.torque_nm, in.external_torque_nm);
    // The back-EMF term −N²K_t²/R·θ̇ of the motor torque acts through the implicit damping row at
    // the end-of-step rate: explicitly it diverges on a light link (c·h/I > 2: c = 0.4 N·m·s/rad,
    // h = 1 ms, I < 2e-4 kg·m², a small arm's wrist). Inside a current limit or with the
    // H-bridge released the offset cancels the row, as the physics wants (no back-EMF torque).
    // The row keeps the cold winding's c₀ = N²K_t²/R₀. A heated winding's torque carries the
    // smaller back-EMF term −c·θ̇₀, c = N²K_t²/R; with the offset +c₀·θ̇₀ the step applies
    // −c₀·θ̇₁ + (c₀ − c)·θ̇₀: the net damping is the hot one, and the implicit row dominates.
    out.damping_offset_nm = back_emf_damping_nm_s_per_rad_ * in.rate_rad_s;
    return out;
  }
  double damping_row_nm_s_per_rad() const override { return back_emf_damping_nm_s_per_rad_; }
  double current_a() const override { return current_a_; }
  double armature() const override { return params_.armature_kg_m2; }
  bool needs_external_torque() const override { return external_; }

 private:
  FirmwareServoParams params_;
  PositionFirmware firmware_;
  bool external_;
  double back_emf_damping_nm_s_per_rad_;  // N²·K_t²/R₀ (the cold winding)
  double current_a_ = 0.0;
  WindingTemperature winding_;  // this rollout's winding
};

}  // namespace

std::vector<std::string> firmware_law_parameter_names(const RobotModel& model,
                                                      std::size_t actuator) {
  std::vector<std::string> names = scoped_law_parameter_names(
      model.actuators[actuator], {std::begin(kLeaves), std::end(kLeaves)});
  // The released joint's friction (the effect released_friction).
  for (auto& name : released_friction_parameter_names(model.actuators[actuator])) {
    names.push_back(std::move(name));
  }
  // The winding's Joule heating (the effect winding_heating), shared by the robot's servos of
  // this law as the bench law reads it.
  names.emplace_back("motor.winding_k_per_w");
  names.emplace_back("motor.winding_heat_j_per_k");
  // The motor's torque saturation (the effect torque_saturation), shared the same way.
  names.emplace_back("motor.torque_saturation_per_a");
  return names;
}

std::unique_ptr<ServoLaw> create_firmware_law(const ServoLawSetup& setup) {
  const ActuatorSpec& spec = setup.model.actuators[setup.actuator];
  const std::string prefix = servo_parameter_prefix(spec);
  const auto get = [&](const char* leaf) { return setup.get(prefix + leaf); };
  FirmwareServoParams p;
  p.firmware.kp = get("kp");
  p.firmware.ki = get("ki");
  p.firmware.kd = get("kd");
  p.firmware.kp_divisor = get("kp_divisor");
  p.firmware.ki_divisor = get("ki_divisor");
  p.firmware.kd_divisor = get("kd_divisor");
  p.firmware.ticks_per_rev = get("ticks_per_rev");
  p.firmware.integer_ticks = get("integer_ticks") >= 0.5;
  p.firmware.deadband_ticks = get("deadband_ticks");
  p.firmware.pwm_limit = get("pwm_limit");
  p.firmware.pwm_full_scale = get("pwm_full_scale");
  p.motor.supply_v = get("supply_v");
  p.motor.torque_constant_nm_per_a = get("Kt_nm_per_a");
  p.motor.resistance_ohm = get("R_ohm");
  p.motor.gear_ratio = get("gear_ratio");
  p.motor.current_limit_a = get("current_limit_a");
  p.torque_off_s = get("torque_off_s");
  if (!(p.motor.resistance_ohm > 0.0)) throw ModelError(prefix + "R_ohm must be positive");
  if (!(p.motor.gear_ratio > 0.0) || p.motor.supply_v < 0.0 || p.motor.current_limit_a < 0.0) {
    throw ModelError(prefix + "gear_ratio must be positive, supply_v and current_limit_a >= 0");
  }
  p.friction = read_friction(setup.get, spec.name, FrictionTerms::kFamily);
  p.released_friction = released_friction(p.friction, read_released_friction(setup.get, spec));
  p.armature_kg_m2 = read_armature(setup.get, spec);
  p.winding = {setup.get("motor.winding_k_per_w"), setup.get("motor.winding_heat_j_per_k")};
  p.motor.saturation_per_a = read_torque_saturation_per_a(setup.get);
  try {
    return std::make_unique<FirmwareServoLaw>(p, setup.dt_s);
  } catch (const std::invalid_argument& error) {
    // A bad candidate in a fit, not a crash.
    throw ModelError(spec.name + ": " + error.what());
  }
}

std::vector<ParameterSpec> firmware_law_defaults(const RobotModel& model, std::size_t actuator,
                                                 const std::vector<FirmwareDefault>& vendor) {
  const std::string prefix = servo_parameter_prefix(model.actuators[actuator]);
  std::vector<ParameterSpec> specs;
  for (const FirmwareDefault& d : vendor) {
    const std::string name = prefix + d.leaf;
    specs.push_back({name, unit_from_parameter_name(name), d.value, d.lower, d.upper});
  }
  return specs;
}

}  // namespace motoflex::detail
