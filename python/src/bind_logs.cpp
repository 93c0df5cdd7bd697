// Joint logs and parameter files from Python:
//   log = motoflex.read_log("reference_data/nao/train/walk_050mm_2s.csv")
//   log["measured_rad"]  # (frames, joints); log["meta"]["rate_hz"]
//   motoflex.write_log("out.csv", log)                  # CSV + sidecar, numbers round-trip
//   motoflex.read_parameters("runs/x/best.json")       # name -> value
//   motoflex.write_parameters("p.json", {"motor.R_ohm": 6.5})

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "numpy_arrays.hpp"

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

namespace motoflex::python {
namespace {

py::dict meta_dict(const JointLogMeta& meta) {
  py::dict out;
  out["robot"] = meta.robot;
  out["rate_hz"] = meta.rate_hz;
  out["motion"] = meta.motion;
  out["origin"] = meta.origin;
  out["parameters"] = meta.parameters;
  out["notes"] = meta.notes;
  return out;
}

py::dict read_log(const std::string& path, bool need_commanded, bool need_measured) {
  JointLogRequirements requirements;
  requirements.need_commanded = need_commanded;
  requirements.need_measured = need_measured;
  JointLog log;
  {
    py::gil_scoped_release release;
    log = read_joint_log(path, requirements);
  }
  py::dict out;
  out["joint_names"] = log.joint_names;
  out["time_s"] = vector_array(log.time_s);
  if (log.has_commanded()) {
    out["commanded_rad"] = matrix_array(log.commanded_rad, log.frames(), log.joints());
  }
  if (log.has_measured()) {
    out["measured_rad"] = matrix_array(log.measured_rad, log.frames(), log.joints());
  }
  if (!log.imu_roll_rad.empty()) out["imu_roll_rad"] = vector_array(log.imu_roll_rad);
  if (!log.imu_pitch_rad.empty()) out["imu_pitch_rad"] = vector_array(log.imu_pitch_rad);
  out["meta"] = meta_dict(log.meta);
  out["warnings"] = log.warnings;
  return out;
}

template <typename T>
T item_or(const py::dict& dict, const char* key, T fallback) {
  return dict.contains(key) ? dict[key].cast<T>() : fallback;
}

JointLogMeta meta_from(const py::dict& log) {
  JointLogMeta meta;
  if (!log.contains("meta")) return meta;
  const py::dict source = log["meta"].cast<py::dict>();
  meta.robot = item_or<std::string>(source, "robot", "");
  meta.rate_hz = item_or<double>(source, "rate_hz", 0.0);
  meta.motion = item_or<std::string>(source, "motion", "");
  meta.origin = item_or<std::string>(source, "origin", "motoflex Python module");
  meta.parameters = item_or<std::map<std::string, double>>(source, "parameters", {});
  meta.notes = item_or<std::string>(source, "notes", "");
  return meta;
}

std::vector<double> optional_values(const py::dict& log, const char* key, std::size_t columns) {
  if (!log.contains(key) || log[key].is_none()) return {};
  return array_values(log[key].cast<DoubleArray>(), columns, key);
}

void write_log(const std::string& path, const py::dict& log, int significant_digits) {
  JointLog out;
  out.joint_names = log["joint_names"].cast<std::vector<std::string>>();
  out.time_s = array_values(log["time_s"].cast<DoubleArray>(), 1, "time_s");
  out.commanded_rad = optional_values(log, "commanded_rad", out.joint_names.size());
  out.measured_rad = optional_values(log, "measured_rad", out.joint_names.size());
  out.imu_roll_rad = optional_values(log, "imu_roll_rad", 1);
  out.imu_pitch_rad = optional_values(log, "imu_pitch_rad", 1);
  out.meta = meta_from(log);
  try {
    write_joint_log(path, out, significant_digits);
  } catch (const std::invalid_argument& error) {
    throw InputError(path, 0, "log", error.what());
  }
}

std::map<std::string, double> read_parameters(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open the parameter file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& error) {
    throw InputError(path, 0, "", std::string("not valid JSON: ") + error.what());
  }
  // best.json keeps the values under "parameters" beside its provenance.
  const nlohmann::json& values =
      json.is_object() && json.contains("parameters") && json["parameters"].is_object()
          ? json["parameters"]
          : json;
  if (!values.is_object()) throw InputError(path, 0, "", "expected an object name -> value");
  std::map<std::string, double> out;
  for (const auto& [name, value] : values.items()) {
    if (!value.is_number()) throw InputError(path, 0, name, "expected a number");
    out[name] = value.get<double>();
  }
  return out;
}

void write_parameters(const std::string& path, const std::map<std::string, double>& values) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const auto& [name, value] : values) {
    if (!std::isfinite(value)) throw InputError(path, 0, name, "must be finite");
    json[name] = value;
  }
  write_file_atomically(path, json.dump(2) + "\n");
}

}  // namespace

void bind_logs(py::module_& m) {
  m.def("read_log", &read_log, py::arg("path"), py::kw_only(), py::arg("need_commanded") = false,
        py::arg("need_measured") = false,
        "Reads a joint log CSV and its sidecar: a dict with joint_names, time_s, commanded_rad "
        "and measured_rad (frames x joints, radians), the IMU columns, meta and warnings.");
  m.def("write_log", &write_log, py::arg("path"), py::arg("log"), py::arg("significant_digits") = 0,
        "Writes a log dict (as read_log returns) as CSV + sidecar; meta needs robot and "
        "rate_hz. significant_digits 0 writes numbers that read back bit-identically.");
  m.def("read_parameters", &read_parameters, py::arg("path"),
        "name -> value of a parameter JSON file or a fit's best.json.");
  m.def("write_parameters", &write_parameters, py::arg("path"), py::arg("values"),
        "Writes name -> value as a parameter JSON file (atomically).");
}

}  // namespace motoflex::python
