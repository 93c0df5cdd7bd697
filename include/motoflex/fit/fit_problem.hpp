#pragma once

#include <memory>
#include <string>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/problem.hpp"
#include "motoflex_es/strategy.hpp"

namespace motoflex {

// The fit as the optimiser sees it: x → parameter set → Σ fitness over the training logs.
// Counts the individuals stopped early by the selection threshold and the frames that saved.
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
  void set_counters(std::uint64_t stopped, std::uint64_t simulated, std::uint64_t saved);
  // {stopped_early, frames_simulated, frames_saved}, summed over MPI ranks by the MpiEvaluator.
  std::vector<std::uint64_t> counters() const override;
  void add_counters(const std::vector<std::uint64_t>& increments) override;

 private:
  const FitConfig& config_;
  std::uint64_t stopped_early_ = 0;
  std::uint64_t frames_simulated_ = 0;
  std::uint64_t frames_saved_ = 0;
};

// The strategy a fit config asks for, seeded with the config's seed.
std::unique_ptr<motoflex_es::Strategy> make_strategy(const FitConfig& config);

}  // namespace motoflex
