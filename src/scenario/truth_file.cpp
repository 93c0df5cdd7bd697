#include "motoflex/scenario/truth_file.hpp"

#include <exception>

#include "motoflex/core/error.hpp"
#include "motoflex/core/random_stream.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

bool is_truth_file(const std::string& path) {
  try {
    const YamlValue root = YamlValue::load_file(path);
    return root.is_map() && root.has("recordings");
  } catch (const std::exception&) {
    return false;
  }
}

TruthFile load_truth_file(const std::string& path) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within(
      {"name", "seed", "digits", "robot", "servo", "physics", "parameters", "recordings"});
  TruthFile truth;
  truth.path = path;
  truth.name = root.get_string("name", "truth");
  truth.seed = root.get_int("seed", 1);
  if (truth.seed < 0) root.at("seed").fail("must be >= 0");
  truth.digits = root.get_int("digits", 0);
  if (truth.digits < 0 || truth.digits > 17) root.at("digits").fail("must be between 0 and 17");
  if (const auto servo = root.find("servo")) {
    if (!find_servo_law(servo->as_string())) {
      servo->fail("unknown servo '" + servo->as_string() + "' (" + servo_law_names() + ")");
    }
    truth.overrides.servo = servo->as_string();
  }
  // The robot and physics go on top of each recording's scenario (the scenario loader checks
  // their keys and values, naming this file).
  truth.overrides.robot = root.find("robot");
  if (const auto physics = root.find("physics")) truth.overrides.physics.push_back(*physics);
  truth.parameters = root.find("parameters");
  for (const YamlValue& item : root.at("recordings").items()) {
    item.require_keys_within({"name", "scenario", "parameters"});
    const std::string name = item.at("name").as_string();
    // A name may hold folders ("train/walk_100"); it must stay inside the output folder.
    if (name.empty() || name.front() == '/' || name.find("..") != std::string::npos) {
      item.at("name").fail("a relative file name without '..' expected");
    }
    truth.recordings.push_back(
        {name, item.resolve_path(item.at("scenario").as_string()), item.find("parameters")});
  }
  if (truth.recordings.empty()) root.at("recordings").fail("no recordings listed");
  return truth;
}

Scenario truth_recording_scenario(const TruthFile& truth, std::size_t index,
                                  const ScenarioOverrides& extra) {
  const TruthRecording& recording = truth.recordings.at(index);
  // The caller's overrides, with the truth's robot and servo where the caller sets none (a truth
  // file sets only these and physics). The truth's physics section is read first and the
  // caller's sections on top of it; the caller's single physics values win over both.
  ScenarioOverrides overrides = extra;
  if (!overrides.servo) overrides.servo = truth.overrides.servo;
  if (!overrides.robot) overrides.robot = truth.overrides.robot;
  overrides.physics = truth.overrides.physics;
  overrides.physics.insert(overrides.physics.end(), extra.physics.begin(), extra.physics.end());
  // The truth values go on top of the scenario's; a parameter file given by the caller wins.
  overrides.parameters_json.reset();
  Scenario scenario = load_scenario(recording.scenario_path, overrides);
  for (const auto& parameters : {truth.parameters, recording.parameters}) {
    if (!parameters) continue;
    for (const auto& [name, value] : parameters->entries()) {
      if (!scenario.parameters.registry().contains(name)) {
        value.fail("robot '" + scenario.model->name + "' has no parameter '" + name + "'");
      }
      scenario.parameters.set(name, value.as_double());
    }
  }
  if (extra.parameters_json) {
    apply_parameter_json_file(*extra.parameters_json, scenario.parameters,
                              {extra.allow_out_of_bounds});
  }
  scenario.rollout.seed = mix64(static_cast<std::uint64_t>(truth.seed) * 0x100000001B3ULL + index);
  return scenario;
}

std::size_t truth_recording_index(const TruthFile& truth, const std::string& name) {
  std::string names;
  for (std::size_t r = 0; r < truth.recordings.size(); ++r) {
    if (truth.recordings[r].name == name) return r;
    names += (r == 0 ? "" : ", ") + truth.recordings[r].name;
  }
  throw InputError(truth.path, 0, "recordings", "no recording '" + name + "' (" + names + ")");
}

Scenario load_scenario_or_truth(const std::string& path, const ScenarioOverrides& overrides,
                                const std::string& recording) {
  if (!is_truth_file(path)) {
    if (!recording.empty()) {
      throw InputError(path, 0, "--recording", "only a truth file has recordings");
    }
    return load_scenario(path, overrides);
  }
  const TruthFile truth = load_truth_file(path);
  const std::size_t index = recording.empty() ? 0 : truth_recording_index(truth, recording);
  return truth_recording_scenario(truth, index, overrides);
}

}  // namespace motoflex
