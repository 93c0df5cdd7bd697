// motoflex's exceptions as Python exceptions: InputError (a file, line or field is wrong: the
// message names them) and ModelError (the model cannot be simulated or exported), both
// subclasses of ValueError so that generic handlers still catch them.

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex::python {

void bind_errors(pybind11::module_& m) {
  pybind11::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  pybind11::register_exception<ModelError>(m, "ModelError", PyExc_ValueError);
}

}  // namespace motoflex::python
