// CmaEs::save_state and CmaEs::load_state: the complete CMA-ES state as JSON.

#include <string>

#include "json_codec.hpp"
#include "motoflex_es/cma_es.hpp"

namespace motoflex_es {

nlohmann::json CmaEs::options_fingerprint() const {
  nlohmann::json fingerprint = {
      {"initial_sigma_relative", detail::double_to_json(options_.initial_sigma_relative)},
      {"population_size", options_.population_size},
      {"active", options_.active},
      {"max_restarts", options_.max_restarts},
      {"population_increase", detail::double_to_json(options_.population_increase)},
      {"eigen_interval", options_.eigen_interval},
      {"seed", options_.seed},
  };
  // Only when set, so that checkpoints written before the option existed still resume.
  if (options_.pooled_negative_tail) fingerprint["pooled_negative_tail"] = true;
  return fingerprint;
}

nlohmann::json CmaEs::save_state() const {
  nlohmann::json state = save_header(options_fingerprint(), options_.seed);
  state["restarts"] = restarts_;
  state["lambda"] = parameters_.lambda;
  state["run_generation"] = run_generation_;
  state["eigen_generation"] = eigen_generation_;
  state["mean"] = detail::eigen_vector_to_json(mean_);
  state["sigma"] = detail::double_to_json(sigma_);
  state["covariance"] = detail::matrix_to_json(covariance_);
  state["eigenvectors"] = detail::matrix_to_json(eigenvectors_);
  state["axis_lengths"] = detail::eigen_vector_to_json(axis_lengths_);
  state["inverse_sqrt_c"] = detail::matrix_to_json(inverse_sqrt_c_);
  state["path_c"] = detail::eigen_vector_to_json(path_c_);
  state["path_sigma"] = detail::eigen_vector_to_json(path_sigma_);
  state["best_history"] = detail::vector_to_json(best_history_);
  state["median_history"] = detail::vector_to_json(median_history_);
  state["run_log"] = run_log_;
  return state;
}

void CmaEs::load_state(const nlohmann::json& state) {
  using detail::member;
  check_identity(state);
  detail::check_same_options(member(state, "options"), options_fingerprint());
  const std::size_t n = dimension();
  load_common(member(state, "common"));
  const nlohmann::json& rng = member(state, "rng");
  if (detail::uint_from_json(member(rng, "seed"), "rng.seed") != options_.seed ||
      detail::uint_from_json(member(rng, "generation"), "rng.generation") != generation_) {
    detail::fail_state("rng keys disagree with the options or the generation");
  }
  restarts_ = detail::uint_from_json(member(state, "restarts"), "restarts");
  const std::uint64_t lambda = detail::uint_from_json(member(state, "lambda"), "lambda");
  if (lambda < 2) detail::fail_state("lambda: must be at least 2");
  parameters_ = cma_parameters(n, lambda, options_.active);
  run_generation_ = detail::uint_from_json(member(state, "run_generation"), "run_generation");
  eigen_generation_ = detail::uint_from_json(member(state, "eigen_generation"), "eigen_generation");
  mean_ = detail::eigen_vector_from_json(member(state, "mean"), "mean", n);
  sigma_ = detail::double_from_json(member(state, "sigma"), "sigma");
  covariance_ = detail::matrix_from_json(member(state, "covariance"), "covariance", n);
  eigenvectors_ = detail::matrix_from_json(member(state, "eigenvectors"), "eigenvectors", n);
  axis_lengths_ = detail::eigen_vector_from_json(member(state, "axis_lengths"), "axis_lengths", n);
  inverse_sqrt_c_ = detail::matrix_from_json(member(state, "inverse_sqrt_c"), "inverse_sqrt_c", n);
  path_c_ = detail::eigen_vector_from_json(member(state, "path_c"), "path_c", n);
  path_sigma_ = detail::eigen_vector_from_json(member(state, "path_sigma"), "path_sigma", n);
  best_history_ =
      detail::vector_from_json(member(state, "best_history"), "best_history", detail::kAnySize);
  median_history_ = detail::vector_from_json(member(state, "median_history"), "median_history",
                                             best_history_.size());
  run_log_.clear();
  const nlohmann::json& log = member(state, "run_log");
  if (!log.is_array()) detail::fail_state("run_log: expected an array");
  for (const auto& line : log) run_log_.push_back(detail::string_from_json(line, "run_log"));
  pending_x_.clear();
}

}  // namespace motoflex_es
