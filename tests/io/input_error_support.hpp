#pragma once
// Checks an InputError's location: the file, line and field it names, and the one-line message
// that starts "file:line: field: ".

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex::testing {

// Runs `action`, which must throw InputError at `line` for `field`; returns the error.
inline InputError expect_input_error_thrown(const std::function<void()>& action,
                                            const std::string& file, int line,
                                            const std::string& field) {
  try {
    action();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    std::string location = file;
    if (line > 0) location += ":" + std::to_string(line);
    location += ": ";
    if (!field.empty()) location += field + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(location, 0), 0u) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e;
  }
  ADD_FAILURE() << "expected InputError at " << file << ":" << line << " " << field;
  return InputError("", 0, "", "");
}

// The same; returns the message without its location.
inline std::string expect_input_error(const std::function<void()>& action, const std::string& file,
                                      int line, const std::string& field) {
  return expect_input_error_thrown(action, file, line, field).message();
}

}  // namespace motoflex::testing
