// motoflex record <truth.yaml> --out DIR
// Simulates every recording of a truth file with the truth parameters and sensor realism and
// writes "measured" logs. The truth parameters go to DIR/truth/, which fitting never reads.
//
//   name: nao_motoflex
//   seed: 7
//   digits: 9                          # significant digits of the angles (0: exact round trip)
//   servo: motoflex                    # optional: replaces each scenario's servo
//   physics: {flex_sub_bodies: 2, gear_substeps: 100, settle_s: 0.5}   # optional overrides
//   parameters: {sensor.resolution_bits: 12, sensor.noise_rad: 0.0005, motor.R_ohm: 6.6}
//   recordings:
//     - {name: squat, scenario: ../nao_default.yaml, parameters: {...}}   # per-recording extra

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/random_stream.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/rollout_log.hpp"

namespace motoflex::cli {
namespace {

struct RecordArgs {
  std::string truth;
  std::string out;
  std::string truth_out;  // default: <out>/truth
};

struct Recording {
  std::string name;
  std::string scenario_path;
  std::optional<YamlValue> parameters;  // this recording's own truth values, if any
};

int run(const RecordArgs& args) {
  const YamlValue root = YamlValue::load_file(args.truth);
  root.require_keys_within(
      {"name", "seed", "digits", "servo", "physics", "parameters", "recordings"});
  const int seed = root.get_int("seed", 1);
  if (seed < 0) root.at("seed").fail("must be >= 0");
  const int digits = root.get_int("digits", 0);
  if (digits < 0 || digits > 17) root.at("digits").fail("must be between 0 and 17");
  ScenarioOverrides overrides;
  if (const auto servo = root.find("servo")) {
    if (!find_servo_law(servo->as_string())) {
      servo->fail("unknown servo '" + servo->as_string() + "' (" + servo_law_names() + ")");
    }
    overrides.servo = servo->as_string();
  }
  if (const auto physics = root.find("physics")) {
    physics->require_keys_within({"flex_sub_bodies", "gear_substeps", "settle_s"});
    if (physics->has("flex_sub_bodies")) {
      overrides.flex_sub_bodies = physics->at("flex_sub_bodies").as_int();
    }
    if (physics->has("gear_substeps"))
      overrides.gear_substeps = physics->at("gear_substeps").as_int();
    if (physics->has("settle_s")) overrides.settle_s = physics->at("settle_s").as_double();
  }
  std::vector<Recording> recordings;
  for (const YamlValue& item : root.at("recordings").items()) {
    item.require_keys_within({"name", "scenario", "parameters"});
    const std::string name = item.at("name").as_string();
    // A name may hold folders ("train/walk_100"); it must stay inside the output folder.
    if (name.empty() || name.front() == '/' || name.find("..") != std::string::npos) {
      item.at("name").fail("a relative file name without '..' expected");
    }
    recordings.push_back(
        {name, item.resolve_path(item.at("scenario").as_string()), item.find("parameters")});
  }
  if (recordings.empty()) root.at("recordings").fail("no recordings listed");

  const std::filesystem::path truth_dir = args.truth_out.empty()
                                              ? std::filesystem::path(args.out) / "truth"
                                              : std::filesystem::path(args.truth_out);
  for (std::size_t r = 0; r < recordings.size(); ++r) {
    const Recording& recording = recordings[r];
    Scenario scenario = load_scenario(recording.scenario_path, overrides);
    for (const auto& parameters : {root.find("parameters"), recording.parameters}) {
      if (!parameters) continue;
      for (const auto& [name, value] : parameters->entries()) {
        if (!scenario.parameters.registry().contains(name)) {
          value.fail("robot '" + scenario.model->name + "' has no parameter '" + name + "'");
        }
        scenario.parameters.set(name, value.as_double());
      }
    }
    scenario.rollout.seed = mix64(static_cast<std::uint64_t>(seed) * 0x100000001B3ULL + r);
    const RolloutResult result =
        run_rollout(*scenario.model, scenario.parameters, scenario.commands, scenario.rollout);
    if (result.end == RolloutEnd::kModelError) {
      throw InputError(args.truth, 0, "recordings[" + std::to_string(r) + "]",
                       "cannot simulate: " + result.end_detail);
    }
    JointLogMeta meta;
    meta.robot = scenario.model->name;
    meta.rate_hz = scenario.log_rate_hz;
    meta.motion = scenario.motion_description;
    meta.parameters = scenario.log_parameters;  // experimental conditions, not the truth
    meta.origin = "motoflex record " + std::filesystem::path(args.truth).filename().string() +
                  " (" + recording.name + ", seed " + std::to_string(seed) + ")";
    if (result.end != RolloutEnd::kCompleted) {
      meta.notes = std::string(to_string(result.end)) + " at " + std::to_string(result.end_time_s) +
                   " s: " + result.end_detail;
    }
    const std::string csv = (std::filesystem::path(args.out) / (recording.name + ".csv")).string();
    std::filesystem::create_directories(std::filesystem::path(csv).parent_path());
    write_joint_log(csv, joint_log_from_rollout(result, meta), digits);

    nlohmann::ordered_json truth;
    truth["recording"] = recording.name;
    truth["truth_file"] = args.truth;
    truth["scenario"] = recording.scenario_path;
    truth["seed"] = seed;
    truth["parameters"] = nlohmann::ordered_json::parse(parameter_set_to_json(scenario.parameters));
    const std::filesystem::path truth_path = truth_dir / (recording.name + ".json");
    std::filesystem::create_directories(truth_path.parent_path());
    write_file_atomically(truth_path.string(), truth.dump(2) + "\n");
    std::printf("recorded %s: %zu of %zu frames (%s)\n", csv.c_str(), result.frames_completed,
                result.frames_requested, to_string(result.end));
  }
  return 0;
}

}  // namespace

CommandRunner add_record_command(CLI::App& app) {
  auto args = std::make_shared<RecordArgs>();
  CLI::App* sub = app.add_subcommand("record", "write 'measured' logs from a truth model");
  sub->add_option("truth", args->truth, "truth YAML (parameters, recordings)")->required();
  sub->add_option("--out", args->out, "output folder")->required();
  sub->add_option("--truth-out", args->truth_out, "folder of the truth files (default OUT/truth)");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
