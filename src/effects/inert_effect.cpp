#include "motoflex/effects/inert_effect.hpp"

#include <string>

namespace motoflex {

bool effect_is_inert(const FitnessFunction& train, const ParameterSpace& refit_space,
                     std::size_t model_parameters, const ParameterSet& refit_best,
                     const ParameterSet& current) {
  if (model_parameters >= refit_space.dimension()) return false;  // no effect parameters
  ParameterSet neutral = refit_best;
  for (std::size_t i = model_parameters; i < refit_space.dimension(); ++i) {
    for (const std::string& target : refit_space.free_parameters()[i].targets) {
      neutral.set(target, current.get(target));
    }
  }
  return train.evaluate(neutral).fitness <= train.evaluate(refit_best).fitness;
}

}  // namespace motoflex
