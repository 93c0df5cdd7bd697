#include "fit_outputs.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fit_sensitivity.hpp"
#include "fit_uncertainty_outputs.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/core/text_hash.hpp"
#include "motoflex/core/utc_time.hpp"
#include "motoflex/fit/excitation_check.hpp"
#include "motoflex/fit/fit_report.hpp"
#include "motoflex/io/plot_script.hpp"

namespace motoflex::detail {
namespace {

namespace fs = std::filesystem;

// The logs a fit read, each with its role and the hash of its CSV (so an export can say which
// data its numbers came from, and a changed file shows).
nlohmann::ordered_json data_files_json(const FitConfig& config) {
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  const auto add = [&files](const std::vector<std::string>& paths, const char* role) {
    for (const auto& path : paths) {
      std::ifstream in(path, std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      files.push_back({{"role", role}, {"path", path}, {"hash", hash_text(text.str())}});
    }
  };
  add(config.train_logs, "train");
  add(config.validation_logs, "validation");
  return files;
}

void write_best_json(const FitConfig& config, const RunResult& result, const ParameterSet& best) {
  nlohmann::ordered_json best_json;
  best_json["fitness"] = result.best_fitness;
  nlohmann::ordered_json free = nlohmann::ordered_json::object();
  for (const auto& [name, value] : config.space->values(result.best_x)) free[name] = value;
  best_json["free"] = free;
  best_json["parameters"] = nlohmann::ordered_json::parse(parameter_set_to_json(best));
  best_json["provenance"] = {{"fit", config.path},
                             {"config_hash", config.hash},
                             {"robot", config.scenario->model->name},
                             {"date", utc_now_iso8601()},
                             {"motoflex_version", version()},
                             {"run", fs::absolute(config.out_dir).lexically_normal().string()},
                             {"data", data_files_json(config)}};
  write_file_atomically((fs::path(config.out_dir) / "best.json").string(),
                        best_json.dump(2) + "\n");
}

std::vector<FittedParameter> fitted_parameters(const FitConfig& config, const RunResult& result) {
  const std::vector<double>& x = result.best_x;
  std::vector<FittedParameter> out;
  const auto values = config.space->values(x);
  const auto& free = config.space->free_parameters();
  for (std::size_t i = 0; i < free.size(); ++i) {
    const FreeParameter& p = free[i];
    out.push_back({p.name, unit_from_parameter_name(p.targets.front()), p.start, p.lower, p.upper,
                   values[i].second, p.log_scale});
    if (i < result.sensitivity.size()) out.back().sensitivity = result.sensitivity[i];
  }
  return out;
}

// Per parameter the relative fitness change per bound-width and whether the data determine it;
// "undetermined" lists the names the data cannot pin down.
nlohmann::ordered_json sensitivity_json(const std::vector<FittedParameter>& parameters) {
  nlohmann::ordered_json per = nlohmann::ordered_json::object();
  nlohmann::ordered_json undetermined = nlohmann::ordered_json::array();
  for (const auto& p : parameters) {
    per[p.name] = {{"relative_fitness_change_per_bound_width", p.sensitivity},
                   {"determined", !p.undetermined()}};
    if (p.undetermined()) undetermined.push_back(p.name);
  }
  return {{"step_share_of_bounds", kSensitivityStep},
          {"undetermined_below", kUndeterminedBelow},
          {"parameters", per},
          {"undetermined", undetermined}};
}

}  // namespace

FitSummary write_fit_outputs(const FitConfig& config, const FitProblem& problem,
                             const RunResult& result) {
  FitSummary summary;
  summary.name = config.name;
  summary.run_dir = config.out_dir;
  summary.strategy = result.strategy;
  summary.evaluator = result.evaluator;
  summary.stop_reason = result.stop_reason;
  summary.converged = result.converged;
  summary.convergence = result.convergence;
  summary.best_fitness = result.best_fitness;
  summary.evaluations = result.evaluations;
  summary.generations = result.generations;
  summary.polish_evaluations = result.polish_evaluations;
  summary.seconds = result.seconds;
  summary.individuals_stopped_early = problem.stopped_early();
  summary.frames_simulated = problem.frames_simulated();
  summary.frames_saved = problem.frames_saved();
  summary.invalid_candidates = problem.invalid_candidates();
  summary.invalid_reasons = problem.invalid_reasons();
  if (result.best_x.empty()) return summary;

  const fs::path dir = config.out_dir;
  const ParameterSet best = config.space->apply(result.best_x);
  write_best_json(config, result, best);
  summary.parameters = fitted_parameters(config, result);

  const DetailedEvaluation train = evaluate_in_detail(*config.train, best);
  nlohmann::ordered_json& json = summary.details;
  json["name"] = config.name;
  json["best_fitness"] = result.best_fitness;
  json["evaluations"] = result.evaluations;
  json["generations"] = result.generations;
  json["stop_reason"] = result.stop_reason;
  json["converged"] = result.converged;
  json["convergence"] = result.convergence;
  json["seconds"] = result.seconds;
  json["strategy"] = result.strategy;
  json["evaluator"] = result.evaluator;  // e.g. "openmp(2 threads)", "mpi(2 ranks x 1 thread)"
  json["rms_deg"] = rms_json(*config.train, train);
  json["robots"] = cases_json(*config.train, train);
  nlohmann::ordered_json free = nlohmann::ordered_json::object();
  for (const auto& p : summary.parameters) free[p.name] = p.value;
  json["free"] = free;
  if (!config.held_identified.empty()) json["held_identified"] = config.held_identified;
  if (const auto still = excitation_warnings(config.train->model(), config.train->cases());
      !still.empty()) {
    json["excitation_warnings"] = still;
  }
  if (!result.sensitivity.empty()) json["sensitivity"] = sensitivity_json(summary.parameters);
  add_uncertainty_outputs(config, result, summary, json);
  summary.train_rms_deg = train.rms_deg;
  if (config.validation) {
    const DetailedEvaluation validation = evaluate_in_detail(*config.validation, best);
    json["validation"] = {{"fitness", validation.breakdown.fitness},
                          {"rms_deg", rms_json(*config.validation, validation)},
                          {"robots", cases_json(*config.validation, validation)}};
    summary.validation_rms_deg = validation.rms_deg;
    write_simulated_logs((dir / "best" / "validation").string(), *config.validation, validation,
                         "motoflex fit " + config.name + " (best, validation)");
  }
  json["early_termination"] = {{"individuals_stopped_early", problem.stopped_early()},
                               {"frames_simulated", problem.frames_simulated()},
                               {"frames_saved", problem.frames_saved()}};
  // Candidates the model rejected (scored +inf): how many, and why (up to 5 distinct reasons).
  json["invalid_candidates"] = {{"count", problem.invalid_candidates()},
                                {"reasons", problem.invalid_reasons()}};
  json["config_hash"] = config.hash;
  write_file_atomically((dir / "summary.json").string(), json.dump(2) + "\n");
  write_simulated_logs((dir / "best").string(), *config.train, train,
                       "motoflex fit " + config.name + " (best)");

  std::vector<std::string> arguments = {dir.string()};
  for (const auto& log : config.train_logs) arguments.push_back(log);
  run_plot_script("plot_fit.py", arguments);
  return summary;
}

}  // namespace motoflex::detail
