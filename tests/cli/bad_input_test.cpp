// The bad-input barrage, data-driven: every folder tests/bad_input/<case>/ holds `args` (the
// motoflex command line) and `expect` (the exit code on line 1, a fragment of the message on
// line 2), plus any input files. The case folder is copied to a fresh temporary folder with
// {src} (the source tree), {case} (the copy) and {tmp} (a scratch folder) replaced in every
// file and in the arguments. Each case must end within 60 s (no hang), with the expected exit
// code, and - when it fails - with one line on stderr of bounded length that names the problem.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kCases = fs::path(MOTOFLEX_SOURCE_DIR) / "tests" / "bad_input";

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kCases)) {
    if (fs::exists(entry.path() / "expect")) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string substitute(std::string text, const fs::path& copy, const fs::path& scratch) {
  const std::pair<std::string, std::string> names[] = {
      {"{src}", MOTOFLEX_SOURCE_DIR}, {"{case}", copy.string()}, {"{tmp}", scratch.string()}};
  for (const auto& [from, to] : names) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
      text.replace(at, from.size(), to);
      at += to.size();
    }
  }
  return text;
}

// Copies `from` into `to`, substituting the placeholders in every file.
void copy_case(const fs::path& from, const fs::path& to, const fs::path& scratch) {
  for (const auto& entry : fs::recursive_directory_iterator(from)) {
    const fs::path target = to / fs::relative(entry.path(), from);
    if (entry.is_directory()) {
      fs::create_directories(target);
    } else {
      fs::create_directories(target.parent_path());
      std::ofstream(target, std::ios::binary) << substitute(slurp(entry.path()), to, scratch);
    }
  }
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, FailsAsExpected) {
  const std::string name = GetParam();
  const fs::path root = fresh_dir("bad_input_" + name);
  const fs::path copy = root / "case";
  const fs::path scratch = root / "tmp";
  fs::create_directories(scratch);
  copy_case(kCases / name, copy, scratch);
  std::istringstream expect(slurp(copy / "expect"));
  int expected_code = -1;
  std::string fragment;
  expect >> expected_code;
  expect.ignore();
  std::getline(expect, fragment);
  std::string args = slurp(copy / "args");
  args.erase(std::remove(args.begin(), args.end(), '\n'), args.end());
  // `timeout` turns a hang into exit code 124 after 60 s.
  const CommandResult result = run_motoflex_with_timeout(args, 60);
  EXPECT_EQ(result.exit_code, expected_code) << result.stderr_text.substr(0, 2000);
  EXPECT_NE(result.stderr_text.find(fragment), std::string::npos)
      << "expected '" << fragment << "' in: " << result.stderr_text.substr(0, 2000);
  if (expected_code != 0) {
    // One line per error (a warning line may precede it); every line starts "motoflex: ".
    std::istringstream lines(result.stderr_text);
    std::string line;
    int count = 0;
    while (std::getline(lines, line)) {
      ++count;
      EXPECT_EQ(line.rfind("motoflex: ", 0), 0u) << line.substr(0, 300);
      EXPECT_LT(line.size(), 1200u) << line.substr(0, 300);  // 400-char message + path + field
    }
    EXPECT_GE(count, 1);
    EXPECT_LE(count, 3) << result.stderr_text.substr(0, 2000);
  }
  fs::remove_all(root);
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::ValuesIn(case_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(BadInputSuite, HasAtLeastSixtyCases) {
  EXPECT_GE(case_names().size(), 60u);
}

}  // namespace
}  // namespace motoflex::testing
