#include "motoflex/model/parameter_domain.hpp"

#include <cmath>
#include <sstream>

namespace motoflex {
namespace {

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

bool ParameterDomain::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (min_open ? !(value > min) : !(value >= min)) return false;
  if (max_open ? !(value < max) : !(value <= max)) return false;
  return !integer || value == std::round(value);
}

bool ParameterDomain::contains_interval(double lower, double upper) const {
  if (!std::isfinite(lower) || !std::isfinite(upper)) return false;
  const bool lower_ok = min_open ? lower > min : lower >= min;
  const bool upper_ok = max_open ? upper < max : upper <= max;
  return lower_ok && upper_ok;
}

std::string ParameterDomain::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  const std::string kind = integer ? "an integer" : "a number";
  if (has_min && has_max) {
    return kind + " in " + std::string(min_open ? "(" : "[") + number_text(min) + ", " +
           number_text(max) + (max_open ? ")" : "]");
  }
  if (has_min) return kind + (min_open ? " > " : " >= ") + number_text(min);
  if (has_max) return kind + (max_open ? " < " : " <= ") + number_text(max);
  return integer ? "an integer" : "any finite number";
}

}  // namespace motoflex
