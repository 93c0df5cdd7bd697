#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "motoflex_es/strategy.hpp"

namespace motoflex_es {

// The NLopt algorithms offered (NLopt 2.7 names in brackets).
enum class NloptAlgorithm {
  kBobyqa,  // local, quadratic models [LN_BOBYQA]; polish of a point on a smooth fitness
  kSbplx,   // local, Subplex [LN_SBPLX]; more robust to noise and kinks than BOBYQA
  kCrs2Lm,  // global, controlled random search with local mutation [GN_CRS2_LM]
  kIsres,   // global, improved stochastic ranking ES [GN_ISRES]
  kEsch,    // global, evolutionary algorithm after Beyer & Schwefel [GN_ESCH]
};
const char* to_string(NloptAlgorithm algorithm);
bool is_local(NloptAlgorithm algorithm);

struct NloptOptions {
  NloptAlgorithm algorithm = NloptAlgorithm::kBobyqa;
  // Where the search starts; empty = the centre of the bounds. For a polish, the point to polish.
  std::vector<double> start_point;
  // Local algorithms: initial step of every coordinate as a fraction of its bound width.
  double initial_step_relative = 0.1;
  // Global algorithms: population size; 0 = NLopt's default (CRS2: 10(n+1), ISRES: 20(n+1)).
  std::size_t population = 0;
  // NLopt's own limit on objective calls. Required for the global algorithms, which NLopt's
  // documentation says otherwise run indefinitely; 0 = none (local algorithms only).
  std::uint64_t max_evaluations = 0;
  // Stop when a step changes every coordinate by less than this fraction of its width
  // (NLopt xtol_abs, set per coordinate); 0 = off.
  double xtol_relative_to_width = 1e-10;
  // NLopt ftol_rel and ftol_abs; 0 = off.
  double ftol_rel = 0.0;
  double ftol_abs = 0.0;
  // NLopt stopval: stop once a fitness <= this is found.
  double target_fitness = -std::numeric_limits<double>::infinity();
  // Handed to nlopt::srand in the thread that runs NLopt (its generator is thread-local).
  std::uint64_t seed = 1;

  bool is_valid(std::string* why) const;
};

// NLopt behind the ask/tell interface. NLopt drives its own loop and calls the objective one
// point at a time, so it runs in a worker thread whose objective callback hands the point to
// ask() and blocks until tell() hands back the fitness: every batch has exactly one point and
// the evaluation is sequential (use it for a polish or a baseline, not for large parallel
// runs). Given the seed and the fitness values the run is deterministic. tell() returns only
// once NLopt has produced its next point or finished, so should_stop() is always current.
// NLopt keeps its state inside the library, so save_state() records only the common fields and
// load_state() throws CheckpointError (can_resume() is false); a resumed fit should restart the
// polish from the best point. Destroying the optimizer mid-run stops NLopt (forced stop) and
// joins the thread.
class NloptOptimizer final : public Strategy {
 public:
  // Throws std::invalid_argument for invalid options or a bad start point.
  NloptOptimizer(Bounds bounds, NloptOptions options);
  ~NloptOptimizer() override;

  std::string name() const override;
  std::vector<std::vector<double>> ask() override;
  void tell(const std::vector<double>& fitness) override;
  std::size_t next_batch_size() const override { return should_stop() ? 0 : 1; }
  nlohmann::json save_state() const override;
  void load_state(const nlohmann::json& state) override;
  bool can_resume() const override { return false; }

  const NloptOptions& options() const { return options_; }

 private:
  enum class Phase { kNotStarted, kRunning, kPointReady, kValueReady, kFinished };

  void run_nlopt();
  // Called by NLopt in the worker thread.
  static double objective(unsigned n, const double* x, double* gradient, void* self);
  double hand_over(const double* x, unsigned n);
  // Waits (lock held) until NLopt has posted a point or finished; applies a finish.
  void wait_for_point(std::unique_lock<std::mutex>& lock);

  NloptOptions options_;
  std::thread worker_;
  std::mutex mutex_;
  std::condition_variable changed_;
  Phase phase_ = Phase::kNotStarted;
  bool cancel_ = false;
  std::vector<double> point_;  // as NLopt asked for it
  double value_ = 0.0;
  StopReason finish_reason_ = StopReason::kNone;
  std::string finish_detail_;
};

}  // namespace motoflex_es
