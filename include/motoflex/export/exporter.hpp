#pragma once

// The export formats, keyed by `motoflex export --format`: each writes a fitted parameter set
// in another simulator's format and names the parser that reads the file back. A new format is
// its writer's file plus one line in src/export/exporter_registry.cpp.

#include <string>
#include <vector>

#include "motoflex/export/export_input.hpp"
#include "motoflex/export/exported_file.hpp"

namespace motoflex {

struct ExportOptions {
  bool armature = true;  // MJCF: write the actuators' armature (rotor inertia)
};

struct Exporter {
  std::string format;       // --format value, e.g. "mjcf"
  std::string description;  // one line for help texts
  // Writes the file's text and the mesh files it refers to (SDF, MJCF). Throws ModelError when
  // the parameters cannot be exported.
  ExportedFile (*write)(const ExportInput& input, const ExportOptions& options);
  // The format's own parser reads the file (with its meshes) back: its complaints, or "" when
  // it accepts it.
  std::string (*read_back_errors)(const ExportedFile& file);
  // Who read it back, for reports ("MuJoCo 2.2.2").
  std::string (*reader_name)();
};

const std::vector<Exporter>& exporters();
// The exporter of `format`, or nullptr.
const Exporter* find_exporter(const std::string& format);
// "json|urdf|sdf|mjcf" for messages.
std::string exporter_formats();

}  // namespace motoflex
