#include "exported_shapes.hpp"

namespace motoflex::detail {

void add_sdf_geometry(XmlElement& parent, const ShapeGeometry& shape, const std::string& mesh_uri) {
  XmlElement& geometry = parent.child("geometry");
  switch (shape.kind) {
    case ShapeKind::kBox:
      geometry.child("box").text_child("size", format_vector(shape.size_m));
      return;
    case ShapeKind::kSphere:
      geometry.child("sphere").text_child("radius", shape.radius_m);
      return;
    case ShapeKind::kCylinder:
    case ShapeKind::kCapsule: {
      XmlElement& element =
          geometry.child(shape.kind == ShapeKind::kCylinder ? "cylinder" : "capsule");
      element.text_child("radius", shape.radius_m);
      element.text_child("length", shape.length_m);
      return;
    }
    case ShapeKind::kMesh: {
      XmlElement& mesh = geometry.child("mesh");
      mesh.text_child("uri", mesh_uri.empty() ? shape.mesh.uri : mesh_uri);
      mesh.text_child("scale", format_vector(shape.mesh.scale));
      return;
    }
  }
}

void set_mjcf_geom(XmlElement& geom, const ShapeGeometry& shape, const std::string& mesh_asset) {
  geom.attribute("type", to_string(shape.kind));
  switch (shape.kind) {
    case ShapeKind::kBox:
      geom.attribute("size", format_vector(0.5 * shape.size_m));
      return;
    case ShapeKind::kSphere:
      geom.attribute("size", shape.radius_m);
      return;
    case ShapeKind::kCylinder:
    case ShapeKind::kCapsule:
      geom.attribute("size", format_numbers({shape.radius_m, 0.5 * shape.length_m}));
      return;
    case ShapeKind::kMesh:
      geom.attribute("mesh", mesh_asset);
      return;
  }
}

void add_mjcf_visual_mesh_asset(XmlElement& asset, const VisualShape& shape,
                                const std::string& file, const std::string& name) {
  asset.child("mesh")
      .attribute("name", name)
      .attribute("file", file)
      .attribute("scale", format_vector(shape.mesh.scale));
}

void add_mjcf_mesh_asset(XmlElement& asset, const CollisionShape& shape, const std::string& name) {
  const std::vector<double>& xyz = shape.hull ? shape.hull->points_m : shape.trimesh->vertices_m;
  asset.child("mesh").attribute("name", name).attribute("vertex", format_numbers(xyz));
}

std::string shape_geom_name(const CollisionShape& shape, std::size_t k) {
  return shape.link + "_" + to_string(shape.kind) + std::to_string(k);
}

std::string visual_geom_name(const std::string& body, const VisualShape& shape, std::size_t k) {
  return body + "_visual_" + to_string(shape.kind) + std::to_string(k);
}

std::string visual_rgba(const VisualShape& shape) {
  const Eigen::Vector4d rgba = shape.rgba ? *shape.rgba : Eigen::Vector4d(0.75, 0.75, 0.78, 1.0);
  return format_numbers({rgba[0], rgba[1], rgba[2], rgba[3]});
}

}  // namespace motoflex::detail
