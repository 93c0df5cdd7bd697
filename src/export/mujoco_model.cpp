#include "mujoco_model.hpp"

#include <cstring>

namespace motoflex::detail {

MjModelPtr load_mjcf_text(const std::string& mjcf_text, std::string& error) {
  // mjVFS holds fixed-size arrays for thousands of files: keep it off the stack.
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "motoflex_export.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(mjcf_text.size())) != 0) {
    error = "cannot create MuJoCo's in-memory file";
    return nullptr;
  }
  const int index = mj_findFileVFS(vfs.get(), name);
  std::memcpy(vfs->filedata[index], mjcf_text.data(), mjcf_text.size());
  char buffer[1000] = "";
  MjModelPtr model(mj_loadXML(name, vfs.get(), buffer, sizeof buffer));
  mj_deleteVFS(vfs.get());
  error = buffer;
  return model;
}

}  // namespace motoflex::detail
