#include "motoflex/core/error.hpp"

#include <utility>

namespace motoflex {
namespace {

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
    : std::runtime_error(format_location(file, line, field, message)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      message_(message) {}

}  // namespace motoflex
