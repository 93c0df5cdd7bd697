#include "motoflex/effects/effect_loop.hpp"
#include "motoflex/effects/refit_candidates.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/folder_lock.hpp"
#include "motoflex/effects/convergence_guard.hpp"
#include "motoflex/effects/inert_effect.hpp"
#include "motoflex/effects/loop_identity.hpp"
#include "motoflex/effects/loop_report.hpp"
#include "motoflex/effects/refit_start_scan.hpp"
#include "motoflex/effects/term_discovery.hpp"
#include "motoflex/fit/effect_parameters.hpp"
#include "motoflex/fit/fit_run.hpp"
#include "motoflex/fit/refit_config.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDiscovered = "discovered_torque";
constexpr const char* kControl = "control";

// The control refit's "effect": the current model's own parameters, nothing added.
const Effect& control_effect() {
  static const Effect kEffect{
      kControl, "the current model refit alone (no effect added)", "none", {}, false, 0};
  return kEffect;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string iteration_dir(const fs::path& out, std::size_t iteration, const std::string& what) {
  char prefix[8];
  std::snprintf(prefix, sizeof prefix, "%02zu_", iteration);
  return (out / (prefix + what)).string();
}

// The effects a fit already models: those it lists and those whose parameters it all frees.
std::vector<std::string> modelled_effects(const FitConfig& config) {
  std::set<std::string> free_names;
  for (const auto& p : config.free_parameters)
    free_names.insert(p.targets.begin(), p.targets.end());
  std::vector<std::string> out;
  for (const Effect& effect : effect_library()) {
    const bool listed = std::find(config.effects.begin(), config.effects.end(), effect.name) !=
                        config.effects.end();
    if (listed || effect_covered_by(effect, config.space->base(), free_names)) {
      out.push_back(effect.name);
    }
  }
  return out;
}

struct Evaluated {
  FinishedFit fit;
  ErrorSummary train, validation;
};

Evaluated evaluate(FinishedFit fit) {
  const std::size_t k = fit.config.space->dimension();
  ErrorSummary train = summarize_errors(*fit.config.train, fit.best, k);
  ErrorSummary validation = summarize_errors(*fit.config.validation, fit.best, k);
  return {std::move(fit), std::move(train), std::move(validation)};
}

// The effect to add and where its refit starts (the signature regression's or the discovery's
// linearised optimum).
struct RefitStart {
  const Effect* effect = nullptr;
  std::vector<std::pair<std::string, double>> estimate;   // effect parameters
  std::vector<std::pair<std::string, double>> fit_start;  // the fit's free parameters
};

using Estimate = std::vector<std::pair<std::string, double>>;

// Writes the refit of `current` with `candidate`'s effect into `dir` and returns its config
// path. The refit starts at the signature regression's linearised optimum, which moves the
// fit's own parameters too (it helps where the effect and a fit parameter trade off). If that
// start is worse on the training logs than the current fit already is, the step has left the
// region where the linearisation holds (a fit parameter the logs barely constrain can take a
// long, wrong step); then the current fit with only the effect's estimate added is tried too,
// and the refit starts at the better of the two; with `refit: {scan: N}` the effect's own
// parameters are then scanned across their bounds (scan_effect_start). `start_rollouts` counts
// the rollouts this took. A refit dir that already has its fit.yaml (a loop run again) keeps it, so
// the refit resumes unchanged. With a start better than the current model, the start is the
// refit's incumbent.
std::string write_refit(const Evaluated& current, const RefitStart& candidate,
                        const std::string& dir, std::uint64_t* start_rollouts) {
  const fs::path yaml = fs::path(dir) / "fit.yaml";
  if (fs::exists(yaml)) return yaml.string();
  const Effect& effect = *candidate.effect;
  const nlohmann::json& fitted = current.fit.best_json["free"];
  const auto training_fitness = [&](const nlohmann::json& start, const Estimate& estimate) {
    const FitConfig config = load_fit_config(
        write_refit_config(current.fit.config, fitted, effect, estimate, dir, start));
    *start_rollouts += config.train->cases().size();
    return config.train->evaluate(config.space->apply(config.space->start())).fitness;
  };
  nlohmann::json start = fitted;
  for (const auto& [name, value] : candidate.fit_start) start[name] = value;
  double start_fitness = training_fitness(start, candidate.estimate);
  const double current_fitness =
      current.fit.summary.value("best_fitness", std::numeric_limits<double>::infinity());
  if (start_fitness > current_fitness) {
    const double fitted_fitness = training_fitness(fitted, candidate.estimate);
    if (fitted_fitness <= start_fitness) {
      start = fitted;
      start_fitness = fitted_fitness;
    }
  }
  Estimate estimate = candidate.estimate;
  const std::size_t points = current.fit.config.loop.refit_scan;
  if (points >= 3 && !effect.parameters.empty()) {
    // One config for the whole scan: the effect's parameters follow the fit's own in its space.
    const FitConfig probe = load_fit_config(
        write_refit_config(current.fit.config, fitted, effect, estimate, dir, start));
    const ParameterSpace& space = *probe.space;
    std::vector<std::size_t> indices;
    for (std::size_t i = current.fit.config.free_parameters.size(); i < space.dimension(); ++i) {
      indices.push_back(i);
    }
    std::vector<double> x = space.start();
    const double before = start_fitness;
    const bool grid = detail::scan_effect_start(
        space, indices, points,
        [&](const std::vector<double>& trial) {
          *start_rollouts += probe.train->cases().size();
          return probe.train->evaluate(space.apply(trial)).fitness;
        },
        x, start_fitness, current.fit.config.loop.refit_scan_pairs);
    estimate.clear();
    for (const std::size_t i : indices) {
      estimate.emplace_back(space.free_parameters()[i].targets.front(), space.to_model(i, x[i]));
    }
    std::printf("loop:   %s: start scan (%zu points %s): training fitness %.4g -> %.4g\n",
                effect.name.c_str(), points,
                grid ? "on each side of the pair's grid" : "per parameter", before, start_fitness);
    std::fflush(stdout);
  }
  return write_refit_config(current.fit.config, fitted, effect, estimate, dir, start,
                            start_fitness < current_fitness);
}

void account(LoopResult& result, const FinishedFit& fit) {
  result.evaluations += fit.summary.value("evaluations", std::uint64_t{0});
  result.fit_seconds += fit.summary.value("seconds", 0.0);
}

// Ranks the library's effects on the current fit's residual (step.ranking).
void rank_iteration(const Evaluated& current, const LoopOptions& options, std::size_t iteration,
                    LoopIteration& step, LoopResult& result) {
  const auto ranking_start = std::chrono::steady_clock::now();
  step.ranking = rank_effects(current.fit.config, current.fit.best, options.effects,
                              current.fit.config.threads);
  step.ranking_seconds = seconds_since(ranking_start);
  step.ranking.reliable = result.unreliable_reason.empty();
  step.ranking.unreliable_reason = result.unreliable_reason;
  std::size_t probes = step.ranking.jacobian_rollouts;
  for (const auto& score : step.ranking.scores) probes += score.scored() ? 1 : 0;
  result.probe_rollouts += probes * current.fit.config.train->cases().size();
  std::printf("loop: iteration %zu ranking (%.1f s):", iteration, step.ranking_seconds);
  for (const auto& score : step.ranking.scores) {
    if (score.scored()) std::printf(" %s %.3g", score.effect.c_str(), score.delta_bic);
  }
  std::printf("\n");
  std::fflush(stdout);
}

// The validation errors a refit must beat by the loop's tests: the current model's, or its
// control refit's where that validates better (LoopOptions::control).
struct ValidationBar {
  double fit_error_rad = 0.0;
  double bic = 0.0;
};

ValidationBar bar_of(const ErrorSummary& validation) {
  return {validation.fit_error_rad, validation.bic};
}

// Whether the refit's effect does nothing at its optimum (inert_effect.hpp); counts the rollouts.
bool effect_inert(const Evaluated& current, const Effect& effect, const Evaluated& refit,
                  LoopResult& result) {
  if (effect.parameters.empty()) return false;
  result.probe_rollouts += 2 * refit.fit.config.train->cases().size();
  return effect_is_inert(*refit.fit.config.train, *refit.fit.config.space,
                         current.fit.config.free_parameters.size(), refit.fit.best,
                         current.fit.best);
}

// Whether `validation` passes the loop's gain and BIC tests against `bar`.
bool passes(const ErrorSummary& validation, const ValidationBar& bar, const LoopOptions& options) {
  return validation.fit_error_rad <= (1.0 - options.min_gain) * bar.fit_error_rad &&
         validation.bic < bar.bic;
}

// Refits the current model with one candidate effect and judges it on the validation logs
// against `bar` (and, for a control or an inert effect, as a re-optimisation against the
// current model).
LoopRefit refit_with(const Evaluated& current, const RefitStart& candidate, const std::string& dir,
                     const LoopOptions& options, const ValidationBar& bar, LoopResult& result,
                     std::vector<Evaluated>& refits) {
  const std::string yaml = write_refit(current, candidate, dir, &result.probe_rollouts);
  std::printf("loop: refit with %s -> %s\n", candidate.effect->name.c_str(), dir.c_str());
  std::fflush(stdout);
  FitConfig config = load_fit_config(yaml);
  config.loop = options;
  config.threads = current.fit.config.threads;
  refits.push_back(evaluate(ensure_fit(config)));
  refits.back().fit.config.threads = config.threads;  // as for the base fit (run_loop)
  const Evaluated& refit = refits.back();
  account(result, refit.fit);
  LoopRefit row;
  row.effect = candidate.effect->name;
  row.run_dir = dir;
  row.train_rms_deg = refit.train.rms_deg;
  row.val_rms_deg = refit.validation.rms_deg;
  row.val_mae_rad = refit.validation.mae_rad;
  row.val_imu_rms_deg = imu_rms_deg(refit.validation);
  row.val_bic = refit.validation.bic;
  row.free_parameters = refit.fit.config.space->dimension();
  row.evaluations = refit.fit.summary.value("evaluations", std::uint64_t{0});
  row.seconds = refit.fit.summary.value("seconds", 0.0);
  // The gain is measured as the fit measures its error: on the joints (with their weights),
  // and on the IMU too when the fitness scores it.
  // (As the fit measures it: RMS for squared errors, mean absolute error for absolute ones.)
  const bool control = candidate.effect->parameters.empty();
  row.inert = effect_inert(current, *candidate.effect, refit, result);
  row.significant = !control && !row.inert && passes(refit.validation, bar, options);
  // (An inert refit's own re-optimisation is judged in reoptimise(), without the effect.)
  row.reoptimises = control && passes(refit.validation, bar_of(current.validation), options);
  std::string verdict = row.significant ? "significant" : "not significant";
  if (row.inert) verdict = "inert: the effect does not help at the refit's optimum";
  if (row.reoptimises) verdict += "; re-optimises";
  std::printf("loop:   %s: validation RMS %.4g -> %.4g deg, MAE %.4g -> %.4g mrad (%s)\n",
              row.effect.c_str(), current.validation.rms_deg, row.val_rms_deg,
              1e3 * current.validation.mae_rad, 1e3 * row.val_mae_rad, verdict.c_str());
  std::fflush(stdout);
  return row;
}

void record_errors_after(const Evaluated& model, LoopIteration& step) {
  step.fitted = model.fit.best_json["free"];
  step.train_rms_after_deg = model.train.rms_deg;
  step.val_rms_after_deg = model.validation.rms_deg;
  step.val_mae_after_rad = model.validation.mae_rad;
  step.val_imu_rms_after_deg = imu_rms_deg(model.validation);
}

// No library effect helped: discover candidate torque terms on the residual and refit with
// them (their refit is step.refits.back()). Returns the terms (empty: none supported, no refit).
std::vector<DiscoveredTerm> discover_and_refit(std::size_t iteration, const fs::path& out,
                                               const LoopOptions& options, const Evaluated& current,
                                               const ValidationBar& bar, LoopIteration& step,
                                               LoopResult& result, std::vector<Evaluated>& refits) {
  const auto start = std::chrono::steady_clock::now();
  // Its probe rollouts (one set of the training logs per free parameter and per candidate term)
  // take minutes on a walking robot: say it has started.
  std::printf("loop: discovery: probing candidate torque terms on the residual (%d threads)\n",
              current.fit.config.threads);
  std::fflush(stdout);
  const TermDiscovery discovery =
      discover_terms(current.fit.config, current.fit.best, current.fit.config.threads,
                     options.discover_terms, options.discover_screen);
  result.probe_rollouts += discovery.probe_rollouts;
  step.discovery_explained = discovery.explained;
  step.discovery_delta_bic = discovery.delta_bic;
  if (discovery.terms.empty()) {
    std::printf("loop: discovery (%.1f s, %zu candidates): no sparse term supported\n",
                seconds_since(start), discovery.candidates);
    return {};
  }
  ParameterSet proposal = current.fit.best;
  for (const auto& [name, value] : discovery.estimate) proposal.set(name, value);
  step.discovery_proposal = discovered_formula(discovery.terms, proposal);
  std::printf("loop: discovery (%.1f s, %zu candidates): %s (explains %.3g, dBIC %.3g)\n",
              seconds_since(start), discovery.candidates, step.discovery_proposal.c_str(),
              discovery.explained, discovery.delta_bic);
  std::fflush(stdout);
  const Effect effect = discovered_effect(discovery.terms);
  const RefitStart refit{&effect, discovery.estimate, discovery.fit_start};
  step.refits.push_back(refit_with(current, refit, iteration_dir(out, iteration, kDiscovered),
                                   options, bar, result, refits));
  return discovery.terms;
}

// The current model, nothing added, at `source`'s values of its own parameters, as a fit of its
// own in `dir` (those values are its incumbent; one evaluation, no search, no polish): an inert
// effect's refit carried over to the model without the effect.
Evaluated without_effect(const Evaluated& current, const Evaluated& source, const std::string& dir,
                         const LoopOptions& options, LoopResult& result) {
  const fs::path yaml = fs::path(dir) / "fit.yaml";
  if (!fs::exists(yaml)) {
    const FitSpec spec = evaluation_spec(current.fit.config, source.fit.best_json["free"], dir);
    fs::create_directories(dir);
    write_file_atomically(yaml.string(),
                          "# Written by `motoflex loop`: " + current.fit.config.name +
                              " at the values of an inert effect's refit "
                              "(JSON is valid YAML)\n" +
                              fit_spec_to_json(spec).dump(2) + "\n");
  }
  FitConfig config = load_fit_config(yaml.string());
  config.loop = options;
  config.threads = current.fit.config.threads;
  Evaluated out = evaluate(ensure_fit(config));
  out.fit.config.threads = config.threads;
  account(result, out.fit);
  return out;
}

// The control refit of an iteration (LoopOptions::control): the current model refit alone,
// judged against the current model. Returns the bar the effects must then beat: the better of
// the two validations.
ValidationBar refit_control(std::size_t iteration, const fs::path& out, const LoopOptions& options,
                            const Evaluated& current, LoopIteration& step, LoopResult& result,
                            std::vector<Evaluated>& refits) {
  ValidationBar bar = bar_of(current.validation);
  if (!options.control) return bar;
  // It starts as an effect's refit does: at the linearised step of the model's own parameters
  // (with no effect column), or at the current model when that step is worse.
  const RefitStart start{&control_effect(), {}, step.ranking.fit_start};
  step.refits.push_back(refit_with(current, start, iteration_dir(out, iteration, kControl), options,
                                   bar, result, refits));
  const ErrorSummary& control = refits.back().validation;
  bar.fit_error_rad = std::min(bar.fit_error_rad, control.fit_error_rad);
  bar.bic = std::min(bar.bic, control.bic);
  return bar;
}

// Refits the ranked candidates (and, when none passes, the next `widen` in rank), each judged
// against `bar`; returns the index into `refits` of the best significant one (lowest validation
// BIC), if any.
std::optional<std::size_t> refit_ranked(std::size_t iteration, const fs::path& out,
                                        const LoopOptions& options, const Evaluated& current,
                                        const std::vector<std::string>& retained,
                                        const ValidationBar& bar, LoopIteration& step,
                                        LoopResult& result, std::vector<Evaluated>& refits) {
  std::optional<std::size_t> winner;
  // The ranking orders; the refit on validation logs decides. (ΔBIC over N_eff is a conservative
  // screen: on a smooth real residual it can leave no effect "supported".) Effects that passed
  // the validation test last time but were not added (`retained`) are refit again on top of the
  // new model, whatever their rank now: the linearised ranking around the new fit can credit a
  // second one with nothing (the first one's parameters re-tuned take up its probe) although
  // the two together fit better, as a current limit and load-dependent friction do on the XL330.
  const std::vector<const EffectScore*> candidates =
      refit_candidates(step.ranking, options.candidates, retained);
  const auto refit_all = [&](const std::vector<const EffectScore*>& round) {
    for (const EffectScore* candidate : round) {
      const std::string dir = iteration_dir(out, iteration, candidate->effect);
      const RefitStart start{&find_effect(candidate->effect), candidate->estimate,
                             candidate->fit_start};
      step.refits.push_back(refit_with(current, start, dir, options, bar, result, refits));
      if (step.refits.back().significant &&
          (!winner || refits.back().validation.bic < refits[*winner].validation.bic)) {
        winner = refits.size() - 1;
      }
    }
  };
  refit_all(candidates);
  if (!winner && options.widen > 0) {
    std::vector<std::string> tried;
    for (const EffectScore* candidate : candidates) tried.push_back(candidate->effect);
    const std::vector<const EffectScore*> next =
        refit_candidates(step.ranking, options.widen, {}, tried);
    if (!next.empty()) {
      std::printf("loop: none of the first %zu passes; widening to the next %zu in rank\n",
                  candidates.size(), next.size());
      refit_all(next);
    }
  }
  return winner;
}

// No effect was credited: the best re-optimisation of the current model that passes the tests
// against it, by validation BIC: the control, or an inert effect's refit carried over without
// the effect (NN_reoptimised_<effect>, judged on its own validation); its index into `refits`.
std::optional<std::size_t> reoptimise(std::size_t iteration, const fs::path& out,
                                      const LoopOptions& options, const Evaluated& current,
                                      LoopIteration& step, LoopResult& result,
                                      std::vector<Evaluated>& refits) {
  std::optional<std::size_t> best;  // into refits
  std::string from;
  const auto consider = [&](std::size_t index, const std::string& effect) {
    if (!best || refits[index].validation.bic < refits[*best].validation.bic) {
      best = index;
      from = effect;
    }
  };
  const std::size_t rows = step.refits.size();
  for (std::size_t i = 0; i < rows; ++i) {
    LoopRefit& row = step.refits[i];
    if (row.reoptimises) consider(i, row.effect);
    if (!row.inert) continue;
    const std::string dir = iteration_dir(out, iteration, "reoptimised_" + row.effect);
    refits.push_back(without_effect(current, refits[i], dir, options, result));
    row.reoptimises = passes(refits.back().validation, bar_of(current.validation), options);
    std::printf(
        "loop:   %s dropped, its refit's values: validation RMS %.4g deg, MAE %.4g mrad "
        "(%s)\n",
        row.effect.c_str(), refits.back().validation.rms_deg,
        1e3 * refits.back().validation.mae_rad,
        row.reoptimises ? "re-optimises" : "does not re-optimise");
    std::fflush(stdout);
    if (row.reoptimises) consider(refits.size() - 1, row.effect);
  }
  if (!best) return std::nullopt;
  step.reoptimised = true;
  step.reoptimised_from = from;
  return best;
}

// One iteration: rank, refit the current model alone (the control) and with each top candidate,
// keep the best significant effect, or else the best re-optimisation. Returns false when the
// model did not change (the loop stops).
bool run_iteration(std::size_t iteration, const fs::path& out, const LoopOptions& options,
                   Evaluated& current, std::vector<std::string>& model,
                   std::vector<std::string>& retained, LoopResult& result) {
  LoopIteration step;
  step.model_run_dir = current.fit.config.out_dir;
  step.train_rms_before_deg = current.train.rms_deg;
  step.val_rms_before_deg = current.validation.rms_deg;
  step.val_mae_before_rad = current.validation.mae_rad;
  step.val_imu_rms_before_deg = imu_rms_deg(current.validation);
  rank_iteration(current, options, iteration, step, result);
  std::vector<Evaluated> refits;
  const ValidationBar bar = refit_control(iteration, out, options, current, step, result, refits);
  std::optional<std::size_t> winner =
      refit_ranked(iteration, out, options, current, retained, bar, step, result, refits);
  std::vector<DiscoveredTerm> discovered;
  if ((!winner || options.discover_always) && options.discover_terms > 0) {
    discovered = discover_and_refit(iteration, out, options, current, bar, step, result, refits);
    if (!discovered.empty() && step.refits.back().significant &&
        (!winner || refits.back().validation.bic < refits[*winner].validation.bic)) {
      winner = refits.size() - 1;
    }
  }
  if (!winner) winner = reoptimise(iteration, out, options, current, step, result, refits);
  if (!winner) {
    record_errors_after(current, step);
    result.iterations.push_back(std::move(step));
    std::printf("loop: no candidate improves the validation error significantly; stop\n");
    return false;
  }
  // (A re-optimisation from an inert refit is a fit of its own, past the end of step.refits.)
  const std::string chosen = step.reoptimised ? step.reoptimised_from : step.refits[*winner].effect;
  retained.clear();
  for (const LoopRefit& refit : step.refits) {
    if (refit.significant && refit.effect != chosen && refit.effect != kDiscovered) {
      retained.push_back(refit.effect);
    }
  }
  Evaluated& best = refits[*winner];
  record_errors_after(best, step);
  if (step.reoptimised) {
    std::printf("loop: no effect is credited; going on from the re-optimised model (%s)\n",
                step.reoptimised_from.c_str());
  } else {
    step.added_effect = chosen;
    model.push_back(step.added_effect);
    if (step.added_effect == kDiscovered) {
      step.discovered_formula = discovered_formula(discovered, best.fit.best);
      std::printf("loop: discovered %s\n", step.discovered_formula.c_str());
    }
    std::printf("loop: added %s\n", step.added_effect.c_str());
  }
  result.iterations.push_back(std::move(step));
  best.fit.config.loop = options;
  current = std::move(best);
  return true;
}

}  // namespace

LoopResult run_loop(const std::string& fit_path, const FitOverrides& overrides, bool force) {
  const auto start = std::chrono::steady_clock::now();
  const FitConfig user = load_fit_config(fit_path, overrides);
  if (user.validation_logs.empty()) {
    throw InputError(user.path, 0, "validation",
                     "the loop chooses effects on validation logs: give `validation:` or "
                     "--validation");
  }
  const LoopOptions& options = user.loop;
  const fs::path out = user.out_dir;
  const FolderLock lock(out.string());  // one loop per folder; each fit locks its own sub-folder
  // A folder resumes only the same loop; another loop's files are moved aside.
  const std::string moved = check_loop_identity(user, out.string());
  if (!moved.empty()) std::printf("loop: %s\n", moved.c_str());
  LoopResult result;
  result.out_dir = out.string();

  FitOverrides base_overrides = overrides;
  base_overrides.out = iteration_dir(out, 0, "base");
  std::printf("loop: base fit -> %s\n", base_overrides.out->c_str());
  std::fflush(stdout);
  Evaluated current = evaluate(ensure_fit(load_fit_config(fit_path, base_overrides)));
  // A finished fit read back from its folder has the thread count it ran with; the ranking,
  // discovery and refits of this run use this run's (--threads), which changes no number.
  current.fit.config.threads = user.threads;
  result.base_run_dir = current.fit.config.out_dir;
  result.unreliable_reason =
      check_converged_for_ranking(current.fit, result.base_run_dir, force, "motoflex loop");
  if (!result.unreliable_reason.empty()) {
    std::printf("loop: %s; going on (--force), every ranking marked unreliable\n",
                result.unreliable_reason.c_str());
  }
  result.base_model = modelled_effects(current.fit.config);
  std::vector<std::string> model = result.base_model;
  account(result, current.fit);
  std::vector<std::string> retained;  // significant last time, not added: refit again
  for (std::size_t iteration = 1; iteration <= options.max_iterations; ++iteration) {
    if (!run_iteration(iteration, out, options, current, model, retained, result)) break;
  }
  result.final_model = model;
  result.final_run_dir = current.fit.config.out_dir;
  result.wall_seconds = seconds_since(start);
  write_loop_outputs(result, user);
  return result;
}

}  // namespace motoflex
