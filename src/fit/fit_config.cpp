#include "motoflex/fit/fit_config.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "fit_hold_identified.hpp"
#include "fit_start_from.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/fit/effect_parameters.hpp"
#include "motoflex/model/effect_library.hpp"
#include "motoflex/sim/effect_hooks.hpp"
#include "motoflex_es/checkpoint.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

InputError error_at(const SourceRef& where, const std::string& message) {
  return InputError(where.file, where.line, where.field, message);
}

const SourceRef& where_of(const std::vector<SourceRef>& sources, std::size_t i,
                          const SourceRef& fallback) {
  return i < sources.size() ? sources[i] : fallback;
}

bool has_flex_joints(const RobotModel& model) {
  return std::any_of(model.joints.begin(), model.joints.end(),
                     [](const JointSpec& j) { return j.kind == JointKind::kFlex; });
}

// The scenario, with the flexible sub-bodies the effects need (link_flexibility).
std::shared_ptr<const Scenario> load_fit_scenario(const FitSpec& spec,
                                                  const std::vector<const Effect*>& effects) {
  ScenarioOverrides overrides;
  overrides.motion_optional = true;
  auto scenario = std::make_shared<const Scenario>(load_scenario(spec.scenario_path, overrides));
  int flex_needed = 0;
  for (const Effect* effect : effects) flex_needed = std::max(flex_needed, effect->flex_sub_bodies);
  if (scenario->model->structure.flex_sub_bodies >= flex_needed) return scenario;
  overrides.flex_sub_bodies = flex_needed;
  scenario = std::make_shared<const Scenario>(load_scenario(spec.scenario_path, overrides));
  if (!has_flex_joints(*scenario->model)) {
    throw error_at(where_of(spec.effects_where, 0, spec.root),
                   "link_flexibility needs flexible links, and robot " + scenario->model->name +
                       " declares none");
  }
  return scenario;
}

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

ParameterSet apply_fixed(const FitSpec& spec, ParameterSet base) {
  ErrorCollector errors;
  for (std::size_t i = 0; i < spec.fixed.size(); ++i) {
    const auto& [name, value] = spec.fixed[i];
    errors.check([&, &name = name, &value = value] {
      if (!base.registry().contains(name)) {
        const std::string hint = base.registry().closest_name(name);
        throw error_at(
            where_of(spec.fixed_where, i, spec.root),
            "unknown parameter" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      const ParameterDomain& domain = base.registry().domain(*base.registry().find(name));
      if (!domain.contains(value)) {
        throw error_at(where_of(spec.fixed_where, i, spec.root), name + " = " + number_text(value) +
                                                                     " is outside its domain (" +
                                                                     domain.describe() + ")");
      }
      base.set(name, value);
    });
  }
  errors.throw_if_any();
  return base;
}

// Every value the search may propose must be one the model accepts: bounds inside the
// domain of every target (an integer parameter's interval is rounded by the model).
void check_free_domain(const FreeParameterSpec& spec, const ParameterRegistry& registry,
                       const std::vector<std::string>& targets, const FreeParameter& p) {
  for (const auto& target : targets) {
    const ParameterDomain& domain = registry.domain(*registry.find(target));
    if (!domain.contains_interval(p.lower, p.upper)) {
      throw error_at(spec.where, "bounds [" + number_text(p.lower) + ", " + number_text(p.upper) +
                                     "] leave the domain of " + target + " (" + domain.describe() +
                                     ")");
    }
  }
}

// One `free:` entry expanded against the robot's parameters: a tie, or one per match (each).
std::vector<FreeParameter> expand_free(const FreeParameterSpec& spec, const ParameterSet& base) {
  const ParameterRegistry& registry = base.registry();
  const std::vector<std::string> targets = match_parameter_pattern(registry, spec.pattern);
  if (targets.empty()) {
    const std::string hint = registry.closest_name(spec.pattern);
    throw error_at(spec.where, "no model parameter matches '" + spec.pattern + "'" +
                                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  const ParameterSpec& first = registry.spec(*registry.find(targets.front()));
  FreeParameter p;
  p.lower = spec.lower.value_or(first.lower);
  p.upper = spec.upper.value_or(first.upper);
  p.log_scale = spec.log_scale;
  if (!(p.lower < p.upper)) throw error_at(spec.where, "lower bound must be below the upper bound");
  if (p.log_scale && !(p.lower > 0.0)) {
    throw error_at(spec.where, "a log-scale parameter needs lower > 0");
  }
  if (spec.start && (*spec.start < p.lower || *spec.start > p.upper)) {
    throw error_at(spec.where, "start " + std::to_string(*spec.start) + " lies outside [" +
                                   std::to_string(p.lower) + ", " + std::to_string(p.upper) + "]");
  }
  check_free_domain(spec, registry, targets, p);
  std::vector<std::vector<std::string>> groups;
  if (spec.each) {
    for (const auto& t : targets) groups.push_back({t});
  } else {
    groups.push_back(targets);
  }
  std::vector<FreeParameter> out;
  for (const auto& group : groups) {
    FreeParameter q = p;
    q.name = spec.each ? group.front() : spec.pattern;
    q.targets = group;
    // A robot default outside the fit's (narrower) bounds starts at the nearest bound.
    q.start = std::clamp(spec.start.value_or(base.get(group.front())), q.lower, q.upper);
    out.push_back(std::move(q));
  }
  return out;
}

std::vector<FreeParameter> expand_all_free(const FitSpec& spec, const ParameterSet& base) {
  std::vector<FreeParameter> out;
  ErrorCollector errors;
  for (const FreeParameterSpec& entry : spec.free) {
    errors.check([&] {
      for (auto& q : expand_free(entry, base)) {
        for (const auto& existing : out) {
          for (const auto& t : existing.targets) {
            if (std::find(q.targets.begin(), q.targets.end(), t) != q.targets.end()) {
              throw error_at(entry.where,
                             "'" + t + "' is already free through '" + existing.name + "'");
            }
          }
        }
        out.push_back(std::move(q));
      }
    });
  }
  errors.throw_if_any();
  return out;
}

// Each listed effect frees its parameters that are not free or fixed already.
void add_effect_parameters(const FitSpec& spec, const std::vector<const Effect*>& effects,
                           const ParameterSet& base, const Scenario& scenario,
                           std::vector<FreeParameter>& free) {
  for (std::size_t e = 0; e < effects.size(); ++e) {
    const Effect& effect = *effects[e];
    const SourceRef& where = where_of(spec.effects_where, e, spec.root);
    if (!effect_applies(effect, *scenario.model, scenario.rollout.servo)) {
      throw error_at(where, "effect '" + effect.name + "' has no hook in robot " +
                                scenario.model->name + " with servo " + scenario.rollout.servo);
    }
    std::set<std::string> taken, fixed_names;
    for (const auto& p : free) taken.insert(p.targets.begin(), p.targets.end());
    for (const auto& [name, value] : spec.fixed) {
      taken.insert(name);
      fixed_names.insert(name);
    }
    if (effect_targets(effect, base).empty()) {
      throw error_at(
          where, "effect '" + effect.name + "' has no parameters in robot " + scenario.model->name);
    }
    if (effect_covered_by(effect, base, fixed_names)) {
      throw error_at(where, "every parameter of effect '" + effect.name +
                                "' is fixed; remove them from `fixed` or drop the effect");
    }
    for (auto& p : effect_free_parameters(effect, base, taken)) free.push_back(p);
  }
}

FitnessOptions fitness_options(const FitSpec& spec, const RobotModel& model) {
  FitnessOptions fitness;
  fitness.m = spec.fitness_m;
  fitness.settle_s = spec.fitness_settle_s;
  fitness.imu_weight = spec.imu_weight;
  fitness.window_s = spec.window_s;
  fitness.absolute_error = spec.absolute_error;
  if (!spec.joint_weights.empty()) {
    fitness.joint_weights.assign(model.actuators.size(), 1.0);
    for (const auto& [joint, weight] : spec.joint_weights) {
      const auto index = model.actuator_index(joint);
      if (!index) {
        SourceRef where = spec.joint_weights_where;
        where.field += "." + joint;
        throw error_at(where, "'" + joint + "' is not an actuated joint");
      }
      fitness.joint_weights[*index] = weight;
    }
    const bool all_zero = std::all_of(fitness.joint_weights.begin(), fitness.joint_weights.end(),
                                      [](double w) { return w == 0.0; });
    if (all_zero && !(fitness.imu_weight > 0.0)) {
      throw error_at(spec.joint_weights_where,
                     "every weight is 0 (and imu_weight too): every fitness would be 0");
    }
  }
  return fitness;
}

void load_fitness_functions(FitConfig& config) {
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
}

// `incumbent` as a point of the search space: every free parameter once, within its bounds.
std::vector<double> incumbent_coordinates(const FitSpec& spec, const ParameterSpace& space) {
  if (spec.incumbent.empty()) return {};
  const SourceRef& where = spec.incumbent_where.file.empty() ? spec.root : spec.incumbent_where;
  std::map<std::string, double> values;
  for (const auto& [name, value] : spec.incumbent) {
    if (!values.emplace(name, value).second) throw error_at(where, "incumbent: " + name + " twice");
  }
  std::vector<double> x;
  for (std::size_t i = 0; i < space.dimension(); ++i) {
    const FreeParameter& p = space.free_parameters()[i];
    const auto found = values.find(p.name);
    if (found == values.end()) {
      throw error_at(where, "incumbent: no value for the free parameter " + p.name +
                                " (give every free parameter)");
    }
    if (!(found->second >= p.lower && found->second <= p.upper)) {
      throw error_at(where, "incumbent: " + p.name + " = " + number_text(found->second) +
                                " is outside its bounds [" + number_text(p.lower) + ", " +
                                number_text(p.upper) + "]");
    }
    x.push_back(space.to_search(i, found->second));
    values.erase(found);
  }
  if (!values.empty()) {
    throw error_at(where, "incumbent: " + values.begin()->first + " is not a free parameter");
  }
  return x;
}

// `hold_identified`: the parameters the --start-from run identified leave the search and are
// held at its values, as `fixed` entries (so the fit's identity and resume see them).
void hold_identified_parameters(FitConfig& config, ParameterSet& base) {
  if (config.start_from.empty()) {
    throw error_at(
        config.hold_identified_where.file.empty() ? config.root : config.hold_identified_where,
        "needs --start-from RUN/best.json (the run whose identified parameters it "
        "holds)");
  }
  const std::string summary = (fs::path(config.start_from).parent_path() / "summary.json").string();
  const auto held = detail::hold_identified(summary, config.free_parameters, config.incumbent);
  if (config.fixed_where.size() != config.fixed.size()) {
    config.fixed_where.resize(config.fixed.size(), config.root);
  }
  for (const detail::HeldParameter& h : held) {
    config.held_identified.push_back(h.name);
    for (const std::string& target : h.targets) {
      base.set(target, h.value);
      config.fixed.emplace_back(target, h.value);
      config.fixed_where.push_back({summary, 0, "confidence_intervals." + h.name});
    }
  }
}

}  // namespace

FitConfig resolve_fit_config(const FitSpec& spec) {
  std::string why;
  if (!spec.is_valid(&why)) throw InputError(spec.path, 0, "", why);
  FitConfig config;
  static_cast<FitSpec&>(config) = spec;
  // Effects first: one may need a different model structure (flexible sub-bodies).
  std::vector<const Effect*> effects;
  for (std::size_t e = 0; e < spec.effects.size(); ++e) {
    const SourceRef& where = where_of(spec.effects_where, e, spec.root);
    effects.push_back(&find_effect(spec.effects[e], where.file, where.line, where.field));
  }
  config.scenario = load_fit_scenario(spec, effects);

  const fs::path import_dir = fs::path(config.out_dir) / "imported";
  config.train_logs = logs_of(spec.train_data, (import_dir / "train").string());
  config.validation_logs = logs_of(spec.validation_data, (import_dir / "validation").string());

  ParameterSet base = apply_fixed(spec, config.scenario->parameters);
  config.free_parameters = expand_all_free(spec, base);
  add_effect_parameters(spec, effects, base, *config.scenario, config.free_parameters);
  if (!spec.start_from.empty()) {
    config.incumbent = detail::start_from_best(spec.start_from, config.free_parameters);
    config.incumbent_where = {spec.start_from, 0, "--start-from"};
  }
  if (spec.hold_identified) hold_identified_parameters(config, base);
  config.fitness = fitness_options(spec, *config.scenario->model);
  config.space = std::make_shared<ParameterSpace>(config.free_parameters, base);
  config.incumbent_x = incumbent_coordinates(config, *config.space);
  load_fitness_functions(config);

  config.identity = fit_identity(config);
  config.hash = motoflex_es::config_hash(config.identity);
  return config;
}

FitConfig load_fit_config(const std::string& path, const FitOverrides& overrides) {
  FitConfig config = resolve_fit_config(load_fit_spec(path, overrides));
  config.overrides = overrides_to_json(overrides);
  return config;
}

}  // namespace motoflex
