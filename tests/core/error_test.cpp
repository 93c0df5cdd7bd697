// InputError keeps every message one line of bounded length, whatever the input echoed into it.

#include <gtest/gtest.h>

#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

TEST(InputError, LongFieldsAndMessagesAreCut) {
  const std::string key(2'000'000, 'k');  // a 2 MB key of a hostile config
  const InputError error("robot.yaml", 3, "parameters." + key, "unknown parameter '" + key + "'");
  EXPECT_EQ(error.field().size(), InputError::kMaxFieldChars + 3);
  EXPECT_EQ(error.field().substr(InputError::kMaxFieldChars), "...");
  EXPECT_EQ(error.message().size(), InputError::kMaxMessageChars + 3);
  EXPECT_LT(std::string(error.what()).size(), 600u);
  EXPECT_EQ(std::string(error.what()).rfind("robot.yaml:3: parameters.kkk", 0), 0u);
}

TEST(InputError, NewlinesBecomeSpaces) {
  const InputError error("log.csv", 0, "a\nb", "line one\nline two\r\n");
  EXPECT_EQ(std::string(error.what()), "log.csv: a b: line one line two  ");
  EXPECT_EQ(error.line(), 0);
}

TEST(InputError, IoErrorIsAnInputErrorWithItsOwnExitCode) {
  try {
    throw IoError("out/best.json", 0, "", "cannot write: No space left on device");
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "out/best.json: cannot write: No space left on device");
    EXPECT_NE(dynamic_cast<const IoError*>(&error), nullptr);
  }
  EXPECT_EQ(exit_code::kBadInput, 2);
  EXPECT_EQ(exit_code::kIo, 3);
  EXPECT_EQ(exit_code::kInterrupted, 4);
}

}  // namespace
}  // namespace motoflex
