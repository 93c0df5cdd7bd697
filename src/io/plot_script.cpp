#include "motoflex/io/plot_script.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "motoflex/core/build_info.hpp"

namespace motoflex {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

bool run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  const std::filesystem::path path =
      std::filesystem::path(data_directory()) / "scripts" / script;
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "motoflex: warning: no plot (missing %s)\n", path.c_str());
    return false;
  }
  // Debian's python3 carries matplotlib; a pyenv python first on PATH may not.
  const char* python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  std::string command = std::string(python) + " " + quoted(path.string());
  for (const auto& argument : arguments) command += " " + quoted(argument);
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "motoflex: warning: plotting failed (%s)\n", command.c_str());
    return false;
  }
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
