#pragma once

// `motoflex report RUN_DIR`: one self-contained HTML page per fit or loop run dir — summary,
// convergence, measured vs simulated logs with residuals, parameters with their uncertainty,
// the residual analysis and a loop's before/after. plotly.js, the page's script and style, the
// data and the PNGs of the residual analysis are all inside the file: it opens offline and
// loads nothing from the network.

#include <cstddef>
#include <string>

#include "motoflex/report/run_record.hpp"

namespace motoflex::report {

struct ReportOptions {
  // Longer logs are thinned to this many points per trace (envelope_indices), so that a report
  // of many long logs stays a few MB and draws quickly.
  std::size_t max_points_per_trace = 2000;
};

// The page for a run dir already read.
std::string render_report(const RunRecord& record, const ReportOptions& options = {});

// Reads `run_dir` and writes its report atomically to `out` (default: run_dir/report.html).
// Returns the path written. Throws InputError for a folder that is no run dir, an unreadable
// file in it, or an output that cannot be written.
std::string write_report(const std::string& run_dir, const std::string& out = "",
                         const ReportOptions& options = {});

// The git revision this motoflex was built from ("" when the source tree was no git checkout
// at configure time).
const char* source_revision();

}  // namespace motoflex::report
