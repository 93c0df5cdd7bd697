#include "motoflex_es/mu_plus_lambda.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "json_codec.hpp"
#include "motoflex_es/random.hpp"

namespace motoflex_es {
namespace {

// Recombines one vector (x or the step sizes) of an offspring from its chosen parents.
// `draws` supplies the discrete choices; its draw order is fixed (one draw per coordinate).
std::vector<double> recombine(const std::vector<const std::vector<double>*>& parents,
                              Recombination type, motoflex::RandomStream& draws) {
  const std::size_t n = parents.front()->size();
  const std::size_t rho = parents.size();
  std::vector<double> child(n);
  switch (type) {
    case Recombination::kNone:
      child = *parents.front();
      break;
    case Recombination::kDiscrete:
      for (std::size_t i = 0; i < n; ++i) child[i] = (*parents[draws.uniform_index(rho)])[i];
      break;
    case Recombination::kIntermediate:
      for (std::size_t i = 0; i < n; ++i) {
        double sum = 0.0;
        for (const auto* parent : parents) sum += (*parent)[i];
        child[i] = sum / static_cast<double>(rho);
      }
      break;
  }
  return child;
}

}  // namespace

const char* to_string(Recombination recombination) {
  switch (recombination) {
    case Recombination::kNone:
      return "none";
    case Recombination::kDiscrete:
      return "discrete";
    case Recombination::kIntermediate:
      return "intermediate";
  }
  return "unknown";
}

bool MuPlusLambdaOptions::is_valid(std::string* why) const {
  const auto fail = [why](const std::string& reason) {
    if (why != nullptr) *why = reason;
    return false;
  };
  if (mu < 1) return fail("mu must be at least 1");
  if (lambda < mu) return fail("lambda must be at least mu");
  if (kappa < 1) return fail("kappa must be at least 1 (1 = comma selection)");
  if (rho < 1 || rho > mu) return fail("rho must be within 1..mu");
  if (!(tau_global >= 0.0) || !std::isfinite(tau_global)) {
    return fail("tau_global must be finite and >= 0 (0 = default)");
  }
  if (!(tau_local >= 0.0) || !std::isfinite(tau_local)) {
    return fail("tau_local must be finite and >= 0 (0 = default)");
  }
  if (!(step_floor_relative > 0.0)) return fail("step_floor_relative must be > 0");
  if (!(step_ceiling_relative >= step_floor_relative) || !std::isfinite(step_ceiling_relative)) {
    return fail("step_ceiling_relative must be finite and >= step_floor_relative");
  }
  if (!(initial_step_relative >= step_floor_relative &&
        initial_step_relative <= step_ceiling_relative)) {
    return fail(
        "initial_step_relative must lie within [step_floor_relative, "
        "step_ceiling_relative]");
  }
  if (std::isnan(target_fitness)) return fail("target_fitness must not be NaN");
  if (!(tol_step_relative >= 0.0)) return fail("tol_step_relative must be >= 0 (0 = off)");
  return true;
}

MuPlusLambda::MuPlusLambda(Bounds bounds, MuPlusLambdaOptions options)
    : Strategy(std::move(bounds)), options_(std::move(options)) {
  std::string why;
  if (!options_.is_valid(&why)) throw std::invalid_argument("MuPlusLambdaOptions: " + why);
  if (!options_.start_point.empty()) {
    if (options_.start_point.size() != dimension()) {
      throw std::invalid_argument("MuPlusLambdaOptions: start_point has " +
                                  std::to_string(options_.start_point.size()) +
                                  " values, the bounds " + std::to_string(dimension()));
    }
    if (!bounds_.contains(options_.start_point)) {
      throw std::invalid_argument("MuPlusLambdaOptions: start_point lies outside the bounds");
    }
  }
  const double n = static_cast<double>(dimension());
  tau_global_ = options_.tau_global > 0.0 ? options_.tau_global : 1.0 / std::sqrt(2.0 * n);
  tau_local_ = options_.tau_local > 0.0 ? options_.tau_local : 1.0 / std::sqrt(2.0 * std::sqrt(n));
}

double MuPlusLambda::clamp_step(double step, std::size_t coordinate) const {
  const double width = bounds_.width(coordinate);
  return std::clamp(step, options_.step_floor_relative * width,
                    options_.step_ceiling_relative * width);
}

std::size_t MuPlusLambda::next_batch_size() const {
  if (should_stop()) return 0;
  return population_.empty() ? options_.mu : options_.lambda;
}

std::vector<Individual> MuPlusLambda::initial_population() const {
  const std::size_t n = dimension();
  std::vector<Individual> initial(options_.mu);
  for (std::size_t k = 0; k < options_.mu; ++k) {
    Individual& individual = initial[k];
    individual.x.resize(n);
    individual.step.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      individual.step[i] = clamp_step(options_.initial_step_relative * bounds_.width(i), i);
    }
    motoflex::RandomStream draws =
        es_stream(options_.seed, generation_, k, Purpose::kInitialPopulation);
    for (std::size_t i = 0; i < n; ++i) {
      const double lower = bounds_.lower[i];
      const double upper = bounds_.upper[i];
      if (options_.start_point.empty()) {
        individual.x[i] = std::min(upper, lower + bounds_.width(i) * draws.uniform());
      } else if (k == 0) {
        individual.x[i] = options_.start_point[i];
      } else {
        individual.x[i] = reflect_into_bounds(
            options_.start_point[i] + individual.step[i] * draws.normal_libm(), lower, upper);
      }
    }
  }
  return initial;
}

Individual MuPlusLambda::make_offspring(std::uint64_t index) const {
  const std::size_t n = dimension();
  const std::size_t mu = population_.size();

  // ρ distinct parents by a partial Fisher–Yates shuffle of the parent indices.
  motoflex::RandomStream parent_draws =
      es_stream(options_.seed, generation_, index, Purpose::kParentChoice);
  std::vector<std::size_t> order(mu);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<const std::vector<double>*> parent_x;
  std::vector<const std::vector<double>*> parent_step;
  for (std::size_t j = 0; j < options_.rho; ++j) {
    std::swap(order[j], order[j + parent_draws.uniform_index(mu - j)]);
    parent_x.push_back(&population_[order[j]].x);
    parent_step.push_back(&population_[order[j]].step);
  }

  motoflex::RandomStream recombination_draws =
      es_stream(options_.seed, generation_, index, Purpose::kRecombination);
  Individual child;
  child.x = recombine(parent_x, options_.object_recombination, recombination_draws);
  child.step = recombine(parent_step, options_.step_recombination, recombination_draws);

  // Step sizes mutate first and the new ones move x, so selection judges a step size by the
  // step it actually made (Schwefel 1995; DEAP's mutESLogNormal does the same).
  motoflex::RandomStream step_draws =
      es_stream(options_.seed, generation_, index, Purpose::kStepSizeMutation);
  const double global = tau_global_ * step_draws.normal_libm();
  for (std::size_t i = 0; i < n; ++i) {
    child.step[i] =
        clamp_step(child.step[i] * std::exp(global + tau_local_ * step_draws.normal_libm()), i);
  }
  motoflex::RandomStream object_draws =
      es_stream(options_.seed, generation_, index, Purpose::kObjectMutation);
  for (std::size_t i = 0; i < n; ++i) {
    child.x[i] = reflect_into_bounds(child.x[i] + child.step[i] * object_draws.normal_libm(),
                                     bounds_.lower[i], bounds_.upper[i]);
  }
  child.age = 0;
  return child;
}

std::vector<std::vector<double>> MuPlusLambda::ask() {
  pending_.clear();
  if (should_stop()) return {};
  if (population_.empty()) {
    pending_ = initial_population();
  } else {
    pending_.reserve(options_.lambda);
    for (std::size_t k = 0; k < options_.lambda; ++k) pending_.push_back(make_offspring(k));
  }
  std::vector<std::vector<double>> xs;
  xs.reserve(pending_.size());
  for (const Individual& individual : pending_) xs.push_back(individual.x);
  return xs;
}

std::vector<double> MuPlusLambda::competing_fitness() const {
  std::vector<double> competing;
  for (const Individual& parent : population_) {
    if (parent.age < options_.kappa) competing.push_back(parent.fitness);
  }
  return competing;
}

double MuPlusLambda::selection_threshold() const {
  if (population_.empty()) return std::numeric_limits<double>::infinity();
  std::vector<double> competing = competing_fitness();
  if (competing.size() < options_.mu) return std::numeric_limits<double>::infinity();
  std::nth_element(competing.begin(), competing.begin() + (options_.mu - 1), competing.end());
  return competing[options_.mu - 1];
}

std::size_t MuPlusLambda::exact_ranks_needed() const {
  // The initial population is the whole first batch and becomes the parents as it is.
  if (population_.empty() || !options_.racing) return next_batch_size();
  return std::min(options_.mu, next_batch_size());
}

std::size_t MuPlusLambda::race_chunk(std::size_t) const {
  return options_.race_chunk > 0 ? options_.race_chunk : exact_ranks_needed();
}

double MuPlusLambda::race_threshold(const std::vector<double>& exact_sorted) const {
  if (population_.empty()) return std::numeric_limits<double>::infinity();
  // An offspring at or above the μ-th best of this pool lands behind μ individuals that win
  // every tie against it (parents, and offspring of lower index), so it is never selected.
  std::vector<double> pool = competing_fitness();
  pool.insert(pool.end(), exact_sorted.begin(), exact_sorted.end());
  if (pool.size() < options_.mu) return std::numeric_limits<double>::infinity();
  std::nth_element(pool.begin(), pool.begin() + (options_.mu - 1), pool.end());
  return pool[options_.mu - 1];
}

void MuPlusLambda::select(const std::vector<double>& fitness) {
  for (std::size_t k = 0; k < pending_.size(); ++k) {
    pending_[k].fitness = ranked_fitness(fitness[k]);
  }
  // The pool, parents first: a stable sort then prefers a parent over an offspring of equal
  // fitness, which is what makes a threshold-stopped offspring provably irrelevant.
  std::vector<Individual> pool;
  pool.reserve(population_.size() + pending_.size());
  for (Individual& parent : population_) {
    if (parent.age < options_.kappa) pool.push_back(std::move(parent));  // Schwefel & Rudolph's κ
  }
  for (Individual& child : pending_) pool.push_back(std::move(child));
  std::stable_sort(pool.begin(), pool.end(),
                   [](const Individual& a, const Individual& b) { return a.fitness < b.fitness; });
  pool.resize(std::min(pool.size(), options_.mu));
  for (Individual& survivor : pool) ++survivor.age;  // offspring: 0 → 1
  population_ = std::move(pool);
}

void MuPlusLambda::tell(const std::vector<double>& fitness) {
  if (should_stop()) throw std::logic_error("MuPlusLambda::tell after the strategy stopped");
  if (pending_.empty()) throw std::logic_error("MuPlusLambda::tell without a preceding ask");
  if (fitness.size() != pending_.size()) {
    throw std::logic_error("MuPlusLambda::tell: " + std::to_string(fitness.size()) +
                           " fitness values for a batch of " + std::to_string(pending_.size()));
  }
  const double best_before = best_fitness_;
  for (std::size_t k = 0; k < pending_.size(); ++k) record_evaluation(pending_[k].x, fitness[k]);
  select(fitness);
  pending_.clear();
  ++generation_;
  if (best_fitness_ < best_before) last_improvement_generation_ = generation_;
  check_stop_criteria();
}

void MuPlusLambda::check_stop_criteria() {
  if (best_fitness_ <= options_.target_fitness) {
    stop(StopReason::kTargetReached, "best fitness reached the target");
    return;
  }
  if (options_.max_stagnation_generations > 0 &&
      generation_ - last_improvement_generation_ >= options_.max_stagnation_generations) {
    stop(StopReason::kStagnation, "no improvement in " +
                                      std::to_string(options_.max_stagnation_generations) +
                                      " generations");
    return;
  }
  if (options_.tol_step_relative > 0.0) {
    for (const Individual& parent : population_) {
      for (std::size_t i = 0; i < dimension(); ++i) {
        if (parent.step[i] >= options_.tol_step_relative * bounds_.width(i)) return;
      }
    }
    stop(StopReason::kTolX, "every step size is below tol_step_relative of its bound width");
  }
}

nlohmann::json MuPlusLambda::options_fingerprint() const {
  // Everything that changes what a generation does; a state may only continue under these.
  return {
      {"mu", options_.mu},
      {"lambda", options_.lambda},
      {"kappa", options_.kappa},
      {"rho", options_.rho},
      {"object_recombination", to_string(options_.object_recombination)},
      {"step_recombination", to_string(options_.step_recombination)},
      {"tau_global", detail::double_to_json(tau_global_)},
      {"tau_local", detail::double_to_json(tau_local_)},
      {"step_floor_relative", detail::double_to_json(options_.step_floor_relative)},
      {"step_ceiling_relative", detail::double_to_json(options_.step_ceiling_relative)},
      {"seed", options_.seed},
  };
}

nlohmann::json MuPlusLambda::save_state() const {
  nlohmann::json population = nlohmann::json::array();
  for (const Individual& individual : population_) {
    population.push_back({
        {"x", detail::vector_to_json(individual.x)},
        {"step", detail::vector_to_json(individual.step)},
        {"fitness", detail::double_to_json(individual.fitness)},
        {"age", individual.age},
    });
  }
  nlohmann::json state = save_header(options_fingerprint(), options_.seed);
  state["last_improvement_generation"] = last_improvement_generation_;
  state["population"] = population;
  return state;
}

void MuPlusLambda::load_state(const nlohmann::json& state) {
  using detail::member;
  check_identity(state);
  detail::check_same_options(member(state, "options"), options_fingerprint());
  load_common(member(state, "common"));
  const nlohmann::json& rng = member(state, "rng");
  if (detail::uint_from_json(member(rng, "seed"), "rng.seed") != options_.seed ||
      detail::uint_from_json(member(rng, "generation"), "rng.generation") != generation_) {
    detail::fail_state("rng keys disagree with the options or the generation");
  }
  last_improvement_generation_ = detail::uint_from_json(
      member(state, "last_improvement_generation"), "last_improvement_generation");
  const nlohmann::json& population = member(state, "population");
  if (!population.is_array()) detail::fail_state("population: expected an array");
  if (!population.empty() && population.size() != options_.mu) {
    detail::fail_state("population: expected " + std::to_string(options_.mu) + " individuals");
  }
  std::vector<Individual> loaded;
  for (std::size_t k = 0; k < population.size(); ++k) {
    const std::string where = "population[" + std::to_string(k) + "].";
    const nlohmann::json& entry = population[k];
    Individual individual;
    individual.x = detail::vector_from_json(member(entry, "x"), where + "x", dimension());
    individual.step = detail::vector_from_json(member(entry, "step"), where + "step", dimension());
    individual.fitness = detail::double_from_json(member(entry, "fitness"), where + "fitness");
    individual.age = detail::uint_from_json(member(entry, "age"), where + "age");
    if (individual.age < 1 || individual.age > options_.kappa) {
      detail::fail_state(where + "age: outside 1..kappa");
    }
    loaded.push_back(std::move(individual));
  }
  population_ = std::move(loaded);
  pending_.clear();
}

}  // namespace motoflex_es
