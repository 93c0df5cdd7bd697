#include "motoflex/studies/seed001/seed001_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <limits>

#include "motoflex/core/error.hpp"
#include "motoflex/core/random_stream.hpp"
#include "motoflex/core/text_hash.hpp"
#include "motoflex/scenario/truth_file.hpp"
#include "motoflex/sim/parallel_rollouts.hpp"

namespace motoflex {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The window of motoflex_2011.md §1's mean speeds: from 1 s to min(9 s, end).
constexpr double kMeanSpeedFrom_s = 1.0;
constexpr double kMeanSpeedTo_s = 9.0;

// One rollout to run: the scenario owns model, parameters and commands; a command file's walk
// brings its step and steady window (a planned walk's come from its plan).
struct Job {
  std::string walk;
  std::string variant;
  Scenario scenario;
  const Seed001Walk* timing = nullptr;
};

Scenario load_variant_walk(const Seed001Variant& variant, const Seed001Walk& walk,
                           const std::map<std::string, double>& walk_options) {
  ScenarioOverrides overrides;
  if (walk.replays_commands()) {
    overrides.motion_log = walk.commands_path;
  } else {
    overrides.motion_scenario = walk.scenario_path;
    overrides.walk_options = walk_options;
  }
  if (!variant.params_path.empty()) overrides.parameters_json = variant.params_path;
  if (variant.physics) overrides.physics.push_back(*variant.physics);
  Scenario scenario = load_scenario_or_truth(variant.scenario_path, overrides);
  if (!walk.replays_commands() && !scenario.walk_plan) {
    throw InputError(walk.scenario_path, 0, "motion", "the seed-001 experiment needs a `walk`");
  }
  return scenario;
}

// Why a walk cannot run (its command file is missing), or "".
std::string walk_pending(const Seed001Walk& walk) {
  if (!walk.replays_commands()) return "";
  std::error_code error;
  if (std::filesystem::is_regular_file(walk.commands_path, error)) return "";
  return "command file " + walk.commands_path + " not found (pass --commands " + walk.name +
         "=FILE)";
}

std::vector<RolloutResult> run_jobs(const std::deque<Job>& jobs, int threads) {
  std::vector<RolloutJob> rollout_jobs;
  for (const Job& job : jobs) {
    rollout_jobs.push_back({job.scenario.model.get(), &job.scenario.parameters,
                            &job.scenario.commands, job.scenario.rollout});
  }
  return run_rollouts(rollout_jobs, threads);
}

Seed001Run evaluate(const Job& job, RolloutResult result) {
  Seed001Run run;
  if (job.scenario.walk_plan) {
    const NaoWalkPlan& plan = *job.scenario.walk_plan;
    run = evaluate_walk_run(std::move(result), plan.steady_start_s, plan.steady_end_s,
                            0.5 * plan.params.step_duration_s);
  } else {
    run = evaluate_walk_run(std::move(result), job.timing->steady_start_s, job.timing->steady_end_s,
                            job.timing->step_s);
  }
  run.walk = job.walk;
  run.variant = job.variant;
  return run;
}

// A copy of the job whose commands carry replica `k`'s noise (Seed001Ensemble).
Job perturbed_copy(const Job& job, int k, double sigma_rad) {
  Job copy = job;
  const std::string tag = job.walk + "/" + job.variant;
  RandomStream noise({static_cast<std::uint64_t>(k), std::stoull(hash_text(tag), nullptr, 16)});
  const CommandTrajectory& c = job.scenario.commands;
  std::vector<double> angles = c.angles_rad();
  for (double& angle : angles) angle += sigma_rad * noise.normal();
  copy.scenario.commands = CommandTrajectory(c.times_s(), std::move(angles), c.joints());
  return copy;
}

// A copy of the job whose quick step starts from ODE random state `seed` (Seed001Ensemble).
Job reseeded_copy(const Job& job, std::uint32_t seed) {
  Job copy = job;
  copy.scenario.rollout.quickstep_seed = seed;
  return copy;
}

Seed001Replica replica_of(const Seed001Run& run) {
  return {run.fell, run.fall_s, run.speed_mm_s, run.mean_speed_mm_s, run.lateral_m};
}

const Seed001Walk& walk_named(const Seed001Config& config, const std::string& name) {
  for (const Seed001Walk& walk : config.walks) {
    if (walk.name == name) return walk;
  }
  throw InputError(config.path, 0, "zmp.walk", "no walk '" + name + "'");
}

const Seed001Variant& variant_named(const Seed001Config& config, const std::string& name) {
  for (const Seed001Variant& variant : config.variants) {
    if (variant.name == name) return variant;
  }
  throw InputError(config.path, 0, "zmp.variants", "no variant '" + name + "'");
}

}  // namespace

Seed001Run evaluate_walk_run(RolloutResult result, double steady_start_s, double steady_end_s,
                             double step_s) {
  Seed001Run run;
  run.end = result.end;
  run.end_time_s = result.end_time_s;
  run.end_detail = result.end_detail;
  run.step_s = step_s;
  run.fell = result.end == RolloutEnd::kFell || result.end == RolloutEnd::kDiverged;
  run.fall_s = run.fell ? result.end_time_s : kNaN;
  const std::vector<double>& t = result.time_s;
  const std::size_t frames = t.size();
  std::vector<double> x(frames), y(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    x[f] = result.torso_position_m[3 * f];
    y[f] = result.torso_position_m[3 * f + 1];
  }
  const double last_s = frames == 0 ? 0.0 : t.back();
  // A fall cuts the steady part at the last step boundary before it: whole steps only, so the
  // window starts and ends at the same phase of the gait and leaves the fall itself out.
  run.steady_start_s = steady_start_s;
  run.steady_end_s = steady_end_s;
  if (last_s < steady_end_s) {
    const double steps = std::floor((last_s - steady_start_s) / step_s + 1e-9);
    run.steady_end_s = steady_start_s + std::max(steps, 0.0) * step_s;
  }
  // At least one gait cycle (two steps), or there is no steady speed to speak of.
  const bool measurable = run.steady_end_s - run.steady_start_s >= 2.0 * step_s - 1e-9;
  run.speed_mm_s = measurable ? mean_speed_mm_s(t, x, run.steady_start_s, run.steady_end_s) : kNaN;
  run.mean_speed_mm_s = mean_speed_mm_s(t, x, kMeanSpeedFrom_s, std::min(kMeanSpeedTo_s, last_s));
  run.distance_m = frames == 0 ? 0.0 : x.back() - x.front();
  run.lateral_m = frames == 0 ? 0.0 : y.back() - y.front();
  if (run.fell && frames > 0) {
    run.fall_roll_rad = result.imu_roll_rad.back();
    run.fall_pitch_rad = result.imu_pitch_rad.back();
    run.fall_direction = fall_direction(run.fall_roll_rad, run.fall_pitch_rad);
  } else {
    run.fall_roll_rad = run.fall_pitch_rad = kNaN;
  }
  const std::vector<double> ranges =
      measurable
          ? window_ranges(t, result.imu_pitch_rad, run.steady_start_s, run.steady_end_s, step_s)
          : std::vector<double>{};
  run.pitch_alternation = alternation_ratio(ranges);
  run.pitch_range_rad = kNaN;
  if (!ranges.empty()) {
    double sum = 0.0;
    for (const double r : ranges) sum += r;
    run.pitch_range_rad = sum / static_cast<double>(ranges.size());
  }
  for (const double roll : result.imu_roll_rad) {
    run.max_abs_roll_rad = std::max(run.max_abs_roll_rad, std::abs(roll));
  }
  run.result = std::move(result);
  return run;
}

int choose_zmp_trial(const std::vector<Seed001ZmpTrial>& trials) {
  int best = -1;
  double best_roll = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < trials.size(); ++k) {
    const Seed001Run& run = trials[k].run;
    if (run.fell || !run.pending.empty() || !run.unplannable.empty()) continue;
    if (run.max_abs_roll_rad < best_roll) {
      best_roll = run.max_abs_roll_rad;
      best = static_cast<int>(k);
    }
  }
  return best;
}

namespace {

// The ZMP search's trials as jobs appended to `jobs` ((variant slot, setting) of each in
// `zmp_jobs`), and the walk's own values of the searched options (from the plan of its first
// loaded run). A value the planner refuses is a trial marked unplannable, not an error.
Seed001ZmpResult load_zmp_trials(const Seed001Config& config, const std::vector<Seed001Run>& runs,
                                 const std::vector<int>& job_of_run, std::deque<Job>& jobs,
                                 std::vector<std::pair<std::size_t, std::size_t>>& zmp_jobs) {
  Seed001ZmpResult zmp;
  zmp.walk = config.zmp.walk;
  const Seed001Walk& walk = walk_named(config, config.zmp.walk);
  for (const std::string& name : config.zmp.variants) {
    const Seed001Variant& variant = variant_named(config, name);
    if (!variant.pending.empty()) continue;
    zmp.variants.push_back(name);
    zmp.trials.emplace_back(config.zmp.settings.size());
    for (std::size_t k = 0; k < config.zmp.settings.size(); ++k) {
      const Seed001ZmpSetting& setting = config.zmp.settings[k];
      Seed001ZmpTrial& trial = zmp.trials.back()[k];
      trial.setting = setting;
      trial.run.walk = walk.name;
      trial.run.variant = name;
      try {
        jobs.push_back({walk.name, name,
                        load_variant_walk(variant, walk, {{setting.option, setting.value}}),
                        &walk});
        zmp_jobs.emplace_back(zmp.variants.size() - 1, k);
      } catch (const InputError& error) {
        // The same variant and walk loaded above and the option is a walk key (checked with
        // the config): this value is one the planner refuses, an answer of the search.
        trial.run.unplannable = error.message();
      }
    }
  }
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (runs[r].walk != walk.name || job_of_run[r] < 0) continue;
    const NaoWalkParams& params = jobs[job_of_run[r]].scenario.walk_plan->params;
    for (const Seed001ZmpSetting& setting : config.zmp.settings) {
      bool listed = false;
      for (const Seed001ZmpSetting& d : zmp.defaults) listed = listed || d.option == setting.option;
      if (!listed) {
        zmp.defaults.push_back({setting.option, params.numeric(setting.option).value_or(kNaN)});
      }
    }
    break;
  }
  return zmp;
}

// The ensemble's replica jobs, (run, job) of each: the noise replicas, then the quick-step seed
// replicas (Seed001Ensemble), appended to `jobs` after those already there.
struct ReplicaJobs {
  std::vector<std::pair<std::size_t, std::size_t>> noise;
  std::vector<std::pair<std::size_t, std::size_t>> seeds;
};

ReplicaJobs add_replica_jobs(const std::vector<int>& job_of_run, const Seed001Ensemble& ensemble,
                             std::deque<Job>& jobs) {
  ReplicaJobs replicas;
  for (std::size_t r = 0; r < job_of_run.size(); ++r) {
    if (job_of_run[r] < 0) continue;
    for (int k = 0; k < ensemble.size; ++k) {
      replicas.noise.emplace_back(r, jobs.size());
      jobs.push_back(
          perturbed_copy(jobs[static_cast<std::size_t>(job_of_run[r])], k, ensemble.sigma_rad));
    }
  }
  for (std::size_t r = 0; r < job_of_run.size(); ++r) {
    if (job_of_run[r] < 0) continue;
    const std::size_t j = static_cast<std::size_t>(job_of_run[r]);
    if (jobs[j].scenario.rollout.solver != StepSolver::kQuickStep) continue;
    for (int k = 1; k <= ensemble.quickstep_seeds; ++k) {
      replicas.seeds.emplace_back(r, jobs.size());
      jobs.push_back(reseeded_copy(jobs[j], static_cast<std::uint32_t>(k)));
    }
  }
  return replicas;
}

}  // namespace

Seed001Results run_seed001(const Seed001Config& config, int threads,
                           const Seed001Ensemble& ensemble) {
  const auto start = std::chrono::steady_clock::now();
  Seed001Results results;
  // Every rollout of the study is loaded first (bad input fails before any simulation), then all
  // run together.
  std::deque<Job> jobs;
  std::vector<int> job_of_run;  // per run: index into jobs, −1 for a pending variant
  for (const Seed001Walk& walk : config.walks) {
    const std::string walk_missing = walk_pending(walk);
    for (const Seed001Variant& variant : config.variants) {
      if (!walk.runs_under(variant.name)) continue;
      Seed001Run run;
      run.walk = walk.name;
      run.variant = variant.name;
      run.pending = variant.pending.empty() ? walk_missing : variant.pending;
      const bool pending = !run.pending.empty();
      results.runs.push_back(std::move(run));
      if (pending) {
        job_of_run.push_back(-1);
        continue;
      }
      job_of_run.push_back(static_cast<int>(jobs.size()));
      jobs.push_back({walk.name, variant.name, load_variant_walk(variant, walk, {}), &walk});
    }
  }
  // ZMP trials: (variant slot, setting) of each job, from first_zmp_job on.
  std::vector<std::pair<std::size_t, std::size_t>> zmp_jobs;
  const std::size_t first_zmp_job = jobs.size();
  if (!config.zmp.walk.empty()) {
    results.zmp = load_zmp_trials(config, results.runs, job_of_run, jobs, zmp_jobs);
  }

  const ReplicaJobs replicas = add_replica_jobs(job_of_run, ensemble, jobs);
  std::vector<RolloutResult> rollouts = run_jobs(jobs, threads);
  // The runs first, so that their replicas are appended to the evaluated runs.
  for (std::size_t r = 0; r < results.runs.size(); ++r) {
    if (job_of_run[r] < 0) continue;
    const std::size_t j = static_cast<std::size_t>(job_of_run[r]);
    results.runs[r] = evaluate(jobs[j], std::move(rollouts[j]));
  }
  for (const auto& [r, j] : replicas.noise) {
    results.runs[r].ensemble.push_back(replica_of(evaluate(jobs[j], std::move(rollouts[j]))));
  }
  for (const auto& [r, j] : replicas.seeds) {
    results.runs[r].seed_ensemble.push_back(replica_of(evaluate(jobs[j], std::move(rollouts[j]))));
  }
  if (results.zmp) {
    for (std::size_t k = 0; k < zmp_jobs.size(); ++k) {
      const auto [slot, setting] = zmp_jobs[k];
      const std::size_t j = first_zmp_job + k;
      Seed001ZmpTrial& trial = results.zmp->trials[slot][setting];
      trial.run = evaluate(jobs[j], std::move(rollouts[j]));
    }
    for (const auto& trials : results.zmp->trials) {
      results.zmp->chosen.push_back(choose_zmp_trial(trials));
    }
  }
  results.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return results;
}

}  // namespace motoflex
