#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace motoflex {

// Bad user input (config, URDF, log, parameter file). Carries the file, the line (0 when the
// format has no lines or the line is unknown) and the field, so the CLI can print one line
//   "<file>:<line>: <field>: <message>"
// and exit with code 2. Each part is made one line (newlines become spaces) and bounded: the
// field to kMaxFieldChars, the message to kMaxMessageChars (longer ones end in "..."), so an
// enormous key or value echoed from the input cannot flood the terminal.
class InputError : public std::runtime_error {
 public:
  static constexpr std::size_t kMaxFieldChars = 80;
  static constexpr std::size_t kMaxMessageChars = 400;
  static constexpr std::size_t kMaxFileChars = 400;

  InputError(std::string file, int line, std::string field, const std::string& message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }
  // The message without the location prefix.
  const std::string& message() const { return message_; }

 private:
  struct Sanitized {};
  InputError(Sanitized, std::string file, int line, std::string field, std::string message);

  std::string file_;
  int line_;
  std::string field_;
  std::string message_;
};

// A file that could not be read or written for a reason outside the input itself: a full disk,
// a read-only file system, no permission. Same one-line format as InputError; exit code 3.
class IoError : public InputError {
 public:
  using InputError::InputError;
};

// The exit codes of the motoflex binary (README, "Exit codes"); every command uses these.
namespace exit_code {
constexpr int kOk = 0;
constexpr int kInternal = 1;     // a bug: an exception that is not about the input
constexpr int kBadInput = 2;     // InputError: a config, log, robot, parameter file or flag
constexpr int kIo = 3;           // IoError: a file could not be written (disk full, permission)
constexpr int kInterrupted = 4;  // SIGINT/SIGTERM: stopped after a checkpoint; `resume` goes on
}  // namespace exit_code

// A model that is valid input but cannot be simulated as configured (for example a gear
// sub-step too long for the gear spring to stay stable). Thrown when a rollout is set up; a fit
// scores it as a failed rollout instead of crashing.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace motoflex
