// FitSpec and its parts as JSON: run.json's overrides, the strategy in identities, and whole
// specs written as fit.yaml files (the loop's refits).

#include <filesystem>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

nlohmann::ordered_json log_paths(const std::vector<LogSource>& sources) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const LogSource& source : sources) out.push_back(source.path);
  return out;
}

nlohmann::ordered_json free_json(const FreeParameterSpec& p) {
  nlohmann::ordered_json entry = nlohmann::ordered_json::object();
  if (p.lower) entry["lower"] = *p.lower;
  if (p.upper) entry["upper"] = *p.upper;
  entry["log"] = p.log_scale;
  if (p.each) entry["each"] = true;
  if (p.start) entry["start"] = *p.start;
  return entry;
}

nlohmann::ordered_json budget_json(const FitBudget& budget) {
  return {{"generations", budget.max_generations},
          {"evaluations", budget.max_evaluations},
          {"seconds", budget.max_seconds},
          {"stall_evaluations", budget.stall_evaluations},
          {"stall_relative", budget.stall_relative}};
}

}  // namespace

nlohmann::ordered_json polish_to_json(const PolishSpec& p) {
  nlohmann::ordered_json out = {{"method", p.method.empty() ? std::string("none") : p.method},
                                {"max_iterations", p.max_iterations},
                                {"jacobian_step", p.jacobian_step},
                                {"covariance", p.covariance}};
  // Only when on, so that the identity of a fit without it is what it was before the key.
  if (p.flat_scan > 0) out["flat_scan"] = p.flat_scan;
  if (p.lm_jacobian == FiniteDifferences::kForward) out["jacobian"] = "forward";
  return out;
}

nlohmann::ordered_json strategy_to_json(const StrategyConfig& s) {
  nlohmann::ordered_json out = {{"kind", s.kind},
                                {"mu", s.mu},
                                {"lambda", s.lambda},
                                {"kappa", s.kappa},
                                {"rho", s.rho},
                                {"object_recombination", s.object_recombination},
                                {"step_recombination", s.step_recombination},
                                {"initial_step", s.initial_step},
                                {"sigma", s.sigma},
                                {"population", s.population},
                                {"restarts", s.restarts},
                                {"algorithm", s.algorithm},
                                {"polish", s.polish},
                                {"polish_evaluations", s.polish_evaluations}};
  // Written only when off, so the identity (and config hash) of every earlier run is unchanged.
  if (!s.active) out["active"] = false;
  if (s.pooled_negative_tail) out["negative_weights"] = "pooled";
  if (!s.racing) out["racing"] = false;
  if (s.race_chunk > 0) out["race_chunk"] = s.race_chunk;
  return out;
}

nlohmann::json overrides_to_json(const FitOverrides& o) {
  nlohmann::json out = nlohmann::json::object();
  if (o.threads) out["threads"] = *o.threads;
  if (o.seed) out["seed"] = *o.seed;
  if (o.max_generations) out["max_generations"] = *o.max_generations;
  if (o.max_evaluations) out["max_evaluations"] = *o.max_evaluations;
  if (o.max_seconds) out["max_seconds"] = *o.max_seconds;
  if (o.out) out["out"] = fs::absolute(*o.out).lexically_normal().string();
  if (o.data) out["data"] = fs::absolute(*o.data).lexically_normal().string();
  if (o.validation) out["validation"] = fs::absolute(*o.validation).lexically_normal().string();
  if (o.start_from) out["start_from"] = fs::absolute(*o.start_from).lexically_normal().string();
  return out;
}

FitOverrides overrides_from_json(const nlohmann::json& j) {
  FitOverrides o;
  if (j.contains("threads")) o.threads = j["threads"].get<int>();
  if (j.contains("seed")) o.seed = j["seed"].get<std::uint64_t>();
  if (j.contains("max_generations")) o.max_generations = j["max_generations"].get<std::uint64_t>();
  if (j.contains("max_evaluations")) o.max_evaluations = j["max_evaluations"].get<std::uint64_t>();
  if (j.contains("max_seconds")) o.max_seconds = j["max_seconds"].get<double>();
  if (j.contains("out")) o.out = j["out"].get<std::string>();
  if (j.contains("data")) o.data = j["data"].get<std::string>();
  if (j.contains("validation")) o.validation = j["validation"].get<std::string>();
  if (j.contains("start_from")) o.start_from = j["start_from"].get<std::string>();
  return o;
}

nlohmann::ordered_json loop_options_to_json(const LoopOptions& options) {
  nlohmann::ordered_json loop = {{"candidates", options.candidates},
                                 {"widen", options.widen},
                                 {"max_iterations", options.max_iterations},
                                 {"min_gain", options.min_gain},
                                 {"effects", options.effects},
                                 {"discover_terms", options.discover_terms},
                                 {"discover_always", options.discover_always},
                                 {"discover_screen", options.discover_screen},
                                 {"control", options.control},
                                 {"refit",
                                  {{"strategy", strategy_to_json(options.refit_strategy)},
                                   {"budget", budget_json(options.refit_budget)}}}};
  if (!options.refit_polish.method.empty()) {
    loop["refit"]["polish"] = polish_to_json(options.refit_polish);
  }
  if (options.refit_scan > 0) loop["refit"]["scan"] = options.refit_scan;
  if (options.refit_scan_pairs) loop["refit"]["scan_pairs"] = true;
  return loop;
}

nlohmann::ordered_json fit_spec_to_json(const FitSpec& spec) {
  nlohmann::ordered_json fit;
  fit["name"] = spec.name;
  fit["scenario"] = spec.scenario_path;
  fit["logs"] = log_paths(spec.train_data);
  if (!spec.validation_data.empty()) fit["validation"] = log_paths(spec.validation_data);
  nlohmann::ordered_json free = nlohmann::ordered_json::object();
  for (const FreeParameterSpec& p : spec.free) free[p.pattern] = free_json(p);
  fit["free"] = free;
  if (!spec.fixed.empty()) {
    nlohmann::ordered_json fixed = nlohmann::ordered_json::object();
    for (const auto& [name, value] : spec.fixed) fixed[name] = value;
    fit["fixed"] = fixed;
  }
  if (!spec.effects.empty()) fit["effects"] = spec.effects;
  if (!spec.incumbent.empty()) {
    nlohmann::ordered_json incumbent = nlohmann::ordered_json::object();
    for (const auto& [name, value] : spec.incumbent) incumbent[name] = value;
    fit["incumbent"] = incumbent;
  }
  nlohmann::ordered_json fitness = {{"m", spec.fitness_m},
                                    {"settle_s", spec.fitness_settle_s},
                                    {"early_termination", spec.early_termination}};
  if (!spec.joint_weights.empty()) {
    for (const auto& [joint, weight] : spec.joint_weights) fitness["weights"][joint] = weight;
  }
  if (spec.imu_weight > 0.0) fitness["imu_weight"] = spec.imu_weight;
  if (spec.window_s > 0.0) fitness["window_s"] = spec.window_s;
  if (spec.absolute_error) fitness["error"] = "absolute";
  fit["fitness"] = fitness;
  fit["strategy"] = strategy_to_json(spec.strategy);
  fit["budget"] = budget_json(spec.budget);
  if (!spec.polish.method.empty()) fit["polish"] = polish_to_json(spec.polish);
  if (spec.hold_identified) fit["hold_identified"] = true;
  fit["loop"] = loop_options_to_json(spec.loop);
  fit["threads"] = spec.threads;
  fit["seed"] = spec.seed;
  fit["out"] = spec.out_dir;
  return fit;
}

}  // namespace motoflex
