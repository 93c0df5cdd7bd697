#include "motoflex/core/error.hpp"

#include <algorithm>
#include <utility>

namespace motoflex {
namespace {

// A message is one line of bounded length, whatever the input echoed into it: a 2 MB key or
// value, or one with newlines, must not flood the terminal or break the one-line format.
std::string one_line(const std::string& text, std::size_t max_chars) {
  std::string out;
  out.reserve(std::min(text.size(), max_chars + 3));
  for (const char c : text) {
    if (out.size() == max_chars) return out + "...";
    out.push_back(c == '\n' || c == '\r' || c == '\t' ? ' ' : c);
  }
  return out;
}

std::string format_location(const std::string& file, int line, const std::string& field,
                            const std::string& message) {
  std::string text;
  text.append(file.empty() ? "<input>" : file);
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ");
  if (!field.empty()) text.append(field).append(": ");
  text.append(message);
  return text;
}

}  // namespace

InputError::InputError(std::string file, int line, std::string field, const std::string& message)
    : InputError(Sanitized{}, one_line(file, kMaxFileChars), line, one_line(field, kMaxFieldChars),
                 one_line(message, kMaxMessageChars)) {}

InputError::InputError(Sanitized, std::string file, int line, std::string field,
                       std::string message)
    : std::runtime_error(format_location(file, line, field, message)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      message_(std::move(message)) {}

}  // namespace motoflex
