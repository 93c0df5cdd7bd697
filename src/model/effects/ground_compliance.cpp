#include "effect_builders.hpp"

namespace motoflex::detail {

Effect ground_compliance_effect() {
  return {"ground_compliance",
          "softer ground contact (contact ERP/CFM)",
          "sinking and rebound of the stance leg at every touchdown",
          {global("contact.soft_cfm", 0.2, true), global("contact.soft_erp", 0.0)},
          true,
          0};
}

}  // namespace motoflex::detail
