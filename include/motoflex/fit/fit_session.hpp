#pragma once

// FitSession runs a resolved fit into its run folder, or continues one from its checkpoint
// (Ceres's Solve, with a progress callback and cooperative cancel):
//
//   FitSession session = FitSession::start(load_fit_config("fit.yaml"));
//   session.set_progress([](const FitProgress& p) { std::puts(p.line().c_str()); });
//   const FitSummary summary = session.run();   // also writes summary.json, best.json, ...
//   std::puts(summary.full_report().c_str());
//
// Every generation appends generations.csv and writes checkpoint.json atomically, so a run
// killed at any moment continues with FitSession::resume(run_dir) exactly where it was.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_summary.hpp"

namespace motoflex_es {
class Evaluator;
}

namespace motoflex {

// One progress event: a finished generation of the main strategy, or the end of the polish.
struct FitProgress {
  bool polish = false;  // the local polish finished (generation fields are then unused)
  std::uint64_t generation = 0;
  std::uint64_t evaluations = 0;
  double best_fitness = 0.0;
  double batch_median = 0.0;
  double mean_sigma = 0.0;  // mean step size relative to the bounds
  std::uint64_t stopped_early = 0;
  double seconds = 0.0;  // wall time of the run so far (all sessions)
  std::string polish_algorithm;
  // The line `motoflex fit` prints for this event.
  std::string line() const;
};

using FitProgressCallback = std::function<void(const FitProgress&)>;

class FitSession {
 public:
  // A new fit into config.out_dir. run() throws InputError if that folder holds a fit already.
  static FitSession start(FitConfig config);
  // Continues the fit of `run_dir` from its checkpoint: the config is rebuilt from run.json as
  // it was first loaded; `overrides` may raise the budget or change the thread count.
  static FitSession resume(const std::string& run_dir, const FitOverrides& overrides = {});
  // start() or resume() with a config built elsewhere (e.g. on every MPI rank).
  FitSession(FitConfig config, bool resume);
  ~FitSession();
  FitSession(FitSession&&) noexcept;
  FitSession& operator=(FitSession&&) noexcept;

  void set_progress(FitProgressCallback callback);
  // Evaluates batches with `evaluator` (not owned; e.g. MPI ranks) instead of the serial or
  // OpenMP evaluator config.threads asks for.
  void set_evaluator(motoflex_es::Evaluator* evaluator);
  // Also stop when *flag becomes true (e.g. set by a signal handler; polled per generation).
  void set_cancel_flag(const std::atomic<bool>* flag);
  // Ends the run after the current generation, with its checkpoint (any thread may call it).
  void cancel();

  // Runs until the strategy stops, the budget ends it or it is cancelled; writes best.json,
  // summary.json, the best parameters' simulated logs and plots. stop_reason "interrupted"
  // means cancelled (resume continues it). Throws InputError for an unusable run folder.
  FitSummary run();

  const FitConfig& config() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The config of the fit in `run_dir`, rebuilt from its run.json (the fit file and the overrides
// it was loaded with), with `overrides`' threads and budget on top and the run folder as out.
FitConfig load_run_config(const std::string& run_dir, const FitOverrides& overrides = {});

}  // namespace motoflex
