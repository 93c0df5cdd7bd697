// motoflex fit <fit.yaml> [--threads N] [--seed S] [--max-generations G] [--max-evaluations E]
//                         [--max-seconds T] [--out DIR] [--data DIR] [--validation DIR]
//                         [--start-from BEST.json]
// motoflex resume <run-dir> [--threads N] [--max-generations G] [--max-evaluations E]
//                           [--max-seconds T]
// Under mpirun/srun with several processes both run distributed (see fit_on_ranks.hpp).

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fit_on_ranks.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_session.hpp"
#include "option_checks.hpp"

namespace motoflex::cli {
namespace {

struct FitArgs {
  std::string target;  // fit.yaml or run dir
  int threads = 0;
  long long seed = -1;
  long long max_generations = -1;
  long long max_evaluations = -1;
  double max_seconds = -1.0;
  std::string out, data, validation, start_from;
};

void add_budget_options(CLI::App* sub, FitArgs& args) {
  sub->add_option("--threads", args.threads, "OpenMP threads evaluating individuals")
      ->check(thread_count());
  sub->add_option("--max-generations", args.max_generations, "stop after this many generations")
      ->check(positive_count());
  sub->add_option("--max-evaluations", args.max_evaluations, "stop before exceeding this many")
      ->check(positive_count());
  sub->add_option("--max-seconds", args.max_seconds, "stop after this wall time")
      ->check(positive_seconds());
}

void apply_budget(const FitArgs& args, FitOverrides& overrides) {
  if (args.threads > 0) overrides.threads = args.threads;
  if (args.max_generations >= 0) overrides.max_generations = args.max_generations;
  if (args.max_evaluations >= 0) overrides.max_evaluations = args.max_evaluations;
  if (args.max_seconds >= 0.0) overrides.max_seconds = args.max_seconds;
}

int run_fit_command(const FitArgs& args) {
  FitOverrides overrides;
  apply_budget(args, overrides);
  if (args.seed >= 0) overrides.seed = static_cast<std::uint64_t>(args.seed);
  if (!args.out.empty()) overrides.out = args.out;
  if (!args.data.empty()) overrides.data = args.data;
  if (!args.validation.empty()) overrides.validation = args.validation;
  if (!args.start_from.empty()) overrides.start_from = args.start_from;
  return run_fit_on_ranks([&] { return load_fit_config(args.target, overrides); }, false);
}

int run_resume_command(const FitArgs& args) {
  FitOverrides overrides;
  apply_budget(args, overrides);  // threads and budget may change on resume
  return run_fit_on_ranks([&] { return load_run_config(args.target, overrides); }, true);
}

}  // namespace

CommandRunner add_fit_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* sub = app.add_subcommand("fit", "fit model parameters to joint logs");
  sub->add_option("fit", args->target, "fit config YAML")->required();
  add_budget_options(sub, *args);
  sub->add_option("--seed", args->seed, "random seed")->check(seed_value());
  sub->add_option("--out", args->out, "run folder (checkpoint, results, plots)");
  sub->add_option("--data", args->data, "folder of training logs");
  sub->add_option("--validation", args->validation, "folder of validation logs");
  sub->add_option("--start-from", args->start_from,
                  "an earlier run's best.json: start there, never end worse (chained fits)");
  return [args] { return run_fit_command(*args); };
}

CommandRunner add_resume_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* sub = app.add_subcommand("resume", "continue a fit from its last checkpoint");
  sub->add_option("run_dir", args->target, "run folder of `motoflex fit`")->required();
  add_budget_options(sub, *args);
  return [args] { return run_resume_command(*args); };
}

}  // namespace motoflex::cli
