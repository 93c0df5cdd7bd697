#include "motoflex/studies/titan/titan_paper_study.hpp"

#include <chrono>
#include <exception>
#include <stdexcept>

#include "motoflex/sim/ode_runtime.hpp"

namespace motoflex {

TitanPaperStudyResults run_titan_paper_study(const TitanPaperStudyPlan& plan, int threads) {
  if (threads < 1) throw std::invalid_argument("TITAN study: threads must be >= 1");
  const auto start = std::chrono::steady_clock::now();
  TitanPaperStudyResults results;
  results.crawls.resize(plan.crawl_postures.size());
  const int jobs = 2 + static_cast<int>(plan.crawl_postures.size());
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(jobs));
  ensure_ode_ready();
  // Longest jobs first (the crawls), so that two threads finish together.
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (int job = 0; job < jobs; ++job) {
    try {
      ensure_ode_ready();
      const int crawl = job;
      if (crawl < static_cast<int>(plan.crawl_postures.size())) {
        TitanCrawlStudyOptions options = plan.crawl;
        options.posture = plan.crawl_postures[static_cast<std::size_t>(crawl)];
        results.crawls[static_cast<std::size_t>(crawl)] = run_titan_crawl(plan.setup, options);
      } else if (job == jobs - 2) {
        results.updown = run_titan_updown(plan.setup, plan.updown);
      } else {
        results.stand = run_titan_static(plan.setup, plan.stand);
      }
    } catch (...) {
      errors[static_cast<std::size_t>(job)] = std::current_exception();
    }
  }
  for (const auto& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  if (plan.timing_crawl_s > 0.0) {
    results.timing =
        time_titan_crawl(plan.setup, plan.timing_posture, plan.timing_crawl_s, plan.timing_repeats);
  }
  results.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return results;
}

}  // namespace motoflex
