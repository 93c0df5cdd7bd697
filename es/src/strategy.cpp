#include "motoflex_es/strategy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "json_codec.hpp"

namespace motoflex_es {
namespace {

struct StopReasonName {
  StopReason reason;
  const char* name;
};
constexpr StopReasonName kStopReasonNames[] = {
    {StopReason::kNone, "none"},
    {StopReason::kTargetReached, "target_reached"},
    {StopReason::kTolX, "tol_x"},
    {StopReason::kTolFun, "tol_fun"},
    {StopReason::kStagnation, "stagnation"},
    {StopReason::kMaxIterations, "max_iterations"},
    {StopReason::kConditionNumber, "condition_number"},
    {StopReason::kNoEffect, "no_effect"},
    {StopReason::kRestartsExhausted, "restarts_exhausted"},
    {StopReason::kEvaluationBudget, "evaluation_budget"},
    {StopReason::kOptimizerConverged, "optimizer_converged"},
    {StopReason::kOptimizerFailed, "optimizer_failed"},
    {StopReason::kTolStall, "tol_stall"},
};

}  // namespace

const char* to_string(StopReason reason) {
  for (const auto& entry : kStopReasonNames) {
    if (entry.reason == reason) return entry.name;
  }
  return "unknown";
}

StopReason stop_reason_from_string(std::string_view text) {
  for (const auto& entry : kStopReasonNames) {
    if (text == entry.name) return entry.reason;
  }
  detail::fail_state("unknown stop reason '" + std::string(text) + "'");
}

Strategy::Strategy(Bounds bounds) : bounds_(std::move(bounds)) {
  std::string why;
  if (!bounds_.is_valid(&why)) throw std::invalid_argument(why);
}

double Strategy::race_threshold(const std::vector<double>& exact_sorted) const {
  const std::size_t exact = exact_ranks_needed();
  double threshold = selection_threshold();
  if (exact > 0 && exact_sorted.size() >= exact && std::isfinite(exact_sorted[exact - 1])) {
    threshold = std::min(threshold, std::nextafter(exact_sorted[exact - 1],
                                                   std::numeric_limits<double>::infinity()));
  }
  return threshold;
}

void Strategy::record_evaluation(const std::vector<double>& x, double fitness) {
  ++evaluations_;
  const double ranked = ranked_fitness(fitness);
  if (ranked < best_fitness_ || best_x_.empty()) {
    best_fitness_ = ranked;
    best_x_ = x;
  }
}

void Strategy::record_incumbent(const std::vector<double>& x, double fitness) {
  if (x.size() != dimension() || !bounds_.contains(x)) {
    throw std::invalid_argument("record_incumbent: the point has " + std::to_string(x.size()) +
                                " coordinates for dimension " + std::to_string(dimension()) +
                                " or lies outside the bounds");
  }
  record_evaluation(x, fitness);
}

void Strategy::stop(StopReason reason, std::string detail) {
  stop_reason_ = reason;
  stop_detail_ = std::move(detail);
}

nlohmann::json Strategy::save_common() const {
  return {
      {"generation", generation_},
      {"evaluations", evaluations_},
      {"best_x", detail::vector_to_json(best_x_)},
      {"best_fitness", detail::double_to_json(best_fitness_)},
      {"stop_reason", to_string(stop_reason_)},
      {"stop_detail", stop_detail_},
  };
}

nlohmann::json Strategy::save_header(nlohmann::json options, std::uint64_t seed) const {
  return {
      {"strategy", name()},
      {"dimension", dimension()},
      {"options", std::move(options)},
      {"common", save_common()},
      {"rng", {{"seed", seed}, {"generation", generation_}}},
  };
}

void Strategy::load_common(const nlohmann::json& common) {
  using detail::member;
  generation_ = detail::uint_from_json(member(common, "generation"), "generation");
  evaluations_ = detail::uint_from_json(member(common, "evaluations"), "evaluations");
  const nlohmann::json& best_x = member(common, "best_x");
  best_x_ = detail::vector_from_json(best_x, "best_x", best_x.empty() ? 0 : dimension());
  best_fitness_ = detail::double_from_json(member(common, "best_fitness"), "best_fitness");
  stop_reason_ = stop_reason_from_string(
      detail::string_from_json(member(common, "stop_reason"), "stop_reason"));
  stop_detail_ = detail::string_from_json(member(common, "stop_detail"), "stop_detail");
}

void Strategy::check_identity(const nlohmann::json& state) const {
  const std::string saved = detail::string_from_json(detail::member(state, "strategy"), "strategy");
  if (saved != name()) {
    detail::fail_state("saved by strategy '" + saved + "', cannot be loaded into '" + name() + "'");
  }
  const std::uint64_t saved_dimension =
      detail::uint_from_json(detail::member(state, "dimension"), "dimension");
  if (saved_dimension != dimension()) {
    detail::fail_state("saved with dimension " + std::to_string(saved_dimension) +
                       ", this problem has dimension " + std::to_string(dimension()));
  }
}

}  // namespace motoflex_es
