#pragma once

// Internal to the exporters: MuJoCo models loaded from MJCF text held in memory.

#include <mujoco/mujoco.h>

#include <memory>
#include <string>
#include <vector>

#include "motoflex/export/exported_file.hpp"

namespace motoflex::detail {

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;
using MjDataPtr = std::unique_ptr<mjData, MjDataDeleter>;

// Compiles `mjcf_text` through a MuJoCo virtual file system holding it and `assets` (the mesh
// files it refers to; MuJoCo's VFS keys files by base name, which mesh_assets keeps unique).
// Returns null and fills `error` (MuJoCo's error buffer) when MuJoCo rejects it; a non-empty
// `error` with a model is a warning.
MjModelPtr load_mjcf_text(const std::string& mjcf_text, const std::vector<ExportedAsset>& assets,
                          std::string& error);

}  // namespace motoflex::detail
