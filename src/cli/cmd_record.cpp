// motoflex record <truth.yaml> --out DIR
// Simulates every recording of a truth file (format: include/motoflex/scenario/truth_file.hpp)
// with the truth parameters and sensor realism and writes "measured" logs. The truth parameters
// go to DIR/truth/, which fitting never reads.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/scenario/truth_file.hpp"
#include "motoflex/sim/rollout_log.hpp"

namespace motoflex::cli {
namespace {

struct RecordArgs {
  std::string truth;
  std::string out;
  std::string truth_out;  // default: <out>/truth
  bool blind = false;     // the logs' origin does not name the truth file (hidden-effect data)
};

int run(const RecordArgs& args) {
  const TruthFile truth = load_truth_file(args.truth);
  const std::filesystem::path truth_dir = args.truth_out.empty()
                                              ? std::filesystem::path(args.out) / "truth"
                                              : std::filesystem::path(args.truth_out);
  for (std::size_t r = 0; r < truth.recordings.size(); ++r) {
    const TruthRecording& recording = truth.recordings[r];
    const Scenario scenario = truth_recording_scenario(truth, r);
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
    const std::string truth_name = args.blind
                                       ? std::string("<truth withheld>")
                                       : std::filesystem::path(args.truth).filename().string();
    meta.origin = "motoflex record " + truth_name + " (" + recording.name + ", seed " +
                  std::to_string(truth.seed) + ")";
    if (result.end != RolloutEnd::kCompleted) {
      meta.notes = std::string(to_string(result.end)) + " at " + std::to_string(result.end_time_s) +
                   " s: " + result.end_detail;
    }
    const std::string csv = (std::filesystem::path(args.out) / (recording.name + ".csv")).string();
    std::filesystem::create_directories(std::filesystem::path(csv).parent_path());
    write_joint_log(csv, joint_log_from_rollout(result, meta), truth.digits);

    nlohmann::ordered_json provenance;
    provenance["recording"] = recording.name;
    provenance["truth_file"] = args.truth;
    provenance["scenario"] = recording.scenario_path;
    provenance["seed"] = truth.seed;
    provenance["parameters"] =
        nlohmann::ordered_json::parse(parameter_set_to_json(scenario.parameters));
    const std::filesystem::path truth_path = truth_dir / (recording.name + ".json");
    std::filesystem::create_directories(truth_path.parent_path());
    write_file_atomically(truth_path.string(), provenance.dump(2) + "\n");
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
  sub->add_flag("--blind", args->blind,
                "the logs' sidecars do not name the truth file (data with an undeclared effect)");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
