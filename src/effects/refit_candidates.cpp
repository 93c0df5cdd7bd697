#include "motoflex/effects/refit_candidates.hpp"

#include <algorithm>

namespace motoflex {
namespace {

bool named_in(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::vector<const EffectScore*> refit_candidates(const EffectRanking& ranking, std::size_t count,
                                                 const std::vector<std::string>& retained,
                                                 const std::vector<std::string>& exclude) {
  std::vector<const EffectScore*> chosen;
  for (const EffectScore& score : ranking.scores) {
    if (chosen.size() == count) break;
    if (score.scored() && score.explained > kMinRefitExplained &&
        !named_in(exclude, score.effect)) {
      chosen.push_back(&score);
    }
  }
  for (const EffectScore& score : ranking.scores) {
    const bool listed = std::find(chosen.begin(), chosen.end(), &score) != chosen.end();
    if (score.scored() && !listed && named_in(retained, score.effect) &&
        !named_in(exclude, score.effect)) {
      chosen.push_back(&score);
    }
  }
  return chosen;
}

}  // namespace motoflex
