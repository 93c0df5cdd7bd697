// motoflex titan <paper.yaml> --out DIR [--threads N] [--no-plots]
// Reproduces the TITAN-VIII torque/power study of seed 000: static standing, the up-and-down
// calibration motion, the crawl in postures A–D and the speed of a 10 s crawl. Writes
// DIR/titan.json, DIR/report.md, CSV series and PNG figures.

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/studies/titan/titan_paper_study.hpp"
#include "motoflex/studies/titan/titan_study_config.hpp"
#include "motoflex/studies/titan/titan_study_report.hpp"
#include "option_checks.hpp"

namespace motoflex::cli {
namespace {

struct TitanArgs {
  std::string config;
  std::string out;
  int threads = 1;
  bool no_plots = false;
};

int run(const TitanArgs& args) {
  if (args.threads < 1) throw InputError("", 0, "--threads", "must be >= 1");
  const TitanStudyConfig config = load_titan_study_config(args.config);
  std::fprintf(stderr,
               "motoflex titan: %zu crawl postures, static, up-and-down on %d thread(s)%s\n",
               config.plan.crawl_postures.size(), args.threads,
               config.plan.timing_crawl_s > 0.0 ? ", then a single-thread timing run" : "");
  TitanPaperStudyResults results;
  try {
    results = run_titan_paper_study(config.plan, args.threads);
  } catch (const std::invalid_argument& error) {
    throw InputError(args.config, 0, "", error.what());
  }
  write_titan_study_report(config, results, args.out, !args.no_plots);
  const nlohmann::ordered_json json = titan_study_json(config, results);
  nlohmann::ordered_json summary;
  summary["out"] = args.out;
  summary["static"] = {{"knee_fz_n", json["static"]["knee_fz_n"]},
                       {"feedback_converge_s", json["static"]["feedback_converge_s"]},
                       {"jacobian_converge_s", json["static"]["jacobian_converge_s"]}};
  summary["updown"] = {{"potential_gain_j", json["updown"]["potential_gain_j"]},
                       {"integrated_power_j", json["updown"]["integrated_power_j"]},
                       {"period_integral_j", json["updown"]["period_integral_j"]}};
  for (const TitanCrawlResult& crawl : results.crawls) {
    summary["crawl_avg_abs_power_w"][to_string(crawl.posture)] = crawl.jacobian.total_w;
  }
  summary["sim_seconds_per_10s_crawl"] = json["sim_seconds_per_10s_crawl"];
  summary["wall_s"] = results.wall_s;
  std::printf("%s\n", summary.dump().c_str());
  bool completed =
      results.stand.end == RolloutEnd::kCompleted && results.updown.end == RolloutEnd::kCompleted;
  for (const TitanCrawlResult& crawl : results.crawls) {
    completed = completed && crawl.end == RolloutEnd::kCompleted;
  }
  if (!completed) {
    std::fprintf(stderr, "motoflex titan: a rollout did not complete (see %s/titan.json)\n",
                 args.out.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

CommandRunner add_titan_command(CLI::App& app) {
  auto args = std::make_shared<TitanArgs>();
  CLI::App* sub = app.add_subcommand(
      "titan", "TITAN-VIII torque/power study of seed 000 (standing, up-and-down, crawl A-D)");
  sub->add_option("config", args->config, "study YAML, e.g. scenarios/titan/paper.yaml")
      ->required();
  sub->add_option("--out", args->out, "output folder (titan.json, report.md, CSV, PNG)")
      ->required();
  sub->add_option("--threads", args->threads,
                  "threads for the study's rollouts (the timing run always uses one)")
      ->check(thread_count());
  sub->add_flag("--no-plots", args->no_plots, "skip the PNG figures");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
