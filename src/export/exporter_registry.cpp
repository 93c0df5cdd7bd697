#include <nlohmann/json.hpp>

#include "motoflex/export/exporter.hpp"
#include "motoflex/export/json_export.hpp"
#include "motoflex/export/mjcf_export.hpp"
#include "motoflex/export/parser_check.hpp"
#include "motoflex/export/sdf_export.hpp"
#include "motoflex/export/urdf_export.hpp"

namespace motoflex {
namespace {

ExportedFile write_json(const ExportInput& input, const ExportOptions&) {
  return {export_json(input), {}};
}
std::string json_errors(const ExportedFile& file) {
  return nlohmann::json::accept(file.text) ? "" : "not valid JSON";
}
std::string json_reader() {
  return "nlohmann::json";
}

ExportedFile write_urdf(const ExportInput& input, const ExportOptions&) {
  return {export_urdf(input), {}};
}
std::string urdf_errors(const ExportedFile& file) {
  return urdfdom_errors(file.text);
}
std::string urdf_reader() {
  return parser_name("urdf");
}

ExportedFile write_sdf(const ExportInput& input, const ExportOptions&) {
  return {export_sdf(input), mesh_assets(input.model)};
}
// sdformat keeps mesh URIs as written (Gazebo resolves them next to the file).
std::string sdf_errors(const ExportedFile& file) {
  return sdformat_errors(file.text);
}
std::string sdf_reader() {
  return parser_name("sdf");
}

ExportedFile write_mjcf(const ExportInput& input, const ExportOptions& options) {
  MjcfOptions mjcf;
  mjcf.armature = options.armature;
  return {export_mjcf(input, mjcf), mesh_assets(input.model)};
}
std::string mjcf_errors(const ExportedFile& file) {
  return mujoco_errors(file.text, file.assets);
}
std::string mjcf_reader() {
  return parser_name("mjcf");
}

}  // namespace

const std::vector<Exporter>& exporters() {
  static const std::vector<Exporter> list = {
      {"json", "every parameter and the joint-level actuator values", write_json, json_errors,
       json_reader},
      {"urdf", "the robot's URDF with fitted joint dynamics and transmissions", write_urdf,
       urdf_errors, urdf_reader},
      {"sdf", "SDFormat 1.9 (Gazebo) with fitted joint dynamics", write_sdf, sdf_errors,
       sdf_reader},
      {"mjcf", "MuJoCo with position actuators standing in for the servos", write_mjcf, mjcf_errors,
       mjcf_reader},
  };
  return list;
}

const Exporter* find_exporter(const std::string& format) {
  for (const Exporter& exporter : exporters()) {
    if (exporter.format == format) return &exporter;
  }
  return nullptr;
}

std::string exporter_formats() {
  std::string names;
  for (const Exporter& exporter : exporters()) {
    names += (names.empty() ? "" : "|") + exporter.format;
  }
  return names;
}

}  // namespace motoflex
