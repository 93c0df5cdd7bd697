#include "motoflex/io/plot_script.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "motoflex/core/build_info.hpp"

namespace motoflex {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The last non-empty line (a Python traceback ends with the exception), at most 200 characters.
std::string last_line(const std::string& text) {
  std::size_t end = text.find_last_not_of(" \n\r\t");
  if (end == std::string::npos) return "no output";
  const std::size_t begin = text.rfind('\n', end);
  std::string line = text.substr(begin == std::string::npos ? 0 : begin + 1,
                                 end + 1 - (begin == std::string::npos ? 0 : begin + 1));
  if (line.size() > 200) line = line.substr(0, 197) + "...";
  return line;
}

}  // namespace

bool run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  const std::filesystem::path path = std::filesystem::path(data_directory()) / "scripts" / script;
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "motoflex: warning: no plot (missing %s)\n", path.c_str());
    return false;
  }
  // Debian's python3 carries matplotlib; a pyenv python first on PATH may not.
  const char* python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  std::string command = std::string(python) + " " + quoted(path.string());
  for (const auto& argument : arguments) command += " " + quoted(argument);
  // The script's output is captured: on success it is passed on; on failure (a full disk, no
  // matplotlib) the user gets one warning line with the script's last words, not a traceback.
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    std::fprintf(stderr, "motoflex: warning: no plot (cannot start %s)\n", python);
    return false;
  }
  std::string output;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  if (pclose(pipe) != 0) {
    std::fprintf(stderr, "motoflex: warning: %s failed, no plot: %s\n", script.c_str(),
                 last_line(output).c_str());
    return false;
  }
  std::fputs(output.c_str(), stdout);
  return true;
}

bool plot_joint_log(const std::string& csv_path, const std::string& png_path,
                    const std::string& compare_csv) {
  std::vector<std::string> arguments = {csv_path, "--out", png_path};
  if (!compare_csv.empty()) {
    arguments.push_back("--compare");
    arguments.push_back(compare_csv);
  }
  return run_plot_script("plot_log.py", arguments);
}

}  // namespace motoflex
