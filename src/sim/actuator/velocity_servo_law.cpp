// `servo: velocity` — seed 000's velocity-controlled joints: θ̇_d = −k_d(θ − θ_d) on the ODE
// joint motor, whose force ODE limits to τ_max (Table I). The joint motor row is the servo, so
// the joint's friction gets a second zero-velocity row beside it: both are solved together, so
// friction shows only where the servo saturates (its stall torque moves by the friction).

#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

class VelocityServoLaw final : public ServoLaw {
 public:
  VelocityServoLaw(VelocityServoParams params, FrictionParams friction, double armature_kg_m2)
      : params_(params), friction_(friction), armature_kg_m2_(armature_kg_m2) {}
  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    out.row = velocity_servo(params_, in.command_rad, in.angle_rad);
    // The servo's torque is the row's force, unknown before the step: only speed-dependent
    // friction (M1, M2) is defined here.
    out.friction_row = joint_friction(friction_, in.rate_rad_s);
    return out;
  }
  double armature_kg_m2() const override { return armature_kg_m2_; }
  // Without friction no row: robots whose joints have none step exactly as before.
  bool has_friction_row() const override {
    return friction_.coulomb_nm > 0.0 || friction_.viscous_nm_s_per_rad > 0.0 ||
           friction_.stribeck_nm > 0.0;
  }

 private:
  VelocityServoParams params_;
  FrictionParams friction_;
  double armature_kg_m2_;
};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  const std::string& name = model.actuators[actuator].name;
  const std::string joint = "joint." + name + ".";
  std::vector<std::string> out = {joint + "gain_per_s", joint + "torque_max_nm"};
  for (auto& friction : friction_parameter_names(name, FrictionTerms::kSpeedOnly)) {
    out.push_back(std::move(friction));
  }
  out.push_back(armature_parameter_name(name));
  return out;
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const std::string& name = setup.model.actuators[setup.actuator].name;
  const std::string joint = "joint." + name + ".";
  return std::make_unique<VelocityServoLaw>(
      VelocityServoParams{setup.get(joint + "gain_per_s"), setup.get(joint + "torque_max_nm")},
      read_friction(setup.get, name, FrictionTerms::kSpeedOnly),
      read_armature_kg_m2(setup.get, name));
}

}  // namespace

ServoLawInfo velocity_servo_law_info() {
  return {"velocity", "seed 000: joint motor at -k_d(q - q_d), limited to torque_max_nm", names,
          create};
}

}  // namespace motoflex
