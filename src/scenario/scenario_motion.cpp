#include "scenario_motion.hpp"

#include "excitation_scenario_motion.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/motion/log_commands.hpp"
#include "nao_scenario_motion.hpp"
#include "titan_scenario_motion.hpp"

namespace motoflex::detail {
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

void read_keyframes(const YamlValue& keyframes, Scenario& scenario) {
  const RobotModel& model = *scenario.model;
  keyframes.require_keys_within({"rate_hz", "frames"});
  const double rate_hz = keyframes.get_double("rate_hz", 100.0);
  if (!(rate_hz > 0.0)) keyframes.at("rate_hz").fail("must be positive");
  std::vector<Keyframe> frames;
  for (const YamlValue& item : keyframes.at("frames").items()) {
    item.require_keys_within({"t_s", "pose"});
    Keyframe frame{item.at("t_s").as_double(), item.find("pose")
                                                   ? pose_from_yaml(model, item.at("pose"))
                                                   : model.stand_pose_vector()};
    if (!frames.empty() && !(frame.time_s > frames.back().time_s)) {
      item.at("t_s").fail("keyframe times must strictly increase");
    }
    frames.push_back(std::move(frame));
  }
  if (frames.size() < 2) keyframes.at("frames").fail("need at least 2 keyframes");
  scenario.commands = keyframe_trajectory(frames, rate_hz);
  scenario.log_rate_hz = rate_hz;
  scenario.motion_description = "keyframes (" + std::to_string(frames.size()) + " frames)";
}

void read_stand(const YamlValue& stand, Scenario& scenario) {
  stand.require_keys_within({"duration_s", "rate_hz"});
  const double duration = stand.at("duration_s").as_double();
  const double rate_hz = stand.get_double("rate_hz", 100.0);
  if (!(duration > 0.0)) stand.at("duration_s").fail("must be positive");
  if (!(rate_hz > 0.0)) stand.at("rate_hz").fail("must be positive");
  const std::vector<double> pose = scenario.model->stand_pose_vector();
  scenario.commands = keyframe_trajectory({{0.0, pose}, {duration, pose}}, rate_hz);
  scenario.log_rate_hz = rate_hz;
  scenario.motion_description = "stand";
}

}  // namespace

void read_scenario_motion(const YamlValue& motion, const ScenarioOverrides& overrides,
                          Scenario& scenario) {
  const RobotModel& model = *scenario.model;
  motion.require_keys_within({"log", "keyframes", "stand", "walk", "kick", "titan_crawl",
                              "titan_updown", "titan_stand", "excitation"});
  if (motion.entries().size() != 1) {
    motion.fail(
        "give exactly one of log, keyframes, stand, walk, kick, titan_crawl, titan_updown, "
        "titan_stand, excitation");
  }
  if (const auto log = motion.find("log")) {
    scenario.commands =
        read_log_commands(model, log->resolve_path(log->as_string()), scenario.parameters,
                          scenario.log_parameters, &scenario.motion_description);
  } else if (const auto keyframes = motion.find("keyframes")) {
    read_keyframes(*keyframes, scenario);
  } else if (auto nao = nao_motion_from_yaml(motion, model, overrides.walk_options)) {
    scenario.commands = std::move(nao->commands);
    scenario.log_rate_hz = nao->rate_hz;
    scenario.motion_description = nao->description;
    scenario.walk_plan = std::move(nao->walk_plan);
  } else if (auto excitation = excitation_motion_from_yaml(motion, model)) {
    scenario.commands = std::move(*excitation);
    scenario.motion_description = "excitation";
  } else if (auto titan = titan_motion_from_yaml(motion, model, scenario.parameters,
                                                 scenario.rollout.servo)) {
    scenario.commands = std::move(titan->commands);
    scenario.log_rate_hz = titan->rate_hz;
    scenario.motion_description = titan->description;
  } else {
    read_stand(motion.at("stand"), scenario);
  }
}

}  // namespace motoflex::detail
