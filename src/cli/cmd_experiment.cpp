// motoflex experiment seed001 --out DIR [--threads N] [--no-plots] [--commands NAME=FILE ...]
// Runs a paper's experiments. seed001: Section 5 of seed 001 (the 200 mm/s walk's pitch
// oscillation and speed, the 50 mm/s walk's fall, the modified reference ZMP) on each model
// variant of scenarios/experiments/seed001.yaml. Writes DIR/seed001.json, torso series and
// figures; prints a one-line JSON summary.

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/studies/seed001/seed001_config.hpp"
#include "motoflex/studies/seed001/seed001_report.hpp"
#include "motoflex/studies/seed001/seed001_study.hpp"
#include "option_checks.hpp"

namespace motoflex::cli {
namespace {

struct ExperimentArgs {
  std::string name;
  std::string out;
  int threads = 1;
  bool no_plots = false;
  std::vector<std::string> commands;  // NAME=FILE: the command file of walk NAME
  Seed001Ensemble ensemble;
};

int run(const ExperimentArgs& args) {
  if (args.threads < 1) throw InputError("", 0, "--threads", "must be >= 1");
  const std::string path = find_experiment_config(args.name);
  Seed001Config config = load_seed001_config(path);
  for (const std::string& item : args.commands) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      throw InputError("", 0, "--commands", "expected NAME=FILE, found '" + item + "'");
    }
    set_walk_command_file(config, item.substr(0, eq), item.substr(eq + 1));
  }
  const Seed001Results results = run_seed001(config, args.threads, args.ensemble);
  write_seed001_report(config, results, args.out, !args.no_plots);

  nlohmann::ordered_json summary;
  summary["out"] = args.out;
  for (const Seed001Run& run : results.runs) {
    if (!run.pending.empty()) {
      summary[run.walk][run.variant] = "pending";
      continue;
    }
    nlohmann::ordered_json r;
    r["speed_mm_s"] = std::isfinite(run.speed_mm_s) ? nlohmann::ordered_json(run.speed_mm_s)
                                                    : nlohmann::ordered_json();
    r["fell"] = run.fell;
    if (run.fell) r["fall_s"] = run.fall_s;
    summary[run.walk][run.variant] = r;
  }
  if (results.zmp) {
    for (std::size_t v = 0; v < results.zmp->variants.size(); ++v) {
      nlohmann::ordered_json chosen;
      if (const int k = results.zmp->chosen[v]; k >= 0) {
        const Seed001ZmpSetting& s = results.zmp->trials[v][static_cast<std::size_t>(k)].setting;
        chosen[s.option] = s.value;
      }
      summary["zmp"][results.zmp->variants[v]] = chosen;
    }
  }
  summary["wall_s"] = results.wall_s;
  std::printf("%s\n", summary.dump().c_str());
  return 0;
}

}  // namespace

CommandRunner add_experiment_command(CLI::App& app) {
  auto args = std::make_shared<ExperimentArgs>();
  CLI::App* sub = app.add_subcommand(
      "experiment", "a paper's experiments: seed001 (seed 001 Section 5: walks, falls, ZMP)");
  sub->add_option("name", args->name,
                  "seed001, or an experiment YAML like scenarios/experiments/seed001.yaml")
      ->required();
  sub->add_option("--out", args->out, "output folder (seed001.json, series/, PNG figures)")
      ->required();
  sub->add_option("--threads", args->threads, "rollouts run at a time (results do not change)")
      ->check(thread_count());
  sub->add_flag("--no-plots", args->no_plots, "skip the PNG figures");
  sub->add_option("--ensemble", args->ensemble.size,
                  "also run every walk N times with its commands perturbed by a tiny noise "
                  "(--ensemble-sigma): how much of a fall time or speed is chaos")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--ensemble-sigma", args->ensemble.sigma_rad,
                  "the perturbation's standard deviation in rad (default 1e-7)")
      ->check(CLI::Range(0.0, 0.01));
  sub->add_option("--seed-ensemble", args->ensemble.quickstep_seeds,
                  "also run every walk of a variant with solver: quick N times with its rows "
                  "shuffled in another order (physics.quickstep_seed 1..N): how much of a fall "
                  "time or speed is the quick step's row order")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--commands", args->commands,
                  "NAME=FILE: replay this command file (2011 MoToFlex format or a joint log) as "
                  "the experiment's command-file walk NAME (e.g. commands_200_1)");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
