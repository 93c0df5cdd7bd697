#pragma once

#include <string>

namespace motoflex {

// UTC time now as "YYYY-MM-DDTHH:MM:SSZ" (provenance of written files).
std::string utc_now_iso8601();

}  // namespace motoflex
