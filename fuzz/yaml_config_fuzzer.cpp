// libFuzzer target: the strict YAML reader every config goes through (scenario, fit, robot,
// truth, sidecar files). Parses the input and walks every value with every typed accessor, as
// the loaders do. Bad input must end in InputError, never a crash, a hang or another exception.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "motoflex/core/error.hpp"
#include "motoflex/io/yaml_reader.hpp"

namespace {

void walk(const motoflex::YamlValue& value, int depth) {
  if (depth > 100) return;
  const auto attempt = [](auto&& read) {
    try {
      read();
    } catch (const motoflex::InputError&) {
    }
  };
  attempt([&] { (void)value.as_double(); });
  attempt([&] { (void)value.as_int(); });
  attempt([&] { (void)value.as_bool(); });
  attempt([&] { (void)value.as_string(); });
  attempt([&] { (void)value.as_double_list(); });
  attempt([&] { (void)value.as_string_list(); });
  attempt([&] { value.require_keys_within({"name", "robot", "physics", "dt_s", "motion"}); });
  attempt([&] {
    for (const auto& [key, child] : value.entries()) walk(child, depth + 1);
  });
  attempt([&] {
    for (const auto& item : value.items()) walk(item, depth + 1);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    walk(motoflex::YamlValue::parse(text, "fuzz.yaml"), 0);
  } catch (const motoflex::InputError&) {
  }
  return 0;
}
