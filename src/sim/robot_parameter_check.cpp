#include "motoflex/sim/robot_parameter_check.hpp"

#include <set>
#include <sstream>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "resolved_parameters.hpp"

namespace motoflex {
namespace {

std::string closest_known(const std::set<std::string>& known, const std::string& name) {
  std::string hint;
  int best = 4;
  for (const auto& candidate : known) {
    const int d = edit_distance(name, candidate);
    if (d < best) {
      best = d;
      hint = candidate;
    }
  }
  return hint;
}

// Every name the laws (as `servo` assigns them) and the rollout read that the robot lacks, each
// once, naming the law that needs it.
void collect_missing(const RobotModel& model, const std::string& servo, ErrorCollector& errors,
                     const std::string& source, int line, const std::string& field,
                     const std::string& advice) {
  std::set<std::string> reported;
  const auto report = [&](const std::string& name, const std::string& who) {
    if (model.parameters.contains(name) || !reported.insert(name).second) return;
    errors.add(source, line, field, "missing '" + name + "', required by " + who + advice);
  };
  // Joints whose law is unknown (reported on its own) are skipped, the others still checked.
  bool point_mass_arm = false;
  for (std::size_t a = 0; a < model.actuators.size(); ++a) {
    const ServoLawInfo* law = find_servo_law(actuator_servo_name(model, servo, a));
    if (law == nullptr) continue;
    if (a == 0) point_mass_arm = law->point_mass_arm;
    for (const auto& name : law->parameter_names(model, a)) {
      report(name, "servo '" + law->name + "'");
    }
  }
  for (const auto& name : detail::rollout_wide_parameter_names(model, point_mass_arm)) {
    report(name, "the rollout");
  }
}

// Where robot.yaml assigns an actuator's law: its `servos:` entry, or `servo:`.
std::pair<int, std::string> law_source(const RobotModel& model, const ActuatorSpec& actuator) {
  if (!actuator.servo.empty()) {
    const auto it = model.source.servos_lines.find(actuator.servo_scope);
    if (it != model.source.servos_lines.end()) {
      return {it->second, "servos." + actuator.servo_scope};
    }
  }
  return {model.source.servo_line, "servo"};
}

// Unknown law names in the robot's assignment (robot.yaml `servo:` and `servos:`), and laws
// given joints they cannot drive (a prismatic joint under a law for revolute ones).
bool collect_unknown_laws(const RobotModel& model, const std::string& servo,
                          ErrorCollector& errors) {
  bool ok = true;
  const auto known = [&](const std::string& name, int line, const std::string& field) {
    if (find_servo_law(name) != nullptr) return true;
    ok = false;
    errors.add(model.source.yaml_path, line, field,
               "unknown servo '" + name + "' (" + servo_law_names() + ")");
    return false;
  };
  if (servo.empty()) known(model.default_servo, model.source.servo_line, "servo");
  std::string prismatic_laws;
  for (const ServoLawInfo& law : servo_laws()) {
    if (law.drives_prismatic) prismatic_laws += (prismatic_laws.empty() ? "" : "|") + law.name;
  }
  for (std::size_t a = 0; a < model.actuators.size(); ++a) {
    const ActuatorSpec& actuator = model.actuators[a];
    const std::string& name = actuator_servo_name(model, servo, a);
    const auto [line, field] = law_source(model, actuator);
    if (servo.empty() && name != model.default_servo && !known(name, line, field)) continue;
    const ServoLawInfo* law = find_servo_law(name);
    if (law == nullptr || !actuator.prismatic || law->drives_prismatic) continue;
    ok = false;
    errors.add(model.source.yaml_path, line, field,
               "joint '" + actuator.name + "' is prismatic and servo '" + name +
                   "' drives revolute joints only (prismatic: " + prismatic_laws +
                   "; assign one in `servos:`)");
  }
  return ok;
}

}  // namespace

std::vector<std::string> rollout_parameter_names(const RobotModel& model,
                                                 const std::string& servo) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  bool point_mass_arm = false;
  for (std::size_t a = 0; a < model.actuators.size(); ++a) {
    const ServoLawInfo& law = servo_law(actuator_servo_name(model, servo, a));
    if (a == 0) point_mass_arm = law.point_mass_arm;
    for (auto& name : law.parameter_names(model, a)) {
      if (seen.insert(name).second) names.push_back(std::move(name));
    }
  }
  for (auto& name : detail::rollout_wide_parameter_names(model, point_mass_arm)) {
    if (seen.insert(name).second) names.push_back(std::move(name));
  }
  return names;
}

std::set<std::string> known_parameter_names(const RobotModel& model) {
  std::set<std::string> known;
  for (const ServoLawInfo& law : servo_laws()) {
    for (auto& name : rollout_parameter_names(model, law.name)) known.insert(std::move(name));
  }
  // Flexible links are split only on request (physics.flex_sub_bodies), and contacts are
  // read only by robots with shapes that touch the ground, so their names are known either way.
  for (const char* name :
       {"flex.spring_nm_per_rad", "flex.damping_nm_s_per_rad", "flex.friction_nm", "contact.mu",
        "contact.soft_erp", "contact.soft_cfm", "contact.slip"}) {
    known.insert(name);
  }
  // The effect parameters every robot has (neutral unless declared).
  for (const auto& spec : model.parameters.specs()) {
    if (!model.source.parameter_lines.count(spec.name)) known.insert(spec.name);
  }
  return known;
}

void check_robot_parameters(const RobotModel& model, ErrorCollector& errors, bool report_unknown) {
  const std::string& file = model.source.yaml_path;
  const std::set<std::string> known = known_parameter_names(model);
  for (const auto& [name, line] : model.source.parameter_lines) {
    if (!report_unknown || known.count(name)) continue;
    const std::string hint = closest_known(known, name);
    errors.add(file, line, "parameters." + name,
               "unknown parameter" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  // A default outside the parameter's domain (a gear ratio of 0, a negative contact.mu) is a
  // model that cannot be simulated as written.
  const ParameterRegistry& registry = model.parameters;
  for (const auto& [name, line] : model.source.parameter_lines) {
    const auto index = registry.find(name);
    if (!index || registry.domain(*index).contains(registry.spec(*index).default_value)) continue;
    std::ostringstream value;
    value << registry.spec(*index).default_value;
    errors.add(file, line, "parameters." + name,
               "default " + value.str() + " is outside its domain (" +
                   registry.domain(*index).describe() + ")");
  }
  // Missing parameters are reported for the joints whose law is known even when another
  // joint's law is not (every problem of the folder at once).
  collect_unknown_laws(model, "", errors);
  collect_missing(model, "", errors, file, model.source.parameters_line, "parameters", "");
}

void check_robot_parameters(const RobotModel& model) {
  ErrorCollector errors;
  check_robot_parameters(model, errors, true);
  errors.throw_if_any();
}

void check_servo_parameters(const RobotModel& model, const std::string& servo,
                            const std::string& source, int line, const std::string& field) {
  const ServoLawInfo* law = find_servo_law(servo);
  if (law == nullptr) {
    throw InputError(source, line, field,
                     "unknown servo '" + servo + "' (" + servo_law_names() + ")");
  }
  ErrorCollector errors;
  ErrorCollector law_errors;
  if (!collect_unknown_laws(model, servo, law_errors)) {
    // The robot's joints the law cannot drive, reported where the law was chosen.
    for (const InputError& error : law_errors.errors())
      errors.add(source, line, field, error.message());
    errors.throw_if_any();
  }
  collect_missing(model, servo, errors, source, line, field,
                  " (robot '" + model.name + "' does not declare it; add it to robot.yaml)");
  errors.throw_if_any();
}

std::optional<RobotModel> load_robot(const std::string& robot_dir,
                                     const StructureOptions& structure, ErrorCollector& errors) {
  const std::size_t before = errors.size();
  std::optional<RobotModel> model = load_robot_model(robot_dir, structure, errors);
  // A declared name for a joint robot.yaml got wrong would be reported twice (the joint, then
  // each of its parameters): unknown names only count when the structure is sound.
  if (model) check_robot_parameters(*model, errors, errors.size() == before);
  return model;
}

RobotModel load_robot(const std::string& robot_dir, const StructureOptions& structure) {
  ErrorCollector errors;
  std::optional<RobotModel> model = load_robot(robot_dir, structure, errors);
  errors.throw_if_any();
  return std::move(*model);
}

}  // namespace motoflex
