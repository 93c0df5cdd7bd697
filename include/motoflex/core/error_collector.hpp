#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/core/error.hpp"

namespace motoflex {

// Every problem of one input at once: an InputError whose what() is the first problem (with
// "(and N more)"), and which carries all of them, each a complete InputError. The CLI prints one
// line per problem, `motoflex: <file>:<line>: <field>: <message>`, and exits with code 2.
class InputErrors : public InputError {
 public:
  explicit InputErrors(std::vector<InputError> errors);
  const std::vector<InputError>& errors() const { return errors_; }

 private:
  std::vector<InputError> errors_;
};

// Gathers the problems of a whole file (or several) so a loader reports them all in one run
// instead of one per run. A loader runs each independent part of its parse through check():
// an InputError thrown there is recorded and the parse goes on with the next part; at the end
// throw_if_any() throws them together.
//
//   ErrorCollector errors;
//   errors.check([&] { spec.name = root.get_string("name", stem); });
//   errors.check([&] { spec.free = read_free(root.at("free"), base); });
//   errors.throw_if_any();
class ErrorCollector {
 public:
  // Runs `part`; an InputError it throws (an InputErrors: each of its problems) is recorded.
  // Returns whether `part` finished without one. Other exceptions propagate.
  template <typename Part>
  bool check(Part&& part) {
    try {
      std::forward<Part>(part)();
      return true;
    } catch (const InputErrors& many) {
      for (const InputError& error : many.errors()) add(error);
    } catch (const InputError& error) {
      add(error);
    }
    return false;
  }

  void add(const InputError& error);
  void add(std::string file, int line, std::string field, const std::string& message);

  bool empty() const { return errors_.empty(); }
  std::size_t size() const { return errors_.size(); }
  const std::vector<InputError>& errors() const { return errors_; }

  // Throws the first problem alone when there is one, InputErrors when there are several.
  void throw_if_any() const;

 private:
  std::vector<InputError> errors_;
};

}  // namespace motoflex
