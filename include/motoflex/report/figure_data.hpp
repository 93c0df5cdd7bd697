#pragma once

// The data behind the report's interactive figures, as the page's script reads it (see
// src/report/report_page.js): the fitness per generation, the logs measured vs simulated, the
// correlation of the fitted parameters.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motoflex/report/log_comparison.hpp"
#include "motoflex/report/parameter_uncertainty.hpp"
#include "motoflex/report/run_record.hpp"

namespace motoflex::report {

// {"generation": [...], "evaluations": [...], "best": [...], "median": [...]}; null without
// rows. Infinite medians (a batch without a finite fitness) are null.
nlohmann::json convergence_json(const std::vector<GenerationRow>& rows);

// {"names": [...], "matrix": [[...]]} rounded to 4 digits; null for an empty matrix.
nlohmann::json correlation_json(const NamedMatrix& correlation);

// Reads every log of the record that has both a measured and a simulated file and compares
// them (compare_logs, at most `max_points` points per trace). A log that cannot be read or has
// only one side is skipped with a line in `notes`, so one moved log file does not cost the
// whole report.
std::vector<LogComparison> load_log_comparisons(const RunRecord& record, std::size_t max_points,
                                                std::vector<std::string>& notes);

}  // namespace motoflex::report
