#pragma once

#include <string>

namespace motoflex {

// The version of this build ("0.1.0"), written into every output's provenance.
const char* version();

// Where motoflex finds its own data (scripts/ for plots, scenarios/robots/ for bundled robots):
// $MOTOFLEX_DATA_DIR when set; else the source tree this build came from, while it exists;
// else the installed copy, <install prefix>/share/motoflex.
std::string data_directory();

}  // namespace motoflex
