#include "motoflex/report/parameter_uncertainty.hpp"

#include <cmath>
#include <utility>

#include "motoflex/core/error.hpp"

namespace motoflex::report {
namespace {

double number_or_missing(const nlohmann::json& value, const std::string& file,
                         const std::string& field) {
  if (value.is_null()) return kNotAvailable;  // NaN and infinities are written as null
  if (!value.is_number()) throw InputError(file, 0, field, "not a number");
  return value.get<double>();
}

NamedMatrix read_matrix(const nlohmann::json& value, const std::string& file,
                        const std::string& field) {
  NamedMatrix out;
  if (value.is_object() && value.contains("names") && value.contains("matrix")) {
    const auto& names = value["names"];
    const auto& rows = value["matrix"];
    if (!names.is_array() || !rows.is_array() || names.size() != rows.size()) {
      throw InputError(file, 0, field, "names and matrix must be arrays of the same length");
    }
    for (const auto& name : names) {
      if (!name.is_string()) throw InputError(file, 0, field + ".names", "not a string");
      out.names.push_back(name.get<std::string>());
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::string row_field = field + ".matrix[" + std::to_string(i) + "]";
      if (!rows[i].is_array() || rows[i].size() != names.size()) {
        throw InputError(
            file, 0, row_field,
            "must have " + std::to_string(names.size()) + " entries (a square matrix)");
      }
      std::vector<double> row;
      for (const auto& entry : rows[i]) row.push_back(number_or_missing(entry, file, row_field));
      out.values.push_back(std::move(row));
    }
    return out;
  }
  if (!value.is_object()) throw InputError(file, 0, field, "not an object");
  // {"a": {"a": 1, "b": 0.3}, "b": {...}}: the rows' keys name the columns.
  for (auto it = value.begin(); it != value.end(); ++it) out.names.push_back(it.key());
  for (const auto& row_name : out.names) {
    const auto& row = value[row_name];
    if (!row.is_object()) throw InputError(file, 0, field + "." + row_name, "not an object");
    std::vector<double> values;
    for (const auto& column_name : out.names) {
      values.push_back(row.contains(column_name)
                           ? number_or_missing(row[column_name], file,
                                               field + "." + row_name + "." + column_name)
                           : kNotAvailable);
    }
    out.values.push_back(std::move(values));
  }
  return out;
}

ParameterInterval read_interval(const nlohmann::json& value, const std::string& file,
                                const std::string& field) {
  ParameterInterval out;
  if (value.is_array()) {
    if (value.size() != 2) throw InputError(file, 0, field, "an interval [lower, upper]");
    out.lower = number_or_missing(value[0], file, field);
    out.upper = number_or_missing(value[1], file, field);
    return out;
  }
  if (!value.is_object()) throw InputError(file, 0, field, "not an object");
  if (value.contains("standard_error")) {
    out.standard_error =
        number_or_missing(value["standard_error"], file, field + ".standard_error");
  }
  if (value.contains("lower"))
    out.lower = number_or_missing(value["lower"], file, field + ".lower");
  if (value.contains("upper"))
    out.upper = number_or_missing(value["upper"], file, field + ".upper");
  if (value.contains("nonlinearity")) {
    out.nonlinearity = number_or_missing(value["nonlinearity"], file, field + ".nonlinearity");
  }
  for (const auto& [key, flag] : {std::pair<const char*, bool*>{"identified", &out.identified},
                                  std::pair<const char*, bool*>{"linear", &out.linear}}) {
    if (!value.contains(key)) continue;
    if (!value[key].is_boolean()) throw InputError(file, 0, field + "." + key, "not true or false");
    *flag = value[key].get<bool>();
  }
  return out;
}

}  // namespace

ParameterUncertainty read_parameter_uncertainty(const nlohmann::json& summary,
                                                const std::string& file) {
  ParameterUncertainty out;
  if (!summary.is_object()) return out;
  if (summary.contains("confidence_intervals")) {
    const auto& intervals = summary["confidence_intervals"];
    if (!intervals.is_object()) throw InputError(file, 0, "confidence_intervals", "not an object");
    for (const auto& [name, value] : intervals.items()) {
      out.intervals[name] = read_interval(value, file, "confidence_intervals." + name);
    }
  }
  NamedMatrix covariance;
  if (summary.contains("covariance")) {
    covariance = read_matrix(summary["covariance"], file, "covariance");
    for (std::size_t i = 0; i < covariance.names.size(); ++i) {
      const double variance = covariance.values[i][i];
      ParameterInterval& interval = out.intervals[covariance.names[i]];
      if (std::isnan(interval.standard_error) && variance >= 0.0) {
        interval.standard_error = std::sqrt(variance);
      }
    }
  }
  if (summary.contains("correlation")) {
    out.correlation = read_matrix(summary["correlation"], file, "correlation");
  } else if (!covariance.empty()) {
    out.correlation.names = covariance.names;
    const std::size_t n = covariance.names.size();
    out.correlation.values.assign(n, std::vector<double>(n, kNotAvailable));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        const double scale = std::sqrt(covariance.values[i][i] * covariance.values[j][j]);
        if (scale > 0.0) out.correlation.values[i][j] = covariance.values[i][j] / scale;
      }
    }
  }
  return out;
}

}  // namespace motoflex::report
