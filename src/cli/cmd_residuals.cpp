// motoflex residuals <run-dir> [--out DIR] [--threads N] [--effects a,b]: residual analysis of a
// finished fit and the ranking of the effects that could explain it.

#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "motoflex/effects/convergence_guard.hpp"
#include "motoflex/effects/effect_signature.hpp"
#include "motoflex/effects/loop_report.hpp"
#include "motoflex/fit/fit_run.hpp"
#include "motoflex/model/effect_library.hpp"
#include "option_checks.hpp"
#include "report_after_run.hpp"

namespace motoflex::cli {
namespace {

struct ResidualsArgs {
  std::string run_dir;
  std::string out;
  int threads = 0;
  std::vector<std::string> effects;
  bool force = false;  // rank an unconverged fit anyway (the ranking is marked unreliable)
};

int run_residuals(const ResidualsArgs& args) {
  for (const auto& name : args.effects) find_effect(name, "", 0, "--effects");
  const FinishedFit fit = load_finished_fit(args.run_dir);
  const std::string unreliable =
      check_converged_for_ranking(fit, args.run_dir, args.force, "motoflex residuals");
  const int threads = args.threads > 0 ? args.threads : fit.config.threads;
  EffectRanking ranking = rank_effects(fit.config, fit.best, args.effects, threads);
  ranking.reliable = unreliable.empty();
  ranking.unreliable_reason = unreliable;
  const std::string out =
      args.out.empty() ? (std::filesystem::path(args.run_dir) / "residuals").string() : args.out;
  write_residual_report(out, fit.config, fit.best, ranking);
  std::printf("residuals of %s -> %s/residuals.md\n", args.run_dir.c_str(), out.c_str());
  if (!ranking.reliable) {
    std::printf("  UNRELIABLE ranking (--force): %s\n", unreliable.c_str());
  }
  std::size_t rank = 0;
  for (const auto& s : ranking.scores) {
    if (!s.scored()) continue;
    std::printf("  %zu. %-18s explains %5.1f %%  dBIC %.4g\n", ++rank, s.effect.c_str(),
                100.0 * s.explained, s.delta_bic);
  }
  // The run's HTML report shows the analysis written into the run dir: refresh it.
  if (args.out.empty()) write_report_after_run(args.run_dir);
  return 0;
}

}  // namespace

CommandRunner add_residuals_command(CLI::App& app) {
  auto args = std::make_shared<ResidualsArgs>();
  CLI::App* sub = app.add_subcommand(
      "residuals", "analyse the residual of a finished fit and rank the effects that explain it");
  sub->add_option("run_dir", args->run_dir, "run folder of a finished `motoflex fit`")->required();
  sub->add_option("--out", args->out, "output folder (default: <run_dir>/residuals)");
  sub->add_option("--threads", args->threads, "threads for the probe rollouts")
      ->check(thread_count());
  sub->add_option("--effects", args->effects, "candidate effects (default: all)")->delimiter(',');
  sub->add_flag("--force", args->force,
                "rank a fit that did not converge (the ranking is marked unreliable)");
  return [args] { return run_residuals(*args); };
}

}  // namespace motoflex::cli
