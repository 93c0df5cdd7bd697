// motoflex.frequency_response and motoflex.parameter_spread: the report's frequency-domain
// validation and the randomisation ranges of several fits, for arrays and run folders in Python.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "json_python.hpp"
#include "motoflex/report/frequency_response.hpp"
#include "motoflex/report/parameter_spread.hpp"
#include "numpy_arrays.hpp"

namespace py = pybind11;

namespace motoflex::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<double> series(const Array& array, const char* what, std::size_t frames) {
  if (array.ndim() != 1) throw py::value_error(std::string(what) + ": expected a 1-D array");
  std::vector<double> values = array_values(array, 1, what);
  if (values.size() != frames) {
    throw py::value_error(std::string(what) + ": " + std::to_string(values.size()) +
                          " values for " + std::to_string(frames) + " times");
  }
  return values;
}

py::object frequency_response(const Array& time_s, const Array& command, const Array& measured,
                              const std::optional<Array>& simulated) {
  const std::vector<double> t = series(time_s, "time_s", static_cast<std::size_t>(time_s.size()));
  const std::vector<double> u = series(command, "command", t.size());
  const std::vector<double> y = series(measured, "measured", t.size());
  if (simulated) {
    const auto comparison =
        report::compare_frequency_responses(t, u, y, series(*simulated, "simulated", t.size()));
    if (!comparison) return py::none();
    return json_to_python(report::frequency_comparison_json(*comparison));
  }
  const auto response = report::estimate_frequency_response(t, u, y);
  if (!response) return py::none();
  py::dict out;
  out["f_hz"] = vector_array(response->frequency_hz);
  out["gain_db"] = vector_array(response->gain_db);
  out["phase_deg"] = vector_array(response->phase_deg);
  out["coherence"] = vector_array(response->coherence);
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("frequency_response", &frequency_response, py::arg("time_s"), py::arg("command"),
        py::arg("measured"), py::arg("simulated") = py::none(),
        "The response of `measured` to `command` (1-D arrays at `time_s`) as the report computes "
        "it (Welch H1, Hann windows, coherence): a dict of arrays f_hz, gain_db, phase_deg, "
        "coherence; with `simulated`, both responses compared (the report's JSON as a dict). "
        "None when the data give no estimate (a constant command, too few samples).");
  m.def(
      "parameter_spread",
      [](const std::vector<std::string>& run_dirs, double k) {
        return json_to_python(report::spread_json(report::parameter_spread(run_dirs, k)));
      },
      py::arg("run_dirs"), py::arg("k") = 2.0,
      "Randomisation ranges from several fits of the same parameters (as `motoflex spread`): a "
      "dict with k, runs and per parameter mean, between_runs, within_run, lower, upper.");
}

}  // namespace motoflex::python
