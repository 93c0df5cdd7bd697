#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "motoflex/studies/titan/titan_study.hpp"

namespace motoflex {

// Everything seed 000 reports, as one plan: static standing, the up-and-down motion, the crawl
// in several postures and the speed of a 10 s crawl.
struct TitanPaperStudyPlan {
  explicit TitanPaperStudyPlan(TitanStudySetup study_setup) : setup(std::move(study_setup)) {}

  TitanStudySetup setup;
  TitanStaticOptions stand;
  TitanUpDownStudyOptions updown;
  std::vector<TitanPosture> crawl_postures = {TitanPosture::kA, TitanPosture::kB, TitanPosture::kC,
                                              TitanPosture::kD};
  TitanCrawlStudyOptions crawl;  // posture replaced by each of crawl_postures
  double timing_crawl_s = 10.0;  // 0: no timing run
  TitanPosture timing_posture = TitanPosture::kA;
  int timing_repeats = 3;  // the fastest of these runs is reported
};

struct TitanPaperStudyResults {
  TitanStaticResult stand;
  TitanUpDownResult updown;
  std::vector<TitanCrawlResult> crawls;  // in crawl_postures order
  std::optional<TitanCrawlTiming> timing;
  double wall_s = 0.0;  // the whole study
};

// Runs the static, up-and-down and crawl rollouts on `threads` OpenMP threads (each rollout in
// one thread; results do not depend on the thread count), then the timing run alone in the
// calling thread so that it measures one thread undisturbed by the others. Throws
// std::invalid_argument for an invalid plan.
TitanPaperStudyResults run_titan_paper_study(const TitanPaperStudyPlan& plan, int threads);

}  // namespace motoflex
