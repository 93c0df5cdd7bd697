#pragma once

// Synthetic run dirs for the report tests: the files a fit writes, made by hand, so that each
// test controls what is there and what is missing.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>
#include "cli/cli_test_support.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex::testing {

// A two-joint log of `frames` frames at 100 Hz: measured = sin(t) (+ `offset_rad` on joint
// "knee"), with .cmd columns.
inline JointLog two_joint_log(std::size_t frames, double offset_rad = 0.0) {
  JointLog log;
  log.joint_names = {"hip", "knee"};
  log.meta.robot = "toy";
  log.meta.rate_hz = 100.0;
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = 0.01 * static_cast<double>(f);
    log.time_s.push_back(t);
    for (std::size_t j = 0; j < 2; ++j) {
      log.commanded_rad.push_back(std::sin(t));
      log.measured_rad.push_back(std::sin(t) + (j == 1 ? offset_rad : 0.0));
    }
  }
  return log;
}

// A fit run dir in `dir` with run.json, inputs.json, summary.json, best.json, generations.csv,
// one training log (measured in dir/data/walk.csv, simulated in dir/best/walk.csv, the
// simulation 0.01 rad off on the knee). `with_optional` false leaves out everything optional
// (inputs.json, generations.csv, best/ and residuals).
inline void write_fit_run_dir(const std::filesystem::path& dir, bool with_optional = true,
                              std::size_t frames = 300) {
  std::filesystem::create_directories(dir);
  write_text(dir / "run.json", R"({"fit": "/somewhere/fit.yaml", "overrides": {}})");
  // R"json(...)json": the evaluator's name "openmp(2 threads)" would end a plain raw string.
  write_text(dir / "summary.json", R"json({"name": "toy_fit", "best_fitness": 1.25e-05,
    "evaluations": 48, "generations": 3, "stop_reason": "max_generations", "seconds": 12.5,
    "strategy": "(4+16)-ES", "evaluator": "openmp(2 threads)",
    "rms_deg": {"overall": 0.41},
    "robots": [{"name": "walk", "fitness": 1.25e-05, "frames": 300, "frames_requested": 300,
                "end": "completed", "rms_deg": 0.41}],
    "free": {"pid.kp_v_per_rad": 321.5}})json");
  write_text(dir / "best.json", R"json({"fitness": 1.25e-05,
    "free": {"pid.kp_v_per_rad": 321.5},
    "provenance": {"robot": "toy", "motoflex_version": "0.1.0",
                   "date": "2026-11-25T00:00:00Z"}})json");
  if (!with_optional) return;
  const std::filesystem::path measured = dir / "data" / "walk.csv";
  std::filesystem::create_directories(dir / "data");
  std::filesystem::create_directories(dir / "best");
  write_joint_log(measured.string(), two_joint_log(frames));
  write_joint_log((dir / "best" / "walk.csv").string(), two_joint_log(frames, -0.01));
  nlohmann::json inputs = nlohmann::json::parse(R"json({"name": "toy_fit", "robot": "toy",
    "seed": 3, "free": [{"name": "pid.kp_v_per_rad", "unit": "V/rad", "start": 150,
                         "lower": 50, "upper": 2000, "log": true}], "validation_logs": []})json");
  inputs["train_logs"] = {measured.string()};
  write_text(dir / "inputs.json", inputs.dump());
  write_text(
      dir / "generations.csv",
      "generation,evaluations,best,median,mean_sigma,seconds\n"
      "1,16,0.001,inf,0.15,4.1\n2,32,0.0001,0.004,0.12,8.2\n3,48,1.25e-05,0.0009,0.1,12.5\n");
}

inline std::string read_file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace motoflex::testing
