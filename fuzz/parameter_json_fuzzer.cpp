// libFuzzer target: parameter JSON files ({"name": value} or a fit's {"parameters": {...}})
// applied to the pendulum bench's parameters. Bad input must end in InputError.

#include <cstddef>
#include <cstdint>
#include <string>

#include "motoflex/core/error.hpp"
#include "motoflex/model/robot_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const motoflex::RobotModel model = motoflex::load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum",
      motoflex::StructureOptions{});
  motoflex::ParameterSet set(model.parameters);
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    motoflex::apply_parameter_json_text(text, "fuzz.json", set);
  } catch (const motoflex::InputError&) {
  }
  return 0;
}
