// `servo: velocity` — seed 000's velocity-controlled joints: θ̇_d = −k_d(θ − θ_d) on the ODE
// joint motor, whose force ODE limits to τ_max (Table I). On a prismatic joint the same law
// in m and N (force_max_n).

#include <cmath>

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

std::string limit_name(const ActuatorSpec& a) {
  return "joint." + a.name + (a.prismatic ? ".force_max_n" : ".torque_max_nm");
}

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  const ActuatorSpec& a = model.actuators[actuator];
  return {"joint." + a.name + ".gain_per_s", limit_name(a)};
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const ActuatorSpec& a = setup.model.actuators[setup.actuator];
  return std::make_unique<VelocityServoLaw>(
      VelocityServoParams{setup.get("joint." + a.name + ".gain_per_s"), setup.get(limit_name(a))});
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
  info.default_parameters = defaults;
  return info;
}

}  // namespace motoflex
