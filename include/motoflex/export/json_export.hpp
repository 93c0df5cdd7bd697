#pragma once

#include <string>

#include "motoflex/export/export_input.hpp"

namespace motoflex {

// The lossless export: a JSON document with
//   "format": "motoflex-parameters", "format_version": 1, "robot", "servo",
//   "parameters": {name: {"value", "unit", "default", "lower", "upper", "free"}} for every
//                 parameter of the robot, in registry order ("free": searched by the fit),
//   "joints": {joint: the joint-level values the URDF/SDF/MJCF exports carry
//   (actuator_export.hpp)}, "provenance": {"source", "fitness", "fit", "config_hash", "date",
//   "motoflex_version",
//                  "exported_at", "exported_by"} (null where best.json has no value).
// Numbers are printed to round-trip exactly.
std::string export_json(const ExportInput& input);

}  // namespace motoflex
