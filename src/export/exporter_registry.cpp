#include <nlohmann/json.hpp>

#include "motoflex/export/exporter.hpp"
#include "motoflex/export/json_export.hpp"
#include "motoflex/export/mjcf_export.hpp"
#include "motoflex/export/parser_check.hpp"
#include "motoflex/export/sdf_export.hpp"
#include "motoflex/export/urdf_export.hpp"

namespace motoflex {
namespace {

std::string write_json(const ExportInput& input, const ExportOptions&) {
  return export_json(input);
}
std::string json_errors(const std::string& text) {
  return nlohmann::json::accept(text) ? "" : "not valid JSON";
}
std::string json_reader() {
  return "nlohmann::json";
}

std::string write_urdf(const ExportInput& input, const ExportOptions&) {
  return export_urdf(input);
}
std::string urdf_reader() {
  return parser_name("urdf");
}

std::string write_sdf(const ExportInput& input, const ExportOptions&) {
  return export_sdf(input);
}
std::string sdf_reader() {
  return parser_name("sdf");
}

std::string write_mjcf(const ExportInput& input, const ExportOptions& options) {
  MjcfOptions mjcf;
  mjcf.armature = options.armature;
  return export_mjcf(input, mjcf);
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
       urdfdom_errors, urdf_reader},
      {"sdf", "SDFormat 1.9 (Gazebo) with fitted joint dynamics", write_sdf, sdformat_errors,
       sdf_reader},
      {"mjcf", "MuJoCo with position actuators standing in for the servos", write_mjcf,
       mujoco_errors, mjcf_reader},
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
