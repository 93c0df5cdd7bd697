// `servo: ideal` — a position servo that reaches the next commanded angle in one physics step,
// within a torque limit (the rigid reference runs of seed 001 and the exporters' "ideal" mode).
// No joint friction: the servo overrides it by definition. The armature shows when the torque
// limit is reached.

#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

class IdealServoLaw final : public ServoLaw {
 public:
  IdealServoLaw(IdealServoParams params, double dt_s, double armature_kg_m2)
      : params_(params), dt_s_(dt_s), armature_kg_m2_(armature_kg_m2) {}
  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    out.row = ideal_servo(params_, in.next_command_rad, in.angle_rad, dt_s_);
    return out;
  }
  double armature_kg_m2() const override { return armature_kg_m2_; }

 private:
  IdealServoParams params_;
  double dt_s_;
  double armature_kg_m2_;
};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  return {"ideal.torque_max_nm", armature_parameter_name(model.actuators[actuator].name)};
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  return std::make_unique<IdealServoLaw>(
      IdealServoParams{setup.get("ideal.torque_max_nm")}, setup.dt_s,
      read_armature_kg_m2(setup.get, setup.model.actuators[setup.actuator].name));
}

}  // namespace

ServoLawInfo ideal_servo_law_info() {
  return {"ideal", "reaches the next commanded angle in one step, torque-limited", names, create};
}

}  // namespace motoflex
