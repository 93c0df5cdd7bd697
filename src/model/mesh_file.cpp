#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "motoflex/core/error.hpp"
#include "motoflex/model/mesh_geometry.hpp"

namespace motoflex {

TriangleMesh load_mesh_file(const std::string& path, const Eigen::Vector3d& scale) {
  Assimp::Importer importer;
  // URDF meshes live in their link's frame; COLLADA's up axis would rotate them (ROS's own
  // loaders ignore it too). Its <unit meter> is kept: it is how CAD exports say millimetres.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // Normals are not needed, and per-face normals would keep a cube's shared corners apart.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_DropNormals);
  if (scene == nullptr) {
    throw InputError(path, 0, "", std::string("cannot read mesh: ") + importer.GetErrorString());
  }
  TriangleMesh mesh;
  // A mirroring scale turns every triangle inside out; ODE's trimesh reads the winding.
  const bool mirrored = scale.x() * scale.y() * scale.z() < 0.0;
  for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& part = *scene->mMeshes[m];
    const auto base = static_cast<std::uint32_t>(mesh.vertex_count());
    for (unsigned int v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      mesh.vertices_m.insert(mesh.vertices_m.end(),
                             {p.x * scale.x(), p.y * scale.y(), p.z * scale.z()});
    }
    for (unsigned int f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      mesh.indices.push_back(base + face.mIndices[0]);
      mesh.indices.push_back(base + face.mIndices[mirrored ? 2 : 1]);
      mesh.indices.push_back(base + face.mIndices[mirrored ? 1 : 2]);
    }
  }
  if (mesh.triangle_count() == 0) throw InputError(path, 0, "", "mesh has no triangles");
  return mesh;
}

}  // namespace motoflex
