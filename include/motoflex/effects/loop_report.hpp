#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "motoflex/effects/effect_loop.hpp"
#include "motoflex/effects/effect_signature.hpp"
#include "motoflex/effects/residual_analysis.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex {

// [{"effect", "score", "delta_bic", "coefficients", "status", "estimate": {...}}, ...]; score is
// the fraction of the residual sum of squares the effect's signature explains.
nlohmann::ordered_json ranking_json(const EffectRanking& ranking);
std::string ranking_markdown(const EffectRanking& ranking);

// `motoflex residuals`: writes into `dir` residuals.json (per-joint analysis of the training and,
// when present, validation logs + the effect ranking), residuals.md, residual_series.csv and
// the PNG plots of scripts/plot_residuals.py.
void write_residual_report(const std::string& dir, const FitConfig& config,
                           const ParameterSet& best, const EffectRanking& ranking);

// `motoflex loop`: loop.json, report.md and plots in result.out_dir.
void write_loop_outputs(const LoopResult& result, const FitConfig& user);

}  // namespace motoflex
