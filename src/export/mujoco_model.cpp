#include "mujoco_model.hpp"

#include <cstring>

namespace motoflex::detail {
namespace {

bool add_vfs_file(mjVFS& vfs, const std::string& name, const std::string& bytes) {
  if (bytes.empty()) return false;
  if (mj_makeEmptyFileVFS(&vfs, name.c_str(), static_cast<int>(bytes.size())) != 0) return false;
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, name.c_str())], bytes.data(), bytes.size());
  return true;
}

}  // namespace

MjModelPtr load_mjcf_text(const std::string& mjcf_text, const std::vector<ExportedAsset>& assets,
                          std::string& error) {
  // mjVFS holds fixed-size arrays for thousands of files: keep it off the stack.
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "motoflex_export.xml";
  if (!add_vfs_file(*vfs, name, mjcf_text)) {
    error = "cannot create MuJoCo's in-memory file";
    mj_deleteVFS(vfs.get());
    return nullptr;
  }
  for (const ExportedAsset& asset : assets) {
    if (!add_vfs_file(*vfs, asset.file, asset.bytes)) {
      error = "cannot put " + asset.file + " into MuJoCo's in-memory files";
      mj_deleteVFS(vfs.get());
      return nullptr;
    }
  }
  char buffer[1000] = "";
  MjModelPtr model(mj_loadXML(name, vfs.get(), buffer, sizeof buffer));
  mj_deleteVFS(vfs.get());
  error = buffer;
  return model;
}

}  // namespace motoflex::detail
