#include "fit_uncertainty_outputs.hpp"

#include <algorithm>
#include <cmath>

namespace motoflex::detail {
namespace {

// JSON has no infinities or NaN: they are written as null (the report reads null as missing).
nlohmann::ordered_json number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json matrix_json(const std::vector<std::string>& names,
                                   const std::vector<std::vector<double>>& m) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& row : m) {
    nlohmann::ordered_json r = nlohmann::ordered_json::array();
    for (const double v : row) r.push_back(number(v));
    rows.push_back(std::move(r));
  }
  return {{"names", names}, {"matrix", rows}};
}

nlohmann::ordered_json polish_json(const LmPolishResult& lm) {
  nlohmann::ordered_json out = {{"method", "lm"},
                                {"iterations", lm.iterations},
                                {"evaluations", lm.rollouts},
                                {"fitness_before", number(lm.fitness_before)},
                                {"fitness_after", number(lm.fitness_after)},
                                {"used", lm.used},
                                {"termination", lm.termination}};
  if (!lm.flat_scan_moves.empty()) {
    nlohmann::ordered_json moves = nlohmann::ordered_json::array();
    for (const FlatScanMove& m : lm.flat_scan_moves) {
      moves.push_back({{"parameter", m.parameter},
                       {"from", m.from},
                       {"to", m.to},
                       {"fitness_before", number(m.fitness_before)},
                       {"fitness_after", number(m.fitness_after)}});
    }
    out["flat_scan_moves"] = std::move(moves);
  }
  return out;
}

// Intervals in model units: the search interval x ± z·s mapped through to_model (monotone), the
// share of the bounds it covers measured in search coordinates; the covariance by the delta
// method (d value / d x = value on a log scale).
void fill_intervals(const FitConfig& config, const RunResult& result, FitSummary& summary) {
  const ParameterSpace& space = *config.space;
  const LeastSquaresCovariance& c = result.uncertainty.search;
  const std::vector<double> lower = space.lower(), upper = space.upper();
  const std::size_t p = space.dimension();
  std::vector<double> derivative(p);
  for (std::size_t i = 0; i < p; ++i) {
    const double x = result.best_x[i], s = c.standard_error[i];
    derivative[i] = space.free_parameters()[i].log_scale ? space.to_model(i, x) : 1.0;
    FittedParameter& f = summary.parameters[i];
    f.standard_error = s * std::abs(derivative[i]);
    const double lo = x - kConfidenceZ95 * s, hi = x + kConfidenceZ95 * s;
    f.ci_lower = std::isfinite(lo) ? space.to_model(i, lo) : -INFINITY;
    f.ci_upper = std::isfinite(hi) ? space.to_model(i, hi) : INFINITY;
    if (space.free_parameters()[i].log_scale && !std::isfinite(lo)) f.ci_lower = 0.0;
    const double covered = std::min(hi, upper[i]) - std::max(lo, lower[i]);
    f.ci_share_of_bounds = std::max(covered, 0.0) / (upper[i] - lower[i]);
    if (i < result.uncertainty.nonlinearity.size()) {
      f.nonlinearity = result.uncertainty.nonlinearity[i];
    }
  }
  summary.covariance.assign(p, std::vector<double>(p));
  for (std::size_t a = 0; a < p; ++a) {
    for (std::size_t b = 0; b < p; ++b) {
      summary.covariance[a][b] = c.covariance[a][b] * derivative[a] * derivative[b];
    }
  }
  summary.correlation = c.correlation;  // invariant under the per-parameter scaling
  summary.residual_autocorrelation = result.uncertainty.autocorrelation;
  summary.residuals = c.residuals;
}

}  // namespace

void add_uncertainty_outputs(const FitConfig& config, const RunResult& result, FitSummary& summary,
                             nlohmann::ordered_json& json) {
  if (result.lm_ran) {
    json["polish"] = polish_json(result.lm);
    summary.polish_method = "lm";
    summary.fitness_before_polish = result.lm.fitness_before;
    summary.polish_used = result.lm.used;
  }
  if (!result.uncertainty.computed) return;
  fill_intervals(config, result, summary);
  std::vector<std::string> names;
  nlohmann::ordered_json intervals = nlohmann::ordered_json::object();
  nlohmann::ordered_json unidentified = nlohmann::ordered_json::array();
  for (const FittedParameter& f : summary.parameters) {
    names.push_back(f.name);
    intervals[f.name] = {{"value", f.value},
                         {"standard_error", number(f.standard_error)},
                         {"lower", number(f.ci_lower)},
                         {"upper", number(f.ci_upper)},
                         {"share_of_bounds", number(f.ci_share_of_bounds)},
                         {"nonlinearity", number(f.nonlinearity)},
                         {"linear", !f.nonlinear()},
                         {"identified", !f.unidentified()}};
    if (f.unidentified()) unidentified.push_back(f.name);
  }
  const LeastSquaresCovariance& c = result.uncertainty.search;
  json["confidence_intervals"] = intervals;
  json["covariance"] = matrix_json(names, summary.covariance);
  json["correlation"] = matrix_json(names, summary.correlation);
  json["uncertainty"] = {
      {"method",
       "kappa sigma^2 (J^T J)^-1 at the best point, J by central finite differences through the "
       "rollout, kappa = (1 + rho)/(1 - rho) from the residuals' lag-1 autocorrelation rho (1 "
       "for white residuals); 95 % intervals x +- 1.96 s in search coordinates (log where log: "
       "true)"},
      {"confidence", 0.95},
      {"sigma2", number(c.sigma2)},
      {"residuals", c.residuals},
      {"lag1_autocorrelation", number(result.uncertainty.autocorrelation.lag1)},
      {"variance_inflation", number(c.variance_inflation)},
      {"effective_residuals", number(result.uncertainty.autocorrelation.effective)},
      {"parameters", c.parameters},
      {"rank", c.rank},
      {"evaluations", result.uncertainty.rollouts},
      {"jacobian_step_share_of_bounds", config.polish.jacobian_step},
      {"unidentified_above_share_of_bounds", FittedParameter::kUnidentifiedShare},
      {"unidentified_above_nonlinearity", FittedParameter::kNonlinearShare},
      {"unidentified", unidentified},
      {"covariance_search", matrix_json(names, c.covariance)}};
}

}  // namespace motoflex::detail
