// motoflex loop <fit.yaml> [--out DIR] [--data DIR] [--validation DIR] [--threads N] [--seed S]
// fit → residuals → attribute → add → refit, until no significant gain (effect_loop.hpp).

#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "motoflex/effects/effect_loop.hpp"
#include "option_checks.hpp"
#include "report_after_run.hpp"

namespace motoflex::cli {
namespace {

struct LoopArgs {
  std::string fit;
  std::string out, data, validation;
  int threads = 0;
  long long seed = -1;
  bool force = false;  // go on from an unconverged base fit (its rankings marked unreliable)
};

int run_loop_command(const LoopArgs& args) {
  FitOverrides overrides;
  if (!args.out.empty()) overrides.out = args.out;
  if (!args.data.empty()) overrides.data = args.data;
  if (!args.validation.empty()) overrides.validation = args.validation;
  if (args.threads > 0) overrides.threads = args.threads;
  if (args.seed >= 0) overrides.seed = static_cast<std::uint64_t>(args.seed);
  const LoopResult result = run_loop(args.fit, overrides, args.force);
  // The final model's effects, or "the base model's" when the base lists none (and nothing
  // was added).
  std::printf("loop done: model %s", result.final_model.empty() ? "as the base fit's" : "");
  for (std::size_t i = 0; i < result.final_model.size(); ++i) {
    std::printf("%s%s", i ? " + " : "", result.final_model[i].c_str());
  }
  if (!result.iterations.empty()) {
    std::printf("; validation RMS %.4g -> %.4g deg, MAE %.4g -> %.4g mrad",
                result.iterations.front().val_rms_before_deg,
                result.iterations.back().val_rms_after_deg,
                1e3 * result.iterations.front().val_mae_before_rad,
                1e3 * result.iterations.back().val_mae_after_rad);
  }
  std::printf("; %llu evaluations, %.1f s; see %s/report.md\n",
              static_cast<unsigned long long>(result.evaluations), result.wall_seconds,
              result.out_dir.c_str());
  // Every fit of the loop is an ordinary run dir and gets its own page; the loop's page shows
  // the before/after and the final model's fit.
  write_report_after_run(result.base_run_dir);
  for (const auto& iteration : result.iterations) {
    for (const auto& refit : iteration.refits) write_report_after_run(refit.run_dir);
  }
  // A re-optimised model carried over from an inert refit is a fit of its own (NN_reoptimised_*).
  if (result.final_run_dir != result.base_run_dir) write_report_after_run(result.final_run_dir);
  write_report_after_run(result.out_dir);
  return 0;
}

}  // namespace

CommandRunner add_loop_command(CLI::App& app) {
  auto args = std::make_shared<LoopArgs>();
  CLI::App* sub = app.add_subcommand(
      "loop", "fit, find the missing effect in the residual, add it, refit; report before/after");
  sub->add_option("fit", args->fit, "fit config YAML (its `loop:` section sets the options)")
      ->required();
  sub->add_option("--out", args->out, "loop folder (one run folder per fit inside)");
  sub->add_option("--data", args->data, "training logs (folder of CSV or BAM JSON logs)");
  sub->add_option("--validation", args->validation, "validation logs (CSV or BAM JSON)");
  sub->add_option("--threads", args->threads, "threads evaluating individuals")
      ->check(thread_count());
  sub->add_option("--seed", args->seed, "random seed")->check(seed_value());
  sub->add_flag("--force", args->force,
                "go on when the base fit did not converge (every ranking marked unreliable)");
  return [args] { return run_loop_command(*args); };
}

}  // namespace motoflex::cli
