#pragma once

// The uncertainty of the fitted parameters, as summary.json carries it once the fit computes
// it. The report reads these keys and shows "not available" when a summary has none of them:
//
//   "confidence_intervals": {"<free parameter>": {"standard_error": s, "lower": l, "upper": u}}
//       95 % confidence interval and standard error in model units (the parameter's own unit);
//       any of the three may be missing; [l, u] alone is accepted too.
//   "covariance":  {"names": [...], "matrix": [[...], ...]}   model units
//   "correlation": {"names": [...], "matrix": [[...], ...]}   dimensionless, in [-1, 1]
//       A matrix may also be written {"<a>": {"<b>": value, ...}, ...}. Without "correlation"
//       the covariance gives it (c_ij / √(c_ii c_jj)), and its diagonal gives the standard
//       errors that "confidence_intervals" leaves out.

#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace motoflex::report {

inline constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();

struct ParameterInterval {
  double standard_error = kNotAvailable;
  double lower = kNotAvailable;  // 95 % confidence interval
  double upper = kNotAvailable;
  // The fit's verdicts (summary.json `identified`, `linear`; true when absent) and the
  // residual's departure from linear over the Jacobian's step (`nonlinearity`; NaN when absent).
  bool identified = true;
  bool linear = true;
  double nonlinearity = kNotAvailable;
};

// A square matrix over named parameters; empty when absent.
struct NamedMatrix {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  // values[i][j], names.size() × names.size()
  bool empty() const { return names.empty(); }
};

struct ParameterUncertainty {
  std::map<std::string, ParameterInterval> intervals;  // by free-parameter name
  NamedMatrix correlation;
};

// Reads the keys above from `summary` (a null or object JSON). `file` names summary.json in
// errors: a key that is present but malformed (not an object, a matrix that is not square or
// whose names do not match its size, non-numeric entries) throws InputError(file, 0, key, ...).
ParameterUncertainty read_parameter_uncertainty(const nlohmann::json& summary,
                                                const std::string& file);

}  // namespace motoflex::report
