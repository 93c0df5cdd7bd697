#pragma once

// Field access for one JSON input file (BAM's logs and calibration tables): every problem is an
// InputError naming the file and the field, e.g. `entries[3].position` or `samples[1].voltage`.

#include <nlohmann/json.hpp>
#include <string>

namespace motoflex::detail {

class JsonFields {
 public:
  explicit JsonFields(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& message) const;
  const nlohmann::json& required(const nlohmann::json& object, const char* key,
                                 const std::string& field) const;
  // A finite number (Python's bare NaN/Infinity named as such).
  double number(const nlohmann::json& value, const std::string& field) const;
  double positive(const nlohmann::json& value, const std::string& field) const;
  std::string text(const nlohmann::json& value, const std::string& field) const;

 private:
  std::string file_;
};

}  // namespace motoflex::detail
