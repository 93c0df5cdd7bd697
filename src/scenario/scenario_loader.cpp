#include <filesystem>

#include "motoflex/core/error.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/motion/log_commands.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "scenario_motion.hpp"
#include "scenario_physics.hpp"

namespace motoflex {
namespace {

// The robot: the scenario's `robot:`, or the overrides' (a truth file's, resolved against that
// file).
std::shared_ptr<const RobotModel> read_robot(const YamlValue& root,
                                             const StructureOptions& structure,
                                             const ScenarioOverrides& overrides) {
  const YamlValue robot_field = overrides.robot ? *overrides.robot : root.at("robot");
  const std::string robot_dir = robot_field.resolve_path(robot_field.as_string());
  if (!std::filesystem::exists(std::filesystem::path(robot_dir) / "robot.yaml")) {
    robot_field.fail("no robot.yaml in '" + robot_dir + "'");
  }
  return std::make_shared<RobotModel>(load_robot(robot_dir, structure));
}

// The servo law: the robot's, the scenario's `servo:`, or the command line's.
std::string read_servo(const YamlValue& root, const RobotModel& model,
                       const ScenarioOverrides& overrides) {
  std::string servo = model.default_servo;
  if (const auto field = root.find("servo")) {
    servo = field->as_string();
    check_servo_parameters(model, servo, root.file(), field->line(), "servo");
  }
  if (overrides.servo) {
    servo = *overrides.servo;
    check_servo_parameters(model, servo, "", 0, "--servo");
  }
  return servo;
}

void read_parameters(const YamlValue& parameters, ParameterSet& set) {
  ErrorCollector errors;
  for (const auto& [name, value] : parameters.entries()) {
    errors.check([&, &name = name, &value = value] {
      if (!set.registry().contains(name)) {
        const std::string hint = set.registry().closest_name(name);
        value.fail("unknown parameter" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      set.set(name, value.as_double());
    });
  }
  errors.throw_if_any();
}

void read_motion(const YamlValue& root, const ScenarioOverrides& overrides, Scenario& scenario) {
  if (overrides.motion_log) {
    scenario.commands =
        read_log_commands(*scenario.model, *overrides.motion_log, scenario.parameters,
                          scenario.log_parameters, &scenario.motion_description);
  } else if (overrides.motion_optional && !overrides.motion_scenario && !root.has("motion")) {
    scenario.motion_description = "none";
  } else {
    const YamlValue motion = overrides.motion_scenario
                                 ? YamlValue::load_file(*overrides.motion_scenario).at("motion")
                                 : root.at("motion");
    detail::read_scenario_motion(motion, overrides, scenario);
  }
  if (scenario.commands.frames() >= 2) {
    scenario.log_rate_hz = (scenario.commands.frames() - 1) / scenario.commands.duration_s();
  }
}

}  // namespace

Scenario load_scenario(const std::string& path, const ScenarioOverrides& overrides) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"name", "robot", "servo", "seed", "physics", "motion", "parameters"});
  ErrorCollector errors;
  detail::ScenarioPhysics physics;
  errors.check([&] { physics = detail::read_scenario_physics(root.find("physics"), overrides); });
  errors.check([&] {
    const int seed = root.get_int("seed", 1);
    if (seed < 0) root.at("seed").fail("must be >= 0");
    physics.rollout.seed = static_cast<std::uint64_t>(seed);
  });
  std::string name;
  errors.check(
      [&] { name = root.get_string("name", std::filesystem::path(path).stem().string()); });
  // The robot is read with the structure the physics section asks for.
  errors.throw_if_any();
  const std::shared_ptr<const RobotModel> model = read_robot(root, physics.structure, overrides);
  physics.rollout.servo = read_servo(root, *model, overrides);

  Scenario scenario{path, name, model, ParameterSet(model->parameters), physics.rollout, {}, 100.0,
                    {},   {},   {}};
  if (const auto parameters = root.find("parameters")) {
    read_parameters(*parameters, scenario.parameters);
  }
  read_motion(root, overrides, scenario);
  if (overrides.parameters_json) {
    apply_parameter_json_file(*overrides.parameters_json, scenario.parameters,
                              {overrides.allow_out_of_bounds});
  }
  if (overrides.duration_s) {
    scenario.commands = truncate_trajectory(scenario.commands, *overrides.duration_s);
  }
  return scenario;
}

}  // namespace motoflex
