#pragma once

#include <memory>
#include <mutex>
#include <set>
#include <string>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/problem.hpp"
#include "motoflex_es/strategy.hpp"

namespace motoflex {

// The fit as the optimiser sees it: x → parameter set → Σ fitness over the training logs.
// Counts the individuals stopped early by the selection threshold and the frames that saved,
// and the invalid candidates: parameter sets the model rejects (a negative backlash, R = 0, a
// gear sub-step too long to be stable, ...). Those score +inf, the worst; they never end a fit.
class FitProblem final : public motoflex_es::Problem {
 public:
  explicit FitProblem(const FitConfig& config);
  std::size_t dimension() const override;
  motoflex_es::Bounds bounds() const override;
  void evaluate_batch(const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                      const motoflex_es::EvaluationContext& context) override;

  std::uint64_t stopped_early() const { return stopped_early_; }
  std::uint64_t frames_simulated() const { return frames_simulated_; }
  std::uint64_t frames_saved() const { return frames_saved_; }
  std::uint64_t invalid_candidates() const { return invalid_candidates_; }
  // Up to kMaxInvalidReasons distinct reasons the model gave, sorted (so the same for any
  // number of threads).
  std::vector<std::string> invalid_reasons() const;
  static constexpr std::size_t kMaxInvalidReasons = 5;
  void set_counters(std::uint64_t stopped, std::uint64_t simulated, std::uint64_t saved,
                    std::uint64_t invalid = 0, const std::vector<std::string>& reasons = {});
  // {stopped_early, frames_simulated, frames_saved, invalid_candidates}, summed over MPI ranks
  // by the MpiEvaluator (3 increments, from an older rank, are accepted too).
  std::vector<std::uint64_t> counters() const override;
  void add_counters(const std::vector<std::uint64_t>& increments) override;

 private:
  const FitConfig& config_;
  std::uint64_t stopped_early_ = 0;
  std::uint64_t frames_simulated_ = 0;
  std::uint64_t frames_saved_ = 0;
  std::uint64_t invalid_candidates_ = 0;
  mutable std::mutex reasons_mutex_;
  std::set<std::string> invalid_reasons_;

  void note_invalid(const std::string& reason);
};

// The strategy a fit config asks for, seeded with the config's seed.
std::unique_ptr<motoflex_es::Strategy> make_strategy(const FitConfig& config);

}  // namespace motoflex
