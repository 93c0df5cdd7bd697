#include "effect_builders.hpp"

namespace motoflex::detail {

Effect foot_slip_effect() {
  return {"foot_slip",
          "feet sliding on the ground (contact slip and friction)",
          "drift of the stance leg angles during single support",
          {global("contact.slip", 0.2, true), global("contact.mu", 0.0)},
          true,
          0};
}

}  // namespace motoflex::detail
