#pragma once

// Domain-randomisation ranges from fits: the spread of each fitted parameter over several fit
// runs (several units of the same servo or robot, several recording sessions, several seeds)
// together with each fit's own standard error, turned into a range a simulator can sample from.
//
// Per parameter, in the fit's own scale (logarithmic for a `log: true` parameter, where spreads
// are relative): the mean over the runs, the standard deviation between runs (two or more
// runs), the RMS of the runs' standard errors (where summary.json has them), and the range
//   [min over runs of (value − k·se), max over runs of (value + k·se)]
//   ∪ [mean − k·between-run std, mean + k·between-run std],
// clipped to the parameter's search bounds. With one run and no standard error there is no
// spread and the range is the fitted value.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace motoflex::report {

struct ParameterSpread {
  std::string name;
  std::string unit;
  bool log_scale = false;
  std::vector<double> values;           // fitted value per run (model units)
  std::vector<double> standard_errors;  // per run; NaN where the run has none
  double mean = 0.0;                    // arithmetic, or geometric for a log parameter
  // Between runs: standard deviation (model units), or for a log parameter the factor
  // exp(std of ln value); NaN with one run.
  double between_runs = 0.0;
  // Within runs: RMS standard error (model units), or for a log parameter the factor
  // exp(RMS of ln(1 + se/value)); NaN when no run has one.
  double within_run = 0.0;
  double lower = 0.0;  // the range (model units)
  double upper = 0.0;
  double bound_lower = 0.0;  // the search bounds (NaN when the run dir does not record them)
  double bound_upper = 0.0;
  bool clipped = false;  // the range reached a bound and was cut there
};

struct SpreadReport {
  double k = 2.0;
  std::vector<std::string> runs;
  std::vector<ParameterSpread> parameters;  // in the first run's order
};

// Reads each run dir (a fit's, or a loop's: its final fit) and computes the spreads with `k`
// standard deviations (or errors) on each side. Every run must fit the same free parameters:
// one that lacks a parameter of the first throws InputError naming its best.json and the
// parameter. Throws InputError for an empty list or a non-positive k.
SpreadReport parameter_spread(const std::vector<std::string>& run_dirs, double k);

// {"k", "runs": [...], "parameters": [{"name", "unit", "log", "values", "standard_errors",
//  "mean", "between_runs", "within_run", "lower", "upper", "bounds": [l, u], "clipped"}]}; NaN
//  as null.
nlohmann::json spread_json(const SpreadReport& report);

// A Markdown table of the report, one row per parameter.
std::string spread_markdown(const SpreadReport& report);

}  // namespace motoflex::report
