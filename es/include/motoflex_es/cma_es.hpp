#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "motoflex_es/strategy.hpp"

namespace motoflex_es {

// Options of CMA-ES with IPOP restarts. Defaults are Hansen's (The CMA Evolution Strategy: A
// Tutorial, 2016, Table 1 and §B.3) and pycma's stop criteria; all "relative" lengths are in the
// normalised search space in which the bounds are the unit box (see CmaEs).
struct CmaEsOptions {
  // Initial mean; empty = uniform in the bounds.
  std::vector<double> start_point;
  // σ0 as a fraction of the bound width (the same for every coordinate, because the search
  // runs in the normalised box). Hansen recommends about a quarter of the domain.
  double initial_sigma_relative = 0.25;
  // λ of the first run; 0 = 4 + ⌊3 ln n⌋.
  std::size_t population_size = 0;
  // Active covariance update: the worst λ−μ samples get negative weights (Hansen 2016, eq. 53).
  bool active = true;
  // With the active update: the ranks from max(μ, ⌊λ/2⌋+1) on share one negative weight, the
  // mean of their eq. 53 weights, and enter the covariance in the order they were sampled. Only
  // which samples form that tail matters then, not their order within it, so the driver can race
  // the tail (below). The update's total negative weight is unchanged; the tail's worst samples
  // push C a little less and its best ones a little more than with their own ranks.
  bool pooled_negative_tail = false;
  // Racing (without the active update, or with pooled_negative_tail): the driver evaluates the
  // first max(μ, ⌊λ/2⌋+1) samples, then stops each other one as soon as it is worse than all of
  // them (the median history reads rank ⌊λ/2⌋). Bit-identical to full evaluation.
  bool racing = true;
  // IPOP (Auger & Hansen 2005): when a run stops on a local criterion, start again with λ
  // multiplied by population_increase, up to max_restarts times. 0 = plain CMA-ES.
  std::size_t max_restarts = 9;
  double population_increase = 2.0;
  // Mean of a restart: uniform in the bounds (pycma's advice for restarts), or the start point.
  bool restart_from_start_point = false;
  // Evaluation budget over all restarts (libcmaes counts it per restart in BIPOP, issue #253;
  // here it is global); a batch that would exceed it is never asked. 0 = unlimited.
  std::uint64_t max_evaluations = 0;
  // Stop everything once the best fitness is <= this.
  double target_fitness = -std::numeric_limits<double>::infinity();
  // Local stop criteria (each ends the current run and triggers a restart):
  // tol_fun: the best fitness of the last 10 + ⌈30n/λ⌉ generations and all of the current one
  // lie within a range below tol_fun.
  double tol_fun = 1e-12;
  // tol_x: σ·max(√C_ii, |p_c,i|) < tol_x for every i (normalised units).
  double tol_x = 1e-12;
  // Generations per run; 0 = 100 + 150(n+3)²/√λ (pycma).
  std::uint64_t max_iterations = 0;
  // Stagnation (Hansen 2009, BIPOP-CMA-ES): over the last 20 % of the run (at least
  // 120 + 30n/λ, at most 20000 generations) the median of the most recent 30 % of both the
  // best-of-generation and the median-of-generation fitness is not better than of the first 30 %.
  bool check_stagnation = true;
  // Stall: the best fitness of the run improved by less than tol_stall_relative·|best| over the
  // last stall_generations generations (0 = 20 + ⌈60n/λ⌉, twice tol_fun's history). It catches
  // what the absolute tol_fun and the median-based stagnation test miss on a simulation
  // fitness: a plateau whose best and median values jitter (contacts make F rugged at small
  // scales) at a level far above tol_fun, while σ wanders instead of shrinking. Like pycma's
  // tolstagnation, but on the best value; 0 switches it off. On a smooth function the best
  // improves geometrically, so the test only fires at a plateau or a noise floor.
  double tol_stall_relative = 1e-3;
  std::uint64_t stall_generations = 0;
  // Condition number of C above which a run stops.
  double max_condition = 1e14;
  // Generations between eigendecompositions of C; 0 = max(1, ⌊1/(10·n·(c1 + cμ))⌋), which keeps
  // the cost per sample O(n²) (Hansen 2016, §B.2). In between, sampling uses the last B and D.
  std::uint64_t eigen_interval = 0;
  // Keys every random stream of the run.
  std::uint64_t seed = 1;

  bool is_valid(std::string* why) const;
};

// The strategy parameters that depend on n and λ only (Hansen 2016, Table 1 and eq. 53).
struct CmaParameters {
  std::size_t lambda = 0;
  std::size_t mu = 0;
  Eigen::VectorXd weights;  // λ weights, best first; the first μ sum to 1, the rest are <= 0
  double mueff = 0.0;
  double cc = 0.0;
  double cs = 0.0;
  double c1 = 0.0;
  double cmu = 0.0;
  double damps = 0.0;
  double chi_n = 0.0;  // E‖N(0, I)‖
  std::uint64_t eigen_interval = 1;
  std::uint64_t max_iterations = 0;
};
// With active = false the negative weights are zero (the original rank-μ update).
CmaParameters cma_parameters(std::size_t n, std::size_t lambda, bool active);

// CMA-ES (Hansen & Ostermeier 2001; Hansen 2016) with the active update and IPOP restarts.
// Bounds: the distribution lives in an unbounded normalised space u; a sample is evaluated at
// x_i = lower_i + width_i·r(u_i), where r mirrors u periodically into [0, 1] (reflect_into_bounds).
// The map is the identity inside the box, continuous, and needs no penalty or resampling; the
// strategy updates with the unmirrored samples, so its internal model stays Gaussian. Because
// r has period 2 the mean is folded back into [-1, 1) after each update, which keeps the
// numbers small without changing any sample. Working in the normalised box also makes the
// search invariant to the units of each parameter.
// selection_threshold() is +inf. With the active update every rank of every sample enters the
// covariance update, so no individual can be stopped early without changing the run; without
// it (active = false), or with its tail pooled (pooled_negative_tail), only the best
// max(μ, ⌊λ/2⌋+1) ranks matter, which exact_ranks_needed() tells the driver (racing), unless
// this generation could end the run by tol_fun, which reads the whole generation's range.
class CmaEs final : public Strategy {
 public:
  // Throws std::invalid_argument for invalid options or a bad start point.
  CmaEs(Bounds bounds, CmaEsOptions options);

  std::string name() const override { return "cma_es"; }
  std::vector<std::vector<double>> ask() override;
  void tell(const std::vector<double>& fitness) override;
  std::size_t next_batch_size() const override;
  std::size_t exact_ranks_needed() const override;
  // The ranks whose order the update reads: max(μ, ⌊λ/2⌋+1) of λ.
  std::size_t ranked_head() const;
  nlohmann::json save_state() const override;
  void load_state(const nlohmann::json& state) override;

  const CmaEsOptions& options() const { return options_; }
  const CmaParameters& parameters() const { return parameters_; }
  // Restarts so far (0 during the first run) and generations of the current run.
  std::size_t restarts() const { return restarts_; }
  std::uint64_t run_generation() const { return run_generation_; }
  double sigma() const { return sigma_; }
  // The mean mapped into the bounds.
  std::vector<double> mean() const;
  // One line per finished run: "run 0 (lambda 10): tol_fun after 312 generations".
  const std::vector<std::string>& run_log() const { return run_log_; }

 private:
  // Generations of best values tol_fun looks back over: 10 + ⌈30n/λ⌉.
  std::size_t tol_fun_history() const;
  void start_run(const Eigen::VectorXd& mean_normalised);
  Eigen::VectorXd normalise(const std::vector<double>& x) const;
  std::vector<double> phenotype(const Eigen::VectorXd& u) const;
  void update_distribution(const std::vector<std::size_t>& ranking);
  // Active update with the ranks from ranked_head() on sharing one weight.
  bool pools_negative_tail() const { return options_.active && options_.pooled_negative_tail; }
  void update_eigensystem();
  // The local criterion that ends the current run, or kNone.
  StopReason run_stop_reason(const std::vector<double>& fitness,
                             const std::vector<std::size_t>& ranking) const;
  void end_run(StopReason reason);
  void check_budget();
  nlohmann::json options_fingerprint() const;

  CmaEsOptions options_;
  CmaParameters parameters_;
  std::size_t restarts_ = 0;
  std::uint64_t run_generation_ = 0;
  std::uint64_t eigen_generation_ = 0;  // run generation of the last eigendecomposition
  Eigen::VectorXd mean_;                // normalised, unbounded
  double sigma_ = 0.0;
  Eigen::MatrixXd covariance_;          // C
  Eigen::MatrixXd eigenvectors_;        // B, columns
  Eigen::VectorXd axis_lengths_;        // D = √eigenvalues(C)
  Eigen::MatrixXd inverse_sqrt_c_;      // C^(-1/2) = B D^-1 Bᵀ
  Eigen::VectorXd path_c_;              // p_c
  Eigen::VectorXd path_sigma_;          // p_σ
  std::vector<double> best_history_;    // best fitness per generation of this run
  std::vector<double> median_history_;  // median fitness per generation of this run
  std::vector<std::string> run_log_;
  Eigen::MatrixXd pending_steps_;  // y_k = B D z_k of the outstanding ask, one column each
  std::vector<std::vector<double>> pending_x_;
};

}  // namespace motoflex_es
