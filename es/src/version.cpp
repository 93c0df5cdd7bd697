#include "motoflex_es/version.hpp"

namespace motoflex_es {

const char* version() {
  return "0.1.0";
}

}  // namespace motoflex_es
