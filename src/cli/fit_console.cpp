#include "fit_console.hpp"
#include "motoflex/core/error.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>

#include "motoflex/fit/fit_session.hpp"

namespace motoflex::cli {
namespace {

// The one piece of process-global mutable state: what a signal handler may set (a lock-free
// atomic is async-signal-safe).
std::atomic<bool> g_stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void request_stop(int) {
  g_stop_requested.store(true);
}

}  // namespace

int run_fit_on_console(FitConfig config, bool resume, motoflex_es::Evaluator* evaluator) {
  const std::string dir = config.out_dir;
  FitSession session(std::move(config), resume);
  session.set_evaluator(evaluator);
  g_stop_requested.store(false);
  session.set_cancel_flag(&g_stop_requested);
  session.set_progress([](const FitProgress& progress) {
    std::printf("%s\n", progress.line().c_str());
    std::fflush(stdout);
  });
  auto previous_int = std::signal(SIGINT, request_stop);
  auto previous_term = std::signal(SIGTERM, request_stop);
  FitSummary summary;
  try {
    summary = session.run();
  } catch (...) {
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
    throw;
  }
  std::signal(SIGINT, previous_int);
  std::signal(SIGTERM, previous_term);
  if (summary.stop_reason == "interrupted") {
    std::printf("interrupted: checkpoint written; continue with `motoflex resume %s`\n",
                dir.c_str());
    return exit_code::kInterrupted;
  } else {
    std::printf("done (%s): best fitness %.6g after %llu evaluations; see %s/summary.json\n",
                summary.stop_reason.c_str(), summary.best_fitness,
                static_cast<unsigned long long>(summary.evaluations), dir.c_str());
    // The parameter table (start, fitted, bounds, sensitivity, undetermined ones named) and the
    // rest of full_report(), after its brief first line: what a user reads first.
    const std::string report = summary.full_report();
    std::printf("%s", report.substr(std::min(report.size(), report.find('\n') + 1)).c_str());
  }
  if (summary.invalid_candidates > 0) {
    std::printf("%llu invalid candidate(s) scored worst (the model rejected them), e.g. %s\n",
                static_cast<unsigned long long>(summary.invalid_candidates),
                summary.invalid_reasons.empty() ? "?" : summary.invalid_reasons.front().c_str());
  }
  return exit_code::kOk;
}

}  // namespace motoflex::cli
