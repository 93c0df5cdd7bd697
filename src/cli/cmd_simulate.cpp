// motoflex simulate <scenario.yaml|truth.yaml> [--params P.json] [--motion LOG.csv]
//                   [--recording NAME] --out OUT.csv [--plot PNG]
// Replays the commanded angles of a scenario (or of any log, or of a 2011 MoToFlex command file)
// and writes a log whose .meas columns are the simulated encoders. A truth file (the input of
// `record`) simulates one of its recordings (the first, or --recording) exactly as `record`
// does: same scenario, truth parameters, sensor seed.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/plot_script.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/scenario/truth_file.hpp"
#include "motoflex/sim/rollout_log.hpp"
#include "option_checks.hpp"

namespace motoflex::cli {
namespace {

struct SimulateArgs {
  std::string scenario;
  std::string params;
  bool allow_out_of_bounds = false;
  std::string motion;
  std::string recording;
  std::string out;
  std::string plot;
  std::string solver;
  double duration_s = 0.0;
};

double rms_tracking_deg(const RolloutResult& r) {
  double sum = 0.0;
  const std::size_t count = r.frames_completed * r.joints();
  for (std::size_t i = 0; i < count; ++i) {
    const double e = r.measured_rad[i] - r.commanded_rad[i];
    sum += e * e;
  }
  return count == 0 ? 0.0 : std::sqrt(sum / count) * 180.0 / M_PI;
}

int run(const SimulateArgs& args) {
  ScenarioOverrides overrides;
  if (!args.params.empty()) overrides.parameters_json = args.params;
  overrides.allow_out_of_bounds = args.allow_out_of_bounds;
  if (!args.motion.empty()) overrides.motion_log = args.motion;
  if (!args.solver.empty()) {
    overrides.solver = parse_step_solver(args.solver);
    if (!overrides.solver) throw InputError("", 0, "--solver", kStepSolverChoices);
  }
  if (args.duration_s > 0.0) overrides.duration_s = args.duration_s;
  const Scenario scenario = load_scenario_or_truth(args.scenario, overrides, args.recording);

  const auto start = std::chrono::steady_clock::now();
  const RolloutResult result =
      run_rollout(*scenario.model, scenario.parameters, scenario.commands, scenario.rollout);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.end == RolloutEnd::kModelError) {
    // The parameters are the input's: R = 0, a negative backlash, an unstable gear sub-step.
    throw InputError(args.params.empty() ? args.scenario : args.params, 0, "parameters",
                     "cannot simulate: " + result.end_detail);
  }
  if (result.frames_completed < 2) {
    // No log to write: say why the rollout ended at once, not that a log needs 2 frames.
    throw InputError(args.scenario, 0, "rollout",
                     std::string("ended at its first frame (t = ") +
                         std::to_string(result.end_time_s) + " s): " + to_string(result.end) +
                         (result.end_detail.empty() ? "" : ": " + result.end_detail));
  }

  JointLogMeta meta;
  meta.robot = scenario.model->name;
  meta.rate_hz = scenario.log_rate_hz;
  meta.motion = scenario.motion_description;
  meta.origin = "motoflex simulate " + args.scenario + " (servo " + scenario.rollout.servo + ")";
  if (result.end != RolloutEnd::kCompleted) {
    meta.notes = std::string("rollout ") + to_string(result.end) + " at " +
                 std::to_string(result.end_time_s) + " s: " + result.end_detail;
  }
  const std::filesystem::path out_dir = std::filesystem::path(args.out).parent_path();
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);
  write_joint_log(args.out, joint_log_from_rollout(result, meta));
  if (!args.plot.empty()) plot_joint_log(args.out, args.plot);

  nlohmann::ordered_json summary;
  summary["scenario"] = scenario.name;
  summary["robot"] = scenario.model->name;
  summary["servo"] = scenario.rollout.servo;
  summary["frames"] = result.frames_requested;
  summary["frames_completed"] = result.frames_completed;
  summary["end"] = to_string(result.end);
  summary["end_time_s"] = result.end_time_s;
  summary["end_detail"] = result.end_detail;
  summary["rms_cmd_vs_meas_deg"] = rms_tracking_deg(result);
  summary["physics_steps"] = result.physics_steps;
  summary["wall_s"] = wall_s;
  summary["out"] = args.out;
  std::printf("%s\n", summary.dump().c_str());
  return 0;
}

}  // namespace

CommandRunner add_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* sub = app.add_subcommand("simulate", "replay commanded angles, write simulated log");
  sub->add_option("scenario", args->scenario, "scenario YAML, or a truth YAML (as for record)")
      ->required();
  sub->add_option("--params", args->params, "parameter set JSON (name -> value)");
  sub->add_flag("--allow-out-of-bounds", args->allow_out_of_bounds,
                "accept --params values outside the parameters' bounds (a warning each)");
  sub->add_option("--motion", args->motion,
                  "replay the .cmd columns of this log (or a 2011 MoToFlex command file) instead");
  sub->add_option("--recording", args->recording,
                  "a truth file's recording to simulate (default: its first)");
  sub->add_option("--out", args->out, "output log CSV (a sidecar YAML is written beside it)")
      ->required();
  sub->add_option("--plot", args->plot, "also draw commanded vs simulated angles into this PNG");
  sub->add_option("--solver", args->solver,
                  "step (exact), sparse (the same LCP, faster solver) or quick (faster, less "
                  "accurate); all reproducible in threads");
  sub->add_option("--duration", args->duration_s, "simulate only the first S seconds")
      ->check(positive_seconds());
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
