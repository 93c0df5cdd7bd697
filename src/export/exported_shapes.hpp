#pragma once

// Internal to the exporters: the robot's collision shapes as SDF and MJCF geometry.

#include <string>

#include "motoflex/model/robot_model.hpp"
#include "xml_writer.hpp"

namespace motoflex::detail {

// Appends <geometry> with the shape to an SDF <collision> or <visual>: box, sphere, cylinder,
// capsule, or the mesh `mesh_uri` (the exported mesh file, relative to the SDF file, see
// exported_file.hpp) with its scale.
void add_sdf_geometry(XmlElement& parent, const ShapeGeometry& shape, const std::string& mesh_uri);

// Sets an MJCF <geom>'s type and size (box half-sizes; radius and half-length for cylinder and
// capsule, whose length MuJoCo also counts without the caps), or its mesh asset.
void set_mjcf_geom(XmlElement& geom, const ShapeGeometry& shape, const std::string& mesh_asset);

// The MJCF <mesh> asset of a mesh visual: the exported file (relative to the MJCF file) with
// the URDF scale.
void add_mjcf_visual_mesh_asset(XmlElement& asset, const VisualShape& shape,
                                const std::string& file, const std::string& name);

// The MJCF <mesh> asset of a mesh collision shape: the vertices motoflex collides (its convex
// hull, or the trimesh's vertices, which MuJoCo hulls again), inline.
void add_mjcf_mesh_asset(XmlElement& asset, const CollisionShape& shape, const std::string& name);

// A name for each shape geom: <link>_<kind><k> (<link>_box<k> for boxes, as before); visuals
// <body>_visual_<kind><k> (body names are unique, lumped link names may repeat shapes).
std::string shape_geom_name(const CollisionShape& shape, std::size_t k);
std::string visual_geom_name(const std::string& body, const VisualShape& shape, std::size_t k);

// The colour a visual is drawn in, "r g b a": its URDF material's, else a light grey.
std::string visual_rgba(const VisualShape& shape);

}  // namespace motoflex::detail
