#pragma once

// Text that goes into the HTML report: everything read from a run dir (names, paths, free-text
// stop reasons, markdown) is data, so it is escaped before it becomes markup or script.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace motoflex::report {

// `text` as HTML character data or a quoted attribute value: & < > " ' escaped.
std::string escape_html(std::string_view text);

// `value` as JSON to place inside <script type="application/json">: every '<' (which JSON has
// only inside strings) is written \u003c, so that no string in the data can close the script
// element early or open a comment; U+2028/U+2029 are written \u2028/\u2029. Non-finite numbers
// are null (JSON has no NaN or infinity); invalid UTF-8 bytes become U+FFFD.
std::string json_for_script(const nlohmann::json& value);

// A number for a table cell: `significant` digits (%g), "−" for a negative sign is not used so
// that values can be copied; "n/a" for NaN, "inf"/"-inf" for infinities.
std::string format_number(double value, int significant = 6);

}  // namespace motoflex::report
