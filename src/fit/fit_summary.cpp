#include "motoflex/fit/fit_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace motoflex {
namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string pad(std::string text, std::size_t width) {
  if (text.size() < width) text.append(width - text.size(), ' ');
  return text;
}

}  // namespace

double FittedParameter::bound_fraction() const {
  if (log_scale && lower > 0.0 && value > 0.0) {
    return (std::log(value) - std::log(lower)) / (std::log(upper) - std::log(lower));
  }
  return (value - lower) / (upper - lower);
}

// The 95 % intervals and the strongest correlations (|r| > 0.9), when the fit computed them.
std::string FitSummary::uncertainty_report(std::size_t width) const {
  if (covariance.empty()) return "";
  std::string out = "\n  " + pad("parameter", width) +
                    "       fitted   std. error   95 % interval                 share of bounds\n";
  std::string unidentified;
  for (const auto& p : parameters) {
    out += "  " + pad(p.name, width) + format(" %12.5g", p.value) +
           format(" %12.3g", p.standard_error) + "   [" + format("%.5g", p.ci_lower) + ", " +
           format("%.5g", p.ci_upper) + "]" + format("  %5.0f %%", 100.0 * p.ci_share_of_bounds) +
           (p.nonlinear() ? format("  NOT LINEAR (%.2f)", p.nonlinearity)
                          : (p.unidentified() ? "  UNIDENTIFIED" : "")) +
           "\n";
    if (p.unidentified()) unidentified += (unidentified.empty() ? "" : ", ") + p.name;
  }
  if (!unidentified.empty()) {
    out +=
        "  unidentified (95 % interval spans > 50 % of the bounds, or the residual is not "
        "linear in the parameter over the Jacobian's step, so that no interval holds): " +
        unidentified + "\n";
  }
  const ResidualAutocorrelation& autocorrelation = residual_autocorrelation;
  if (autocorrelation.inflation > 1.0) {
    out += format("  intervals widened %.3gx for correlated residuals",
                  std::sqrt(autocorrelation.inflation)) +
           format(" (lag-1 autocorrelation %.4f: ", autocorrelation.lag1) +
           format("%.4g effective of ", autocorrelation.effective) + std::to_string(residuals) +
           " residuals)\n";
    if (autocorrelation.effective <= static_cast<double>(parameters.size())) {
      out +=
          "  fewer effective residuals than free parameters: the residual is model error more "
          "than noise, and no interval here is reliable\n";
    }
  }
  for (std::size_t a = 0; a < correlation.size(); ++a) {
    for (std::size_t b = a + 1; b < correlation.size(); ++b) {
      if (std::abs(correlation[a][b]) > 0.9) {
        out += "  correlated: " + parameters[a].name + " / " + parameters[b].name +
               format(" r = %.3f", correlation[a][b]) + "\n";
      }
    }
  }
  return out;
}

std::string FitSummary::brief_report() const {
  std::string line = name + ": " + stop_reason + (converged ? " (converged)" : " (not converged)");
  line += " after " + std::to_string(generations) + " generations, " + std::to_string(evaluations) +
          " evaluations: best fitness " + format("%.6g", best_fitness) + ", train RMS " +
          format("%.3g", train_rms_deg) + " deg";
  if (validation_rms_deg >= 0.0) {
    line += ", validation RMS " + format("%.3g", validation_rms_deg) + " deg";
  }
  if (!covariance.empty()) {
    const auto unidentified =
        std::count_if(parameters.begin(), parameters.end(),
                      [](const FittedParameter& p) { return p.unidentified(); });
    line += ", " + std::to_string(unidentified) + " of " + std::to_string(parameters.size()) +
            " parameters unidentified";
  }
  return line + " (" + format("%.1f", seconds) + " s)";
}

std::string FitSummary::full_report() const {
  std::string out = brief_report() + "\n";
  out += "  strategy   " + strategy + "\n";
  out += "  evaluator  " + evaluator + "\n";
  out += "  " + convergence + "\n";
  if (polish_evaluations > 0) {
    out += "  polish     " + std::to_string(polish_evaluations) + " evaluations";
    if (polish_method == "lm") {
      out += ", Levenberg-Marquardt: fitness " + format("%.6g", fitness_before_polish) +
             (polish_used ? " -> " + format("%.6g", best_fitness) : std::string(" (not lowered)"));
    }
    out += "\n";
  }
  std::size_t width = 10;
  for (const auto& p : parameters) width = std::max(width, p.name.size());
  out += "\n  " + pad("parameter", width) +
         "        start       fitted        lower        upper  in bounds  sensitivity\n";
  for (const auto& p : parameters) {
    const double fraction = p.bound_fraction();
    std::string flag = fraction < 0.01 || fraction > 0.99 ? "  at a bound" : "";
    out += "  " + pad(p.name, width) + format(" %12.5g", p.start) + format(" %12.5g", p.value) +
           format(" %12.5g", p.lower) + format(" %12.5g", p.upper) +
           format("  %5.0f %%", 100.0 * fraction) +
           (p.sensitivity >= 0.0 ? format("  %11.3g", p.sensitivity) : std::string()) + flag + " " +
           p.unit + (p.undetermined() ? "  NOT DETERMINED by the data" : "") + "\n";
  }
  std::string undetermined;
  for (const auto& p : parameters) {
    if (p.undetermined()) undetermined += (undetermined.empty() ? "" : ", ") + p.name;
  }
  if (!undetermined.empty()) {
    out += "  the training data cannot determine: " + undetermined +
           " (a 1 % step in its range moves the fitness by < 0.1 %)\n";
  }
  out += uncertainty_report(width);
  if (details.contains("robots")) {
    out += "\n  training logs: fitness, frames simulated / requested, end, RMS (deg)\n";
    for (const auto& robot : details["robots"]) {
      out += "  " + pad(robot.value("name", std::string("?")), width) +
             format(" %12.5g", robot.value("fitness", 0.0)) + "  " +
             std::to_string(robot.value("frames", 0)) + "/" +
             std::to_string(robot.value("frames_requested", 0)) + "  " +
             robot.value("end", std::string("?")) + format("  %.3g", robot.value("rms_deg", 0.0)) +
             "\n";
    }
  }
  if (frames_simulated > 0) {
    out += "\n  early termination: " + std::to_string(individuals_stopped_early) +
           " individuals stopped, " + std::to_string(frames_saved) + " of " +
           std::to_string(frames_simulated + frames_saved) + " frames saved\n";
  }
  if (invalid_candidates > 0) {
    out += "\n  invalid candidates (scored worst): " + std::to_string(invalid_candidates) + "\n";
    for (const auto& reason : invalid_reasons) out += "    " + reason + "\n";
  }
  return out;
}

}  // namespace motoflex
