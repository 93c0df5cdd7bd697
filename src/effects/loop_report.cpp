#include "motoflex/effects/loop_report.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_run.hpp"
#include "motoflex/io/plot_script.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string format(const char* fmt, double value) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, value);
  return text;
}

std::string percent_change(double before, double after) {
  return before > 0.0 ? format("%+.1f %%", 100.0 * (after - before) / before) : "–";
}

std::string joint_table(const ResidualAnalysis& before, const ResidualAnalysis* after) {
  std::ostringstream md;
  md << "| joint | RMS before (deg) |" << (after ? " RMS after (deg) | change |" : "")
     << " bias (deg) | best lag (ms) |\n|---|---|" << (after ? "---|---|" : "") << "---|---|\n";
  for (std::size_t j = 0; j < before.joints.size(); ++j) {
    const JointResiduals& b = before.joints[j];
    md << "| " << b.joint << " | " << format("%.4f", b.rms_deg) << " | ";
    if (after) {
      const JointResiduals& a = after->joints[j];
      md << format("%.4f", a.rms_deg) << " | " << percent_change(b.rms_deg, a.rms_deg) << " | ";
    }
    md << format("%.4f", b.mean_deg) << " | " << format("%.0f", 1e3 * b.best_lag_s) << " |\n";
  }
  return md.str();
}

void write_analysis(const fs::path& dir, const ResidualAnalysis& analysis, const char* stem) {
  write_file_atomically((dir / (std::string(stem) + "_series.csv")).string(),
                        residual_series_csv(analysis));
}

}  // namespace

nlohmann::ordered_json ranking_json(const EffectRanking& ranking) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const EffectScore& s : ranking.scores) {
    nlohmann::ordered_json item;
    item["effect"] = s.effect;
    item["status"] = s.status;
    if (s.scored()) {
      item["score"] = s.explained;
      item["delta_bic"] = s.delta_bic;
      item["coefficients"] = s.coefficients;
      nlohmann::ordered_json estimate = nlohmann::ordered_json::object();
      for (const auto& [name, value] : s.estimate) estimate[name] = value;
      item["estimate"] = estimate;
    }
    out.push_back(item);
  }
  return out;
}

std::string ranking_markdown(const EffectRanking& ranking) {
  const std::string warning =
      ranking.reliable ? std::string()
                       : "**UNRELIABLE ranking**: " + ranking.unreliable_reason +
                             ". Resume the fit until it converges before trusting this order.\n\n";
  std::ostringstream md;
  md << warning
     << "| rank | effect | explained | ΔBIC | coefficients | signature |\n"
        "|---|---|---|---|---|---|\n";
  std::size_t rank = 0;
  for (const EffectScore& s : ranking.scores) {
    const Effect& effect = find_effect(s.effect);
    if (s.scored()) {
      md << "| " << ++rank << " | " << s.effect << " | " << format("%.1f %%", 100.0 * s.explained)
         << " | " << format("%.4g", s.delta_bic) << " | " << s.coefficients << " | "
         << effect.signature << " |\n";
    } else {
      md << "| – | " << s.effect << " | " << s.status << " | | | " << effect.signature << " |\n";
    }
  }
  md << "\nN = " << ranking.samples
     << " residual samples (N_eff = " << format("%.0f", ranking.effective_samples)
     << "), RSS₀ = " << format("%.4g", ranking.rss0_rad2)
     << " rad². Score: share of the residual sum of squares the effect's probe signature "
        "explains beyond re-tuning the fit's own parameters; ΔBIC = N_eff·ln(RSS₁/RSS₀) + "
        "k·ln N_eff (negative = supported).\n";
  return md.str();
}

void write_residual_report(const std::string& dir_text, const FitConfig& config,
                           const ParameterSet& best, const EffectRanking& ranking) {
  const fs::path dir(dir_text);
  fs::create_directories(dir);
  const ResidualAnalysis train = analyse_residuals(*config.train, best);
  nlohmann::ordered_json json;
  json["fit"] = config.path;
  json["unit"] = "deg";
  json["train"] = residual_analysis_json(train);
  write_analysis(dir, train, "train");
  std::ostringstream md;
  md << "# Residuals of " << config.name << "\n\nTraining logs: overall RMS "
     << format("%.4f", train.rms_deg) << " deg.\n\n"
     << joint_table(train, nullptr);
  if (config.validation) {
    const ResidualAnalysis validation = analyse_residuals(*config.validation, best);
    json["validation"] = residual_analysis_json(validation);
    write_analysis(dir, validation, "validation");
    md << "\nValidation logs: overall RMS " << format("%.4f", validation.rms_deg) << " deg.\n\n"
       << joint_table(validation, nullptr);
  }
  json["ranking_reliable"] = ranking.reliable;
  if (!ranking.reliable) json["ranking_unreliable_because"] = ranking.unreliable_reason;
  json["ranking"] = ranking_json(ranking);
  json["samples"] = ranking.samples;
  json["effective_samples"] = ranking.effective_samples;
  md << "\n## Candidate effects\n\n"
     << ranking_markdown(ranking)
     << "\nPlots: residual_time.png, residual_vs_velocity.png, residual_vs_torque.png, "
        "residual_lag.png, ranking.png.\n";
  write_file_atomically((dir / "residuals.json").string(), json.dump(2) + "\n");
  write_file_atomically((dir / "residuals.md").string(), md.str());
  run_plot_script("plot_residuals.py", {dir.string()});
}

namespace {

nlohmann::ordered_json iteration_json(const LoopIteration& it) {
  nlohmann::ordered_json item;
  nlohmann::ordered_json ranking = nlohmann::ordered_json::array();
  for (const EffectScore& s : it.ranking.scores) {
    if (s.scored())
      ranking.push_back({{"effect", s.effect}, {"score", s.explained}, {"delta_bic", s.delta_bic}});
  }
  item["ranking"] = ranking;
  item["ranking_reliable"] = it.ranking.reliable;
  item["ranking_detail"] = ranking_json(it.ranking);
  item["added_effect"] = it.added_effect.empty() ? nlohmann::ordered_json(nullptr)
                                                 : nlohmann::ordered_json(it.added_effect);
  item["reoptimised"] = it.reoptimised;
  if (it.reoptimised) item["reoptimised_from"] = it.reoptimised_from;
  if (!it.discovery_proposal.empty()) {
    item["discovery"] = {{"proposal", it.discovery_proposal},
                         {"explained", it.discovery_explained},
                         {"delta_bic", it.discovery_delta_bic}};
  }
  if (!it.discovered_formula.empty()) item["discovered_formula"] = it.discovered_formula;
  item["fitted"] = it.fitted;
  item["train_rms_before"] = it.train_rms_before_deg;
  item["train_rms_after"] = it.train_rms_after_deg;
  item["val_rms_before"] = it.val_rms_before_deg;
  item["val_rms_after"] = it.val_rms_after_deg;
  item["val_mae_before_rad"] = it.val_mae_before_rad;
  item["val_mae_after_rad"] = it.val_mae_after_rad;
  if (std::isfinite(it.val_imu_rms_before_deg)) {
    item["val_imu_rms_before"] = it.val_imu_rms_before_deg;
    item["val_imu_rms_after"] = it.val_imu_rms_after_deg;
  }
  item["unit"] = "deg";
  nlohmann::ordered_json refits = nlohmann::ordered_json::array();
  for (const LoopRefit& r : it.refits) {
    refits.push_back({{"effect", r.effect},
                      {"run_dir", r.run_dir},
                      {"train_rms", r.train_rms_deg},
                      {"val_rms", r.val_rms_deg},
                      {"val_mae_rad", r.val_mae_rad},
                      {"val_imu_rms", std::isfinite(r.val_imu_rms_deg)
                                          ? nlohmann::ordered_json(r.val_imu_rms_deg)
                                          : nlohmann::ordered_json(nullptr)},
                      {"val_bic", r.val_bic},
                      {"free_parameters", r.free_parameters},
                      {"evaluations", r.evaluations},
                      {"seconds", r.seconds},
                      {"significant", r.significant},
                      {"inert", r.inert},
                      {"reoptimises", r.reoptimises}});
  }
  item["refits"] = refits;
  item["model_run_dir"] = it.model_run_dir;
  item["ranking_seconds"] = it.ranking_seconds;
  return item;
}

nlohmann::ordered_json loop_json(const LoopResult& result, const FitConfig& user) {
  nlohmann::ordered_json loop;
  loop["fit"] = user.path;
  // The options that decide its path, as run (the config file may change after it): its
  // `loop:` section as the spec writer gives it (the section loop_identity.json hashes) and
  // its seed. A report comparing loops reads them here (scripts/report_real_servos.py).
  loop["options"] = loop_options_to_json(user.loop);
  loop["options"]["seed"] = user.seed;
  loop["base_model"] = result.base_model;
  loop["iterations"] = nlohmann::ordered_json::array();
  for (const LoopIteration& it : result.iterations)
    loop["iterations"].push_back(iteration_json(it));
  loop["final_model"] = result.final_model;
  loop["base_run_dir"] = result.base_run_dir;
  loop["rankings_reliable"] = result.unreliable_reason.empty();
  if (!result.unreliable_reason.empty())
    loop["rankings_unreliable_because"] = result.unreliable_reason;
  loop["final_run_dir"] = result.final_run_dir;
  loop["evaluations"] = result.evaluations;
  loop["probe_rollouts"] = result.probe_rollouts;
  loop["fit_seconds"] = result.fit_seconds;
  loop["wall_seconds"] = result.wall_seconds;
  return loop;
}

// Logs of a robot without a torso IMU (a servo bench) carry zero IMU columns that the
// simulation matches exactly: a line of 0 → 0 says nothing, so it is left out.
bool has_imu_signal(const LoopResult& result) {
  for (const LoopIteration& it : result.iterations) {
    if (std::isfinite(it.val_imu_rms_before_deg) &&
        (it.val_imu_rms_before_deg != 0.0 || it.val_imu_rms_after_deg != 0.0)) {
      return true;
    }
  }
  return false;
}

// The summary table of report.md: what each iteration added and the errors before and after.
void write_loop_summary(std::ostringstream& md, const LoopResult& result, const FitConfig& user) {
  md << "# Closing the loop: " << user.name << "\n\n";
  md << "Base model: " << (result.base_model.empty() ? "–" : "");
  for (std::size_t i = 0; i < result.base_model.size(); ++i) {
    md << (i ? ", " : "") << result.base_model[i];
  }
  md << ". Final model adds: ";
  bool any = false;
  for (const auto& it : result.iterations) {
    if (it.added_effect.empty()) continue;
    md << (any ? ", " : "") << it.added_effect;
    if (!it.discovered_formula.empty()) md << " (" << it.discovered_formula << ")";
    any = true;
  }
  md << (any ? "" : "nothing") << ".\n\n";
  if (user.loop.control) {
    md << "Each iteration also refits the current model alone (`control`); an effect must beat "
          "the better of the two. An effect that does nothing at its refit's optimum (*inert*) is "
          "never credited. An iteration marked re-optimised credited no effect and went on from "
          "the control or from an inert refit's values without the effect.\n\n";
  }
  md << "| iteration | added | train RMS before → after (deg) | validation RMS before → after "
        "(deg) | validation MAE before → after (mrad) |\n|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < result.iterations.size(); ++i) {
    const LoopIteration& it = result.iterations[i];
    const std::string added = !it.added_effect.empty() ? it.added_effect
                              : it.reoptimised ? "– (re-optimised: " + it.reoptimised_from + ")"
                                               : "–";
    md << "| " << i + 1 << " | " << added << " | " << format("%.4f", it.train_rms_before_deg)
       << " → " << format("%.4f", it.train_rms_after_deg) << " | "
       << format("%.4f", it.val_rms_before_deg) << " → " << format("%.4f", it.val_rms_after_deg)
       << " (" << percent_change(it.val_rms_before_deg, it.val_rms_after_deg) << ") | "
       << format("%.3f", 1e3 * it.val_mae_before_rad) << " → "
       << format("%.3f", 1e3 * it.val_mae_after_rad) << " |\n";
  }
  const bool imu = has_imu_signal(result);
  for (std::size_t i = 0; imu && i < result.iterations.size(); ++i) {
    const LoopIteration& it = result.iterations[i];
    if (!std::isfinite(it.val_imu_rms_before_deg)) continue;
    md << (i == 0 ? "\nTorso IMU (roll and pitch), validation RMS: " : "; ") << "iteration "
       << i + 1 << " " << format("%.4f", it.val_imu_rms_before_deg) << " → "
       << format("%.4f", it.val_imu_rms_after_deg) << " deg"
       << (i + 1 == result.iterations.size() ? ".\n" : "");
  }
  md << "\nEvaluations: " << result.evaluations << " (fits) + " << result.probe_rollouts
     << " probe rollouts; fit time " << format("%.1f", result.fit_seconds) << " s; wall time "
     << format("%.1f", result.wall_seconds) << " s.\n";
}

// One section per iteration: its ranking and its refits.
void write_loop_iterations(std::ostringstream& md, const LoopResult& result) {
  for (std::size_t i = 0; i < result.iterations.size(); ++i) {
    const LoopIteration& it = result.iterations[i];
    md << "\n## Iteration " << i + 1 << "\n\nRanking of the residual of `" << it.model_run_dir
       << "`:\n\n"
       << ranking_markdown(it.ranking) << "\nRefits (warm-started):\n\n"
       << "| effect | train RMS (deg) | validation RMS (deg) | validation BIC | free | "
          "evaluations | seconds | significant |\n|---|---|---|---|---|---|---|---|\n";
    for (const LoopRefit& r : it.refits) {
      md << "| " << r.effect << " | " << format("%.4f", r.train_rms_deg) << " | "
         << format("%.4f", r.val_rms_deg) << " | " << format("%.1f", r.val_bic) << " | "
         << r.free_parameters << " | " << r.evaluations << " | " << format("%.1f", r.seconds)
         << " | "
         << (r.significant   ? "yes"
             : r.inert       ? (r.reoptimises ? "no (inert; re-optimises)" : "no (inert)")
             : r.reoptimises ? "re-optimises"
                             : "no")
         << " |\n";
    }
    if (!it.discovery_proposal.empty()) {
      md << "\nNo library effect helped; discovery proposed " << it.discovery_proposal
         << " (linearised; explains " << format("%.3g", it.discovery_explained)
         << " of the residual, ΔBIC " << format("%.3g", it.discovery_delta_bic) << ")"
         << (it.discovered_formula.empty() ? ".\n"
                                           : "; after the refit: " + it.discovered_formula + ".\n");
    }
  }
}

}  // namespace

void write_loop_outputs(const LoopResult& result, const FitConfig& user) {
  const fs::path dir(result.out_dir);
  write_file_atomically((dir / "loop.json").string(), loop_json(result, user).dump(2) + "\n");

  // Residuals before (base fit) and after (final fit) on the validation logs.
  const FinishedFit base = load_finished_fit(result.base_run_dir);
  const FinishedFit final_fit = load_finished_fit(result.final_run_dir);
  const ResidualAnalysis before = analyse_residuals(*base.config.validation, base.best);
  const ResidualAnalysis after = analyse_residuals(*final_fit.config.validation, final_fit.best);
  write_file_atomically((dir / "before_series.csv").string(), residual_series_csv(before));
  write_file_atomically((dir / "after_series.csv").string(), residual_series_csv(after));

  std::ostringstream md;
  write_loop_summary(md, result, user);
  write_loop_iterations(md, result);
  md << "\n## Per-joint validation error, base vs final model\n\n" << joint_table(before, &after);
  md << "\n![residuals before and after](residuals_before_after.png)\n\n"
        "![ranking of the first iteration](ranking.png)\n";
  write_file_atomically((dir / "report.md").string(), md.str());
  run_plot_script("plot_loop.py", {dir.string()});
}

}  // namespace motoflex
