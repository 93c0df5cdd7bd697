#include "motoflex/core/error_collector.hpp"

namespace motoflex {
namespace {

InputError first_with_count(const std::vector<InputError>& errors) {
  const InputError& first = errors.at(0);
  std::string message = first.message();
  if (errors.size() > 1) {
    message += " (and " + std::to_string(errors.size() - 1) + " more)";
  }
  return InputError(first.file(), first.line(), first.field(), message);
}

}  // namespace

InputErrors::InputErrors(std::vector<InputError> errors)
    : InputError(first_with_count(errors)), errors_(std::move(errors)) {}

void ErrorCollector::add(const InputError& error) {
  // The same problem reached twice (two parts reading one field) is reported once.
  for (const InputError& known : errors_) {
    if (std::string(known.what()) == error.what()) return;
  }
  errors_.push_back(error);
}

void ErrorCollector::add(std::string file, int line, std::string field,
                         const std::string& message) {
  add(InputError(std::move(file), line, std::move(field), message));
}

void ErrorCollector::throw_if_any() const {
  if (errors_.empty()) return;
  if (errors_.size() == 1) throw errors_.front();
  throw InputErrors(errors_);
}

}  // namespace motoflex
