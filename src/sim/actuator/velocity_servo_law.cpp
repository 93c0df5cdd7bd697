// `servo: velocity` — seed 000's velocity-controlled joints: θ̇_d = −k_d(θ − θ_d) on the ODE
// joint motor, whose force ODE limits to τ_max (Table I).

#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

class VelocityServoLaw final : public ServoLaw {
 public:
  explicit VelocityServoLaw(VelocityServoParams params) : params_(params) {}
  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    out.row = velocity_servo(params_, in.command_rad, in.angle_rad);
    return out;
  }

 private:
  VelocityServoParams params_;
};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  const std::string joint = "joint." + model.actuators[actuator].name + ".";
  return {joint + "gain_per_s", joint + "torque_max_nm"};
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const std::string joint = "joint." + setup.model.actuators[setup.actuator].name + ".";
  return std::make_unique<VelocityServoLaw>(
      VelocityServoParams{setup.get(joint + "gain_per_s"), setup.get(joint + "torque_max_nm")});
}

}  // namespace

ServoLawInfo velocity_servo_law_info() {
  return {"velocity", "seed 000: joint motor at -k_d(q - q_d), limited to torque_max_nm", names,
          create};
}

}  // namespace motoflex
