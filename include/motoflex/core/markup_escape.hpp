#pragma once

// Text for XML and HTML: the five characters with a meaning in markup (& < > " ') as entities,
// safe in element text and in attributes of either quote. Used by the exporters (URDF, SDF,
// MJCF) and the HTML report.

#include <string>
#include <string_view>

namespace motoflex {

std::string escape_markup(std::string_view text);

}  // namespace motoflex
