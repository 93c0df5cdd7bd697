// `servo: ideal` — a position servo that reaches the next commanded angle in one physics step,
// within a torque limit (the rigid reference runs of seed 001 and the exporters' "ideal" mode).

#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

class IdealServoLaw final : public ServoLaw {
 public:
  IdealServoLaw(IdealServoParams params, double dt_s) : params_(params), dt_s_(dt_s) {}
  ServoOutput step(const ServoInput& in) override {
    ServoOutput out;
    out.row = ideal_servo(params_, in.next_command_rad, in.angle_rad, dt_s_);
    return out;
  }

 private:
  IdealServoParams params_;
  double dt_s_;
};

std::vector<std::string> names(const RobotModel&, std::size_t) {
  return {"ideal.torque_max_nm"};
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  return std::make_unique<IdealServoLaw>(IdealServoParams{setup.get("ideal.torque_max_nm")},
                                         setup.dt_s);
}

}  // namespace

ServoLawInfo ideal_servo_law_info() {
  return {"ideal", "reaches the next commanded angle in one step, torque-limited", names, create};
}

}  // namespace motoflex
