#pragma once

// Internal to FitSession: how strongly the training data pin down each fitted parameter. From
// the best point x*, each free coordinate is moved by a small share h of its search range to
// both sides (finite differences, clamped to the bounds) and the fitness change is measured:
//
//   s_i = ½ (|F(x* + δ_i) − F*| + |F(x* − δ_i) − F*|) / (h · F*),   δ_i = h·(upper_i − lower_i)
//
// the relative fitness change per bound-width, extrapolated linearly. A parameter with
// s_i < kUndeterminedBelow (a 1 % step moves the fitness by less than 0.1 %) is one the data
// cannot determine: any value near the fitted one explains the logs as well.

#include <vector>

#include "motoflex/fit/fit_problem.hpp"
#include "motoflex_es/evaluator.hpp"

namespace motoflex::detail {

inline constexpr double kSensitivityStep = 0.01;   // h: share of the bound width
inline constexpr double kUndeterminedBelow = 0.1;  // s_i below this: not determined by the data

// s_i for every coordinate of `best_x` (one batch of 2n + 1 evaluations through `evaluator`,
// the best point itself included so that F* is measured the same way). Counters of `problem`
// are restored afterwards, so the fit's own statistics do not include these probes.
std::vector<double> fitness_sensitivity(FitProblem& problem, motoflex_es::Evaluator& evaluator,
                                        const std::vector<double>& best_x);

}  // namespace motoflex::detail
