#pragma once

// Numbers for the report's JSON (internal to the report module): non-finite values as null
// (JSON has no NaN or infinity; the page and the readers take null as "not available"), and,
// where a figure needs no more, rounded to a few significant digits so the page stays small.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <vector>

namespace motoflex::report::detail {

// `value` rounded to `significant` digits (through its decimal text); non-finite values and 0
// as they are.
inline double rounded(double value, int significant) {
  if (!std::isfinite(value) || value == 0.0) return value;
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return std::strtod(buffer, nullptr);
}

// `value`, rounded to `significant` digits when that is positive, or null when not finite.
inline nlohmann::json number_json(double value, int significant = 0) {
  if (!std::isfinite(value)) return nullptr;
  return significant > 0 ? rounded(value, significant) : value;
}

inline nlohmann::json numbers_json(const std::vector<double>& values, int significant = 0) {
  nlohmann::json out = nlohmann::json::array();
  for (const double v : values) out.push_back(number_json(v, significant));
  return out;
}

}  // namespace motoflex::report::detail
