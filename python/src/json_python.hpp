#pragma once

// JSON to Python objects (dict, list, float, ...) through Python's own json module, for the
// bindings that return what motoflex writes as JSON (summaries, specs, reports).

#include <pybind11/pybind11.h>

#include <string>

namespace motoflex::python {

inline pybind11::object json_text_to_python(const std::string& text) {
  return pybind11::module_::import("json").attr("loads")(text);
}

// For nlohmann::json and nlohmann::ordered_json alike.
template <typename Json>
pybind11::object json_to_python(const Json& json) {
  return json_text_to_python(json.dump());
}

}  // namespace motoflex::python
