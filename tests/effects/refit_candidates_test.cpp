// Which ranked effects the loop refits (refit_candidates.hpp): the first N scored above the
// floor, then effects retained from the last iteration, and the widened round after them.

#include "motoflex/effects/refit_candidates.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace motoflex {
namespace {

EffectScore score(const std::string& effect, const std::string& status, double explained) {
  EffectScore s;
  s.effect = effect;
  s.status = status;
  s.explained = explained;
  return s;
}

// Rank order as the ranking gives it: scored ones by ΔBIC first, then the others.
EffectRanking ranking() {
  EffectRanking r;
  r.scores = {score("current_limit", "scored", 0.40),  score("winding_heating", "scored", 0.13),
              score("encoder_scale", "scored", 0.04),  score("sensor_delay", "scored", 0.0005),
              score("load_friction", "scored", 0.010), score("stribeck", "scored", 0.002),
              score("armature", "not applicable", 0.0)};
  return r;
}

std::vector<std::string> names(const std::vector<const EffectScore*>& chosen) {
  std::vector<std::string> out;
  for (const EffectScore* s : chosen) out.push_back(s->effect);
  return out;
}

TEST(RefitCandidatesTest, TheFirstNScoredAboveTheFloorInRankOrder) {
  const EffectRanking r = ranking();
  EXPECT_EQ(names(refit_candidates(r, 2, {})),
            (std::vector<std::string>{"current_limit", "winding_heating"}));
  // sensor_delay explains less than the floor (1e-3) and armature is not scored: neither counts.
  EXPECT_EQ(names(refit_candidates(r, 4, {})),
            (std::vector<std::string>{"current_limit", "winding_heating", "encoder_scale",
                                      "load_friction"}));
  EXPECT_EQ(refit_candidates(r, 10, {}).size(), 5u);
}

TEST(RefitCandidatesTest, RetainedEffectsAreRefitWhateverTheirRank) {
  const EffectRanking r = ranking();
  EXPECT_EQ(names(refit_candidates(r, 2, {"stribeck", "armature"})),
            (std::vector<std::string>{"current_limit", "winding_heating", "stribeck"}));
}

TEST(RefitCandidatesTest, TheWidenedRoundTakesTheNextInRankAndSkipsWhatWasTried) {
  const EffectRanking r = ranking();
  const std::vector<std::string> tried = names(refit_candidates(r, 2, {}));
  EXPECT_EQ(names(refit_candidates(r, 2, {}, tried)),
            (std::vector<std::string>{"encoder_scale", "load_friction"}));
  EXPECT_EQ(names(refit_candidates(r, 5, {}, tried)),
            (std::vector<std::string>{"encoder_scale", "load_friction", "stribeck"}));
  EXPECT_TRUE(refit_candidates(r, 5, {}, names(refit_candidates(r, 10, {}))).empty());
}

}  // namespace
}  // namespace motoflex
