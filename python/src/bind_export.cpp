// Exports from Python, as `motoflex export` writes them:
//   motoflex.export("runs/q/best.json", "scenarios/robots/nao", "mjcf", "nao.xml")
// The file is read back by the format's own parser (MuJoCo, sdformat, urdfdom) before it is
// written; a rejection is a ModelError.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/export/exporter.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace motoflex::python {
namespace {

struct ExportRequest {
  std::string parameters;  // best.json or a parameter JSON
  std::string robot_dir;
  std::string format;
  std::string out;
  std::optional<std::string> servo;
  int flex_sub_bodies = 1;
  double dt_s = 0.001;
  bool armature = true;
};

py::dict export_file(const ExportRequest& request) {
  const Exporter* exporter = find_exporter(request.format);
  if (exporter == nullptr) {
    throw InputError("", 0, "format", "expected one of " + exporter_formats());
  }
  if (!(request.dt_s > 0.0 && request.dt_s <= 0.01)) {
    throw InputError("", 0, "dt_s", "must be in (0, 0.01] s");
  }
  StructureOptions structure;
  structure.flex_sub_bodies = request.flex_sub_bodies;
  std::string servo;
  std::string reader;
  {
    py::gil_scoped_release release;
    const RobotModel model = load_robot(request.robot_dir, structure);
    servo = model.default_servo;
    if (request.servo) {
      check_servo_parameters(model, *request.servo, "", 0, "servo");
      servo = *request.servo;
    }
    ExportInput input{model, ParameterSet(model.parameters), servo, {}, request.dt_s};
    input.provenance = read_fitted_parameters(request.parameters, model.name, input.parameters);
    ExportOptions options;
    options.armature = request.armature;
    const ExportedFile file = exporter->write(input, options);
    const std::string complaint = exporter->read_back_errors(file);
    reader = exporter->reader_name();
    if (!complaint.empty()) {
      throw ModelError(reader + " rejects the " + request.format + " export: " + complaint);
    }
    write_exported_file(file, request.out);
  }
  py::dict out;
  out["format"] = request.format;
  out["out"] = request.out;
  out["servo"] = servo;
  out["read_back_by"] = reader;
  return out;
}

}  // namespace

void bind_export(py::module_& m) {
  m.def(
      "export",
      [](const std::string& parameters, const std::string& robot, const std::string& format,
         const std::string& out, std::optional<std::string> servo, int flex_sub_bodies, double dt_s,
         bool armature) {
        return export_file(
            {parameters, robot, format, out, servo, flex_sub_bodies, dt_s, armature});
      },
      py::arg("parameters"), py::arg("robot"), py::arg("format"), py::arg("out"), py::kw_only(),
      py::arg("servo") = py::none(), py::arg("flex_sub_bodies") = 1, py::arg("dt_s") = 0.001,
      py::arg("armature") = true,
      "Writes the fitted parameters (best.json or a parameter JSON) for the robot folder in "
      "format json|urdf|sdf|mjcf, checked by that format's parser.");
  m.def(
      "export_formats",
      [] {
        std::vector<std::string> formats;
        for (const auto& exporter : exporters()) formats.push_back(exporter.format);
        return formats;
      },
      "The formats export() writes.");
}

}  // namespace motoflex::python
