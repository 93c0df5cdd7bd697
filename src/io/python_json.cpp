#include "python_json.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

using nlohmann::json;

// Bare words become strings with this prefix (a control character no real log string has).
constexpr std::string_view kBareWordMarker = "\001bare:";

std::string read_whole_file(const std::string& path, const std::string& shown) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(shown, 0, "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(shown, 0, "", "cannot read file");
  return text.str();
}

// Replaces bare NaN / Infinity / -Infinity outside strings by marker strings (see
// kBareWordMarker). Newlines are untouched, so line numbers stay valid.
std::string quote_bare_words(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 64);
  bool in_string = false;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      ++i;
      continue;
    }
    if (c == '"') in_string = true;
    bool replaced = false;
    for (const std::string_view word : {"-Infinity", "Infinity", "NaN"}) {
      if (text.substr(i, word.size()) == word) {
        out += "\"\\u0001bare:";  // kBareWordMarker, spelled as JSON
        out += word;
        out += '"';
        i += word.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) {
      out += c;
      ++i;
    }
  }
  return out;
}

}  // namespace

json read_python_json(const std::string& path, const std::string& shown) {
  std::string text = read_whole_file(path, shown);
  if (text.find("NaN") != std::string::npos || text.find("Infinity") != std::string::npos) {
    text = quote_bare_words(text);
  }
  try {
    return json::parse(text);
  } catch (const json::parse_error& error) {
    const std::size_t end = std::min<std::size_t>(error.byte, text.size());
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + end, '\n'));
    // nlohmann's message starts "[json.exception.parse_error.101] parse error at line L,
    // column C: "; keep only the reason after it.
    std::string reason = error.what();
    const std::size_t column = reason.find("column ");
    const std::size_t colon = reason.find(": ", column == std::string::npos ? 0 : column);
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw InputError(shown, line, "", "not valid JSON: " + reason);
  }
}

std::optional<std::string> bare_non_finite_word(const json& value) {
  if (!value.is_string()) return std::nullopt;
  const auto& text = value.get_ref<const std::string&>();
  if (!text.starts_with(kBareWordMarker)) return std::nullopt;
  return text.substr(kBareWordMarker.size());
}

}  // namespace motoflex
