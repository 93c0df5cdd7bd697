#include "motoflex/export/exported_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/model/mesh_geometry.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// A binary STL is 84 bytes of header and triangle count, then 50 bytes per triangle; an ASCII
// STL ("solid ...") practically never has that size.
bool is_binary_stl(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error || size < 84) return false;
  std::ifstream in(path, std::ios::binary);
  in.seekg(80);
  std::uint32_t count = 0;
  in.read(reinterpret_cast<char*>(&count), sizeof count);
  return in && size == 84 + 50 * static_cast<std::uintmax_t>(count);
}

// MuJoCo 2.2.2 reads binary STL, OBJ and its own MSH; everything else (COLLADA, ASCII STL as
// CAD exporters write it: "number of faces should be between 1 and 200000") becomes binary STL.
bool copied_as_is(const std::string& path) {
  const std::string extension = lower(fs::path(path).extension().string());
  return extension == ".obj" || (extension == ".stl" && is_binary_stl(path));
}

// Each distinct mesh file of the robot (visual and collision shapes, model order) with the
// asset file it becomes. MuJoCo's virtual file system keys files by base name, so base names
// are kept unique.
std::vector<std::pair<std::string, std::string>> mesh_names(const RobotModel& model) {
  std::vector<std::pair<std::string, std::string>> out;
  std::set<std::string> sources, names;
  auto add = [&](const ShapeGeometry& shape) {
    if (shape.kind != ShapeKind::kMesh || shape.mesh.path.empty()) return;
    if (!sources.insert(shape.mesh.path).second) return;
    const fs::path source(shape.mesh.path);
    const std::string stem = source.stem().string();
    const std::string extension =
        copied_as_is(shape.mesh.path) ? source.extension().string() : ".stl";
    std::string name = stem + extension;
    for (int k = 2; !names.insert(lower(name)).second; ++k) {
      name = stem + "_" + std::to_string(k) + extension;
    }
    out.emplace_back(shape.mesh.path, model.name + "_meshes/" + name);
  };
  for (const BodySpec& body : model.bodies) {
    for (const VisualShape& shape : body.visuals) add(shape);
    for (const CollisionShape& shape : body.collisions) add(shape);
  }
  return out;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "mesh", "cannot read the mesh file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void append_floats(std::string& out, const float* values, std::size_t count) {
  out.append(reinterpret_cast<const char*>(values), count * sizeof(float));
}

// Binary STL (little-endian, as on every platform motoflex builds on): 80-byte header,
// triangle count, then per triangle its unit normal, three vertices and a 2-byte attribute.
std::string binary_stl(const TriangleMesh& mesh, const std::string& source) {
  std::string out(80, '\0');
  const std::string header = "motoflex export of " + fs::path(source).filename().string();
  std::memcpy(out.data(), header.data(), std::min<std::size_t>(header.size(), 79));
  const auto count = static_cast<std::uint32_t>(mesh.triangle_count());
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    Eigen::Vector3d v[3];
    for (int k = 0; k < 3; ++k) {
      const std::size_t i = mesh.indices[3 * t + k];
      v[k] = {mesh.vertices_m[3 * i], mesh.vertices_m[3 * i + 1], mesh.vertices_m[3 * i + 2]};
    }
    const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
    float values[12];
    for (int k = 0; k < 3; ++k) {
      values[k] = static_cast<float>(std::isfinite(n[k]) ? n[k] : 0.0);
      for (int c = 0; c < 3; ++c) values[3 + 3 * k + c] = static_cast<float>(v[k][c]);
    }
    append_floats(out, values, 12);
    out.append(2, '\0');
  }
  return out;
}

}  // namespace

std::vector<ExportedAsset> mesh_assets(const RobotModel& model) {
  std::vector<ExportedAsset> out;
  for (const auto& [source, file] : mesh_names(model)) {
    out.push_back(
        {file, copied_as_is(source)
                   ? read_bytes(source)
                   : binary_stl(load_mesh_file(source, Eigen::Vector3d::Ones()), source)});
  }
  return out;
}

std::string mesh_asset_file(const RobotModel& model, const std::string& source_path) {
  for (const auto& [source, file] : mesh_names(model)) {
    if (source == source_path) return file;
  }
  throw ModelError("mesh " + source_path + " is not one of robot " + model.name + "'s meshes");
}

void write_exported_file(const ExportedFile& file, const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  if (!folder.empty()) fs::create_directories(folder);
  for (const ExportedAsset& asset : file.assets) {
    const fs::path target = folder / asset.file;
    fs::create_directories(target.parent_path());
    write_file_atomically(target.string(), asset.bytes);
  }
  write_file_atomically(path, file.text);
}

}  // namespace motoflex
