#pragma once

// The pieces of the Python module `motoflex` (python/motoflex/__init__.py re-exports them from
// the extension `motoflex._motoflex`). Each bind_* adds one group of functions and classes.

#include <pybind11/pybind11.h>

namespace motoflex::python {

void bind_errors(pybind11::module_& m);    // motoflex.InputError, motoflex.ModelError
void bind_simulate(pybind11::module_& m);  // Scenario, simulate
void bind_logs(pybind11::module_& m);      // read_log, write_log, parameter files
void bind_fit(pybind11::module_& m);       // FitSpec, fit, resume, run_summary
void bind_export(pybind11::module_& m);    // export, export_formats
void bind_analysis(pybind11::module_& m);  // frequency_response, parameter_spread

}  // namespace motoflex::python
