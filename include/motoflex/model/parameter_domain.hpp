#pragma once

#include <limits>
#include <string>

namespace motoflex {

// The values a model parameter can physically take (resistance > 0, backlash >= 0, friction
// model an integer in 1..6, ...), as opposed to its search bounds. A fit whose bounds leave
// the domain is rejected when it is loaded; a value outside it makes the model invalid.
struct ParameterDomain {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // min itself excluded (> rather than >=)
  bool max_open = false;
  bool integer = false;  // whole numbers only

  bool contains(double value) const;
  // Whether every value of [lower, upper] lies in the domain (integer-ness aside: a search
  // interval of an integer parameter is rounded by the model).
  bool contains_interval(double lower, double upper) const;
  // "> 0", ">= 0", "an integer in [1, 6]", "any real number".
  std::string describe() const;
};

// The domain of a parameter, from the parameter catalog's rules on its name (its last dotted
// part: `gear.A.backlash_rad` → `backlash_rad` → >= 0). Names no rule knows are unconstrained.
ParameterDomain parameter_domain(const std::string& name);

}  // namespace motoflex
