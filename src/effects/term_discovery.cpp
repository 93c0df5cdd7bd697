#include "motoflex/effects/term_discovery.hpp"

#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <span>

#include "linearised_residual.hpp"
#include "motoflex/model/torque_terms.hpp"
#include "support_refinement.hpp"

namespace motoflex {
namespace {

using detail::Residual;

constexpr double kTermProbeFraction = 0.05;  // probe step of a coefficient, of its bound
constexpr double kRidge = 1e-6;              // on the standardised normal equations
// Thresholds of the STLSQ path, as fractions of the largest standardised term coefficient.
constexpr double kThresholds[] = {0.7, 0.5, 0.35, 0.25, 0.15, 0.1, 0.05, 0.02};
constexpr int kStlsqSweeps = 10;
// A proposal must lower the training fitness by this fraction (checked with rollouts).
constexpr double kMinTrainingGain = 0.05;
constexpr double kLineSearch[] = {0.5, 1.0, 2.0};
constexpr int kRefineIterations = 4;  // Levenberg–Marquardt iterations of a screened support
// Supports checked by a line search on rollouts, the best by linearised ΔBIC first (at least
// `screen`): every single candidate is a support, and on a walking robot (ten joints × 23 terms)
// a line search of each of them, six rollouts of every training log, took hours.
// A one-joint robot has at most 23 single-term supports + 2 forward + 8 STLSQ ones (two terms): all
// of them are searched there, as before this cap.
constexpr std::size_t kMaxLineSearched = 40;

// One candidate column: a term on one joint, its response to a probe step of `step_coef`.
struct Candidate {
  const TorqueTerm* term = nullptr;
  std::size_t joint = 0;  // actuator index
  std::string parameter;
  double current = 0.0, step_coef = 0.0;
  std::size_t field = 0;  // index into the probe responses (one per term)
};

// The Gram matrix of [fit Jacobian | candidates] and their products with the residual.
struct Normal {
  Eigen::MatrixXd gram;
  Eigen::VectorXd rhs;
  std::size_t fit_columns = 0;
};

// Column value of `col` at (case c, row) for channel i; fit columns are on every channel, a
// candidate's on its joint's channel and a share of the IMU channels.
struct ColumnSource {
  const detail::FitJacobian* jacobian;
  const std::vector<std::vector<std::vector<double>>>* fields;
  const std::vector<Candidate>* candidates;
  std::size_t joints = 0;
  double value(std::size_t col, std::size_t c, std::size_t row, std::size_t channel) const {
    const std::size_t p = jacobian->columns.size();
    if (col < p) return jacobian->columns[col][c][row];
    const Candidate& cand = (*candidates)[col - p];
    double scale = 0.0;
    if (channel == cand.joint) scale = 1.0;
    if (channel >= joints) scale = 1.0 / static_cast<double>(joints);
    return scale == 0.0 ? 0.0 : scale * (*fields)[cand.field][c][row];
  }
};

Normal normal_equations(const ColumnSource& source, std::size_t columns, const Residual& residual) {
  detail::NormalEquations ne = detail::normal_equations(
      residual, columns,
      [&source](std::size_t col, std::size_t c, std::size_t row, std::size_t channel) {
        return source.value(col, c, row, channel);
      });
  return {std::move(ne.gram), std::move(ne.rhs), source.jacobian->columns.size()};
}

// Least squares on the fit columns plus the candidates in `active` (indices into candidates),
// in standardised units (each column scaled to unit norm). Returns the coefficients (fit
// columns first) in the original units and the residual sum of squares.
Eigen::VectorXd solve_subset(const Normal& n, const std::vector<std::size_t>& active, double rr,
                             double* rss) {
  std::vector<std::size_t> cols;
  for (std::size_t a = 0; a < n.fit_columns; ++a) cols.push_back(a);
  for (const std::size_t a : active) cols.push_back(n.fit_columns + a);
  const Eigen::Index k = static_cast<Eigen::Index>(cols.size());
  if (k == 0) {
    *rss = rr;
    return Eigen::VectorXd();
  }
  Eigen::MatrixXd g(k, k);
  Eigen::VectorXd b(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    b(i) = n.rhs(cols[i]);
    for (Eigen::Index j = 0; j < k; ++j) g(i, j) = n.gram(cols[i], cols[j]);
  }
  double reduction = 0.0;
  const Eigen::VectorXd beta = detail::standardised_solve(g, b, kRidge, &reduction);
  *rss = rr - reduction;
  return beta;
}

// Sequentially thresholded least squares from the full candidate set: drop the candidates
// whose standardised coefficient is below `threshold` × the largest, refit, repeat.
std::vector<std::size_t> stlsq(const Normal& n, std::size_t candidates, double threshold,
                               double rr) {
  std::vector<std::size_t> active(candidates);
  for (std::size_t a = 0; a < candidates; ++a) active[a] = a;
  for (int sweep = 0; sweep < kStlsqSweeps && !active.empty(); ++sweep) {
    double rss = 0.0;
    const Eigen::VectorXd beta = solve_subset(n, active, rr, &rss);
    std::vector<double> size(active.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < active.size(); ++i) {
      const std::size_t col = n.fit_columns + active[i];
      size[i] = std::abs(beta(static_cast<Eigen::Index>(n.fit_columns + i))) *
                std::sqrt(n.gram(col, col));
      largest = std::max(largest, size[i]);
    }
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < active.size(); ++i) {
      if (size[i] >= threshold * largest) kept.push_back(active[i]);
    }
    if (kept.size() == active.size()) break;
    active = std::move(kept);
  }
  return active;
}

std::vector<Candidate> candidates_of(const FitConfig& config, const ParameterSet& current) {
  std::set<std::string> free_names;
  for (const auto& p : config.free_parameters)
    free_names.insert(p.targets.begin(), p.targets.end());
  const RobotModel& model = config.train->model();
  std::vector<Candidate> out;
  std::size_t field = 0;
  for (const TorqueTerm& term : torque_terms()) {
    bool any = false;
    for (std::size_t j = 0; j < model.actuators.size(); ++j) {
      const std::string name = term_parameter(model.actuators[j].name, term.leaf);
      if (free_names.count(name) != 0 || !model.parameters.find(name)) continue;
      out.push_back({&term, j, name, current.get(name), kTermProbeFraction * term.bound, field});
      any = true;
    }
    if (any) ++field;
  }
  return out;
}

}  // namespace

namespace {

// The responses of the simulated channels to a probe step of each term's coefficients (all
// joints of a term at once), in term (field) order.
std::vector<std::vector<std::vector<double>>> term_responses(
    const FitConfig& config, const ParameterSet& current, const std::vector<Candidate>& candidates,
    const Residual& residual, int threads) {
  std::size_t fields = 0;
  for (const Candidate& c : candidates) fields = std::max(fields, c.field + 1);
  std::vector<std::vector<std::vector<double>>> out(fields);
  const int n = static_cast<int>(fields);
#pragma omp parallel for schedule(dynamic) num_threads(std::max(threads, 1))
  for (int f = 0; f < n; ++f) {
    ParameterSet moved = current;
    for (const Candidate& c : candidates) {
      if (c.field == static_cast<std::size_t>(f)) moved.set(c.parameter, c.current + c.step_coef);
    }
    out[f] = detail::response(*config.train, moved, residual);
  }
  return out;
}

// Forward selection: the supports of 1..max_terms candidates, each adding the candidate that
// lowers the RSS most (robust where the full least squares of many collinear candidates, which
// STLSQ starts from, is not).
std::vector<std::vector<std::size_t>> forward_supports(const Normal& n, std::size_t candidates,
                                                       double rr, std::size_t max_terms) {
  std::vector<std::vector<std::size_t>> out;
  std::vector<std::size_t> active;
  while (active.size() < std::min(max_terms, candidates)) {
    double best_rss = std::numeric_limits<double>::infinity();
    std::size_t best = candidates;
    for (std::size_t a = 0; a < candidates; ++a) {
      if (std::find(active.begin(), active.end(), a) != active.end()) continue;
      std::vector<std::size_t> trial = active;
      trial.push_back(a);
      double rss = 0.0;
      solve_subset(n, trial, rr, &rss);
      if (rss < best_rss) best_rss = rss, best = a;
    }
    active.push_back(best);
    std::vector<std::size_t> sorted = active;
    std::sort(sorted.begin(), sorted.end());
    out.push_back(sorted);
  }
  return out;
}

struct Support {
  std::vector<std::size_t> active;
  double rss = 0.0, delta_bic = 0.0;
  Eigen::VectorXd beta;
};

// The supports of 1..max_terms candidates on the forward and the STLSQ paths, and every single
// candidate, by ΔBIC (best first). With a smooth residual N_eff is a handful of samples and the
// ΔBIC a weak screen: the rollouts (proposal_fitness) and the refit's validation decide.
std::vector<Support> supported(const Normal& n, std::size_t candidates, double rr, double rss_base,
                               double n_eff, std::size_t max_terms) {
  std::set<std::vector<std::size_t>> seen;
  std::vector<std::vector<std::size_t>> supports = forward_supports(n, candidates, rr, max_terms);
  for (const double threshold : kThresholds) {
    supports.push_back(stlsq(n, candidates, threshold, rr));
  }
  for (std::size_t a = 0; a < candidates; ++a) supports.push_back({a});
  std::vector<Support> out;
  for (const std::vector<std::size_t>& active : supports) {
    if (active.empty() || active.size() > max_terms || !seen.insert(active).second) continue;
    Support s;
    s.active = active;
    s.beta = solve_subset(n, active, rr, &s.rss);
    const double rss1 = std::clamp(s.rss, 1e-300, rss_base);
    s.delta_bic = n_eff * std::log(rss1 / std::max(rss_base, 1e-300)) +
                  static_cast<double>(active.size()) * std::log(n_eff);
    out.push_back(std::move(s));
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Support& a, const Support& b) { return a.delta_bic < b.delta_bic; });
  return out;
}

// What a support proposes: its terms at the linearised estimate, and the fit's parameters
// after the same step.
TermDiscovery proposal(const Support& best, const std::vector<Candidate>& candidates,
                       const Normal& n, const detail::FitJacobian& jacobian,
                       const FitConfig& config) {
  TermDiscovery out;
  out.delta_bic = best.delta_bic;
  for (std::size_t i = 0; i < best.active.size(); ++i) {
    const Candidate& c = candidates[best.active[i]];
    const double beta = best.beta(static_cast<Eigen::Index>(n.fit_columns + i));
    const double value = std::clamp(c.current + beta * c.step_coef, -c.term->bound, c.term->bound);
    out.terms.push_back(
        {c.parameter, config.train->model().actuators[c.joint].name, c.term->formula, value});
    out.estimate.emplace_back(c.parameter, value);
  }
  const ParameterSpace& space = *config.space;
  for (std::size_t i = 0; i < n.fit_columns; ++i) {
    const detail::Direction& d = jacobian.directions[i];
    const double coordinate =
        std::clamp(d.current + best.beta(static_cast<Eigen::Index>(i)) * d.step, d.lower, d.upper);
    out.fit_start.emplace_back(space.free_parameters()[i].name, space.to_model(i, coordinate));
  }
  return out;
}

// `p` scaled from `current` by `scale`: each term coefficient and (with `move_fit`) each of the
// fit's parameters moved `scale` times its proposed step, then held inside its bounds (the
// terms' ±bound, the fit space's [lower, upper]). A step of 2× from a parameter near a bound
// would otherwise leave it: a sensor delay fitted at 0.4 ms with a proposed start of 0 became
// −0.4 ms, which the encoder rejects. Without `move_fit` the fit start is cleared (the refit
// then starts from the fit's own values).
TermDiscovery scaled_proposal(const TermDiscovery& p, const FitConfig& config,
                              const ParameterSet& current, bool move_fit, double scale) {
  TermDiscovery out = p;
  const auto scaled_term = [&](const std::string& name, double value) {
    const TorqueTerm* term = find_torque_term(name);
    const double bound = term != nullptr ? term->bound : std::numeric_limits<double>::infinity();
    return std::clamp(current.get(name) + scale * (value - current.get(name)), -bound, bound);
  };
  for (auto& [name, value] : out.estimate) value = scaled_term(name, value);
  for (auto& term : out.terms) term.estimate = scaled_term(term.parameter, term.estimate);
  if (!move_fit) {
    out.fit_start.clear();
    return out;
  }
  const ParameterSpace& space = *config.space;
  for (std::size_t i = 0; i < out.fit_start.size(); ++i) {
    const double from = current.get(space.free_parameters()[i].targets.front());
    const double a = space.to_model(i, space.lower()[i]);
    const double b = space.to_model(i, space.upper()[i]);
    out.fit_start[i].second =
        std::clamp(from + scale * (out.fit_start[i].second - from), std::min(a, b), std::max(a, b));
  }
  return out;
}

// The training fitness of a proposal (already scaled) with its terms and fit start set on
// `current`: the nonlinear check of the linearised choice. Where collinear candidates fit the
// linearised residual about equally, the one the rollouts confirm wins. A set the model
// rejects scores infinity, as a rejected candidate does in the fit itself.
double proposal_fitness(const TermDiscovery& p, const FitConfig& config,
                        const ParameterSet& current) {
  ParameterSet trial = current;
  for (const auto& [name, value] : p.estimate) trial.set(name, value);
  const ParameterSpace& space = *config.space;
  for (std::size_t i = 0; i < p.fit_start.size(); ++i) {
    for (const auto& target : space.free_parameters()[i].targets) {
      trial.set(target, p.fit_start[i].second);
    }
  }
  try {
    return config.train->evaluate(trial).fitness;
  } catch (const std::bad_alloc&) {
    throw;  // the machine, not the proposal
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

// The proposal's step scaled by the best of kLineSearch (the linearised size of a term's
// coefficient can be far off where the response is not linear), with the fit's parameters kept
// or moved: `p` is updated to that step; returns its training fitness and counts the rollouts.
// The trials run in parallel (each a rollout of every training log: minutes on a walking
// robot) and are compared in a fixed order, so the choice does not depend on `threads`.
double line_search(TermDiscovery& p, const FitConfig& config, const ParameterSet& current,
                   int threads, std::size_t* rollouts) {
  constexpr int kTrials = 2 * static_cast<int>(std::size(kLineSearch));  // × fit kept / moved
  std::array<double, kTrials> fitness{};
#pragma omp parallel for schedule(dynamic) num_threads(std::max(threads, 1))
  for (int k = 0; k < kTrials; ++k) {
    fitness[static_cast<std::size_t>(k)] = proposal_fitness(
        scaled_proposal(p, config, current, k % 2 == 1, kLineSearch[k / 2]), config, current);
  }
  *rollouts += kTrials * config.train->cases().size();
  double best = std::numeric_limits<double>::infinity();
  int best_trial = 2;  // scale 1, fit kept: where every trial fails
  for (int k = 0; k < kTrials; ++k) {
    if (fitness[static_cast<std::size_t>(k)] < best) {
      best = fitness[static_cast<std::size_t>(k)];
      best_trial = k;
    }
  }
  p = scaled_proposal(p, config, current, best_trial % 2 == 1, kLineSearch[best_trial / 2]);
  return best;
}

// The coordinates of a proposal for refine_support: the fit's free parameters (at the
// proposal's fit_start, or the fit's own values) and the proposal's term coefficients.
std::vector<detail::RefinedCoordinate> coordinates_of(const TermDiscovery& p,
                                                      const FitConfig& config,
                                                      const ParameterSet& current,
                                                      const detail::FitJacobian& jacobian) {
  const ParameterSpace& space = *config.space;
  std::vector<detail::RefinedCoordinate> out;
  for (std::size_t i = 0; i < space.dimension(); ++i) {
    const FreeParameter& free = space.free_parameters()[i];
    const double model_value =
        p.fit_start.empty() ? current.get(free.targets.front()) : p.fit_start[i].second;
    const detail::Direction& d = jacobian.directions[i];
    out.push_back({free.targets, i, false, space.to_search(i, model_value), std::abs(d.step),
                   d.lower, d.upper});
  }
  for (const auto& [name, value] : p.estimate) {
    const TorqueTerm* term = find_torque_term(name);
    const double bound = term != nullptr ? term->bound : 1.0;
    out.push_back({{name}, 0, true, value, kTermProbeFraction * bound, -bound, bound});
  }
  return out;
}

// Writes a refined point back into the proposal (terms and fit start).
void adopt(TermDiscovery& p, const std::vector<detail::RefinedCoordinate>& coordinates,
           const std::vector<double>& values, const FitConfig& config) {
  const ParameterSpace& space = *config.space;
  p.fit_start.clear();
  std::size_t term = 0;
  for (std::size_t j = 0; j < coordinates.size(); ++j) {
    const detail::RefinedCoordinate& c = coordinates[j];
    if (!c.term) {
      p.fit_start.emplace_back(space.free_parameters()[c.free_index].name,
                               space.to_model(c.free_index, values[j]));
      continue;
    }
    p.estimate[term].second = values[j];
    p.terms[term].estimate = values[j];
    ++term;
  }
}

struct Screened {
  TermDiscovery proposal;
  double fitness = 0.0;
};

}  // namespace

TermDiscovery discover_terms(const FitConfig& config, const ParameterSet& current, int threads,
                             std::size_t max_terms, std::size_t screen) {
  TermDiscovery out;
  const Residual residual = detail::residual_of(*config.train, current);
  const detail::FitJacobian jacobian = detail::fit_jacobian(config, current, residual, threads);
  const std::vector<Candidate> candidates = candidates_of(config, current);
  out.candidates = candidates.size();
  if (candidates.empty() || residual.rss <= 0.0) return out;
  const auto fields = term_responses(config, current, candidates, residual, threads);
  const std::size_t cases = config.train->cases().size();
  out.probe_rollouts = (jacobian.columns.size() + fields.size() + 1) * cases;
  const ColumnSource source{&jacobian, &fields, &candidates,
                            config.train->model().actuators.size()};
  const Normal n = normal_equations(source, jacobian.columns.size() + candidates.size(), residual);
  double rss_base = residual.rss;
  solve_subset(n, {}, residual.rss, &rss_base);
  const std::vector<Support> supports = supported(n, candidates.size(), residual.rss, rss_base,
                                                  residual.effective_samples, max_terms);
  const double base_fitness = config.train->evaluate(current).fitness;
  std::size_t rollouts = out.probe_rollouts + cases;
  std::vector<Screened> screened;
  const std::size_t searched = std::min(supports.size(), std::max(kMaxLineSearched, screen));
  for (const Support& s : std::span(supports).first(searched)) {
    TermDiscovery p = proposal(s, candidates, n, jacobian, config);
    const double fitness = line_search(p, config, current, threads, &rollouts);
    p.explained = (rss_base - std::clamp(s.rss, 0.0, rss_base)) / residual.rss;
    p.candidates = out.candidates;
    screened.push_back({std::move(p), fitness});
  }
  // The `screen` best supports by ΔBIC (all, if screen >= their number) refined on rollouts;
  // each support's refinement is serial, the supports run in parallel (deterministic).
  const int refined = static_cast<int>(std::min(screen, screened.size()));
  std::vector<std::size_t> refine_rollouts(static_cast<std::size_t>(refined), 0);
#pragma omp parallel for schedule(dynamic) num_threads(std::max(threads, 1))
  for (int k = 0; k < refined; ++k) {
    Screened& s = screened[static_cast<std::size_t>(k)];
    const auto coordinates = coordinates_of(s.proposal, config, current, jacobian);
    const detail::RefinedSupport r =
        detail::refine_support(config, current, coordinates, s.fitness, kRefineIterations);
    refine_rollouts[static_cast<std::size_t>(k)] = r.rollouts;
    if (r.accepted_steps > 0) {
      adopt(s.proposal, coordinates, r.values, config);
      s.fitness = r.fitness;
    }
  }
  for (const std::size_t r : refine_rollouts) rollouts += r;
  // Without screening the lowest training fitness wins (at least 5 % below the fit's); with it,
  // refined supports of more terms fit better by construction, so they are compared by the
  // ΔBIC of their rollouts: N_eff·ln(F/F₀) + k·ln N_eff.
  const double n_eff = residual.effective_samples;
  double best_score = std::numeric_limits<double>::infinity();
  const Screened* best = nullptr;
  for (const Screened& s : screened) {
    if (!(s.fitness < (1.0 - kMinTrainingGain) * base_fitness)) continue;
    const double k = static_cast<double>(s.proposal.terms.size());
    const double score = screen == 0 ? s.fitness
                                     : n_eff * std::log(s.fitness / base_fitness) +
                                           k * std::log(std::max(n_eff, 2.0));
    if (score < best_score) best_score = score, best = &s;
  }
  if (best != nullptr) out = best->proposal;
  out.probe_rollouts = rollouts;
  return out;
}

Effect discovered_effect(const std::vector<DiscoveredTerm>& terms) {
  Effect effect{"discovered_torque",
                "a joint torque found by sparse regression on candidate terms",
                "a sparse combination of candidate torques (torque_terms.hpp)",
                {},
                false,
                0};
  for (const DiscoveredTerm& term : terms) {
    const TorqueTerm* t = find_torque_term(term.parameter);
    const double bound = t != nullptr ? t->bound : 1.0;
    effect.parameters.push_back({term.parameter, true, false, -bound, bound, kTermProbeFraction});
  }
  return effect;
}

std::string discovered_formula(const std::vector<DiscoveredTerm>& terms,
                               const ParameterSet& values) {
  std::map<std::string, std::string> per_joint;
  for (const DiscoveredTerm& term : terms) {
    const double c = values.get(term.parameter);
    char text[96];
    std::string& line = per_joint[term.joint];
    if (line.empty()) {
      std::snprintf(text, sizeof text, "%.4g·%s", c, term.formula.c_str());
    } else {
      std::snprintf(text, sizeof text, " %s %.4g·%s", c < 0.0 ? "−" : "+", std::abs(c),
                    term.formula.c_str());
    }
    line += text;
  }
  std::string out;
  for (const auto& [joint, line] : per_joint) {
    out += (out.empty() ? "" : "; ") + ("τ_" + joint + " = " + line + " (SI units)");
  }
  return out;
}

}  // namespace motoflex
