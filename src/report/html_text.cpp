#include "motoflex/report/html_text.hpp"

#include <cmath>
#include <cstdio>

#include "motoflex/core/markup_escape.hpp"

namespace motoflex::report {

std::string escape_html(std::string_view text) {
  return escape_markup(text);
}

std::string json_for_script(const nlohmann::json& value) {
  // nlohmann writes NaN and infinities as null; strict UTF-8 replacement keeps a log name with
  // broken bytes from aborting the report.
  const std::string json = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(json.size() + 16);
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<') {
      // The same character to a JSON parser, but it can end no script element.
      out += "\\u003c";
      continue;
    }
    // U+2028 and U+2029 (E2 80 A8/A9) are line terminators to older JavaScript parsers.
    if (static_cast<unsigned char>(c) == 0xE2 && i + 2 < json.size() &&
        static_cast<unsigned char>(json[i + 1]) == 0x80 &&
        (static_cast<unsigned char>(json[i + 2]) == 0xA8 ||
         static_cast<unsigned char>(json[i + 2]) == 0xA9)) {
      out += static_cast<unsigned char>(json[i + 2]) == 0xA8 ? "\\u2028" : "\\u2029";
      i += 2;
      continue;
    }
    out += c;
  }
  return out;
}

std::string format_number(double value, int significant) {
  if (std::isnan(value)) return "n/a";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

}  // namespace motoflex::report
