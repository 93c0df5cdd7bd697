// libFuzzer target: the joint-log reader. The input is the CSV, then a line "=====" and the
// sidecar YAML (no sidecar when the separator is absent). Bad input must end in InputError.

#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto [csv, sidecar] = motoflex::fuzz::split_input(data, size);
  const auto csv_path = motoflex::fuzz::scratch_dir() / "log.csv";
  const auto sidecar_path = motoflex::fuzz::scratch_dir() / "log.yaml";
  motoflex::fuzz::write_file(csv_path, csv);
  std::filesystem::remove(sidecar_path);
  if (!sidecar.empty()) motoflex::fuzz::write_file(sidecar_path, sidecar);
  try {
    (void)motoflex::read_joint_log(csv_path.string(), motoflex::JointLogRequirements{});
  } catch (const motoflex::InputError&) {
  }
  return 0;
}
