#include "effect_builders.hpp"

namespace motoflex::detail {

Effect link_flexibility_effect() {
  return {"link_flexibility",
          "bending of thighs and tibias (sub-bodies and springs)",
          "oscillations under load and a load-dependent offset of the legs",
          {global("flex.spring_nm_per_rad", -0.3, true),
           global("flex.damping_nm_s_per_rad", 0.0, true)},
          false,
          2};
}

}  // namespace motoflex::detail
