#pragma once

// A FitSpec resolved against the files it names: the scenario (robot, servo, physics), the
// logs as fit cases, the free parameters expanded into a ParameterSpace, and the identity hash
// that makes a run folder resumable. Built once, shared read-only by every evaluation thread.

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motoflex/fit/fit_spec.hpp"
#include "motoflex/fit/fitness.hpp"
#include "motoflex/fit/parameter_space.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex {

struct FitConfig : FitSpec {
  std::vector<std::string> train_logs;         // absolute paths, sorted per folder
  std::vector<std::string> validation_logs;    // may be empty
  std::vector<FreeParameter> free_parameters;  // `free` and the effects' parameters, expanded
  FitnessOptions fitness;                      // the spec's fitness fields for this robot

  std::shared_ptr<const Scenario> scenario;
  std::shared_ptr<FitnessFunction> train;
  std::shared_ptr<FitnessFunction> validation;  // null without validation logs
  std::shared_ptr<ParameterSpace> space;
  std::vector<double> incumbent_x;  // `incumbent` in search coordinates (empty: none)
  // `hold_identified`: the free parameters held at the --start-from run's values (their names as
  // in `free`); summary.json lists them, so a fit chained on this one holds them too.
  std::vector<std::string> held_identified;

  // What decides the result of the run: every spec field except threads, budget and out_dir,
  // with the contents of the scenario, robot and log files. Two configs with the same hash give
  // the same generations bit for bit.
  nlohmann::json identity;
  std::string hash;
  // The command-line overrides this config was loaded with (written to run.json, so that
  // `motoflex resume` rebuilds the same config).
  nlohmann::json overrides = nlohmann::json::object();
};

// Loads what `spec` names. Throws InputError(s) naming file, line and field for anything wrong
// in the spec, the scenario, the robot or the logs (a log of another robot, missing columns,
// unknown parameters).
FitConfig resolve_fit_config(const FitSpec& spec);

// load_fit_spec + resolve_fit_config, remembering the overrides for run.json.
FitConfig load_fit_config(const std::string& path, const FitOverrides& overrides = {});

nlohmann::json overrides_to_json(const FitOverrides& overrides);
FitOverrides overrides_from_json(const nlohmann::json& json);
// Every field of a strategy, as the `strategy:` section of a fit config reads it back.
nlohmann::ordered_json strategy_to_json(const StrategyConfig& strategy);
// The `polish:` section as fit.yaml reads it back.
nlohmann::ordered_json polish_to_json(const PolishSpec& polish);
// A spec as fit.yaml reads it back (JSON is valid YAML), paths absolute.
nlohmann::ordered_json fit_spec_to_json(const FitSpec& spec);
// The `loop:` section alone, as fit_spec_to_json writes it.
nlohmann::ordered_json loop_options_to_json(const LoopOptions& options);

// The identity of a resolved config (see FitConfig::identity).
nlohmann::json fit_identity(const FitConfig& config);

// The logs of a list of sources: folders (every *.csv, sorted), files, and folders without
// *.csv that hold BAM JSON logs in them or in subfolders (imported into `import_dir` first, see
// import_bam_directory: a recording kept raw and processed counts once).
std::vector<std::string> logs_of(const std::vector<LogSource>& sources,
                                 const std::string& import_dir);

// The fit cases of a list of logs for a scenario's robot (used for training and validation).
// Each case keeps the log's IMU columns when it has them; when the fitness scores them
// (imu_weight > 0) a log without them throws InputError naming the log. A fitness window_s > 0
// keeps only the frames within window_s seconds of each log's start.
std::vector<FitCase> load_fit_cases(const Scenario& scenario,
                                    const std::vector<std::string>& log_paths,
                                    const FitnessOptions& fitness = {});

// Logs of a folder (every *.csv, sorted by name) or a single log file.
std::vector<std::string> list_logs(const std::string& folder_or_file, const std::string& field);

}  // namespace motoflex
