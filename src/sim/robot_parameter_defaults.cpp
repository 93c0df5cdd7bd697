#include "motoflex/sim/robot_parameter_defaults.hpp"

#include <map>

#include "motoflex/sim/actuator/servo_stages.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"

namespace motoflex {
namespace {

// The rollout's own names: ground contact and world as TITAN-VIII and the pendulum bench use
// them (ODE's defaults in double precision), exact encoders, and the Nao's flexible links.
const ParameterDefault kRolloutDefaults[] = {
    {"contact.mu", 1.0, 0.1, 2.0, "ODE soft contact (TITAN-VIII, bench)"},
    {"contact.soft_erp", 0.2, 0.05, 0.9, "ODE soft contact (TITAN-VIII, bench)"},
    {"contact.soft_cfm", 1.0e-4, 1.0e-7, 1.0e-2, "ODE soft contact (TITAN-VIII, bench)"},
    {"contact.slip", 1.0e-3, 1.0e-5, 0.05, "ODE soft contact (TITAN-VIII, bench)"},
    {"world.erp", 0.2, 0.05, 0.9, "ODE default"},
    {"world.cfm", 1.0e-10, 1.0e-12, 1.0e-4, "ODE default (double precision)"},
    {"sensor.resolution_bits", 0.0, 0.0, 16.0, "exact encoder"},
    {"sensor.noise_rad", 0.0, 0.0, 0.01, "exact encoder"},
    {"sensor.delay_s", 0.0, 0.0, 0.05, "exact encoder"},
    {"flex.spring_nm_per_rad", 2006.5, 100.0, 50000.0, "Nao thighs/tibias"},
    {"flex.damping_nm_s_per_rad", 0.5, 0.001, 50.0, "Nao thighs/tibias"},
    {"flex.friction_nm", 0.0, 0.0, 10.0, "Nao thighs/tibias"},
};

}  // namespace

std::vector<ParameterDefault> robot_parameter_defaults(const RobotModel& model,
                                                       const std::string& servo,
                                                       const std::vector<JointHints>& hints) {
  std::map<std::string, ParameterDefault> offered;
  const auto offer = [&](const std::vector<ParameterDefault>& entries) {
    for (const ParameterDefault& entry : entries) offered.try_emplace(entry.name, entry);
  };
  for (std::size_t a = 0; a < model.actuators.size(); ++a) {
    const JointHints joint_hints = a < hints.size() ? hints[a] : JointHints{};
    const ServoLawInfo& law = servo_law(actuator_servo_name(model, servo, a));
    if (law.init_defaults != nullptr) {
      offer(law.init_defaults(model, a, joint_hints));
    } else if (law.default_parameters != nullptr) {
      for (const ParameterSpec& spec : law.default_parameters(model, a)) {
        offer({{spec.name, spec.default_value, spec.lower, spec.upper,
                "servo '" + law.name + "' default"}});
      }
    }
    offer(joint_friction_defaults(model.actuators[a], joint_hints));
  }
  offer({std::begin(kRolloutDefaults), std::end(kRolloutDefaults)});

  std::vector<ParameterDefault> out;
  for (const std::string& name : rollout_parameter_names(model, servo)) {
    if (const auto it = offered.find(name); it != offered.end()) {
      out.push_back(it->second);
    } else if (const auto index = model.parameters.find(name)) {
      const ParameterSpec& spec = model.parameters.spec(*index);
      out.push_back({name, spec.default_value, spec.lower, spec.upper, "neutral (model effect)"});
    } else {
      out.push_back({name, 0.0, 0.0, 1.0, kNoDefault});
    }
  }
  return out;
}

}  // namespace motoflex
