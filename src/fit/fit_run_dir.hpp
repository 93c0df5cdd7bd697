#pragma once

// Internal to FitSession: the run folder of a fit. generations.csv gets one row per generation,
// checkpoint.json (atomic, versioned by the es library) the full state after it, run.json what
// `resume` needs to rebuild the config.

#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "motoflex/core/folder_lock.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex_es/driver.hpp"
#include "motoflex_es/strategy.hpp"

namespace motoflex::detail {

// What a checkpoint carries besides the strategy's own state.
struct RunDirState {
  double seconds_before = 0.0;  // wall time of earlier sessions of this run
  bool main_done = false;       // the main strategy finished (the polish may follow)
  bool converged = false;       // how it finished (when main_done)
  std::string convergence;
  // budget.stall_evaluations: the best fitness at the last real improvement and when it came
  // (motoflex_es::ImprovementStall), so a resumed run stalls exactly where an uninterrupted one
  // would. +inf before the first generation.
  double stall_anchor_fitness = std::numeric_limits<double>::infinity();
  std::uint64_t stall_anchor_evaluations = 0;
};

class RunDir {
 public:
  explicit RunDir(const FitConfig& config);
  // A new run: takes the folder's lock (FolderLock), refuses a folder that holds a fit,
  // removes temporary files a killed run left, creates generations.csv.
  RunDirState start();
  // Takes the folder's lock, removes stale temporary files, loads the checkpoint into `strategy`
  // and `problem`'s counters; drops generations.csv rows the checkpoint does not have (a kill
  // between the row and the checkpoint).
  RunDirState resume(motoflex_es::Strategy& strategy, FitProblem& problem);
  void write_run_json() const;
  void append_generation(const motoflex_es::GenerationReport& report, double mean_sigma,
                         double seconds) const;
  void write_checkpoint(const motoflex_es::Strategy& strategy, const FitProblem& problem,
                        const RunDirState& state, double seconds) const;

 private:
  const FitConfig& config_;
  std::string dir_;
  std::unique_ptr<FolderLock> lock_;  // held from start()/resume() until the run ends

  void take_lock();
};

// Mean step size relative to the bound widths (μ+λ: over the population; CMA-ES: σ; 0 else).
double mean_sigma(const motoflex_es::Strategy& strategy);

}  // namespace motoflex::detail
