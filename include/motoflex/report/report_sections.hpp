#pragma once

// The HTML of each section of the report. Figures are empty <div>s with ids that the page's
// script (src/report/report_page.js) fills from the page's JSON data; everything else is
// static HTML, escaped.

#include <string>
#include <vector>

#include "motoflex/report/log_comparison.hpp"
#include "motoflex/report/parameter_table.hpp"
#include "motoflex/report/run_record.hpp"

namespace motoflex::report {

// Config, robot, strategy, seed, evaluations, generations, best fitness, stop reason (and
// "converged" when the summary has it), wall time, errors, provenance; then one row per log.
std::string summary_section_html(const RunRecord& record);

// The convergence figure's place, or a note that generations.csv is missing.
std::string convergence_section_html(const RunRecord& record);

// Per log: a channel selector (preselecting the joint, not IMU angle, with the largest residual
// RMS), the figure's place and a table of every channel's residual RMS and largest error.
std::string logs_section_html(const std::vector<LogComparison>& logs, std::size_t max_points);

// The parameter table and the correlation heatmap's place (or "not available").
std::string parameters_section_html(const std::vector<ParameterRow>& rows, bool correlation);

// `motoflex residuals`' residuals.md with its PNGs inlined, or how to make it.
std::string residuals_section_html(const RunRecord& record);

// A loop's before/after table (from loop.json) and its report.md; "" for a plain fit.
std::string loop_section_html(const RunRecord& record);

}  // namespace motoflex::report
