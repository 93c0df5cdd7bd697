#include "report_after_run.hpp"

#include <cstdio>
#include <exception>

#include "motoflex/report/report_page.hpp"

namespace motoflex::cli {

bool write_report_after_run(const std::string& run_dir) {
  try {
    const std::string path = report::write_report(run_dir);
    std::printf("report: %s\n", path.c_str());
    std::fflush(stdout);
    return true;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "motoflex: warning: no report for %s: %s\n", run_dir.c_str(),
                 error.what());
    return false;
  }
}

}  // namespace motoflex::cli
