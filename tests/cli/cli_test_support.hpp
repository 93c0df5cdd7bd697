#pragma once

// Runs the built motoflex binary in tests and captures what it printed.

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.hpp"

namespace motoflex::testing {

struct CommandResult {
  int exit_code = -1;
  std::string stdout_text;
  std::string stderr_text;
};

// Runs `motoflex <arguments>`; with timeout_s > 0 under timeout(1), which ends a hang with exit
// code 124; shell_setup (e.g. "ulimit -f 8") runs first in the same shell.
inline CommandResult run_motoflex_with_timeout(const std::string& arguments, int timeout_s,
                                               const std::string& shell_setup = "") {
  // ctest runs tests in parallel processes: one stderr file per process and call.
  static int calls = 0;
  const auto dir = scratch_root() / "cli_stderr";
  std::filesystem::create_directories(dir);
  const auto err =
      dir / ("stderr_" + std::to_string(getpid()) + "_" + std::to_string(++calls) + ".txt");
  const std::string prefix =
      timeout_s > 0 ? "timeout -s KILL " + std::to_string(timeout_s) + " " : "";
  const std::string setup = shell_setup.empty() ? "" : shell_setup + "; exec ";
  const std::string command =
      setup + prefix + std::string(MOTOFLEX_TEST_BINARY) + " " + arguments + " 2> " + err.string();
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.stdout_text.append(buffer.data(), n);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  {
    std::ifstream in(err);
    result.stderr_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::filesystem::remove(err);
  return result;
}

inline CommandResult run_motoflex(const std::string& arguments) {
  return run_motoflex_with_timeout(arguments, 0);
}

// A fresh, empty folder for one test, under the process's scratch root (scratch_dir.hpp).
inline std::filesystem::path fresh_dir(const std::string& name) {
  return scratch_dir(name);
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace motoflex::testing
