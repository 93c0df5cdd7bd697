#pragma once

// Synthetic fit problems for tests: "measured" logs of the pendulum bench from a known truth,
// and fit configs over them.

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include <gtest/gtest.h>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex/fit/fit_session.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/rollout_log.hpp"
#include "scratch_dir.hpp"

namespace motoflex::testing {

inline const std::string kPendulumScenario =
    std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/servo_pendulum_replay.yaml";

// The truth the synthetic logs are recorded with.
inline std::map<std::string, double> pendulum_truth() {
  return {{"bench.Kt_nm_per_a", 0.35},
          {"bench.R_ohm", 2.6},
          {"joint.pendulum.friction_nm", 0.08},
          {"joint.pendulum.viscous_nm_s_per_rad", 0.02},
          {"bench.armature_kg_m2", 0.003}};
}

// Records `name`.csv into `folder` from the truth (plus `extra` parameters such as sensor noise).
inline void record_pendulum_log(const std::filesystem::path& folder, const std::string& name,
                                const std::map<std::string, double>& extra = {},
                                std::uint64_t seed = 1) {
  Scenario scenario = load_scenario(kPendulumScenario);
  for (const auto& [key, value] : pendulum_truth()) scenario.parameters.set(key, value);
  for (const auto& [key, value] : extra) scenario.parameters.set(key, value);
  scenario.rollout.seed = seed;
  const RolloutResult result =
      run_rollout(*scenario.model, scenario.parameters, scenario.commands, scenario.rollout);
  JointLogMeta meta;
  meta.robot = scenario.model->name;
  meta.rate_hz = scenario.log_rate_hz;
  meta.motion = scenario.motion_description;
  meta.origin = "test truth";
  meta.parameters = scenario.log_parameters;
  std::filesystem::create_directories(folder);
  write_joint_log((folder / (name + ".csv")).string(), joint_log_from_rollout(result, meta));
}

// A fit config over the logs of `data`, written to `folder`/fit.yaml.
inline std::string write_pendulum_fit(const std::filesystem::path& folder,
                                      const std::filesystem::path& data,
                                      const std::string& strategy, const std::string& budget,
                                      const std::string& extra = "") {
  const std::string path = (folder / "fit.yaml").string();
  std::ofstream(path) << "name: pendulum\n"
                      << "scenario: " << kPendulumScenario << "\n"
                      << "data: " << data.string() << "\n"
                      << "free:\n"
                      << "  bench.Kt_nm_per_a: {lower: 0.1, upper: 3.0, log: true}\n"
                      << "  joint.pendulum.friction_nm: {lower: 0.001, upper: 0.5, log: true}\n"
                      << "  joint.pendulum.viscous_nm_s_per_rad: {lower: 0.001, upper: 1.0, log: "
                         "true}\n"
                      << "  bench.armature_kg_m2: {lower: 0.0001, upper: 0.05, log: true}\n"
                      << "strategy: " << strategy << "\n"
                      << "budget: " << budget << "\n"
                      << "seed: 7\n"
                      << extra;
  return path;
}

// A 10-evaluation CMA-ES pendulum fit over `data` in `dir` with `fitness: <fitness>`, loaded.
inline FitConfig pendulum_fitness_config(const std::filesystem::path& dir,
                                         const std::filesystem::path& data,
                                         const std::string& fitness) {
  std::filesystem::create_directories(dir);
  return load_fit_config(write_pendulum_fit(dir, data, "{kind: cma_es}", "{evaluations: 10}",
                                            "fitness: " + fitness + "\n"));
}

// A CMA-ES pendulum fit (σ 0.3, `evaluations` samples) of a clean recording in `dir`/data, run
// into `dir`/first/run: the earlier run of a chained (`--start-from`) fit. Returns its best.json.
inline std::filesystem::path first_pendulum_fit(const std::filesystem::path& dir, int evaluations) {
  record_pendulum_log(dir / "data", "clean");
  std::filesystem::create_directories(dir / "first");
  const std::string yaml =
      write_pendulum_fit(dir / "first", dir / "data", "{kind: cma_es, sigma: 0.3, restarts: 0}",
                         "{evaluations: " + std::to_string(evaluations) + "}");
  FitOverrides overrides;
  overrides.out = (dir / "first" / "run").string();
  FitSession(load_fit_config(yaml, overrides), false).run();
  return dir / "first" / "run" / "best.json";
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// generations.csv without its last (seconds) column.
inline std::string generations_without_seconds(const std::filesystem::path& run_dir) {
  std::ifstream in(run_dir / "generations.csv");
  std::string line, out;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

// best.json without its provenance date.
// best.json without what names the run rather than its result: the date and the run folder.
inline std::string best_without_date(const std::filesystem::path& run_dir) {
  nlohmann::ordered_json best = nlohmann::ordered_json::parse(read_text(run_dir / "best.json"));
  best["provenance"].erase("date");
  best["provenance"].erase("run");
  return best.dump(2);
}

// Runs the fit at `fit` with 1 and with 2 threads into dir/one and dir/two and expects the
// same generations (without seconds) and the same best.json (without its date).
inline void expect_one_and_two_threads_identical(const std::string& fit,
                                                 const std::filesystem::path& dir) {
  FitOverrides one, two;
  one.threads = 1;
  one.out = (dir / "one").string();
  two.threads = 2;
  two.out = (dir / "two").string();
  FitSession(load_fit_config(fit, one), false).run();
  FitSession(load_fit_config(fit, two), false).run();
  EXPECT_EQ(generations_without_seconds(dir / "one"), generations_without_seconds(dir / "two"));
  EXPECT_EQ(best_without_date(dir / "one"), best_without_date(dir / "two"));
}

}  // namespace motoflex::testing
