// libFuzzer target: the robot loader (robot.yaml and the URDF it names). The input is the
// robot.yaml, then a line "=====" and the URDF (written as robot.urdf; the seed corpus's
// robot.yaml files name it so). Bad input must end in InputError.

#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/robot_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto [yaml, urdf] = motoflex::fuzz::split_input(data, size);
  const auto dir = motoflex::fuzz::scratch_dir() / "robot";
  std::filesystem::create_directories(dir);
  motoflex::fuzz::write_file(dir / "robot.yaml", yaml);
  motoflex::fuzz::write_file(dir / "robot.urdf", urdf);
  try {
    (void)motoflex::load_robot_model(dir.string(), motoflex::StructureOptions{});
  } catch (const motoflex::InputErrors&) {
  } catch (const motoflex::InputError&) {
  }
  return 0;
}
