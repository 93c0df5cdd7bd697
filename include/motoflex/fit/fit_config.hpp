#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/fit/fitness.hpp"
#include "motoflex/fit/parameter_space.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex {

// Which optimiser a fit runs, with its options (the es library's option structs are filled
// from these).
struct StrategyConfig {
  std::string kind = "mu_plus_lambda";  // mu_plus_lambda | cma_es | nlopt
  // mu_plus_lambda (seed 001: mu 10, lambda 800, kappa 3)
  std::size_t mu = 10;
  std::size_t lambda = 40;
  std::uint64_t kappa = 3;  // 0 = unlimited (plus selection)
  std::size_t rho = 2;
  std::string object_recombination = "discrete";
  std::string step_recombination = "intermediate";
  double initial_step = 0.1;  // relative to each bound width
  // cma_es
  double sigma = 0.25;  // relative to the bound widths
  std::size_t population = 0;
  std::size_t restarts = 9;
  // nlopt: bobyqa | sbplx | crs2_lm | isres | esch
  std::string algorithm = "bobyqa";
  // optional local polish of the best point after the main strategy (nlopt local algorithm)
  std::string polish;  // "" = none
  std::uint64_t polish_evaluations = 0;
};

struct FitBudget {
  std::uint64_t max_generations = 0;  // 0 = no limit
  std::uint64_t max_evaluations = 0;
  double max_seconds = 0.0;
};

// What `motoflex loop` does with a fit (the `loop:` section of fit.yaml; plain fits ignore it).
struct LoopOptions {
  std::size_t candidates = 3;      // top-ranked effects refit per iteration
  std::size_t max_iterations = 3;  // effects added at most
  // A candidate is added only if it lowers the validation RMS (over the fitness's channels:
  // the joints, and the IMU when it is scored) by at least this fraction and its validation
  // BIC (n·ln MSE + k·ln n, over the same channels) beats the current model's.
  double min_gain = 0.05;
  std::vector<std::string> effects;  // candidates considered (empty: the whole library)
  StrategyConfig refit_strategy;     // the short warm-started refits
  FitBudget refit_budget;
  LoopOptions() {
    refit_strategy.kind = "cma_es";
    refit_strategy.sigma = 0.1;
    refit_strategy.restarts = 0;
    refit_budget.max_evaluations = 240;
  }
};

// Command-line replacements (they win over the file).
struct FitOverrides {
  std::optional<int> threads;
  std::optional<std::uint64_t> seed;
  std::optional<std::uint64_t> max_generations;
  std::optional<std::uint64_t> max_evaluations;
  std::optional<double> max_seconds;
  std::optional<std::string> out;
  std::optional<std::string> data;
  std::optional<std::string> validation;
};

// A fit read from fit.yaml:
//   name: nao_quick
//   scenario: ../nao_fit_base.yaml      # robot, servo, physics (its motion, if any, is unused)
//   data: ../../reference_data/nao/train   # a folder of logs, or `logs: [a.csv, b.csv]`
//   validation: ../../reference_data/nao/validation   # optional, never fitted on
//   free:                               # name or pattern ('*' within a dotted level)
//     motor.R_ohm: {lower: 3, upper: 12, log: true}
//     joint.*.friction_nm: {lower: 0.01, upper: 3, log: true}        # one tied value
//     gear.*.backlash_rad: {lower: 1e-7, upper: 1e-2, each: true}    # one value per match
//   fixed: {motor.stiffness: 0.7}      # values on top of the robot defaults
//   effects: [stribeck, sensor_delay]  # frees each effect's parameters (effect_library.hpp)
//   fitness: {m: 2, settle_s: 0.0, weights: {LKneePitch: 2.0}, early_termination: true}
//   # imu_weight: 1 also scores the logs' imu.roll/imu.pitch (fitness.hpp); default 0
//   strategy: {kind: mu_plus_lambda, mu: 10, lambda: 40, kappa: 3}
//   budget: {generations: 30, evaluations: 2000, seconds: 600}
//   threads: 2
//   seed: 1
//   out: ../../runs/nao_quick
//   loop: {candidates: 3, max_iterations: 3, min_gain: 0.05, effects: [...],
//          refit: {strategy: {kind: cma_es, sigma: 0.1}, budget: {evaluations: 240}}}
// `data` and `validation` take a folder, a file, or a list of them; a folder of BAM JSON logs
// (and no *.csv) is imported on the fly into <out>/imported/{train,validation}/.
struct FitConfig {
  std::string path;  // the fit.yaml
  std::string name;
  std::string scenario_path;
  std::vector<std::string> train_logs;       // absolute paths, sorted
  std::vector<std::string> validation_logs;  // may be empty
  std::vector<FreeParameter> free;           // expanded patterns, with start values
  std::vector<std::pair<std::string, double>> fixed;
  std::vector<std::string> effects;  // declared with `effects:` (their parameters are in `free`)
  LoopOptions loop;
  FitnessOptions fitness;
  StrategyConfig strategy;
  FitBudget budget;
  int threads = 1;
  std::uint64_t seed = 1;
  std::string out_dir;
  // Stop rollouts that cannot beat the selection threshold (fitness: {early_termination: ..}).
  // Selection is identical either way, so it is not part of the identity.
  bool early_termination = true;

  // Loaded from the files above.
  std::shared_ptr<const Scenario> scenario;
  std::shared_ptr<FitnessFunction> train;
  std::shared_ptr<FitnessFunction> validation;  // null without validation logs
  std::shared_ptr<ParameterSpace> space;

  // What decides the result of the run: everything above except threads, budget and out_dir,
  // with the contents of the scenario, robot and log files. Two configs with the same hash give
  // the same generations bit for bit.
  nlohmann::json identity;
  std::string hash;
  // The command-line overrides this config was loaded with (written to run.json, so that
  // `motoflex resume` rebuilds the same config).
  nlohmann::json overrides = nlohmann::json::object();
};

nlohmann::json overrides_to_json(const FitOverrides& overrides);
// Every field of a strategy, as the `strategy:` section of a fit config reads it back.
nlohmann::ordered_json strategy_to_json(const StrategyConfig& strategy);
FitOverrides overrides_from_json(const nlohmann::json& json);

// Throws InputError naming file, line and field for anything wrong in the fit config, the
// scenario, or the logs (a log of another robot, missing columns, unknown parameters).
FitConfig load_fit_config(const std::string& path, const FitOverrides& overrides = {});

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
