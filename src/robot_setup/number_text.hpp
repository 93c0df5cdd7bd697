#pragma once

// Internal to robot_setup: numbers as the shortest text that reads back as the same double.

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
