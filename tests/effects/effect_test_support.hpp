#pragma once

// Fit configs over reference_data/hidden/<effect>/ (bench logs with an undeclared effect) and
// the truth those logs were recorded with (read only here, never by a fit).

#include <filesystem>
#include <fstream>
#include <string>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_report.hpp"
#include "motoflex/model/parameters.hpp"

namespace motoflex::testing {

inline std::filesystem::path hidden_dir(const std::string& effect) {
  return std::filesystem::path(MOTOFLEX_SOURCE_DIR) / "reference_data" / "hidden" / effect;
}

// scenarios/fit/bench_hidden.yaml pointed at one effect's logs, with the given loop options.
inline std::string write_hidden_bench_fit(const std::filesystem::path& folder,
                                          const std::string& effect, const std::string& loop,
                                          const std::string& extra = "",
                                          const std::string& budget = "{evaluations: 480}") {
  std::filesystem::create_directories(folder);
  const std::string source = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/";
  const std::string path = (folder / "fit.yaml").string();
  std::ofstream(path)
      << "name: hidden_" << effect << "\n"
      << "scenario: " << source << "bench/chirp.yaml\n"
      << "data: " << (hidden_dir(effect) / "train").string() << "\n"
      << "validation: " << (hidden_dir(effect) / "validation").string() << "\n"
      << "free:\n"
      << "  bench.Kt_nm_per_a: {lower: 0.1, upper: 1.0, log: true, start: 0.5}\n"
      << "  bench.armature_kg_m2: {lower: 1.0e-4, upper: 0.02, log: true, start: 0.005}\n"
      << "  joint.pendulum.friction_nm: {lower: 0.0, upper: 0.3, start: 0.05}\n"
      << "  joint.pendulum.viscous_nm_s_per_rad: {lower: 0.0, upper: 0.2, start: 0.05}\n"
      << "fitness: {m: 2}\n"
      << "strategy: {kind: cma_es, sigma: 0.2, restarts: 0}\n"
      << "budget: " << budget << "\n"
      << "threads: 2\nseed: 1\n"
      << "out: " << (folder / "run").string() << "\n"
      << "loop: " << loop << "\n"
      << extra;
  return path;
}

// The truth of a hidden-effect recording, as a parameter set of `base`'s model; with
// `sensor_free` the encoder noise and quantisation are switched off (the simulated angles are
// then the noise-free truth, and their RMS against the log is the noise floor).
inline ParameterSet hidden_truth(const std::string& effect, const std::string& recording,
                                 const ParameterSet& base, bool sensor_free) {
  ParameterSet truth = base;
  apply_parameter_json_file((hidden_dir("truth") / effect / (recording + ".json")).string(), truth);
  if (sensor_free) {
    truth.set("sensor.noise_rad", 0.0);
    truth.set("sensor.resolution_bits", 0.0);
  }
  return truth;
}

// RMS (deg) of the validation logs against the noise-free truth.
inline double noise_floor_deg(const FitConfig& config, const std::string& effect) {
  const ParameterSet truth =
      hidden_truth(effect, "validation/multisine_fast", config.space->base(), true);
  return evaluate_in_detail(*config.validation, truth).rms_deg;
}

}  // namespace motoflex::testing
