#pragma once

// Numbers as text for messages and files: the shortest text that reads back as the same double
// (std::to_chars), or four significant digits for tables meant to be read.

#include <charconv>
#include <string>

namespace motoflex {

// Four significant digits, for tables meant to be read.
inline std::string short_number_text(double value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 4);
  return std::string(buffer, result.ptr);
}

inline std::string number_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace motoflex
