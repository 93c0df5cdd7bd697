#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

// Each law's file defines its entry; adding a law is its file plus one line in each list below.
ServoLawInfo motoflex_servo_law_info();
ServoLawInfo motoflex_2011_servo_law_info();
ServoLawInfo velocity_servo_law_info();
ServoLawInfo ideal_servo_law_info();
ServoLawInfo bench_servo_law_info();
ServoLawInfo pd_torque_servo_law_info();
ServoLawInfo dynamixel_servo_law_info();
ServoLawInfo feetech_servo_law_info();

const std::vector<ServoLawInfo>& servo_laws() {
  static const std::vector<ServoLawInfo> laws = {
      motoflex_servo_law_info(),  motoflex_2011_servo_law_info(), velocity_servo_law_info(),
      ideal_servo_law_info(),     bench_servo_law_info(),         pd_torque_servo_law_info(),
      dynamixel_servo_law_info(), feetech_servo_law_info(),
  };
  return laws;
}

const ServoLawInfo* find_servo_law(const std::string& name) {
  for (const ServoLawInfo& law : servo_laws()) {
    if (law.name == name) return &law;
  }
  return nullptr;
}

std::string servo_law_names() {
  std::string names;
  for (const ServoLawInfo& law : servo_laws()) names += (names.empty() ? "" : "|") + law.name;
  return names;
}

const ServoLawInfo& servo_law(const std::string& name) {
  if (const ServoLawInfo* law = find_servo_law(name)) return *law;
  throw std::invalid_argument("unknown servo '" + name + "' (" + servo_law_names() + ")");
}

const std::string& actuator_servo_name(const RobotModel& model, const std::string& override_servo,
                                       std::size_t actuator) {
  if (!override_servo.empty()) return override_servo;
  const std::string& own = model.actuators.at(actuator).servo;
  return own.empty() ? model.default_servo : own;
}

std::vector<std::string> add_servo_law_defaults(RobotModel& model,
                                                const std::string& override_servo) {
  std::vector<std::string> added;
  for (std::size_t a = 0; a < model.actuators.size(); ++a) {
    const ServoLawInfo& law = servo_law(actuator_servo_name(model, override_servo, a));
    if (law.default_parameters == nullptr) continue;
    for (ParameterSpec& spec : law.default_parameters(model, a)) {
      if (model.parameters.contains(spec.name)) continue;
      added.push_back(spec.name);
      model.parameters.add(std::move(spec));
    }
  }
  return added;
}

double ParameterReader::operator()(const std::string& name) const {
  const auto index = values_.registry().find(name);
  if (!index) {
    throw ModelError("parameter '" + name + "' is needed by servo '" + law_ +
                     "' but the robot does not declare it");
  }
  return values_.get(*index);
}

}  // namespace motoflex
