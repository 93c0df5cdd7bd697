#include "json_fields.hpp"

#include <cmath>

#include "motoflex/core/error.hpp"
#include "motoflex/core/number_text.hpp"
#include "python_json.hpp"

namespace motoflex::detail {

using nlohmann::json;

void JsonFields::fail(const std::string& field, const std::string& message) const {
  throw InputError(file_, 0, field, message);
}

const json& JsonFields::required(const json& object, const char* key,
                                 const std::string& field) const {
  const auto found = object.find(key);
  if (found == object.end()) fail(field, "missing key");
  return *found;
}

double JsonFields::number(const json& value, const std::string& field) const {
  if (const auto word = bare_non_finite_word(value)) {
    fail(field, *word + " is not a finite number");
  }
  if (!value.is_number()) {
    fail(field, std::string("expected a number, found ") + value.type_name());
  }
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(field, "number out of range");
  return x;
}

double JsonFields::positive(const json& value, const std::string& field) const {
  const double x = number(value, field);
  if (!(x > 0.0)) fail(field, "must be > 0, found " + number_text(x));
  return x;
}

std::string JsonFields::text(const json& value, const std::string& field) const {
  if (!value.is_string()) {
    fail(field, std::string("expected a string, found ") + value.type_name());
  }
  return value.get<std::string>();
}

}  // namespace motoflex::detail
