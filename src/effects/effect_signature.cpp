#include "motoflex/effects/effect_signature.hpp"

#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "linearised_residual.hpp"
#include "motoflex/fit/effect_parameters.hpp"
#include "motoflex/model/effect_library.hpp"
#include "motoflex/sim/effect_hooks.hpp"

namespace motoflex {
namespace {

using detail::Direction;
using detail::direction;
using detail::fit_jacobian;
using detail::FitJacobian;
using detail::Residual;
using detail::residual_of;
using detail::response;

// Actuators a parameter acts on: joint.<J>.* → J; gear.<G>.* → the joints of group G; anything
// else → every joint.
std::vector<std::size_t> owners(const RobotModel& model, const std::string& name) {
  std::vector<std::size_t> out;
  const auto dot = name.find('.');
  const auto second = name.find('.', dot + 1);
  const std::string head = name.substr(0, dot);
  const std::string middle =
      second == std::string::npos ? "" : name.substr(dot + 1, second - dot - 1);
  for (std::size_t j = 0; j < model.actuators.size(); ++j) {
    const ActuatorSpec& a = model.actuators[j];
    if ((head == "joint" && a.name != middle) || (head == "gear" && a.group != middle)) continue;
    out.push_back(j);
  }
  return out;
}

// The model of `config` with at least `flex_sub_bodies` sub-bodies per flexible link, and its
// fitness on the training logs; null when the robot has no flexible links.
std::shared_ptr<const FitnessFunction> variant_fitness(const FitConfig& config,
                                                       int flex_sub_bodies) {
  ScenarioOverrides overrides;
  overrides.motion_optional = true;
  overrides.flex_sub_bodies = flex_sub_bodies;
  const Scenario scenario = load_scenario(config.scenario_path, overrides);
  const auto& joints = scenario.model->joints;
  if (std::none_of(joints.begin(), joints.end(),
                   [](const JointSpec& j) { return j.kind == JointKind::kFlex; })) {
    return nullptr;
  }
  return std::make_shared<const FitnessFunction>(
      scenario.model, load_fit_cases(scenario, config.train_logs, config.fitness), config.fitness);
}

ParameterSet transfer(const ParameterSet& from, const ParameterRegistry& to) {
  ParameterSet out(to);
  for (std::size_t i = 0; i < from.registry().size(); ++i) {
    const auto index = to.find(from.registry().spec(i).name);
    if (index) out.set(*index, from.get(i));
  }
  return out;
}

double to_search(const EffectTarget& t, double value) {
  return t.log_scale ? std::log(std::max(value, t.lower)) : value;
}
double to_model(const EffectTarget& t, double coordinate) {
  return t.log_scale ? std::exp(coordinate) : coordinate;
}

struct Probe {
  const Effect* effect = nullptr;
  std::shared_ptr<const FitnessFunction> fitness;  // the model the probe runs on
  std::vector<EffectTarget> targets;               // in the probe model's registry
};

// Least squares of the residual on columns; returns the coefficients and the residual sum of
// squares. A column is a per-case field scaled per channel: 1 on the channels it explains, 0 on
// those it does not, and a share on the IMU channels for one joint's parameter of an effect
// probed on all joints at once (see score_probe).
struct Column {
  const std::vector<std::vector<double>>* field;
  std::vector<double> scale;  // per channel
};

Column on_every_channel(const std::vector<std::vector<double>>* field, std::size_t channels) {
  return {field, std::vector<double>(channels, 1.0)};
}

Eigen::VectorXd solve(const std::vector<Column>& columns, const Residual& residual, double* rss) {
  const std::size_t k = columns.size();
  auto [normal, rhs] = detail::normal_equations(
      residual, k, [&columns](std::size_t a, std::size_t c, std::size_t row, std::size_t i) {
        return columns[a].scale[i] * (*columns[a].field)[c][row];
      });
  // A tiny ridge keeps collinear directions (e.g. K_t and the viscous term) solvable.
  const double ridge = 1e-9 * std::max(normal.diagonal().maxCoeff(), 1e-300);
  normal.diagonal().array() += ridge;
  const Eigen::VectorXd beta =
      k == 0 ? Eigen::VectorXd() : Eigen::VectorXd(normal.ldlt().solve(rhs));
  // RSS = r·r − 2βᵀAᵀr + βᵀAᵀAβ
  *rss = residual.rss - (k == 0 ? 0.0 : 2.0 * beta.dot(rhs) - beta.dot(normal * beta));
  return beta;
}

// Σ (r − Σ_a β_a·column_a)² over the scored frames.
double rss_of(const std::vector<Column>& columns, const std::vector<double>& beta,
              const Residual& residual) {
  double sum = 0.0;
  const std::size_t channels = residual.channels;
  for (std::size_t c = 0; c < residual.r_rad.size(); ++c) {
    for (std::size_t f = residual.first_frame[c]; f < residual.end_frame[c]; ++f) {
      for (std::size_t i = 0; i < channels; ++i) {
        const std::size_t row = f * channels + i;
        double e = residual.r_rad[c][row];
        for (std::size_t a = 0; a < columns.size(); ++a) {
          e -= beta[a] * columns[a].scale[i] * (*columns[a].field)[c][row];
        }
        sum += e * e;
      }
    }
  }
  return sum;
}

// The effect's parameter that the probe moves (the one with a probe fraction).
std::size_t probed_parameter(const Effect& effect) {
  std::size_t probed = effect.parameters.size();
  for (std::size_t p = 0; p < effect.parameters.size(); ++p) {
    if (effect.parameters[p].probe_fraction != 0.0) probed = p;
  }
  return probed;
}

// The fit's own directions as regression columns, each on every channel.
std::vector<Column> base_columns(const FitJacobian& jacobian, std::size_t channels) {
  std::vector<Column> columns;
  for (const auto& field : jacobian.columns) columns.push_back(on_every_channel(&field, channels));
  return columns;
}

// The regression's columns: the fit's own directions first, then one coefficient per target
// of an `each` parameter (on its joints' channels) or one for the tied targets of a global
// parameter (their joints' channels and the IMU's). The probe moved all targets of an `each`
// parameter at once, so its response on the IMU channels (which no single joint owns) is
// shared out equally among their coefficients: equal coefficients then reproduce the probe
// exactly. `coefficient_targets[c]` lists the targets of effect coefficient c.
std::vector<Column> regression_columns(const Probe& probe, std::size_t probed,
                                       const std::vector<std::vector<double>>& effect_field,
                                       const Residual& residual, const RobotModel& model,
                                       const FitJacobian& jacobian,
                                       std::vector<std::vector<std::size_t>>& coefficient_targets) {
  const Effect& effect = *probe.effect;
  const std::size_t channels = residual.channels;
  const std::size_t n_joints = model.actuators.size();
  std::vector<Column> columns = base_columns(jacobian, channels);
  const bool each = effect.parameters[probed].each;
  std::size_t each_count = 0;
  for (const auto& target : probe.targets) each_count += target.parameter == probed ? 1 : 0;
  for (std::size_t t = 0; t < probe.targets.size(); ++t) {
    if (probe.targets[t].parameter != probed) continue;
    if (each) {
      coefficient_targets.push_back({t});
      Column column{&effect_field, std::vector<double>(channels, 0.0)};
      for (const std::size_t j : owners(model, probe.targets[t].name)) column.scale[j] = 1.0;
      for (std::size_t i = n_joints; i < channels; ++i) {
        column.scale[i] = 1.0 / static_cast<double>(each_count);
      }
      columns.push_back(std::move(column));
    } else {
      // One coefficient for the tied targets: on the joints of any of them, and the IMU.
      if (coefficient_targets.empty()) {
        coefficient_targets.push_back({});
        Column column{&effect_field, std::vector<double>(channels, 0.0)};
        for (std::size_t i = n_joints; i < channels; ++i) column.scale[i] = 1.0;
        columns.push_back(std::move(column));
      }
      coefficient_targets.back().push_back(t);
      for (const std::size_t j : owners(model, probe.targets[t].name)) {
        columns.back().scale[j] = 1.0;
      }
    }
  }
  return columns;
}

// The fit's own free parameters (name → value) after the Gauss-Newton step `beta` (its first
// jacobian.columns.size() coefficients), clipped to the bounds.
std::vector<std::pair<std::string, double>> fit_step(const Eigen::VectorXd& beta,
                                                     const FitConfig& config,
                                                     const FitJacobian& jacobian) {
  const ParameterSpace& space = *config.space;
  std::vector<std::pair<std::string, double>> start;
  for (std::size_t i = 0; i < jacobian.columns.size(); ++i) {
    const Direction& d = jacobian.directions[i];
    const double coordinate = std::clamp(d.current + beta(i) * d.step, d.lower, d.upper);
    start.emplace_back(space.free_parameters()[i].name, space.to_model(i, coordinate));
  }
  return start;
}

// The warm start (the Gauss-Newton step of the fit's parameters, clipped) and the effect's
// estimated values from the coefficients `beta`.
void warm_start_and_estimate(const Probe& probe, const std::vector<Direction>& dirs,
                             const std::vector<std::vector<std::size_t>>& coefficient_targets,
                             const Eigen::VectorXd& beta, std::size_t base_columns,
                             const FitConfig& config, const FitJacobian& jacobian,
                             EffectScore& score) {
  score.fit_start = fit_step(beta, config, jacobian);
  for (std::size_t t = 0; t < probe.targets.size(); ++t) {
    double coordinate = dirs[t].current;
    for (std::size_t c = 0; c < coefficient_targets.size(); ++c) {
      for (const std::size_t u : coefficient_targets[c]) {
        if (u == t) coordinate += beta(base_columns + c) * dirs[t].step;
      }
    }
    score.estimate.emplace_back(probe.targets[t].name, to_model(probe.targets[t], coordinate));
  }
}

// The Gauss-Newton step of the fit's own parameters on their columns alone (clipped to the
// bounds), as free parameter name → value.
std::vector<std::pair<std::string, double>> base_step(const Residual& residual,
                                                      const FitConfig& config,
                                                      const FitJacobian& jacobian) {
  const std::vector<Column> columns = base_columns(jacobian, residual.channels);
  if (columns.empty()) return {};
  double rss = residual.rss;
  return fit_step(solve(columns, residual, &rss), config, jacobian);
}

EffectScore score_probe(const Probe& probe, const Residual& residual, const ParameterSet& current,
                        const RobotModel& model, const FitConfig& config,
                        const FitJacobian& jacobian) {
  EffectScore score;
  score.effect = probe.effect->name;
  const Effect& effect = *probe.effect;
  const std::size_t probed = probed_parameter(effect);
  ParameterSet start = transfer(current, probe.fitness->model().parameters);
  ParameterSet moved = start;
  std::vector<Direction> dirs(probe.targets.size());
  for (std::size_t t = 0; t < probe.targets.size(); ++t) {
    const EffectTarget& target = probe.targets[t];
    const double value = std::clamp(start.get(target.name), target.lower, target.upper);
    const double fraction =
        target.parameter == probed ? effect.parameters[probed].probe_fraction : 0.0;
    dirs[t] = direction(to_search(target, value), to_search(target, target.lower),
                        to_search(target, target.upper), fraction);
    if (fraction != 0.0) moved.set(target.name, to_model(target, dirs[t].current + dirs[t].step));
  }
  const std::vector<std::vector<double>> effect_field = response(*probe.fitness, moved, residual);

  std::vector<std::vector<std::size_t>> coefficient_targets;
  const std::vector<Column> columns = regression_columns(probe, probed, effect_field, residual,
                                                         model, jacobian, coefficient_targets);
  const std::size_t base_columns = jacobian.columns.size();
  double rss_base = residual.rss, rss_full = residual.rss;
  const std::vector<Column> base_only(columns.begin(),
                                      columns.begin() + static_cast<long>(base_columns));
  solve(base_only, residual, &rss_base);
  Eigen::VectorXd beta = solve(columns, residual, &rss_full);
  // Coefficients that imply values outside the bounds (a negative friction) are clipped.
  for (std::size_t c = 0; c < coefficient_targets.size(); ++c) {
    for (const std::size_t t : coefficient_targets[c]) {
      const Direction& d = dirs[t];
      const double implied =
          std::clamp(d.current + beta(base_columns + c) * d.step, d.lower, d.upper);
      beta(base_columns + c) = d.step != 0.0 ? (implied - d.current) / d.step : 0.0;
    }
  }
  const double rss_clipped =
      rss_of(columns, std::vector<double>(beta.data(), beta.data() + beta.size()), residual);
  const double n = residual.effective_samples;
  const double rss1 = std::min(std::max(rss_clipped, 1e-300), rss_base);
  score.status = "scored";
  score.coefficients = coefficient_targets.size();
  score.explained = residual.rss > 0.0 ? (rss_base - rss1) / residual.rss : 0.0;
  score.delta_bic = n * std::log(rss1 / std::max(rss_base, 1e-300)) +
                    static_cast<double>(score.coefficients) * std::log(n);
  warm_start_and_estimate(probe, dirs, coefficient_targets, beta, base_columns, config, jacobian,
                          score);
  return score;
}

}  // namespace

EffectRanking rank_effects(const FitConfig& config, const ParameterSet& current,
                           const std::vector<std::string>& candidates, int threads) {
  const FitnessFunction& train = *config.train;
  const RobotModel& model = train.model();
  std::vector<const Effect*> effects;
  if (candidates.empty()) {
    for (const Effect& effect : effect_library()) effects.push_back(&effect);
  } else {
    for (const std::string& name : candidates) effects.push_back(&find_effect(name));
  }
  std::set<std::string> free_names;
  for (const auto& p : config.free_parameters)
    free_names.insert(p.targets.begin(), p.targets.end());
  std::set<std::string> free_or_fixed = free_names;
  for (const auto& [name, value] : config.fixed) free_or_fixed.insert(name);

  EffectRanking ranking;
  const Residual residual = residual_of(train, current);
  ranking.rss0_rad2 = residual.rss;
  ranking.samples = residual.samples;
  ranking.effective_samples = residual.effective_samples;

  std::vector<Probe> probes;
  std::vector<EffectScore> unscored;
  std::map<int, std::shared_ptr<const FitnessFunction>> variants;
  const auto base = std::shared_ptr<const FitnessFunction>(config.train);
  for (const Effect* effect : effects) {
    EffectScore score;
    score.effect = effect->name;
    Probe probe{effect, base, {}};
    if (!effect_applies(*effect, model, config.scenario->rollout.servo)) {
      score.status = "not applicable";
    } else if (effect_covered_by(*effect, current, free_names)) {
      score.status = "in model";
    } else if (effect_covered_by(*effect, current, free_or_fixed)) {
      // The config holds its parameters at values of its own (a measured offset, say), or those
      // it does not hold are free already: a refit could free nothing, and a fit listing an
      // effect whose parameters are all fixed is an error (add_effect_parameters).
      score.status = "held fixed";
    } else if (effect->flex_sub_bodies > model.structure.flex_sub_bodies) {
      auto& variant = variants[effect->flex_sub_bodies];
      if (!variant) variant = variant_fitness(config, effect->flex_sub_bodies);
      if (!variant) score.status = "not applicable";
      probe.fitness = variant;
    }
    if (score.status.empty()) {
      probe.targets = effect_targets(*effect, ParameterSet(probe.fitness->model().parameters));
      if (probe.targets.empty()) score.status = "no parameters";
    }
    if (score.status.empty()) {
      probes.push_back(probe);
    } else {
      unscored.push_back(score);
    }
  }

  const FitJacobian jacobian = fit_jacobian(config, current, residual, threads);
  ranking.jacobian_rollouts = config.space->dimension();
  ranking.fit_start = base_step(residual, config, jacobian);
  std::vector<EffectScore> scored(probes.size());
  const int n = static_cast<int>(probes.size());
#pragma omp parallel for schedule(dynamic) num_threads(std::max(threads, 1))
  for (int i = 0; i < n; ++i) {
    try {
      scored[i] = score_probe(probes[i], residual, current, model, config, jacobian);
    } catch (const std::exception& error) {
      scored[i].effect = probes[i].effect->name;
      scored[i].status = std::string("probe failed: ") + error.what();
    }
  }
  std::vector<EffectScore> failed;
  for (auto& s : scored) {
    (s.scored() ? ranking.scores : failed).push_back(std::move(s));
  }
  std::stable_sort(
      ranking.scores.begin(), ranking.scores.end(),
      [](const EffectScore& a, const EffectScore& b) { return a.delta_bic < b.delta_bic; });
  for (auto& s : failed) ranking.scores.push_back(std::move(s));
  for (auto& s : unscored) ranking.scores.push_back(std::move(s));
  return ranking;
}

}  // namespace motoflex
