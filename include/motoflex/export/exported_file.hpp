#pragma once

// An exported file with the files it refers to (meshes), written side by side.

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// A file an export refers to by a path relative to the exported file ('/'-separated).
struct ExportedAsset {
  std::string file;   // e.g. "mini_arm_meshes/base.stl"
  std::string bytes;  // its contents
};

struct ExportedFile {
  std::string text;                   // the URDF, SDF, MJCF or JSON document
  std::vector<ExportedAsset> assets;  // written next to it
};

// Every mesh file the robot's visual and collision shapes name, as the SDF and MJCF exports
// refer to them: "<robot>_meshes/<file name>" (a number appended to a repeated name). STL and
// OBJ files are copied byte for byte; other formats (DAE, ...), which MuJoCo 2.2.2 cannot read,
// are converted to binary STL through assimp (as motoflex reads them: node transforms and the
// COLLADA unit applied, unscaled; the export applies the URDF scale). Throws InputError when a
// mesh cannot be read.
std::vector<ExportedAsset> mesh_assets(const RobotModel& model);

// The asset file name of the mesh at `source_path` (MeshSource::path), as mesh_assets names it.
std::string mesh_asset_file(const RobotModel& model, const std::string& source_path);

// Writes `file.text` to `path` (atomically) and each asset relative to its folder.
void write_exported_file(const ExportedFile& file, const std::string& path);

}  // namespace motoflex
