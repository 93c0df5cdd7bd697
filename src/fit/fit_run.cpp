#include "motoflex/fit/fit_run.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_session.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& path, const std::string& run_dir) {
  std::ifstream in(path);
  if (!in) {
    throw InputError(run_dir, 0, "",
                     "no finished fit here (" + path.filename().string() + " is missing)");
  }
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw InputError(path.string(), 0, "", std::string("corrupt: ") + error.what());
  }
}

bool finished(const fs::path& dir) {
  const fs::path summary = dir / "summary.json";
  if (!fs::exists(summary) || !fs::exists(dir / "best.json")) return false;
  std::ifstream in(summary);
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    return json.value("stop_reason", std::string("interrupted")) != "interrupted";
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

}  // namespace

FinishedFit load_finished_fit(const std::string& run_dir) {
  const fs::path dir(run_dir);
  read_json(dir / "run.json", run_dir);  // a clear message when this is no run folder
  if (!finished(dir)) {
    throw InputError(
        run_dir, 0, "",
        "the fit here has not finished (resume it with `motoflex resume " + run_dir + "`)");
  }
  FitConfig config = load_run_config(run_dir);
  ParameterSet best = config.space->base();  // refers to the model's registry (shared_ptr)
  apply_parameter_json_file((dir / "best.json").string(), best);
  FinishedFit out{std::move(config), std::move(best), read_json(dir / "best.json", run_dir),
                  read_json(dir / "summary.json", run_dir)};
  return out;
}

FinishedFit ensure_fit(const FitConfig& config) {
  const fs::path dir(config.out_dir);
  if (!finished(dir)) {
    const bool resume = fs::exists(dir / "checkpoint.json") && config.strategy.kind != "nlopt";
    if (!resume && fs::exists(dir / "checkpoint.json")) fs::remove(dir / "checkpoint.json");
    FitSession session(config, resume);
    session.run();
    if (!finished(dir)) {
      throw InputError(config.out_dir, 0, "", "the fit did not finish (interrupted?)");
    }
  }
  return load_finished_fit(config.out_dir);
}

ErrorSummary summarize_errors(const FitnessFunction& fitness, const ParameterSet& set,
                              std::size_t free_parameters) {
  ErrorSummary out;
  out.detail = evaluate_in_detail(fitness, set);
  const std::size_t n = fitness.model().actuators.size();
  const std::size_t k = fitness.channels();
  std::vector<double> measured(k), simulated(k);
  double squared = 0.0, absolute = 0.0, fit_terms = 0.0;
  std::size_t joint_samples = 0;
  for (std::size_t c = 0; c < fitness.cases().size(); ++c) {
    const FitCase& fit_case = fitness.cases()[c];
    const RolloutResult& r = out.detail.rollouts[c];
    for (std::size_t f = first_scored_frame(fit_case, fitness.options().settle_s);
         f < r.frames_completed; ++f) {
      for (std::size_t j = 0; j < n; ++j) {
        absolute += std::abs(fit_case.measured_rad[f * n + j] - r.measured_rad[f * n + j]);
        ++joint_samples;
      }
      fitness.measured_channels(c, f, measured.data());
      fitness.simulated_channels(r, f, simulated.data());
      for (std::size_t i = 0; i < k; ++i) {
        squared += (measured[i] - simulated[i]) * (measured[i] - simulated[i]);
        const double r = fitness.channel_residual(i, measured[i] - simulated[i]);
        fit_terms += r * r;  // the frame's term of the fit's own error sum
        ++out.samples;
      }
    }
  }
  const double samples = static_cast<double>(std::max<std::size_t>(out.samples, 1));
  out.rms_deg = out.detail.rms_deg;
  out.mae_rad = absolute / static_cast<double>(std::max<std::size_t>(joint_samples, 1));
  out.channel_rms_rad = std::sqrt(squared / samples);
  out.fit_error_rad = fitness.options().absolute_error ? fit_terms / samples : out.channel_rms_rad;
  out.bic = 2.0 * samples * std::log(std::max(out.fit_error_rad, 1e-150)) +
            static_cast<double>(free_parameters) * std::log(samples);
  return out;
}

double imu_rms_deg(const ErrorSummary& errors) {
  const std::vector<double>& rms = errors.detail.imu_rms_deg;
  if (rms.size() != 2) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(0.5 * (rms[0] * rms[0] + rms[1] * rms[1]));
}

}  // namespace motoflex
