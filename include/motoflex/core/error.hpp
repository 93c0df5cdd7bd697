#pragma once

#include <stdexcept>
#include <string>

namespace motoflex {

// Bad user input (config, URDF, log, parameter file). Carries the file, the line (0 when the
// format has no lines or the line is unknown) and the field, so the CLI can print one line
//   "<file>:<line>: <field>: <message>"
// and exit with code 2.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string field, const std::string& message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }
  // The message without the location prefix.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
  std::string message_;
};

// A model that is valid input but cannot be simulated as configured (for example a gear
// sub-step too long for the gear spring to stay stable). Thrown when a rollout is set up; a fit
// scores it as a failed rollout instead of crashing.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace motoflex
