#include "motoflex/fit/fit_config.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "motoflex/core/error.hpp"
#include "motoflex/core/text_hash.hpp"
#include "motoflex/model/effect_library.hpp"
#include "motoflex/sim/effect_hooks.hpp"
#include "motoflex/fit/effect_parameters.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/io/bam_import.hpp"
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
  return fs::exists(path) ? hash_text(file_text(path)) : std::string("absent");
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

FitBudget read_budget(const YamlValue& budget) {
  budget.require_keys_within({"generations", "evaluations", "seconds"});
  FitBudget out;
  out.max_generations = static_cast<std::uint64_t>(budget.get_int("generations", 0));
  out.max_evaluations = static_cast<std::uint64_t>(budget.get_int("evaluations", 0));
  out.max_seconds = budget.get_double("seconds", 0.0);
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
      if (text.empty() && std::string(key) == "polish") continue;  // no polish
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

bool has_extension(const fs::path& folder, const char* extension) {
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) return true;
  }
  return false;
}

// A folder of BAM JSON logs (and no *.csv) is imported into `import_dir`; anything else is
// listed as it is.
std::vector<std::string> logs_of(const std::string& folder_or_file, const std::string& field,
                                 const fs::path& import_dir) {
  if (fs::is_directory(folder_or_file) && !has_extension(folder_or_file, ".csv") &&
      has_extension(folder_or_file, ".json")) {
    std::error_code error;
    fs::create_directories(import_dir, error);
    if (error) {
      throw InputError(import_dir.string(), 0, field, "cannot create: " + error.message());
    }
    for (const BamDirectoryItem& item : import_bam_directory(folder_or_file)) {
      if (!item.import) continue;
      const fs::path csv = import_dir / (item.output_stem + ".csv");
      write_joint_log(csv.string(), item.import->log);
    }
    return list_logs(import_dir.string(), field);
  }
  return list_logs(folder_or_file, field);
}

// `data:`/`validation:` — a folder, a file, or a list of them (relative to the fit file).
std::vector<std::string> logs_of_node(const YamlValue& node, const fs::path& import_dir) {
  std::vector<std::string> out;
  const std::vector<YamlValue> items = node.is_sequence() ? node.items() : std::vector{node};
  for (const YamlValue& item : items) {
    for (auto& log : logs_of(item.resolve_path(item.as_string()), item.field(), import_dir)) {
      out.push_back(std::move(log));
    }
  }
  return out;
}

LoopOptions read_loop(const YamlValue& node) {
  node.require_keys_within({"candidates", "max_iterations", "min_gain", "effects", "refit"});
  LoopOptions loop;
  const int candidates = node.get_int("candidates", static_cast<int>(loop.candidates));
  if (candidates < 1) node.at("candidates").fail("must be >= 1");
  loop.candidates = static_cast<std::size_t>(candidates);
  const int iterations = node.get_int("max_iterations", static_cast<int>(loop.max_iterations));
  if (iterations < 0) node.at("max_iterations").fail("must be >= 0");
  loop.max_iterations = static_cast<std::size_t>(iterations);
  loop.min_gain = node.get_double("min_gain", loop.min_gain);
  if (!(loop.min_gain >= 0.0 && loop.min_gain < 1.0)) {
    node.at("min_gain").fail("must be in [0, 1)");
  }
  if (const auto effects = node.find("effects")) {
    for (const YamlValue& item : effects->items()) {
      find_effect(item.as_string(), item.file(), item.line(), item.field());
      loop.effects.push_back(item.as_string());
    }
  }
  if (const auto refit = node.find("refit")) {
    refit->require_keys_within({"strategy", "budget"});
    if (const auto strategy = refit->find("strategy")) {
      loop.refit_strategy = read_strategy(*strategy);
    }
    if (const auto budget = refit->find("budget")) loop.refit_budget = read_budget(*budget);
  }
  return loop;
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
                                    const std::vector<std::string>& log_paths,
                                    const FitnessOptions& fitness) {
  const bool need_imu = fitness.imu_weight > 0.0;
  const double window_s = fitness.window_s;
  const RobotModel& model = *scenario.model;
  const std::size_t n = model.actuators.size();
  std::vector<FitCase> cases;
  for (const auto& path : log_paths) {
    // A log of another robot is named as such before its columns are checked.
    const std::string sidecar = joint_log_sidecar_path(path);
    if (fs::exists(sidecar)) {
      const YamlValue meta = YamlValue::load_file(sidecar);
      const std::string robot = meta.is_map() ? meta.get_string("robot", "") : "";
      if (!robot.empty() && robot != model.name) {
        throw InputError(
            sidecar, meta.at("robot").line(), "robot",
            "log of robot '" + robot + "', but the fit's scenario simulates '" + model.name + "'");
      }
    }
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
    std::size_t frames = log.frames();
    if (window_s > 0.0) {
      frames = 0;
      while (frames < log.frames() && log.time_s[frames] - log.time_s[0] <= window_s + 1e-9) {
        ++frames;
      }
      if (frames < 2) {
        throw InputError(path, 0, "fitness.window_s",
                         "window of " + std::to_string(window_s) + " s keeps fewer than 2 frames");
      }
    }
    std::vector<double> time_s(log.time_s.begin(),
                               log.time_s.begin() + static_cast<std::ptrdiff_t>(frames));
    std::vector<double> commanded(frames * n), measured(frames * n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t column = *log.joint_index(model.actuators[j].name);
      for (std::size_t f = 0; f < frames; ++f) {
        commanded[f * n + j] = log.commanded(f, column);
        measured[f * n + j] = log.measured(f, column);
      }
    }
    fit_case.commands = CommandTrajectory(std::move(time_s), std::move(commanded), n);
    fit_case.measured_rad = std::move(measured);
    if (!log.imu_roll_rad.empty() && !log.imu_pitch_rad.empty()) {
      fit_case.measured_imu_rad.resize(2 * frames);
      for (std::size_t f = 0; f < frames; ++f) {
        fit_case.measured_imu_rad[2 * f] = log.imu_roll_rad[f];
        fit_case.measured_imu_rad[2 * f + 1] = log.imu_pitch_rad[f];
      }
    } else if (need_imu) {
      throw InputError(path, 1, log.imu_roll_rad.empty() ? "imu.roll" : "imu.pitch",
                       "missing column: the fit scores the IMU (fitness.imu_weight > 0)");
    }
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

nlohmann::ordered_json strategy_to_json(const StrategyConfig& s) {
  return {{"kind", s.kind},
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
                            "effects", "fitness", "strategy", "budget", "threads", "seed", "out",
                            "loop"});
  FitConfig config;
  config.path = fs::absolute(path).lexically_normal();
  config.name = root.get_string("name", fs::path(path).stem().string());
  config.scenario_path = root.resolve_path(root.at("scenario").as_string());
  config.out_dir = root.has("out") ? root.resolve_path(root.at("out").as_string())
                                   : (fs::path("runs") / config.name).string();
  if (overrides.out) config.out_dir = *overrides.out;

  // Effects first: one may need a different model structure (flexible sub-bodies).
  std::vector<const Effect*> effects;
  ScenarioOverrides scenario_overrides;
  scenario_overrides.motion_optional = true;
  if (const auto list = root.find("effects")) {
    for (const YamlValue& item : list->items()) {
      const Effect& effect = find_effect(item.as_string(), item.file(), item.line(), item.field());
      if (std::find(effects.begin(), effects.end(), &effect) != effects.end()) {
        item.fail("effect '" + effect.name + "' is listed twice");
      }
      effects.push_back(&effect);
      config.effects.push_back(effect.name);
    }
  }
  config.scenario =
      std::make_shared<const Scenario>(load_scenario(config.scenario_path, scenario_overrides));
  int flex_needed = 0;
  for (const Effect* effect : effects) flex_needed = std::max(flex_needed, effect->flex_sub_bodies);
  if (config.scenario->model->structure.flex_sub_bodies < flex_needed) {
    scenario_overrides.flex_sub_bodies = flex_needed;
    config.scenario =
        std::make_shared<const Scenario>(load_scenario(config.scenario_path, scenario_overrides));
  }
  const auto& joints = config.scenario->model->joints;
  if (scenario_overrides.flex_sub_bodies &&
      std::none_of(joints.begin(), joints.end(),
                   [](const JointSpec& j) { return j.kind == JointKind::kFlex; })) {
    root.at("effects").fail("link_flexibility needs flexible links, and robot " +
                            config.scenario->model->name + " declares none");
  }

  // Logs: --data wins over `data`/`logs`.
  const fs::path import_dir = fs::path(config.out_dir) / "imported";
  if (overrides.data) {
    config.train_logs = logs_of(*overrides.data, "--data", import_dir / "train");
  } else if (const auto data = root.find("data")) {
    config.train_logs = logs_of_node(*data, import_dir / "train");
  } else if (const auto logs = root.find("logs")) {
    config.train_logs = logs_of_node(*logs, import_dir / "train");
  } else {
    root.fail("give the training logs with `data: FOLDER` or `logs: [...]` (or --data)");
  }
  if (overrides.validation) {
    config.validation_logs =
        logs_of(*overrides.validation, "--validation", import_dir / "validation");
  } else if (const auto validation = root.find("validation")) {
    config.validation_logs = logs_of_node(*validation, import_dir / "validation");
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
  // Each listed effect frees its parameters that are not free or fixed already.
  for (std::size_t e = 0; e < effects.size(); ++e) {
    const Effect& effect = *effects[e];
    const YamlValue item = root.at("effects").items()[e];
    if (!effect_applies(effect, *config.scenario->model, config.scenario->rollout.servo)) {
      item.fail("effect '" + effect.name + "' has no hook in robot " +
                config.scenario->model->name + " with servo " +
                config.scenario->rollout.servo);
    }
    std::set<std::string> taken, fixed_names;
    for (const auto& p : config.free) taken.insert(p.targets.begin(), p.targets.end());
    for (const auto& [name, value] : config.fixed) {
      taken.insert(name);
      fixed_names.insert(name);
    }
    if (effect_targets(effect, base).empty()) {
      item.fail("effect '" + effect.name + "' has no parameters in robot " +
                config.scenario->model->name);
    }
    if (effect_covered_by(effect, base, fixed_names)) {
      item.fail("every parameter of effect '" + effect.name +
                "' is fixed; remove them from `fixed` or drop the effect");
    }
    for (auto& p : effect_free_parameters(effect, base, taken)) config.free.push_back(p);
  }

  if (const auto fitness = root.find("fitness")) {
    fitness->require_keys_within(
        {"m", "settle_s", "weights", "imu_weight", "window_s", "early_termination"});
    config.early_termination = fitness->get_bool("early_termination", true);
    config.fitness.m = fitness->get_double("m", config.fitness.m);
    if (!(config.fitness.m >= 0.0)) fitness->at("m").fail("must be >= 0");
    config.fitness.settle_s = fitness->get_double("settle_s", 0.0);
    config.fitness.imu_weight = fitness->get_double("imu_weight", 0.0);
    if (!(config.fitness.imu_weight >= 0.0)) fitness->at("imu_weight").fail("must be >= 0");
    config.fitness.window_s = fitness->get_double("window_s", 0.0);
    if (!(config.fitness.window_s >= 0.0)) fitness->at("window_s").fail("must be >= 0");
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
  if (const auto budget = root.find("budget")) config.budget = read_budget(*budget);
  if (const auto loop = root.find("loop")) config.loop = read_loop(*loop);
  config.threads = root.get_int("threads", 1);
  const int seed = root.get_int("seed", 1);
  if (seed < 0) root.at("seed").fail("must be >= 0");
  config.seed = static_cast<std::uint64_t>(seed);
  if (overrides.threads) config.threads = *overrides.threads;
  if (overrides.seed) config.seed = *overrides.seed;
  if (overrides.max_generations) config.budget.max_generations = *overrides.max_generations;
  if (overrides.max_evaluations) config.budget.max_evaluations = *overrides.max_evaluations;
  if (overrides.max_seconds) config.budget.max_seconds = *overrides.max_seconds;
  if (config.threads < 1) throw InputError(config.path, 0, "threads", "must be >= 1");

  config.space = std::make_shared<ParameterSpace>(config.free, base);
  try {
    config.train = std::make_shared<FitnessFunction>(
        config.scenario->model, load_fit_cases(*config.scenario, config.train_logs, config.fitness),
        config.fitness);
    if (!config.validation_logs.empty()) {
      config.validation = std::make_shared<FitnessFunction>(
          config.scenario->model,
          load_fit_cases(*config.scenario, config.validation_logs, config.fitness), config.fitness);
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
  if (!config.effects.empty()) id["effects"] = config.effects;
  id["flex_sub_bodies"] = config.scenario->model->structure.flex_sub_bodies;
  id["fitness"] = {{"m", config.fitness.m},
                   {"settle_s", config.fitness.settle_s},
                   {"weights", config.fitness.joint_weights}};
  // Only when used, so that the hashes of existing joint-only run dirs stay valid.
  if (config.fitness.imu_weight > 0.0) id["fitness"]["imu_weight"] = config.fitness.imu_weight;
  if (config.fitness.window_s > 0.0) id["fitness"]["window_s"] = config.fitness.window_s;
  id["strategy"] = strategy_to_json(config.strategy);
  id["seed"] = config.seed;
  config.identity = nlohmann::json(id);
  config.hash = motoflex_es::config_hash(config.identity);
  config.overrides = overrides_to_json(overrides);
  return config;
}

}  // namespace motoflex
