#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "excitation_scenario_motion.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/motion/log_commands.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "nao_scenario_motion.hpp"
#include "titan_scenario_motion.hpp"

namespace motoflex {
namespace {

std::vector<double> pose_from_yaml(const RobotModel& model, const YamlValue& pose) {
  std::vector<double> out = model.stand_pose_vector();
  for (const auto& [joint, angle] : pose.entries()) {
    const auto index = model.actuator_index(joint);
    if (!index) angle.fail("'" + joint + "' is not an actuated joint of " + model.name);
    out[*index] = angle.as_double();
  }
  return out;
}

// Reads every key of a `physics:` section that is present into `structure` and `rollout`,
// leaving the others as they are (a truth file's section goes on top of a scenario's).
void read_physics(const YamlValue& physics, StructureOptions& structure, RolloutOptions& rollout) {
  physics.require_keys_within({"dt_s", "solver", "quickstep_iterations", "quickstep_w",
                               "gear_substeps", "flex_sub_bodies", "flex_model", "max_contacts",
                               "universal_joints", "settle_s", "hold_torso"});
  read_step_settings(physics, rollout);
  rollout.quickstep_iterations =
      physics.get_int("quickstep_iterations", rollout.quickstep_iterations);
  if (rollout.quickstep_iterations < 1) physics.at("quickstep_iterations").fail("must be >= 1");
  rollout.quickstep_w = physics.get_double("quickstep_w", rollout.quickstep_w);
  if (!(rollout.quickstep_w > 0.0 && rollout.quickstep_w < 2.0)) {
    physics.at("quickstep_w").fail("must be in (0, 2) (SOR over-relaxation)");
  }
  rollout.gear_substeps = physics.get_int("gear_substeps", rollout.gear_substeps);
  if (rollout.gear_substeps < 1) physics.at("gear_substeps").fail("must be >= 1");
  structure.flex_sub_bodies = physics.get_int("flex_sub_bodies", structure.flex_sub_bodies);
  if (structure.flex_sub_bodies < 1 || structure.flex_sub_bodies > 16) {
    physics.at("flex_sub_bodies").fail("must be between 1 and 16");
  }
  if (const auto flex_model = physics.find("flex_model")) {
    const std::string name = flex_model->as_string();
    if (name == "implicit") {
      rollout.flex_model = FlexModel::kImplicit;
    } else if (name == "explicit_cfm") {
      rollout.flex_model = FlexModel::kExplicitCfm;
    } else {
      flex_model->fail("expected 'implicit' or 'explicit_cfm'");
    }
  }
  rollout.max_contacts_per_foot = physics.get_int("max_contacts", rollout.max_contacts_per_foot);
  if (rollout.max_contacts_per_foot < 1 || rollout.max_contacts_per_foot > 64) {
    physics.at("max_contacts").fail("must be between 1 and 64");
  }
  structure.universal_joints = physics.get_bool("universal_joints", structure.universal_joints);
  rollout.settle_s = physics.get_double("settle_s", rollout.settle_s);
  if (rollout.settle_s < 0.0) physics.at("settle_s").fail("must be >= 0");
  rollout.hold_torso = physics.get_bool("hold_torso", rollout.hold_torso);
}

}  // namespace

std::optional<StepSolver> parse_step_solver(const std::string& text) {
  if (text == "step") return StepSolver::kStep;
  if (text == "quick") return StepSolver::kQuickStep;
  return std::nullopt;
}

void read_step_settings(const YamlValue& physics, RolloutOptions& rollout) {
  rollout.dt_s = physics.get_double("dt_s", rollout.dt_s);
  if (!(rollout.dt_s > 0.0 && rollout.dt_s <= 0.01)) {
    physics.at("dt_s").fail("must be in (0, 0.01] s");
  }
  if (const auto solver = physics.find("solver")) {
    const auto parsed = parse_step_solver(solver->as_string());
    if (!parsed) solver->fail("expected 'step' or 'quick'");
    rollout.solver = *parsed;
  }
}

Scenario load_scenario(const std::string& path, const ScenarioOverrides& overrides) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"name", "robot", "servo", "seed", "physics", "motion", "parameters"});
  const YamlValue robot_field = overrides.robot ? *overrides.robot : root.at("robot");

  StructureOptions structure;
  RolloutOptions rollout;
  if (const auto physics = root.find("physics")) read_physics(*physics, structure, rollout);
  if (overrides.physics) read_physics(*overrides.physics, structure, rollout);
  if (overrides.solver) rollout.solver = *overrides.solver;
  if (overrides.flex_sub_bodies) structure.flex_sub_bodies = *overrides.flex_sub_bodies;
  if (overrides.gear_substeps) rollout.gear_substeps = *overrides.gear_substeps;
  if (overrides.universal_joints) structure.universal_joints = *overrides.universal_joints;
  if (overrides.settle_s) rollout.settle_s = *overrides.settle_s;
  const int seed = root.get_int("seed", 1);
  if (seed < 0) root.at("seed").fail("must be >= 0");
  rollout.seed = static_cast<std::uint64_t>(seed);

  const std::string robot_dir = robot_field.resolve_path(robot_field.as_string());
  if (!std::filesystem::exists(std::filesystem::path(robot_dir) / "robot.yaml")) {
    robot_field.fail("no robot.yaml in '" + robot_dir + "'");
  }
  auto model = std::make_shared<RobotModel>(load_robot(robot_dir, structure));

  rollout.servo = model->default_servo;
  if (const auto servo = root.find("servo")) {
    rollout.servo = servo->as_string();
    check_servo_parameters(*model, rollout.servo, path, servo->line(), "servo");
  }
  if (overrides.servo) {
    rollout.servo = *overrides.servo;
    check_servo_parameters(*model, rollout.servo, "", 0, "--servo");
  }

  Scenario scenario{path,    root.get_string("name", std::filesystem::path(path).stem().string()),
                    model,   ParameterSet(model->parameters),
                    rollout, {},
                    100.0,   {},
                    {},      {}};
  if (const auto parameters = root.find("parameters")) {
    for (const auto& [name, value] : parameters->entries()) {
      if (!model->parameters.contains(name)) {
        const std::string hint = model->parameters.closest_name(name);
        value.fail("unknown parameter" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      scenario.parameters.set(name, value.as_double());
    }
  }

  if (overrides.motion_log) {
    scenario.commands = read_log_commands(*model, *overrides.motion_log, scenario.parameters,
                                          scenario.log_parameters, &scenario.motion_description);
  } else if (overrides.motion_optional && !overrides.motion_scenario && !root.has("motion")) {
    scenario.motion_description = "none";
  } else {
    const YamlValue motion = overrides.motion_scenario
                                 ? YamlValue::load_file(*overrides.motion_scenario).at("motion")
                                 : root.at("motion");
    motion.require_keys_within({"log", "keyframes", "stand", "walk", "kick", "titan_crawl",
                                "titan_updown", "titan_stand", "excitation"});
    if (motion.entries().size() != 1) {
      motion.fail(
          "give exactly one of log, keyframes, stand, walk, kick, titan_crawl, titan_updown, "
          "titan_stand, excitation");
    }
    if (const auto log = motion.find("log")) {
      scenario.commands =
          read_log_commands(*model, log->resolve_path(log->as_string()), scenario.parameters,
                            scenario.log_parameters, &scenario.motion_description);
    } else if (const auto keyframes = motion.find("keyframes")) {
      keyframes->require_keys_within({"rate_hz", "frames"});
      const double rate_hz = keyframes->get_double("rate_hz", 100.0);
      if (!(rate_hz > 0.0)) keyframes->at("rate_hz").fail("must be positive");
      std::vector<Keyframe> frames;
      for (const YamlValue& item : keyframes->at("frames").items()) {
        item.require_keys_within({"t_s", "pose"});
        Keyframe frame{item.at("t_s").as_double(), item.find("pose")
                                                       ? pose_from_yaml(*model, item.at("pose"))
                                                       : model->stand_pose_vector()};
        if (!frames.empty() && !(frame.time_s > frames.back().time_s)) {
          item.at("t_s").fail("keyframe times must strictly increase");
        }
        frames.push_back(std::move(frame));
      }
      if (frames.size() < 2) keyframes->at("frames").fail("need at least 2 keyframes");
      scenario.commands = keyframe_trajectory(frames, rate_hz);
      scenario.log_rate_hz = rate_hz;
      scenario.motion_description = "keyframes (" + std::to_string(frames.size()) + " frames)";
    } else if (auto nao = detail::nao_motion_from_yaml(motion, *model, overrides.walk_options)) {
      scenario.commands = std::move(nao->commands);
      scenario.log_rate_hz = nao->rate_hz;
      scenario.motion_description = nao->description;
      scenario.walk_plan = std::move(nao->walk_plan);
    } else if (auto excitation = detail::excitation_motion_from_yaml(motion, *model)) {
      scenario.commands = std::move(*excitation);
      scenario.motion_description = "excitation";
    } else if (auto titan = detail::titan_motion_from_yaml(motion, *model, scenario.parameters,
                                                           scenario.rollout.servo)) {
      scenario.commands = std::move(titan->commands);
      scenario.log_rate_hz = titan->rate_hz;
      scenario.motion_description = titan->description;
    } else {
      const YamlValue stand = motion.at("stand");
      stand.require_keys_within({"duration_s", "rate_hz"});
      const double duration = stand.at("duration_s").as_double();
      const double rate_hz = stand.get_double("rate_hz", 100.0);
      if (!(duration > 0.0)) stand.at("duration_s").fail("must be positive");
      if (!(rate_hz > 0.0)) stand.at("rate_hz").fail("must be positive");
      const std::vector<double> pose = model->stand_pose_vector();
      scenario.commands = keyframe_trajectory({{0.0, pose}, {duration, pose}}, rate_hz);
      scenario.log_rate_hz = rate_hz;
      scenario.motion_description = "stand";
    }
  }
  if (scenario.commands.frames() >= 2) {
    scenario.log_rate_hz = (scenario.commands.frames() - 1) / scenario.commands.duration_s();
  }
  if (overrides.parameters_json) {
    apply_parameter_json_file(*overrides.parameters_json, scenario.parameters);
  }
  if (overrides.duration_s)
    scenario.commands = truncate_trajectory(scenario.commands, *overrides.duration_s);
  return scenario;
}

}  // namespace motoflex
