#include "option_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace motoflex::cli {
namespace {

// "" when `text` is a decimal integer in [min, max], else why not.
std::string integer_error(const std::string& text, std::int64_t min, std::int64_t max) {
  std::int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec == std::errc::result_out_of_range) {
    return "'" + text + "' is out of range (" + std::to_string(min) + " to " + std::to_string(max) +
           ")";
  }
  if (ec != std::errc() || ptr != end) return "'" + text + "' is not a whole number";
  if (value < min || value > max) {
    return std::to_string(value) + " is out of range (" + std::to_string(min) + " to " +
           std::to_string(max) + ")";
  }
  return "";
}

// "" when `text` is a finite number above `min` (or at it when `inclusive`).
std::string number_error(const std::string& text, double min, bool inclusive) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return "'" + text + "' is not a number";
  if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
  if (inclusive ? value < min : value <= min) {
    return "'" + text + "' must be " + (inclusive ? ">= 0" : "> 0");
  }
  return "";
}

constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

}  // namespace

CLI::Validator thread_count() {
  return CLI::Validator([](std::string& s) { return integer_error(s, 1, 1024); }, "INT in 1..1024",
                        "thread_count");
}

CLI::Validator seed_value() {
  return CLI::Validator([](std::string& s) { return integer_error(s, 0, kMaxInt64); }, "INT >= 0",
                        "seed_value");
}

CLI::Validator positive_count() {
  return CLI::Validator([](std::string& s) { return integer_error(s, 1, kMaxInt64); }, "INT >= 1",
                        "positive_count");
}

CLI::Validator positive_seconds() {
  return CLI::Validator([](std::string& s) { return number_error(s, 0.0, false); }, "SECONDS > 0",
                        "positive_seconds");
}

CLI::Validator non_negative_seconds() {
  return CLI::Validator([](std::string& s) { return number_error(s, 0.0, true); }, "SECONDS >= 0",
                        "non_negative_seconds");
}

}  // namespace motoflex::cli
