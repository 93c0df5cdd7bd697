#pragma once

#include <string>

namespace motoflex::cli {

// Writes `run_dir`/report.html after `fit`, `resume` or `loop` and prints where. A report that
// cannot be written is one warning line on stderr, never a failed run: the run's results are
// already on disk, and `motoflex report` can write it later. Returns whether it was written.
bool write_report_after_run(const std::string& run_dir);

}  // namespace motoflex::cli
