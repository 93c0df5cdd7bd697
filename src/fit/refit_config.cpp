#include "motoflex/fit/refit_config.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/fit/effect_parameters.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

FreeParameterSpec free_spec(const FreeParameter& p, double start) {
  FreeParameterSpec spec;
  spec.pattern = p.name;
  spec.lower = p.lower;
  spec.upper = p.upper;
  spec.log_scale = p.log_scale;
  spec.start = std::clamp(start, p.lower, p.upper);
  return spec;
}

std::vector<LogSource> sources(const std::vector<std::string>& logs) {
  std::vector<LogSource> out;
  for (const auto& log : logs) out.push_back({log, {}});
  return out;
}

}  // namespace

FitSpec refit_spec(const FitConfig& from, const nlohmann::json& fitted_free, const Effect& effect,
                   const std::vector<std::pair<std::string, double>>& effect_start,
                   const std::string& dir, const nlohmann::json& start_free,
                   bool start_is_incumbent) {
  FitSpec spec;
  spec.name = from.name + "+" + effect.name;
  spec.scenario_path = from.scenario_path;
  spec.train_data = sources(from.train_logs);
  spec.validation_data = sources(from.validation_logs);
  std::set<std::string> taken;
  const auto value_in = [](const nlohmann::json& free, const FreeParameter& p, double fallback) {
    return free.is_object() && free.contains(p.name) ? free[p.name].get<double>() : fallback;
  };
  for (const FreeParameter& p : from.free_parameters) {
    const double fitted = value_in(fitted_free, p, p.start);
    spec.free.push_back(free_spec(p, value_in(start_free, p, fitted)));
    spec.incumbent.emplace_back(p.name, std::clamp(fitted, p.lower, p.upper));
    taken.insert(p.targets.begin(), p.targets.end());
  }
  spec.fixed = from.fixed;
  for (const auto& [name, value] : from.fixed) taken.insert(name);
  for (const FreeParameter& p : effect_free_parameters(effect, from.space->base(), taken)) {
    double start = p.start;
    for (const auto& [name, value] : effect_start) {
      if (name == p.targets.front()) start = value;
    }
    spec.free.push_back(free_spec(p, start));
    // The current model has the effect at its neutral value (the nearest one the bounds allow).
    spec.incumbent.emplace_back(
        p.name, std::clamp(from.space->base().get(p.targets.front()), p.lower, p.upper));
  }
  if (start_is_incumbent) {
    for (std::size_t i = 0; i < spec.free.size(); ++i) {
      if (spec.free[i].start) spec.incumbent[i].second = *spec.free[i].start;
    }
  }
  spec.effects = from.effects;
  // An effect built on the fly (the loop's discovered terms) is not listed: its parameters are
  // in `free` above, and `effects:` names library entries only.
  const auto& library = effect_library();
  const bool in_library = std::any_of(library.begin(), library.end(),
                                      [&](const Effect& e) { return e.name == effect.name; });
  if (in_library &&
      std::find(spec.effects.begin(), spec.effects.end(), effect.name) == spec.effects.end()) {
    spec.effects.push_back(effect.name);
  }
  spec.fitness_m = from.fitness_m;
  spec.fitness_settle_s = from.fitness_settle_s;
  spec.joint_weights = from.joint_weights;
  spec.imu_weight = from.imu_weight;
  spec.window_s = from.window_s;
  spec.absolute_error = from.absolute_error;
  spec.early_termination = from.early_termination;
  spec.strategy = from.loop.refit_strategy;
  spec.budget = from.loop.refit_budget;
  spec.polish = from.loop.refit_polish;
  spec.threads = from.threads;
  spec.seed = from.seed;
  spec.out_dir = fs::absolute(dir).lexically_normal().string();
  return spec;
}

FitSpec evaluation_spec(const FitConfig& from, const nlohmann::json& fitted_free,
                        const std::string& dir) {
  const Effect nothing{"evaluation", "", "", {}, false, 0};
  FitSpec spec = refit_spec(from, fitted_free, nothing, {}, dir, nullptr, true);
  spec.name = from.name;
  spec.budget = FitBudget{};
  spec.budget.max_evaluations = 1;
  spec.polish = PolishSpec{};
  spec.polish.covariance = false;
  return spec;
}

std::string write_refit_config(const FitConfig& from, const nlohmann::json& fitted_free,
                               const Effect& effect,
                               const std::vector<std::pair<std::string, double>>& effect_start,
                               const std::string& dir, const nlohmann::json& start_free,
                               bool start_is_incumbent) {
  const FitSpec spec =
      refit_spec(from, fitted_free, effect, effect_start, dir, start_free, start_is_incumbent);
  fs::create_directories(dir);
  const std::string path = (fs::path(dir) / "fit.yaml").string();
  write_file_atomically(
      path, "# Written by `motoflex loop`: " + from.name + " refit with effect '" + effect.name +
                "' (JSON is valid YAML)\n" + fit_spec_to_json(spec).dump(2) + "\n");
  return path;
}

}  // namespace motoflex
