#pragma once

// The evolution-strategy library (issue: the optimiser). It depends on nothing robot-specific.
namespace motoflex_es {

// Library version string, "major.minor.patch".
const char* version();

}  // namespace motoflex_es
