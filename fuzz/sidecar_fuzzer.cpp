// libFuzzer target: the joint-log sidecar reader (robot, rate_hz, units, column maps,
// parameters). Bad input must end in InputError.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "../src/io/joint_log_sidecar.hpp"
#include "fuzz_support.hpp"
#include "motoflex/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = motoflex::fuzz::scratch_dir() / "sidecar.yaml";
  motoflex::fuzz::write_file(path, std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    (void)motoflex::detail::read_joint_log_sidecar(path.string());
  } catch (const motoflex::InputError&) {
  }
  return 0;
}
