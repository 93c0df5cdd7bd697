#include "fit_spec_sections.hpp"

#include "motoflex/model/effect_library.hpp"

namespace motoflex {

FitBudget read_budget(const YamlValue& budget) {
  budget.require_keys_within(
      {"generations", "evaluations", "seconds", "stall_evaluations", "stall_relative"});
  FitBudget out;
  const auto count = [&](const char* key) {
    const int value = budget.get_int(key, 0);
    if (value < 0) budget.at(key).fail("must be >= 0 (0 = no limit)");
    return static_cast<std::uint64_t>(value);
  };
  out.max_generations = count("generations");
  out.max_evaluations = count("evaluations");
  out.max_seconds = budget.get_double("seconds", 0.0);
  if (out.max_seconds < 0.0) budget.at("seconds").fail("must be >= 0 (0 = no limit)");
  out.stall_evaluations = count("stall_evaluations");
  out.stall_relative = budget.get_double("stall_relative", out.stall_relative);
  if (!(out.stall_relative >= 0.0 && out.stall_relative < 1.0)) {
    budget.at("stall_relative").fail("must be in [0, 1) (a share of the best fitness)");
  }
  return out;
}

StrategyConfig read_strategy(const YamlValue& node) {
  node.require_keys_within({"kind", "mu", "lambda", "kappa", "rho", "object_recombination",
                            "step_recombination", "initial_step", "sigma", "population", "restarts",
                            "active", "negative_weights", "racing", "race_chunk", "algorithm",
                            "polish", "polish_evaluations"});
  StrategyConfig s;
  s.kind = node.get_string("kind", s.kind);
  if (s.kind != "mu_plus_lambda" && s.kind != "cma_es" && s.kind != "nlopt") {
    node.at("kind").fail("expected mu_plus_lambda, cma_es or nlopt");
  }
  auto positive = [&](const char* key, int fallback) {
    const int v = node.get_int(key, fallback);
    if (v < 0) node.at(key).fail("must be >= 0");
    return static_cast<std::size_t>(v);
  };
  s.mu = positive("mu", static_cast<int>(s.mu));
  s.lambda = positive("lambda", static_cast<int>(s.lambda));
  s.kappa = positive("kappa", static_cast<int>(s.kappa));
  s.rho = positive("rho", static_cast<int>(s.rho));
  s.object_recombination = node.get_string("object_recombination", s.object_recombination);
  s.step_recombination = node.get_string("step_recombination", s.step_recombination);
  for (const char* key : {"object_recombination", "step_recombination"}) {
    if (const auto v = node.find(key)) {
      const std::string text = v->as_string();
      if (text != "none" && text != "discrete" && text != "intermediate") {
        v->fail("expected none, discrete or intermediate");
      }
    }
  }
  s.initial_step = node.get_double("initial_step", s.initial_step);
  s.sigma = node.get_double("sigma", s.sigma);
  s.population = positive("population", 0);
  s.restarts = positive("restarts", static_cast<int>(s.restarts));
  s.active = node.get_bool("active", s.active);
  s.racing = node.get_bool("racing", s.racing);
  s.race_chunk = positive("race_chunk", 0);
  if (const auto v = node.find("negative_weights")) {
    const std::string text = v->as_string();
    if (text != "ranked" && text != "pooled") v->fail("expected ranked or pooled");
    s.pooled_negative_tail = text == "pooled";
  }
  s.algorithm = node.get_string("algorithm", s.algorithm);
  for (const char* key : {"algorithm", "polish"}) {
    if (const auto v = node.find(key)) {
      const std::string text = v->as_string();
      if (text.empty() && std::string(key) == "polish") continue;  // no polish
      const bool local = text == "bobyqa" || text == "sbplx";
      const bool global = text == "crs2_lm" || text == "isres" || text == "esch";
      if (!(local || (global && std::string(key) == "algorithm"))) {
        v->fail(std::string(key) == "polish" ? "expected bobyqa or sbplx"
                                             : "expected bobyqa, sbplx, crs2_lm, isres or esch");
      }
    }
  }
  s.polish = node.get_string("polish", "");
  s.polish_evaluations = positive("polish_evaluations", s.polish.empty() ? 0 : 200);
  return s;
}

PolishSpec read_polish(const YamlValue& node) {
  node.require_keys_within(
      {"method", "max_iterations", "jacobian", "jacobian_step", "covariance", "flat_scan"});
  PolishSpec p;
  p.method = node.get_string("method", "lm");
  if (p.method != "lm" && p.method != "none") node.at("method").fail("expected lm or none");
  const int iterations = node.get_int("max_iterations", static_cast<int>(p.max_iterations));
  if (iterations < 1) node.at("max_iterations").fail("must be >= 1");
  p.max_iterations = static_cast<std::size_t>(iterations);
  p.jacobian_step = node.get_double("jacobian_step", p.jacobian_step);
  if (!(p.jacobian_step > 0.0 && p.jacobian_step <= 0.1)) {
    node.at("jacobian_step").fail("must be in (0, 0.1] (a share of the bound width)");
  }
  const std::string jacobian = node.get_string("jacobian", "central");
  if (jacobian == "forward") {
    p.lm_jacobian = FiniteDifferences::kForward;
  } else if (jacobian != "central") {
    node.at("jacobian").fail("expected central or forward");
  }
  if (p.lm_jacobian == FiniteDifferences::kForward && p.method != "lm") {
    node.at("jacobian").fail("needs method: lm");
  }
  p.covariance = node.get_bool("covariance", p.covariance);
  const int scan = node.get_int("flat_scan", 0);
  if (scan < 0 || scan == 1 || scan == 2) node.at("flat_scan").fail("must be 0 (none) or >= 3");
  if (scan > 0 && p.method != "lm") node.at("flat_scan").fail("needs method: lm");
  p.flat_scan = static_cast<std::size_t>(scan);
  return p;
}

LoopOptions read_loop(const YamlValue& node) {
  node.require_keys_within({"candidates", "widen", "max_iterations", "min_gain", "effects", "refit",
                            "discover_terms", "discover_always", "discover_screen", "control"});
  LoopOptions loop;
  const int candidates = node.get_int("candidates", static_cast<int>(loop.candidates));
  if (candidates < 1) node.at("candidates").fail("must be >= 1");
  loop.candidates = static_cast<std::size_t>(candidates);
  const int widen = node.get_int("widen", 0);
  if (widen < 0) node.at("widen").fail("must be >= 0");
  loop.widen = static_cast<std::size_t>(widen);
  const int iterations = node.get_int("max_iterations", static_cast<int>(loop.max_iterations));
  if (iterations < 0) node.at("max_iterations").fail("must be >= 0");
  loop.max_iterations = static_cast<std::size_t>(iterations);
  loop.min_gain = node.get_double("min_gain", loop.min_gain);
  if (!(loop.min_gain >= 0.0 && loop.min_gain < 1.0)) {
    node.at("min_gain").fail("must be in [0, 1)");
  }
  const int discover = node.get_int("discover_terms", 0);
  if (discover < 0) node.at("discover_terms").fail("must be >= 0");
  loop.discover_terms = static_cast<std::size_t>(discover);
  loop.discover_always = node.get_bool("discover_always", false);
  loop.control = node.get_bool("control", loop.control);
  const int screen = node.get_int("discover_screen", 0);
  if (screen < 0) node.at("discover_screen").fail("must be >= 0");
  loop.discover_screen = static_cast<std::size_t>(screen);
  if (const auto effects = node.find("effects")) {
    for (const YamlValue& item : effects->items()) {
      find_effect(item.as_string(), item.file(), item.line(), item.field());
      loop.effects.push_back(item.as_string());
    }
  }
  if (const auto refit = node.find("refit")) {
    refit->require_keys_within({"strategy", "budget", "polish", "scan", "scan_pairs"});
    const int scan = refit->get_int("scan", 0);
    if (scan < 0 || scan == 1 || scan == 2) refit->at("scan").fail("must be 0 (none) or >= 3");
    loop.refit_scan = static_cast<std::size_t>(scan);
    loop.refit_scan_pairs = refit->get_bool("scan_pairs", false);
    if (loop.refit_scan_pairs && scan == 0) {
      refit->at("scan_pairs").fail("needs `scan` (points per parameter, >= 3)");
    }
    if (const auto polish = refit->find("polish")) loop.refit_polish = read_polish(*polish);
    if (const auto strategy = refit->find("strategy")) {
      loop.refit_strategy = read_strategy(*strategy);
    }
    if (const auto budget = refit->find("budget")) loop.refit_budget = read_budget(*budget);
  }
  return loop;
}

}  // namespace motoflex
