#include "motoflex/fit/refit_config.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "motoflex/fit/effect_parameters.hpp"
#include "motoflex/core/atomic_file.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

nlohmann::ordered_json free_entry(const FreeParameter& p, double start) {
  return {{"lower", p.lower},
          {"upper", p.upper},
          {"log", p.log_scale},
          {"start", std::clamp(start, p.lower, p.upper)}};
}

}  // namespace

std::string write_refit_config(const FitConfig& from, const nlohmann::json& fitted_free,
                               const Effect& effect,
                               const std::vector<std::pair<std::string, double>>& effect_start,
                               const std::string& dir) {
  nlohmann::ordered_json fit;
  fit["name"] = from.name + "+" + effect.name;
  fit["scenario"] = from.scenario_path;
  fit["logs"] = from.train_logs;
  if (!from.validation_logs.empty()) fit["validation"] = from.validation_logs;

  nlohmann::ordered_json free = nlohmann::ordered_json::object();
  std::set<std::string> taken;
  for (const FreeParameter& p : from.free) {
    const double start = fitted_free.contains(p.name) ? fitted_free[p.name].get<double>() : p.start;
    free[p.name] = free_entry(p, start);
    taken.insert(p.targets.begin(), p.targets.end());
  }
  nlohmann::ordered_json fixed = nlohmann::ordered_json::object();
  for (const auto& [name, value] : from.fixed) {
    fixed[name] = value;
    taken.insert(name);
  }
  for (const FreeParameter& p : effect_free_parameters(effect, from.space->base(), taken)) {
    double start = p.start;
    for (const auto& [name, value] : effect_start) {
      if (name == p.targets.front()) start = value;
    }
    free[p.name] = free_entry(p, start);
  }
  fit["free"] = free;
  if (!fixed.empty()) fit["fixed"] = fixed;
  std::vector<std::string> effects = from.effects;
  if (std::find(effects.begin(), effects.end(), effect.name) == effects.end()) {
    effects.push_back(effect.name);
  }
  fit["effects"] = effects;

  nlohmann::ordered_json fitness = {{"m", from.fitness.m},
                                    {"settle_s", from.fitness.settle_s},
                                    {"early_termination", from.early_termination}};
  if (!from.fitness.joint_weights.empty()) {
    const RobotModel& model = *from.scenario->model;
    for (std::size_t j = 0; j < model.actuators.size(); ++j) {
      fitness["weights"][model.actuators[j].name] = from.fitness.joint_weights[j];
    }
  }
  if (from.fitness.imu_weight > 0.0) fitness["imu_weight"] = from.fitness.imu_weight;
  fit["fitness"] = fitness;
  fit["strategy"] = strategy_to_json(from.loop.refit_strategy);
  const FitBudget& budget = from.loop.refit_budget;
  fit["budget"] = {{"generations", budget.max_generations},
                   {"evaluations", budget.max_evaluations},
                   {"seconds", budget.max_seconds}};
  fit["threads"] = from.threads;
  fit["seed"] = from.seed;
  fit["out"] = ".";

  fs::create_directories(dir);
  const std::string path = (fs::path(dir) / "fit.yaml").string();
  write_file_atomically(path, "# Written by `motoflex loop`: " + from.name +
                                  " refit with effect '" + effect.name +
                                  "' (JSON is valid YAML)\n" + fit.dump(2) + "\n");
  return path;
}

}  // namespace motoflex
