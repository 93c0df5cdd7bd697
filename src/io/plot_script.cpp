#include "plot.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace motoflex::cli {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

bool plot_joint_log(const std::string& csv_path, const std::string& png_path) {
  const std::filesystem::path script =
      std::filesystem::path(MOTOFLEX_SOURCE_DIR) / "scripts" / "plot_log.py";
  if (!std::filesystem::exists(script)) {
    std::fprintf(stderr, "motoflex: warning: no plot (missing %s)\n", script.c_str());
    return false;
  }
  // Debian's python3 carries matplotlib; a pyenv python on PATH may not.
  const char* python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = std::string(python) + " " + quoted(script.string()) + " " +
                              quoted(csv_path) + " --out " + quoted(png_path);
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "motoflex: warning: plotting failed (%s)\n", command.c_str());
    return false;
  }
  return true;
}

}  // namespace motoflex::cli
