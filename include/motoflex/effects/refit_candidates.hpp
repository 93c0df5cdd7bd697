#pragma once

// Which ranked effects `motoflex loop` refits in an iteration (effect_loop.hpp).
//
// The ranking is a linearised screen; the refit on the validation logs decides. An iteration
// refits the first `candidates` effects the ranking scores above a floor, plus any effect that
// passed the validation test last time without being added (`retained`). When none of them
// passes, the loop can widen once (`loop.widen`) to the next effects in rank before it turns
// to discovered terms: a new library entry that ranks high but does not validate must not push
// the one that does out of reach.

#include <cstddef>
#include <string>
#include <vector>

#include "motoflex/effects/effect_signature.hpp"

namespace motoflex {

// An effect that explains less than this fraction of the residual is never refit.
constexpr double kMinRefitExplained = 1e-3;

// The first `count` scored effects of `ranking` above the floor, skipping those in `exclude`,
// in rank order; then every scored effect named in `retained` not yet chosen or excluded.
std::vector<const EffectScore*> refit_candidates(const EffectRanking& ranking, std::size_t count,
                                                 const std::vector<std::string>& retained,
                                                 const std::vector<std::string>& exclude = {});

}  // namespace motoflex
