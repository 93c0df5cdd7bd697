#include "motoflex/fit/fit_config.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex_es/checkpoint.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string file_hash(const std::string& path) {
  return fs::exists(path) ? motoflex_es::hash_text(file_text(path)) : std::string("absent");
}

std::vector<FreeParameter> read_free(const YamlValue& free, const ParameterSet& base) {
  std::vector<FreeParameter> out;
  const ParameterRegistry& registry = base.registry();
  for (const auto& [pattern, spec] : free.entries()) {
    spec.require_keys_within({"lower", "upper", "log", "each", "start"});
    const std::vector<std::string> targets = match_parameter_pattern(registry, pattern);
    if (targets.empty()) {
      const std::string hint = registry.closest_name(pattern);
      spec.fail("no model parameter matches '" + pattern + "'" +
                (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    const ParameterSpec& first = registry.spec(*registry.find(targets.front()));
    FreeParameter p;
    p.lower = spec.get_double("lower", first.lower);
    p.upper = spec.get_double("upper", first.upper);
    p.log_scale = spec.get_bool("log", false);
    if (!(p.lower < p.upper)) spec.fail("lower bound must be below the upper bound");
    if (p.log_scale && !(p.lower > 0.0)) spec.fail("a log-scale parameter needs lower > 0");
    const bool each = spec.get_bool("each", false);
    const std::vector<std::vector<std::string>> groups =
        each ? [&] {
          std::vector<std::vector<std::string>> g;
          for (const auto& t : targets) g.push_back({t});
          return g;
        }()
             : std::vector<std::vector<std::string>>{targets};
    for (const auto& group : groups) {
      FreeParameter q = p;
      q.name = each ? group.front() : pattern;
      q.targets = group;
      q.start = spec.has("start") ? spec.at("start").as_double() : base.get(group.front());
      q.start = std::clamp(q.start, q.lower, q.upper);
      for (const auto& existing : out) {
        for (const auto& t : existing.targets) {
          if (std::find(group.begin(), group.end(), t) != group.end()) {
            spec.fail("'" + t + "' is already free through '" + existing.name + "'");
          }
        }
      }
      out.push_back(std::move(q));
    }
  }
  if (out.empty()) free.fail("no free parameters");
  return out;
}

StrategyConfig read_strategy(const YamlValue& node) {
  node.require_keys_within({"kind", "mu", "lambda", "kappa", "rho", "object_recombination",
                            "step_recombination", "initial_step", "sigma", "population", "restarts",
                            "algorithm", "polish", "polish_evaluations"});
  StrategyConfig s;
  s.kind = node.get_string("kind", s.kind);
  if (s.kind != "mu_plus_lambda" && s.kind != "cma_es" && s.kind != "nlopt") {
    node.at("kind").fail("expected mu_plus_lambda, cma_es or nlopt");
  }
  auto positive = [&](const char* key, int fallback) {
    const int v = node.get_int(key, fallback);
    if (v < 0) node.at(key).fail("must be >= 0");
    return static_cast<std::size_t>(v);
  };
  s.mu = positive("mu", static_cast<int>(s.mu));
  s.lambda = positive("lambda", static_cast<int>(s.lambda));
  s.kappa = positive("kappa", static_cast<int>(s.kappa));
  s.rho = positive("rho", static_cast<int>(s.rho));
  s.object_recombination = node.get_string("object_recombination", s.object_recombination);
  s.step_recombination = node.get_string("step_recombination", s.step_recombination);
  for (const char* key : {"object_recombination", "step_recombination"}) {
    if (const auto v = node.find(key)) {
      const std::string text = v->as_string();
      if (text != "none" && text != "discrete" && text != "intermediate") {
        v->fail("expected none, discrete or intermediate");
      }
    }
  }
  s.initial_step = node.get_double("initial_step", s.initial_step);
  s.sigma = node.get_double("sigma", s.sigma);
  s.population = positive("population", 0);
  s.restarts = positive("restarts", static_cast<int>(s.restarts));
  s.algorithm = node.get_string("algorithm", s.algorithm);
  for (const char* key : {"algorithm", "polish"}) {
    if (const auto v = node.find(key)) {
      const std::string text = v->as_string();
      const bool local = text == "bobyqa" || text == "sbplx";
      const bool global = text == "crs2_lm" || text == "isres" || text == "esch";
      if (!(local || (global && std::string(key) == "algorithm"))) {
        v->fail(std::string(key) == "polish" ? "expected bobyqa or sbplx"
                                             : "expected bobyqa, sbplx, crs2_lm, isres or esch");
      }
    }
  }
  s.polish = node.get_string("polish", "");
  s.polish_evaluations = positive("polish_evaluations", s.polish.empty() ? 0 : 200);
  return s;
}

}  // namespace

std::vector<std::string> list_logs(const std::string& folder_or_file, const std::string& field) {
  std::vector<std::string> logs;
  if (fs::is_regular_file(folder_or_file)) return {fs::absolute(folder_or_file).lexically_normal()};
  if (!fs::is_directory(folder_or_file)) {
    throw InputError(folder_or_file, 0, field, "no such log folder or file");
  }
  for (const auto& entry : fs::directory_iterator(folder_or_file)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv") {
      logs.push_back(fs::absolute(entry.path()).lexically_normal());
    }
  }
  std::sort(logs.begin(), logs.end());
  if (logs.empty()) throw InputError(folder_or_file, 0, field, "no *.csv logs in this folder");
  return logs;
}

std::vector<FitCase> load_fit_cases(const Scenario& scenario,
                                    const std::vector<std::string>& log_paths) {
  const RobotModel& model = *scenario.model;
  const std::size_t n = model.actuators.size();
  std::vector<FitCase> cases;
  for (const auto& path : log_paths) {
    JointLogRequirements requirements;
    requirements.need_commanded = true;
    requirements.need_measured = true;
    requirements.joints = model.actuator_names();
    const JointLog log = read_joint_log(path, requirements);
    if (!log.meta.robot.empty() && log.meta.robot != model.name) {
      throw InputError(joint_log_sidecar_path(path), 0, "robot",
                       "log of robot '" + log.meta.robot + "', but the fit's scenario simulates '" +
                           model.name + "'");
    }
    FitCase fit_case;
    fit_case.name = fs::path(path).stem().string();
    std::vector<double> commanded(log.frames() * n), measured(log.frames() * n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t column = *log.joint_index(model.actuators[j].name);
      for (std::size_t f = 0; f < log.frames(); ++f) {
        commanded[f * n + j] = log.commanded(f, column);
        measured[f * n + j] = log.measured(f, column);
      }
    }
    fit_case.commands = CommandTrajectory(log.time_s, std::move(commanded), n);
    fit_case.measured_rad = std::move(measured);
    fit_case.options = scenario.rollout;
    for (const auto& [name, value] : log.meta.parameters) {
      const auto index = model.parameters.find(name);
      if (!index) {
        throw InputError(joint_log_sidecar_path(path), 0, "parameters." + name,
                         "unknown parameter for robot " + model.name);
      }
      fit_case.parameter_overrides.emplace_back(*index, value);
    }
    cases.push_back(std::move(fit_case));
  }
  return cases;
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
  return o;
}

FitConfig load_fit_config(const std::string& path, const FitOverrides& overrides) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"name", "scenario", "data", "logs", "validation", "free", "fixed",
                            "fitness", "strategy", "budget", "threads", "seed", "out"});
  FitConfig config;
  config.path = fs::absolute(path).lexically_normal();
  config.name = root.get_string("name", fs::path(path).stem().string());
  config.scenario_path = root.resolve_path(root.at("scenario").as_string());
  ScenarioOverrides scenario_overrides;
  scenario_overrides.motion_optional = true;
  config.scenario =
      std::make_shared<const Scenario>(load_scenario(config.scenario_path, scenario_overrides));

  // Logs: --data wins over `data`/`logs`.
  if (overrides.data) {
    config.train_logs = list_logs(*overrides.data, "--data");
  } else if (const auto data = root.find("data")) {
    config.train_logs = list_logs(data->resolve_path(data->as_string()), "data");
  } else if (const auto logs = root.find("logs")) {
    for (const YamlValue& item : logs->items()) {
      config.train_logs.push_back(
          list_logs(item.resolve_path(item.as_string()), item.field()).front());
    }
  } else {
    root.fail("give the training logs with `data: FOLDER` or `logs: [...]` (or --data)");
  }
  if (overrides.validation) {
    config.validation_logs = list_logs(*overrides.validation, "--validation");
  } else if (const auto validation = root.find("validation")) {
    config.validation_logs =
        list_logs(validation->resolve_path(validation->as_string()), "validation");
  }

  ParameterSet base = config.scenario->parameters;
  if (const auto fixed = root.find("fixed")) {
    for (const auto& [name, value] : fixed->entries()) {
      if (!base.registry().contains(name)) {
        const std::string hint = base.registry().closest_name(name);
        value.fail("unknown parameter" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      base.set(name, value.as_double());
      config.fixed.emplace_back(name, value.as_double());
    }
  }
  config.free = read_free(root.at("free"), base);

  if (const auto fitness = root.find("fitness")) {
    fitness->require_keys_within({"m", "settle_s", "weights", "early_termination"});
    config.early_termination = fitness->get_bool("early_termination", true);
    config.fitness.m = fitness->get_double("m", config.fitness.m);
    if (!(config.fitness.m >= 0.0)) fitness->at("m").fail("must be >= 0");
    config.fitness.settle_s = fitness->get_double("settle_s", 0.0);
    if (const auto weights = fitness->find("weights")) {
      const RobotModel& model = *config.scenario->model;
      config.fitness.joint_weights.assign(model.actuators.size(), 1.0);
      for (const auto& [joint, w] : weights->entries()) {
        const auto index = model.actuator_index(joint);
        if (!index) w.fail("'" + joint + "' is not an actuated joint");
        const double value = w.as_double();
        if (value < 0.0) w.fail("weights must be >= 0");
        config.fitness.joint_weights[*index] = value;
      }
    }
  }
  config.strategy = root.find("strategy") ? read_strategy(root.at("strategy")) : StrategyConfig{};
  if (const auto budget = root.find("budget")) {
    budget->require_keys_within({"generations", "evaluations", "seconds"});
    config.budget.max_generations = static_cast<std::uint64_t>(budget->get_int("generations", 0));
    config.budget.max_evaluations = static_cast<std::uint64_t>(budget->get_int("evaluations", 0));
    config.budget.max_seconds = budget->get_double("seconds", 0.0);
  }
  config.threads = root.get_int("threads", 1);
  const int seed = root.get_int("seed", 1);
  if (seed < 0) root.at("seed").fail("must be >= 0");
  config.seed = static_cast<std::uint64_t>(seed);
  config.out_dir = root.has("out") ? root.resolve_path(root.at("out").as_string())
                                   : (fs::path("runs") / config.name).string();
  if (overrides.threads) config.threads = *overrides.threads;
  if (overrides.seed) config.seed = *overrides.seed;
  if (overrides.max_generations) config.budget.max_generations = *overrides.max_generations;
  if (overrides.max_evaluations) config.budget.max_evaluations = *overrides.max_evaluations;
  if (overrides.max_seconds) config.budget.max_seconds = *overrides.max_seconds;
  if (overrides.out) config.out_dir = *overrides.out;
  if (config.threads < 1) throw InputError(config.path, 0, "threads", "must be >= 1");

  config.space = std::make_shared<ParameterSpace>(config.free, base);
  try {
    config.train = std::make_shared<FitnessFunction>(
        config.scenario->model, load_fit_cases(*config.scenario, config.train_logs),
        config.fitness);
    if (!config.validation_logs.empty()) {
      config.validation = std::make_shared<FitnessFunction>(
          config.scenario->model, load_fit_cases(*config.scenario, config.validation_logs),
          config.fitness);
    }
  } catch (const std::invalid_argument& error) {
    throw InputError(config.path, 0, "fitness", error.what());
  }

  // The identity: every input that decides the generations, with file contents by hash.
  nlohmann::ordered_json id;
  id["format"] = 1;
  id["scenario"] = file_hash(config.scenario_path);
  id["robot_yaml"] =
      file_hash((fs::path(config.scenario->model->directory) / "robot.yaml").string());
  id["urdf"] = file_hash(config.scenario->model->urdf_path);
  for (const auto& log : config.train_logs) {
    id["train"].push_back({fs::path(log).filename().string(), file_hash(log),
                           file_hash(joint_log_sidecar_path(log))});
  }
  for (const auto& log : config.validation_logs) {
    id["validation"].push_back({fs::path(log).filename().string(), file_hash(log)});
  }
  for (const auto& p : config.free) {
    id["free"].push_back({{"name", p.name},
                          {"targets", p.targets},
                          {"lower", p.lower},
                          {"upper", p.upper},
                          {"log", p.log_scale},
                          {"start", p.start}});
  }
  for (const auto& [name, value] : config.fixed) id["fixed"][name] = value;
  id["fitness"] = {{"m", config.fitness.m},
                   {"settle_s", config.fitness.settle_s},
                   {"weights", config.fitness.joint_weights}};
  const StrategyConfig& s = config.strategy;
  id["strategy"] = {{"kind", s.kind},
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
  id["seed"] = config.seed;
  config.identity = nlohmann::json(id);
  config.hash = motoflex_es::config_hash(config.identity);
  config.overrides = overrides_to_json(overrides);
  return config;
}

}  // namespace motoflex
