#pragma once

#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"

namespace motoflex {

// One free variable of a fit. It sets every model parameter in `targets` to the same value
// (a tie, e.g. one friction for all pitch joints), searched within [lower, upper], optionally
// on a log scale (the optimiser then sees log(value)).
struct FreeParameter {
  std::string name;                  // as written in the fit config (may be a pattern)
  std::vector<std::string> targets;  // model parameter names it sets
  double lower = 0.0;
  double upper = 0.0;
  bool log_scale = false;
  double start = 0.0;  // starting value (model units)
};

// The map between the optimiser's vector x and a model ParameterSet: x[i] is free parameter i,
// in log units where log_scale is set. Everything not free keeps the base set's value.
class ParameterSpace {
 public:
  ParameterSpace(std::vector<FreeParameter> free, ParameterSet base);

  std::size_t dimension() const { return free_.size(); }
  const std::vector<FreeParameter>& free_parameters() const { return free_; }
  const ParameterSet& base() const { return base_; }

  // Search-space bounds (log-transformed where log_scale).
  std::vector<double> lower() const;
  std::vector<double> upper() const;
  std::vector<double> start() const;

  // Model units ↔ search coordinates.
  double to_model(std::size_t i, double coordinate) const;
  double to_search(std::size_t i, double value) const;

  // The base set with x applied.
  ParameterSet apply(const std::vector<double>& x) const;
  // Free parameter values in model units, by free-parameter name.
  std::vector<std::pair<std::string, double>> values(const std::vector<double>& x) const;

 private:
  std::vector<FreeParameter> free_;
  ParameterSet base_;
  std::vector<std::vector<std::size_t>> target_indices_;
};

// Expands a parameter pattern to the matching names of a registry, in registry order: '*'
// matches any run of characters other than '.' ("joint.*.friction_nm"), "**" any run at all.
std::vector<std::string> match_parameter_pattern(const ParameterRegistry& registry,
                                                 const std::string& pattern);

}  // namespace motoflex
