#pragma once

// Shared by the libFuzzer targets: a private scratch folder per process, and splitting one
// input into the files a reader needs (a CSV and its sidecar, a robot.yaml and its URDF).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>

namespace motoflex::fuzz {

inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const auto path =
        std::filesystem::temp_directory_path() / ("motoflex_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return dir;
}

inline void write_file(const std::filesystem::path& path, std::string_view text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(text.data(), static_cast<long>(text.size()));
}

// The input before and after the first line "=====" (the second part empty without one).
inline std::pair<std::string_view, std::string_view> split_input(const std::uint8_t* data,
                                                                 std::size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSeparator = "\n=====\n";
  const std::size_t at = all.find(kSeparator);
  if (at == std::string_view::npos) return {all, {}};
  return {all.substr(0, at), all.substr(at + kSeparator.size())};
}

}  // namespace motoflex::fuzz
