// `servo: velocity` — seed 000's velocity-controlled joints: θ̇_d = −k_d(θ − θ_d) on the ODE
// joint motor, whose force ODE limits to τ_max (Table I). The joint motor row is the servo, so
// the joint's friction gets a second zero-velocity row beside it: both are solved together, so
// friction shows only where the servo saturates (its stall torque moves by the friction). On a
// prismatic joint the same law in m and N (force_max_n).

#include <cmath>

#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

class VelocityServoLaw final : public ServoLaw {
 public:
  VelocityServoLaw(VelocityServoParams params, FrictionParams friction, double armature)
      : params_(params), friction_(friction), armature_(armature) {}
  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    out.row = velocity_servo(params_, in.command_rad, in.angle_rad);
    // The servo's torque is the row's force, unknown before the step: only speed-dependent
    // friction (M1, M2) is defined here.
    out.friction_row = joint_friction(friction_, in.rate_rad_s);
    return out;
  }
  double armature() const override { return armature_; }  // kg·m², kg on a slider
  // Without friction no row: robots whose joints have none step exactly as before.
  bool has_friction_row() const override {
    return friction_.coulomb_nm > 0.0 || friction_.viscous_nm_s_per_rad > 0.0 ||
           friction_.stribeck_nm > 0.0;
  }

 private:
  VelocityServoParams params_;
  FrictionParams friction_;
  double armature_;
};

std::string limit_name(const ActuatorSpec& a) {
  return "joint." + a.name + (a.prismatic ? ".force_max_n" : ".torque_max_nm");
}

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  const ActuatorSpec& a = model.actuators[actuator];
  std::vector<std::string> out = {"joint." + a.name + ".gain_per_s", limit_name(a)};
  for (auto& friction : friction_parameter_names(a, FrictionTerms::kSpeedOnly)) {
    out.push_back(std::move(friction));
  }
  out.push_back(armature_parameter_name(a));
  return out;
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const ActuatorSpec& a = setup.model.actuators[setup.actuator];
  return std::make_unique<VelocityServoLaw>(
      VelocityServoParams{setup.get("joint." + a.name + ".gain_per_s"), setup.get(limit_name(a))},
      read_friction(setup.get, a, FrictionTerms::kSpeedOnly), read_armature(setup.get, a));
}

// Gains from TITAN-VIII (seed 000 Table I); the limit is the URDF's effort when it has one.
std::vector<ParameterDefault> defaults(const RobotModel& model, std::size_t actuator,
                                       const JointHints& hints) {
  const ActuatorSpec& a = model.actuators[actuator];
  ParameterDefault limit{limit_name(a), a.prismatic ? 100.0 : 10.0, a.prismatic ? 10.0 : 1.0,
                         a.prismatic ? 1000.0 : 100.0, "no effort in the URDF"};
  if (std::isfinite(hints.effort) && hints.effort > 0.0) {
    limit = {limit.name, hints.effort, 0.1 * hints.effort, 10.0 * hints.effort, "URDF effort"};
  }
  return {{"joint." + a.name + ".gain_per_s", 4.0, 0.4, 40.0, "TITAN-VIII (seed 000 Table I)"},
          limit};
}

}  // namespace

ServoLawInfo velocity_servo_law_info() {
  ServoLawInfo info{"velocity", "seed 000: joint motor at -k_d(q - q_d), limited to torque_max_nm",
                    names, create};
  info.drives_prismatic = true;
  info.init_defaults = defaults;
  return info;
}

}  // namespace motoflex
