// Where a URDF's mesh `filename` points. ROS resolves `package://pkg/...` through its package
// index, which a robot folder copied out of a workspace does not have; the package is almost
// always the URDF's own folder or one of its ancestors (pkg/urdf/robot.urdf beside pkg/meshes/),
// or a sibling in the same workspace, so those are searched instead.

#include <filesystem>
#include <system_error>

#include "motoflex/model/urdf_tree.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

bool is_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

std::string absolute_normal(const fs::path& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  return (error ? path : absolute).lexically_normal().string();
}

std::string find_in_ancestors(const std::string& package, const fs::path& rest,
                              const fs::path& urdf_folder) {
  // First an ancestor that is the package itself, then a package folder or the bare rest
  // below any ancestor (nearest first).
  for (fs::path folder = urdf_folder;; folder = folder.parent_path()) {
    if (folder.filename() == package && is_file(folder / rest))
      return absolute_normal(folder / rest);
    if (folder == folder.parent_path() || folder.empty()) break;
  }
  for (fs::path folder = urdf_folder;; folder = folder.parent_path()) {
    if (is_file(folder / package / rest)) return absolute_normal(folder / package / rest);
    if (is_file(folder / rest)) return absolute_normal(folder / rest);
    if (folder == folder.parent_path() || folder.empty()) break;
  }
  return {};
}

}  // namespace

std::string resolve_mesh_path(const std::string& uri, const std::string& urdf_path) {
  const fs::path urdf_folder = fs::absolute(fs::path(urdf_path)).parent_path();
  const std::string package_scheme = "package://";
  const std::string file_scheme = "file://";
  if (uri.rfind(package_scheme, 0) == 0) {
    const std::string rest = uri.substr(package_scheme.size());
    const auto slash = rest.find('/');
    if (slash == std::string::npos) return {};
    return find_in_ancestors(rest.substr(0, slash), fs::path(rest.substr(slash + 1)), urdf_folder);
  }
  const fs::path path(uri.rfind(file_scheme, 0) == 0 ? uri.substr(file_scheme.size()) : uri);
  // Normalised first: the OS cannot walk `urdf/..` when the URDF's folder does not exist.
  const fs::path full = (path.is_absolute() ? path : urdf_folder / path).lexically_normal();
  return is_file(full) ? absolute_normal(full) : std::string();
}

}  // namespace motoflex
