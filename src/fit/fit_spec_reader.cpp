// fit.yaml → FitSpec. Each section has its own reader; the file's problems are collected and
// reported together (one line each), not one per run.

#include <filesystem>

#include "fit_spec_sections.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/fit/fit_spec.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

SourceRef where(const YamlValue& value) {
  return {value.file(), value.line(), value.field()};
}

// `data:`/`logs:`/`validation:` — a folder, a file, or a list of them (relative to the file).
std::vector<LogSource> read_log_sources(const YamlValue& node) {
  std::vector<LogSource> out;
  const std::vector<YamlValue> items = node.is_sequence() ? node.items() : std::vector{node};
  for (const YamlValue& item : items) {
    out.push_back({item.resolve_path(item.as_string()), where(item)});
  }
  return out;
}

std::vector<FreeParameterSpec> read_free(const YamlValue& free) {
  std::vector<FreeParameterSpec> out;
  ErrorCollector errors;
  for (const auto& [pattern, entry] : free.entries()) {
    errors.check([&, &pattern = pattern, &entry = entry] {
      entry.require_keys_within({"lower", "upper", "log", "each", "start"});
      FreeParameterSpec spec;
      spec.pattern = pattern;
      if (entry.has("lower")) spec.lower = entry.at("lower").as_double();
      if (entry.has("upper")) spec.upper = entry.at("upper").as_double();
      if (entry.has("start")) spec.start = entry.at("start").as_double();
      spec.log_scale = entry.get_bool("log", false);
      spec.each = entry.get_bool("each", false);
      spec.where = where(entry);
      if (spec.lower && spec.upper && !(*spec.lower < *spec.upper)) {
        entry.fail("lower bound must be below the upper bound");
      }
      if (spec.log_scale && spec.lower && !(*spec.lower > 0.0)) {
        entry.fail("a log-scale parameter needs lower > 0");
      }
      out.push_back(std::move(spec));
    });
  }
  errors.throw_if_any();
  if (out.empty()) free.fail("no free parameters");
  return out;
}

void read_fixed(const YamlValue& fixed, FitSpec& spec) {
  for (const auto& [name, value] : fixed.entries()) {
    spec.fixed.emplace_back(name, value.as_double());
    spec.fixed_where.push_back(where(value));
  }
}

void read_effects(const YamlValue& list, FitSpec& spec) {
  ErrorCollector errors;
  for (const YamlValue& item : list.items()) {
    errors.check([&] {
      const Effect& effect = find_effect(item.as_string(), item.file(), item.line(), item.field());
      for (const auto& name : spec.effects) {
        if (name == effect.name) item.fail("effect '" + effect.name + "' is listed twice");
      }
      spec.effects.push_back(effect.name);
      spec.effects_where.push_back(where(item));
    });
  }
  errors.throw_if_any();
}

void read_fitness(const YamlValue& fitness, FitSpec& spec) {
  fitness.require_keys_within(
      {"m", "error", "settle_s", "weights", "imu_weight", "window_s", "early_termination"});
  ErrorCollector errors;
  errors.check([&] { spec.early_termination = fitness.get_bool("early_termination", true); });
  errors.check([&] {
    spec.fitness_m = fitness.get_double("m", spec.fitness_m);
    // Beyond 10, T^m overflows for long logs and every fitness becomes 0 (MoToFlex uses 1-2).
    if (!(spec.fitness_m >= 0.0 && spec.fitness_m <= 10.0)) {
      fitness.at("m").fail("must be in [0, 10]");
    }
  });
  errors.check([&] {
    spec.fitness_settle_s = fitness.get_double("settle_s", 0.0);
    if (!(spec.fitness_settle_s >= 0.0)) fitness.at("settle_s").fail("must be >= 0");
  });
  errors.check([&] {
    spec.imu_weight = fitness.get_double("imu_weight", 0.0);
    if (!(spec.imu_weight >= 0.0)) fitness.at("imu_weight").fail("must be >= 0");
  });
  errors.check([&] {
    const std::string norm = fitness.get_string("error", "squared");
    if (norm != "squared" && norm != "absolute") {
      fitness.at("error").fail("must be squared or absolute, found '" + norm + "'");
    }
    spec.absolute_error = norm == "absolute";
  });
  errors.check([&] {
    spec.window_s = fitness.get_double("window_s", 0.0);
    if (!(spec.window_s >= 0.0)) fitness.at("window_s").fail("must be >= 0");
  });
  if (const auto weights = fitness.find("weights")) {
    spec.joint_weights_where = where(*weights);
    for (const auto& [joint, weight] : weights->entries()) {
      errors.check([&, &joint = joint, &weight = weight] {
        const double value = weight.as_double();
        if (value < 0.0) weight.fail("weights must be >= 0");
        spec.joint_weights[joint] = value;
      });
    }
  }
  errors.throw_if_any();
}

void read_run_settings(const YamlValue& root, FitSpec& spec, ErrorCollector& errors) {
  errors.check([&] {
    spec.threads = root.get_int("threads", 1);
    if (spec.threads < 1) root.at("threads").fail("must be >= 1");
  });
  errors.check([&] {
    const int seed = root.get_int("seed", 1);
    if (seed < 0) root.at("seed").fail("must be >= 0");
    spec.seed = static_cast<std::uint64_t>(seed);
  });
  errors.check([&] {
    spec.out_dir = root.has("out") ? root.resolve_path(root.at("out").as_string())
                                   : (fs::path("runs") / spec.name).string();
  });
}

void read_sections(const YamlValue& root, FitSpec& spec, ErrorCollector& errors) {
  errors.check([&] { spec.scenario_path = root.resolve_path(root.at("scenario").as_string()); });
  errors.check([&] {
    if (const auto data = root.find("data")) {
      spec.train_data = read_log_sources(*data);
    } else if (const auto logs = root.find("logs")) {
      spec.train_data = read_log_sources(*logs);
    }
  });
  errors.check([&] {
    if (const auto validation = root.find("validation")) {
      spec.validation_data = read_log_sources(*validation);
    }
  });
  errors.check([&] { spec.free = read_free(root.at("free")); });
  errors.check([&] {
    if (const auto fixed = root.find("fixed")) read_fixed(*fixed, spec);
  });
  errors.check([&] {
    if (const auto effects = root.find("effects")) read_effects(*effects, spec);
  });
  errors.check([&] {
    if (const auto incumbent = root.find("incumbent")) {
      spec.incumbent_where = where(*incumbent);
      for (const auto& [name, value] : incumbent->entries()) {
        spec.incumbent.emplace_back(name, value.as_double());
      }
    }
  });
  errors.check([&] {
    if (const auto fitness = root.find("fitness")) read_fitness(*fitness, spec);
  });
  errors.check([&] {
    if (const auto strategy = root.find("strategy")) spec.strategy = read_strategy(*strategy);
  });
  errors.check([&] {
    if (const auto budget = root.find("budget")) spec.budget = read_budget(*budget);
  });
  errors.check([&] {
    if (const auto polish = root.find("polish")) spec.polish = read_polish(*polish);
  });
  errors.check([&] {
    if (const auto loop = root.find("loop")) spec.loop = read_loop(*loop);
  });
  errors.check([&] {
    if (const auto hold = root.find("hold_identified")) {
      spec.hold_identified = hold->as_bool();
      spec.hold_identified_where = where(*hold);
    }
  });
  read_run_settings(root, spec, errors);
}

}  // namespace

FitSpec load_fit_spec(const std::string& path, const FitOverrides& overrides) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"name", "scenario", "data", "logs", "validation", "free", "fixed",
                            "effects", "fitness", "strategy", "budget", "threads", "seed", "out",
                            "polish", "loop", "incumbent", "hold_identified"});
  FitSpec spec;
  spec.path = fs::absolute(path).lexically_normal();
  spec.root = {path, root.line(), ""};
  ErrorCollector errors;
  errors.check([&] { spec.name = root.get_string("name", fs::path(path).stem().string()); });
  read_sections(root, spec, errors);
  apply_fit_overrides(spec, overrides);
  if (spec.train_data.empty() && !root.has("data") && !root.has("logs")) {
    errors.add(path, root.line(), "data",
               "give the training logs with `data: FOLDER` or `logs: [...]` (or --data)");
  }
  errors.throw_if_any();
  std::string why;
  if (!spec.is_valid(&why)) throw InputError(path, 0, "", why);
  return spec;
}

}  // namespace motoflex
