#include "motoflex/fit/fit_inputs.hpp"

namespace motoflex {

nlohmann::ordered_json fit_inputs_json(const FitConfig& config) {
  nlohmann::ordered_json out;
  out["name"] = config.name;
  out["fit"] = config.path;
  out["scenario"] = config.scenario_path;
  out["robot"] = config.scenario ? config.scenario->model->name : std::string();
  out["seed"] = config.seed;
  out["strategy"] = strategy_to_json(config.strategy);
  out["budget"] = {{"generations", config.budget.max_generations},
                   {"evaluations", config.budget.max_evaluations},
                   {"seconds", config.budget.max_seconds},
                   {"stall_evaluations", config.budget.stall_evaluations},
                   {"stall_relative", config.budget.stall_relative}};
  out["effects"] = config.effects;
  out["fitness"] = {{"m", config.fitness.m},
                    {"settle_s", config.fitness.settle_s},
                    {"window_s", config.fitness.window_s},
                    {"imu_weight", config.fitness.imu_weight},
                    {"error", config.fitness.absolute_error ? "absolute" : "squared"}};
  nlohmann::ordered_json free = nlohmann::ordered_json::array();
  for (const FreeParameter& p : config.free_parameters) {
    // A tied pattern ("joint.*.friction_nm") names its unit by the same suffix as its targets.
    const std::string& unit_source = p.targets.empty() ? p.name : p.targets.front();
    free.push_back({{"name", p.name},
                    {"unit", unit_from_parameter_name(unit_source)},
                    {"start", p.start},
                    {"lower", p.lower},
                    {"upper", p.upper},
                    {"log", p.log_scale},
                    {"targets", p.targets}});
  }
  out["free"] = free;
  out["train_logs"] = config.train_logs;
  out["validation_logs"] = config.validation_logs;
  return out;
}

}  // namespace motoflex
