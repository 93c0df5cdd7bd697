// `servo: ideal` — a position servo that reaches the next commanded angle in one physics step,
// within a torque limit (the rigid reference runs of seed 001 and the exporters' "ideal" mode).
// No joint friction: the servo overrides it by definition. The armature shows when the torque
// limit is reached.

#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

class IdealServoLaw final : public ServoLaw {
 public:
  IdealServoLaw(IdealServoParams params, double dt_s, double armature)
      : params_(params), dt_s_(dt_s), armature_(armature) {}
  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    out.row = ideal_servo(params_, in.next_command_rad, in.angle_rad, dt_s_);
    return out;
  }
  double armature() const override { return armature_; }  // kg·m², kg on a slider

 private:
  IdealServoParams params_;
  double dt_s_;
  double armature_;
};

// One robot-wide limit per kind of joint: a torque for hinges, a force for sliders.
std::string limit_name(const RobotModel& model, std::size_t actuator) {
  return model.actuators[actuator].prismatic ? "ideal.force_max_n" : "ideal.torque_max_nm";
}

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  return {limit_name(model, actuator), armature_parameter_name(model.actuators[actuator])};
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  return std::make_unique<IdealServoLaw>(
      IdealServoParams{setup.get(limit_name(setup.model, setup.actuator))}, setup.dt_s,
      read_armature(setup.get, setup.model.actuators[setup.actuator]));
}

// TITAN-VIII's and the Nao's reference runs use 100 and 20 N·m; a stiff reference servo
// should not be the limit, so the larger.
std::vector<ParameterDefault> defaults(const RobotModel& model, std::size_t actuator,
                                       const JointHints&) {
  if (model.actuators[actuator].prismatic) {
    return {{"ideal.force_max_n", 1000.0, 10.0, 10000.0, "reference servo, 1 kN"}};
  }
  return {{"ideal.torque_max_nm", 100.0, 10.0, 1000.0, "TITAN-VIII reference runs"}};
}

}  // namespace

ServoLawInfo ideal_servo_law_info() {
  ServoLawInfo info{"ideal", "reaches the next commanded angle in one step, torque-limited", names,
                    create};
  info.drives_prismatic = true;
  info.init_defaults = defaults;
  return info;
}

}  // namespace motoflex
