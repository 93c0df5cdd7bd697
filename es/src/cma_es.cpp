#include "motoflex_es/cma_es.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "motoflex_es/random.hpp"

namespace motoflex_es {
namespace {

constexpr std::size_t kMaxHistory = 20000;  // Hansen 2009: stagnation looks back at most this far

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

CmaEs::CmaEs(Bounds bounds, CmaEsOptions options)
    : Strategy(std::move(bounds)), options_(std::move(options)) {
  std::string why;
  if (!options_.is_valid(&why)) throw std::invalid_argument("CmaEsOptions: " + why);
  const std::size_t n = dimension();
  if (!options_.start_point.empty()) {
    if (options_.start_point.size() != n) {
      throw std::invalid_argument("CmaEsOptions: start_point has " +
                                  std::to_string(options_.start_point.size()) +
                                  " values, the bounds " + std::to_string(n));
    }
    if (!bounds_.contains(options_.start_point)) {
      throw std::invalid_argument("CmaEsOptions: start_point lies outside the bounds");
    }
  }
  const std::size_t lambda =
      options_.population_size > 0
          ? options_.population_size
          : 4 + static_cast<std::size_t>(std::floor(3.0 * std::log(static_cast<double>(n))));
  parameters_ = cma_parameters(n, lambda, options_.active);
  if (options_.max_evaluations > 0 && options_.max_evaluations < lambda) {
    throw std::invalid_argument("CmaEsOptions: max_evaluations is below one population (" +
                                std::to_string(lambda) + ")");
  }
  Eigen::VectorXd start(n);
  if (options_.start_point.empty()) {
    motoflex::RandomStream draws = es_stream(options_.seed, 0, 0, Purpose::kRestart);
    for (std::size_t i = 0; i < n; ++i) start(static_cast<Eigen::Index>(i)) = draws.uniform();
  } else {
    start = normalise(options_.start_point);
  }
  start_run(start);
}

Eigen::VectorXd CmaEs::normalise(const std::vector<double>& x) const {
  Eigen::VectorXd u(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    u(static_cast<Eigen::Index>(i)) = (x[i] - bounds_.lower[i]) / bounds_.width(i);
  }
  return u;
}

std::vector<double> CmaEs::phenotype(const Eigen::VectorXd& u) const {
  std::vector<double> x(dimension());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = reflect_into_bounds(u(static_cast<Eigen::Index>(i)), 0.0, 1.0);
    x[i] = std::min(bounds_.upper[i], bounds_.lower[i] + bounds_.width(i) * r);
  }
  return x;
}

std::vector<double> CmaEs::mean() const {
  return phenotype(mean_);
}

void CmaEs::start_run(const Eigen::VectorXd& mean_normalised) {
  const Eigen::Index n = static_cast<Eigen::Index>(dimension());
  mean_ = mean_normalised;
  sigma_ = options_.initial_sigma_relative;
  covariance_ = Eigen::MatrixXd::Identity(n, n);
  eigenvectors_ = Eigen::MatrixXd::Identity(n, n);
  axis_lengths_ = Eigen::VectorXd::Ones(n);
  inverse_sqrt_c_ = Eigen::MatrixXd::Identity(n, n);
  path_c_ = Eigen::VectorXd::Zero(n);
  path_sigma_ = Eigen::VectorXd::Zero(n);
  run_generation_ = 0;
  eigen_generation_ = 0;
  best_history_.clear();
  median_history_.clear();
}

std::size_t CmaEs::next_batch_size() const {
  return should_stop() ? 0 : parameters_.lambda;
}

std::size_t CmaEs::ranked_head() const {
  return std::min(parameters_.lambda, std::max(parameters_.mu, parameters_.lambda / 2 + 1));
}

std::size_t CmaEs::exact_ranks_needed() const {
  const std::size_t lambda = next_batch_size();
  const bool every_rank = options_.active && !pools_negative_tail();
  if (!options_.racing || every_rank || lambda == 0) return lambda;
  // tol_fun compares the range of the whole generation (with the recent bests): unless the
  // recent bests alone already span tol_fun, so that this generation cannot make it fire,
  // every value must be exact.
  const std::size_t history = tol_fun_history();
  if (best_history_.size() + 1 >= history) {
    const auto recent = best_history_.end() - static_cast<std::ptrdiff_t>(history - 1);
    const auto [low, high] = std::minmax_element(recent, best_history_.end());
    if (!(*high - *low >= options_.tol_fun)) return lambda;
  }
  // The recombination reads ranks 0..μ−1, the median history rank ⌊λ/2⌋.
  return ranked_head();
}

std::size_t CmaEs::tol_fun_history() const {
  return 10 + static_cast<std::size_t>(std::ceil(30.0 * static_cast<double>(dimension()) /
                                                 static_cast<double>(parameters_.lambda)));
}

std::vector<std::vector<double>> CmaEs::ask() {
  pending_x_.clear();
  if (should_stop()) return {};
  const Eigen::Index n = static_cast<Eigen::Index>(dimension());
  const std::size_t lambda = parameters_.lambda;
  pending_steps_.resize(n, static_cast<Eigen::Index>(lambda));
  Eigen::VectorXd z(n);
  for (std::size_t k = 0; k < lambda; ++k) {
    motoflex::RandomStream draws = es_stream(options_.seed, generation_, k, Purpose::kCmaSample);
    for (Eigen::Index i = 0; i < n; ++i) z(i) = draws.normal_libm();
    // y_k = B D z_k ~ N(0, C); x_k = m + σ y_k (Hansen 2016, eq. 38–40)
    pending_steps_.col(static_cast<Eigen::Index>(k)) =
        eigenvectors_ * axis_lengths_.cwiseProduct(z);
    pending_x_.push_back(
        phenotype(mean_ + sigma_ * pending_steps_.col(static_cast<Eigen::Index>(k))));
  }
  return pending_x_;
}

void CmaEs::update_distribution(const std::vector<std::size_t>& ranking) {
  const CmaParameters& p = parameters_;
  const Eigen::Index n = static_cast<Eigen::Index>(dimension());
  const double nd = static_cast<double>(n);
  const auto step = [&](std::size_t rank) {
    return pending_steps_.col(static_cast<Eigen::Index>(ranking[rank]));
  };

  // Recombination: <y>_w = Σ_{i≤μ} w_i y_{i:λ}, m ← m + σ <y>_w (eq. 41, c_m = 1).
  Eigen::VectorXd weighted_step = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < p.mu; ++i)
    weighted_step += p.weights(static_cast<Eigen::Index>(i)) * step(i);
  mean_ += sigma_ * weighted_step;

  // Step-size path (eq. 43) and the h_σ stall of the rank-one path (footnote 18 / eq. 45).
  path_sigma_ = (1.0 - p.cs) * path_sigma_ +
                std::sqrt(p.cs * (2.0 - p.cs) * p.mueff) * (inverse_sqrt_c_ * weighted_step);
  const double generations = static_cast<double>(run_generation_ + 1);
  const double path_norm = path_sigma_.norm();
  const bool h_sigma = path_norm / std::sqrt(1.0 - std::pow(1.0 - p.cs, 2.0 * generations)) <
                       (1.4 + 2.0 / (nd + 1.0)) * p.chi_n;
  path_c_ = (1.0 - p.cc) * path_c_ +
            (h_sigma ? std::sqrt(p.cc * (2.0 - p.cc) * p.mueff) : 0.0) * weighted_step;

  // Covariance (eq. 47 with the active weights w°_i of eq. 46).
  const double delta_h = h_sigma ? 0.0 : p.cc * (2.0 - p.cc);
  const double weight_sum = p.weights.sum();
  covariance_ *= 1.0 + p.c1 * delta_h - p.c1 - p.cmu * weight_sum;
  covariance_.noalias() += p.c1 * path_c_ * path_c_.transpose();
  // With a pooled tail the ranks from ranked_head() on share their mean weight, in sample order.
  const std::size_t head = pools_negative_tail() ? ranked_head() : p.lambda;
  const auto add = [&](double w, const auto& y) {
    if (w == 0.0) return;
    if (w < 0.0) w *= nd / (inverse_sqrt_c_ * y).squaredNorm();
    covariance_.noalias() += (p.cmu * w) * y * y.transpose();
  };
  for (std::size_t i = 0; i < head; ++i) add(p.weights(static_cast<Eigen::Index>(i)), step(i));
  if (head < p.lambda) {
    const auto tail = static_cast<Eigen::Index>(p.lambda - head);
    const double w = p.weights.tail(tail).mean();
    std::vector<std::size_t> samples(ranking.begin() + static_cast<std::ptrdiff_t>(head),
                                     ranking.end());
    std::sort(samples.begin(), samples.end());
    for (const std::size_t k : samples) add(w, pending_steps_.col(static_cast<Eigen::Index>(k)));
  }

  // Step size (eq. 44).
  sigma_ *= std::exp(p.cs / p.damps * (path_norm / p.chi_n - 1.0));

  // r(u) has period 2: moving the mean by a multiple of 2 changes no sample, only keeps it small.
  for (Eigen::Index i = 0; i < n; ++i) mean_(i) -= 2.0 * std::floor((mean_(i) + 1.0) / 2.0);
}

void CmaEs::update_eigensystem() {
  // Symmetrise from the upper triangle so rounding never makes C asymmetric.
  const Eigen::MatrixXd symmetric = covariance_.triangularView<Eigen::Upper>();
  covariance_ = symmetric;
  covariance_.triangularView<Eigen::StrictlyLower>() = symmetric.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance_);
  eigenvectors_ = solver.eigenvectors();
  const Eigen::VectorXd eigenvalues = solver.eigenvalues();
  // A non-positive eigenvalue is caught by run_stop_reason (condition number); floor it here so
  // the square roots stay finite until then.
  const double largest = std::max(eigenvalues.maxCoeff(), std::numeric_limits<double>::min());
  axis_lengths_ = eigenvalues.cwiseMax(largest * 1e-300).cwiseSqrt();
  inverse_sqrt_c_ =
      eigenvectors_ * axis_lengths_.cwiseInverse().asDiagonal() * eigenvectors_.transpose();
  eigen_generation_ = run_generation_;
}

StopReason CmaEs::run_stop_reason(const std::vector<double>& fitness,
                                  const std::vector<std::size_t>& ranking) const {
  const CmaParameters& p = parameters_;
  const std::size_t n = dimension();
  const double nd = static_cast<double>(n);
  const double lambda_d = static_cast<double>(p.lambda);

  const std::uint64_t max_iterations =
      options_.max_iterations > 0 ? options_.max_iterations : p.max_iterations;
  if (run_generation_ >= max_iterations) return StopReason::kMaxIterations;

  // tol_fun: recent best values and the whole current generation within tol_fun.
  const std::size_t history = tol_fun_history();
  if (best_history_.size() >= history) {
    const auto recent = best_history_.end() - static_cast<std::ptrdiff_t>(history);
    const auto [low, high] = std::minmax_element(recent, best_history_.end());
    const double current_range =
        ranked_fitness(fitness[ranking.back()]) - ranked_fitness(fitness[ranking.front()]);
    if (*high - *low < options_.tol_fun && current_range < options_.tol_fun) {
      return StopReason::kTolFun;
    }
  }

  // tol_x: every coordinate's standard deviation and path below tol_x.
  bool all_small = true;
  for (std::size_t i = 0; i < n && all_small; ++i) {
    const Eigen::Index ii = static_cast<Eigen::Index>(i);
    all_small =
        sigma_ * std::max(std::sqrt(covariance_(ii, ii)), std::abs(path_c_(ii))) < options_.tol_x;
  }
  if (all_small) return StopReason::kTolX;

  // Condition number of C, from the last eigendecomposition.
  const double ratio = axis_lengths_.maxCoeff() / axis_lengths_.minCoeff();
  if (!(ratio * ratio <= options_.max_condition)) return StopReason::kConditionNumber;

  // No effect along the principal axis of this generation, or along any coordinate.
  const Eigen::Index axis = static_cast<Eigen::Index>(run_generation_ % n);
  const Eigen::VectorXd shifted =
      mean_ + 0.1 * sigma_ * axis_lengths_(axis) * eigenvectors_.col(axis);
  if ((shifted.array() == mean_.array()).all()) return StopReason::kNoEffect;
  for (Eigen::Index i = 0; i < mean_.size(); ++i) {
    if (mean_(i) == mean_(i) + 0.2 * sigma_ * std::sqrt(covariance_(i, i))) {
      return StopReason::kNoEffect;
    }
  }

  if (options_.tol_stall_relative > 0.0) {
    const std::size_t stall = options_.stall_generations > 0
                                  ? static_cast<std::size_t>(options_.stall_generations)
                                  : 20 + static_cast<std::size_t>(std::ceil(60.0 * nd / lambda_d));
    if (best_history_.size() > stall) {
      const auto split = best_history_.end() - static_cast<std::ptrdiff_t>(stall);
      const double before = *std::min_element(best_history_.begin(), split);
      const double now = std::min(before, *std::min_element(split, best_history_.end()));
      if (std::isfinite(before) && before - now <= options_.tol_stall_relative * std::abs(before)) {
        return StopReason::kTolStall;
      }
    }
  }

  if (options_.check_stagnation) {
    const double minimum_window = 120.0 + 30.0 * nd / lambda_d;
    const std::size_t window = static_cast<std::size_t>(std::min<double>(
        kMaxHistory, std::max(minimum_window, 0.2 * static_cast<double>(run_generation_))));
    if (best_history_.size() >= window && window >= 10) {
      const std::size_t part =
          static_cast<std::size_t>(std::ceil(0.3 * static_cast<double>(window)));
      const auto stagnates = [&](const std::vector<double>& values) {
        const auto begin = values.end() - static_cast<std::ptrdiff_t>(window);
        const double early =
            median_of(std::vector<double>(begin, begin + static_cast<std::ptrdiff_t>(part)));
        const double late = median_of(
            std::vector<double>(values.end() - static_cast<std::ptrdiff_t>(part), values.end()));
        return late >= early;
      };
      if (stagnates(best_history_) && stagnates(median_history_)) return StopReason::kStagnation;
    }
  }
  return StopReason::kNone;
}

void CmaEs::end_run(StopReason reason) {
  run_log_.push_back("run " + std::to_string(restarts_) + " (lambda " +
                     std::to_string(parameters_.lambda) + "): " + to_string(reason) + " after " +
                     std::to_string(run_generation_) + " generations");
  if (restarts_ >= options_.max_restarts) {
    if (options_.max_restarts == 0) {
      stop(reason, run_log_.back());
    } else {
      stop(StopReason::kRestartsExhausted, run_log_.back());
    }
    return;
  }
  ++restarts_;
  const auto lambda = static_cast<std::size_t>(
      std::round(static_cast<double>(parameters_.lambda) * options_.population_increase));
  parameters_ = cma_parameters(dimension(), lambda, options_.active);
  Eigen::VectorXd start;
  if (options_.restart_from_start_point && !options_.start_point.empty()) {
    start = normalise(options_.start_point);
  } else {
    motoflex::RandomStream draws = es_stream(options_.seed, generation_, 0, Purpose::kRestart);
    start.resize(static_cast<Eigen::Index>(dimension()));
    for (Eigen::Index i = 0; i < start.size(); ++i) start(i) = draws.uniform();
  }
  start_run(start);
}

void CmaEs::check_budget() {
  if (should_stop() || options_.max_evaluations == 0) return;
  if (evaluations_ + parameters_.lambda > options_.max_evaluations) {
    stop(StopReason::kEvaluationBudget,
         "another generation of " + std::to_string(parameters_.lambda) +
             " would exceed max_evaluations = " + std::to_string(options_.max_evaluations));
  }
}

void CmaEs::tell(const std::vector<double>& fitness) {
  if (should_stop()) throw std::logic_error("CmaEs::tell after the strategy stopped");
  if (pending_x_.empty()) throw std::logic_error("CmaEs::tell without a preceding ask");
  if (fitness.size() != pending_x_.size()) {
    throw std::logic_error("CmaEs::tell: " + std::to_string(fitness.size()) +
                           " fitness values for a batch of " + std::to_string(pending_x_.size()));
  }
  for (std::size_t k = 0; k < fitness.size(); ++k) record_evaluation(pending_x_[k], fitness[k]);

  std::vector<std::size_t> ranking(fitness.size());
  std::iota(ranking.begin(), ranking.end(), std::size_t{0});
  std::stable_sort(ranking.begin(), ranking.end(), [&](std::size_t a, std::size_t b) {
    return ranked_fitness(fitness[a]) < ranked_fitness(fitness[b]);
  });
  best_history_.push_back(ranked_fitness(fitness[ranking.front()]));
  median_history_.push_back(ranked_fitness(fitness[ranking[ranking.size() / 2]]));
  if (best_history_.size() > kMaxHistory) {
    best_history_.erase(best_history_.begin());
    median_history_.erase(median_history_.begin());
  }

  update_distribution(ranking);
  ++generation_;
  ++run_generation_;
  if (run_generation_ - eigen_generation_ >= parameters_.eigen_interval) update_eigensystem();
  pending_x_.clear();

  if (best_fitness_ <= options_.target_fitness) {
    stop(StopReason::kTargetReached, "best fitness reached the target");
    return;
  }
  const StopReason local = run_stop_reason(fitness, ranking);
  if (local != StopReason::kNone) end_run(local);
  check_budget();
}

}  // namespace motoflex_es
