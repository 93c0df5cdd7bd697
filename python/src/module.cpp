// The extension module motoflex._motoflex: motoflex's simulator, logs, fits and exports for
// Python. Rollouts and fits run with the GIL released; results are the CLI's, bit for bit.

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "motoflex/core/build_info.hpp"

PYBIND11_MODULE(_motoflex, m) {
  m.doc() = "motoflex: fit robot simulation parameters to recorded joint logs";
  m.attr("__version__") = motoflex::version();
  motoflex::python::bind_errors(m);
  motoflex::python::bind_simulate(m);
  motoflex::python::bind_logs(m);
  motoflex::python::bind_fit(m);
  motoflex::python::bind_export(m);
  motoflex::python::bind_analysis(m);
}
