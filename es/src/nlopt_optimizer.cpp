#include "motoflex_es/nlopt_optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <stdexcept>
#include <utility>

#include "json_codec.hpp"
#include "motoflex_es/checkpoint.hpp"

namespace motoflex_es {
namespace {

nlopt::algorithm nlopt_algorithm(NloptAlgorithm algorithm) {
  switch (algorithm) {
    case NloptAlgorithm::kBobyqa:
      return nlopt::LN_BOBYQA;
    case NloptAlgorithm::kSbplx:
      return nlopt::LN_SBPLX;
    case NloptAlgorithm::kCrs2Lm:
      return nlopt::GN_CRS2_LM;
    case NloptAlgorithm::kIsres:
      return nlopt::GN_ISRES;
    case NloptAlgorithm::kEsch:
      return nlopt::GN_ESCH;
  }
  throw std::invalid_argument("unknown NLopt algorithm");
}

const char* result_name(nlopt::result result) {
  switch (result) {
    case nlopt::SUCCESS:
      return "NLopt: success";
    case nlopt::STOPVAL_REACHED:
      return "NLopt: stopval (target fitness) reached";
    case nlopt::FTOL_REACHED:
      return "NLopt: ftol reached";
    case nlopt::XTOL_REACHED:
      return "NLopt: xtol reached";
    case nlopt::MAXEVAL_REACHED:
      return "NLopt: maxeval reached";
    case nlopt::MAXTIME_REACHED:
      return "NLopt: maxtime reached";
    default:
      return "NLopt: finished";
  }
}

}  // namespace

const char* to_string(NloptAlgorithm algorithm) {
  switch (algorithm) {
    case NloptAlgorithm::kBobyqa:
      return "bobyqa";
    case NloptAlgorithm::kSbplx:
      return "sbplx";
    case NloptAlgorithm::kCrs2Lm:
      return "crs2_lm";
    case NloptAlgorithm::kIsres:
      return "isres";
    case NloptAlgorithm::kEsch:
      return "esch";
  }
  return "unknown";
}

bool is_local(NloptAlgorithm algorithm) {
  return algorithm == NloptAlgorithm::kBobyqa || algorithm == NloptAlgorithm::kSbplx;
}

bool NloptOptions::is_valid(std::string* why) const {
  const auto fail = [why](const std::string& reason) {
    if (why != nullptr) *why = reason;
    return false;
  };
  if (!is_local(algorithm) && max_evaluations == 0) {
    return fail(std::string("max_evaluations is required for the global algorithm ") +
                to_string(algorithm) + " (NLopt would run indefinitely)");
  }
  if (!(initial_step_relative > 0.0) || !std::isfinite(initial_step_relative)) {
    return fail("initial_step_relative must be finite and > 0");
  }
  if (!(xtol_relative_to_width >= 0.0)) return fail("xtol_relative_to_width must be >= 0");
  if (!(ftol_rel >= 0.0) || !(ftol_abs >= 0.0)) return fail("ftol_rel and ftol_abs must be >= 0");
  if (std::isnan(target_fitness)) return fail("target_fitness must not be NaN");
  return true;
}

NloptOptimizer::NloptOptimizer(Bounds bounds, NloptOptions options)
    : Strategy(std::move(bounds)), options_(std::move(options)) {
  std::string why;
  if (!options_.is_valid(&why)) throw std::invalid_argument("NloptOptions: " + why);
  if (options_.start_point.empty()) {
    options_.start_point.resize(dimension());
    for (std::size_t i = 0; i < dimension(); ++i) {
      options_.start_point[i] = bounds_.lower[i] + 0.5 * bounds_.width(i);
    }
  }
  if (options_.start_point.size() != dimension() || !bounds_.contains(options_.start_point)) {
    throw std::invalid_argument("NloptOptions: start_point must have " +
                                std::to_string(dimension()) + " values within the bounds");
  }
}

NloptOptimizer::~NloptOptimizer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancel_ = true;
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
}

std::string NloptOptimizer::name() const {
  return std::string("nlopt_") + to_string(options_.algorithm);
}

void NloptOptimizer::run_nlopt() {
  StopReason reason = StopReason::kOptimizerConverged;
  std::string detail;
  try {
    nlopt::srand(static_cast<unsigned long>(options_.seed));
    const unsigned n = static_cast<unsigned>(dimension());
    nlopt::opt optimizer(nlopt_algorithm(options_.algorithm), n);
    optimizer.set_lower_bounds(bounds_.lower);
    optimizer.set_upper_bounds(bounds_.upper);
    optimizer.set_min_objective(&NloptOptimizer::objective, this);
    std::vector<double> step(n), xtol(n);
    for (unsigned i = 0; i < n; ++i) {
      step[i] = options_.initial_step_relative * bounds_.width(i);
      xtol[i] = options_.xtol_relative_to_width * bounds_.width(i);
    }
    if (is_local(options_.algorithm)) optimizer.set_initial_step(step);
    if (options_.population > 0) {
      optimizer.set_population(static_cast<unsigned>(options_.population));
    }
    if (options_.max_evaluations > 0) {
      optimizer.set_maxeval(static_cast<int>(std::min<std::uint64_t>(
          options_.max_evaluations, static_cast<std::uint64_t>(std::numeric_limits<int>::max()))));
    }
    optimizer.set_xtol_abs(xtol);
    optimizer.set_ftol_rel(options_.ftol_rel);
    optimizer.set_ftol_abs(options_.ftol_abs);
    if (std::isfinite(options_.target_fitness)) optimizer.set_stopval(options_.target_fitness);
    std::vector<double> x = options_.start_point;
    double f = 0.0;
    const nlopt::result result = optimizer.optimize(x, f);
    detail = result_name(result);
    // NLopt counts hitting its evaluation limit or the stop value as success; the caller
    // needs to know the search was cut off rather than converged.
    if (result == nlopt::MAXEVAL_REACHED) reason = StopReason::kEvaluationBudget;
    if (result == nlopt::STOPVAL_REACHED) reason = StopReason::kTargetReached;
  } catch (const nlopt::forced_stop&) {
    reason = StopReason::kOptimizerFailed;
    detail = "NLopt: stopped by the caller";
  } catch (const nlopt::roundoff_limited&) {
    detail = "NLopt: roundoff limited (no further progress possible)";
  } catch (const std::exception& error) {
    reason = StopReason::kOptimizerFailed;
    detail = std::string("NLopt: ") + error.what();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finish_reason_ = reason;
    finish_detail_ = std::move(detail);
    phase_ = Phase::kFinished;
  }
  changed_.notify_all();
}

double NloptOptimizer::objective(unsigned n, const double* x, double* /*gradient*/, void* self) {
  return static_cast<NloptOptimizer*>(self)->hand_over(x, n);
}

double NloptOptimizer::hand_over(const double* x, unsigned n) {
  std::unique_lock<std::mutex> lock(mutex_);
  point_.assign(x, x + n);
  phase_ = Phase::kPointReady;
  changed_.notify_all();
  changed_.wait(lock, [this] { return phase_ == Phase::kValueReady || cancel_; });
  // NLopt's C++ wrapper turns this into a clean stop of optimize().
  if (cancel_) throw nlopt::forced_stop();
  phase_ = Phase::kRunning;
  return value_;
}

void NloptOptimizer::wait_for_point(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock,
                [this] { return phase_ == Phase::kPointReady || phase_ == Phase::kFinished; });
  if (phase_ == Phase::kFinished && !should_stop()) stop(finish_reason_, finish_detail_);
}

std::vector<std::vector<double>> NloptOptimizer::ask() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (phase_ == Phase::kNotStarted) {
    phase_ = Phase::kRunning;
    worker_ = std::thread(&NloptOptimizer::run_nlopt, this);
  }
  wait_for_point(lock);
  if (should_stop()) return {};
  // NLopt keeps to the bounds up to rounding; the problem is promised points within them.
  std::vector<double> x = point_;
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = std::clamp(x[i], bounds_.lower[i], bounds_.upper[i]);
  }
  return {x};
}

void NloptOptimizer::tell(const std::vector<double>& fitness) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (should_stop()) throw std::logic_error("NloptOptimizer::tell after the strategy stopped");
  if (phase_ != Phase::kPointReady) {
    throw std::logic_error("NloptOptimizer::tell without a preceding ask");
  }
  if (fitness.size() != 1) {
    throw std::logic_error("NloptOptimizer::tell: batches have exactly one point");
  }
  std::vector<double> x = point_;
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = std::clamp(x[i], bounds_.lower[i], bounds_.upper[i]);
  }
  record_evaluation(x, fitness[0]);
  ++generation_;
  value_ = ranked_fitness(fitness[0]);
  phase_ = Phase::kValueReady;
  changed_.notify_all();
  wait_for_point(lock);
}

nlohmann::json NloptOptimizer::save_state() const {
  return {
      {"strategy", name()},
      {"dimension", dimension()},
      {"resumable", false},
      {"common", save_common()},
  };
}

void NloptOptimizer::load_state(const nlohmann::json& /*state*/) {
  throw CheckpointError("strategy state: " + name() +
                        " cannot resume (NLopt keeps its state internally); restart it from the "
                        "best point instead");
}

}  // namespace motoflex_es
