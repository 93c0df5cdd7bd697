#pragma once

// The fitted parameters as a table: what the fit searched (unit, start, bounds) and what it
// found, with standard error and 95 % confidence interval where the summary carries them.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motoflex/report/parameter_uncertainty.hpp"

namespace motoflex::report {

struct ParameterRow {
  std::string name;  // free parameter as the fit config writes it (may be a tied pattern)
  std::string unit;  // "1" when dimensionless
  double start = kNotAvailable;
  double lower = kNotAvailable;
  double upper = kNotAvailable;
  double fitted = kNotAvailable;
  bool log_scale = false;
  ParameterInterval interval;  // all not available unless the summary has them
  // summary.json "sensitivity": relative fitness change per bound-width around the best point,
  // and whether the training data determine the value (not available in older summaries).
  double sensitivity = kNotAvailable;
  bool undetermined = false;
};

// One row per free parameter: names, units, start and bounds from inputs.json's "free" list
// (fit_inputs.hpp), the fitted value from best.json's "free" object (else summary.json's), the
// intervals from `uncertainty`. Without inputs.json (a run dir of an older motoflex) the rows
// come from the fitted values alone, the unit from the name's suffix, start and bounds not
// available. Any of the JSON arguments may be null.
std::vector<ParameterRow> parameter_rows(const nlohmann::json& inputs, const nlohmann::json& best,
                                         const nlohmann::json& summary,
                                         const ParameterUncertainty& uncertainty);

// Whether the fitted value lies within 1 % of the bound width of a bound (the fit may want to go
// further: widen the bound or doubt the model).
bool at_bound(const ParameterRow& row);

// A <table> of the rows: name, unit, start, lower, upper, fitted, standard error, 95 % CI;
// "not available" in the uncertainty columns when no row has them (and a note saying so).
std::string parameter_table_html(const std::vector<ParameterRow>& rows);

}  // namespace motoflex::report
