// Reading URDFs as they come: package:// meshes found beside or above the URDF, <capsule>
// accepted, a floating root joint read as a free base, and every bad link or joint reported
// at once with its line.

#include "motoflex/model/urdf_tree.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_test_support.hpp"
#include "robot_test_support.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using testing::collision;
using testing::joint;
using testing::link;

const std::string kInertial = testing::box_inertial(1.0, 0.1, 0.1, 0.1);

UrdfTree read(const fs::path& path, const std::string& text, ErrorCollector& errors) {
  testing::write_file(path, text);
  return read_urdf_tree(path.string(), errors);
}

TEST(UrdfTreeTest, PackagePathsResolveAgainstTheUrdfsFolderAndItsParents) {
  const std::string data = std::string(MOTOFLEX_SOURCE_DIR) + "/tests/data/robots/quadruped";
  ErrorCollector errors;
  const UrdfTree quad = read_urdf_tree(data + "/urdf/quad.urdf", errors);
  EXPECT_TRUE(errors.empty());
  const UrdfLink& foot = quad.links[quad.link_index("FL_foot")];
  ASSERT_EQ(foot.collisions.size(), 1u);
  EXPECT_EQ(foot.collisions[0].shape.mesh.path,
            fs::path(data + "/meshes/foot.stl").lexically_normal());

  // A workspace: the mesh in a sibling package, and a package cloned under another name.
  const fs::path ws = testing::fresh_dir("mesh_paths");
  testing::write_file(ws / "src/meshes_pkg/meshes/m.stl", "solid m\nendsolid m\n");
  testing::write_file(ws / "src/clone/meshes/c.stl", "solid c\nendsolid c\n");
  const std::string urdf = (ws / "src/robot_pkg/urdf/r.urdf").string();
  testing::write_file(urdf, "");
  EXPECT_EQ(resolve_mesh_path("package://meshes_pkg/meshes/m.stl", urdf),
            (ws / "src/meshes_pkg/meshes/m.stl").string());
  const std::string cloned = (ws / "src/clone/urdf/c.urdf").string();
  EXPECT_EQ(resolve_mesh_path("package://original_name/meshes/c.stl", cloned),
            (ws / "src/clone/meshes/c.stl").string());
  EXPECT_EQ(resolve_mesh_path("../meshes/c.stl", cloned), (ws / "src/clone/meshes/c.stl").string());
  EXPECT_EQ(resolve_mesh_path("file://" + (ws / "src/clone/meshes/c.stl").string(), urdf),
            (ws / "src/clone/meshes/c.stl").string());
  EXPECT_EQ(resolve_mesh_path("package://nowhere/meshes/x.stl", urdf), "");
}

TEST(UrdfTreeTest, CapsuleTagIsACapsuleAndTheLinksOtherShapesStay) {
  // urdfdom alone rejects <capsule> and drops every shape of the link with it.
  ErrorCollector errors;
  const UrdfTree tree =
      read(testing::fresh_dir("capsule") / "c.urdf",
           testing::robot(
               "c", link("a", kInertial + collision("<capsule radius=\"0.02\" length=\"0.1\"/>") +
                                  collision("<box size=\"0.1 0.1 0.1\"/>"))),
           errors);
  EXPECT_TRUE(errors.empty());
  const UrdfLink& a = tree.links[tree.link_index("a")];
  ASSERT_EQ(a.collisions.size(), 2u);
  EXPECT_EQ(a.collisions[0].shape.kind, ShapeKind::kCapsule);
  EXPECT_EQ(a.collisions[0].shape.radius_m, 0.02);
  EXPECT_EQ(a.collisions[0].shape.length_m, 0.1);
  EXPECT_EQ(a.collisions[1].shape.kind, ShapeKind::kBox);
}

TEST(UrdfTreeTest, FloatingRootJointMakesItsChildTheBase) {
  ErrorCollector errors;
  const UrdfTree tree = read(testing::fresh_dir("floating") / "f.urdf",
                             testing::robot("f", link("world", "") + link("base", kInertial) +
                                                     joint("float", "floating", "world", "base")),
                             errors);
  EXPECT_TRUE(errors.empty());
  EXPECT_EQ(tree.links[tree.root_link].name, "base");
}

TEST(UrdfTreeTest, EveryBadLinkAndJointIsReportedWithItsLine) {
  ErrorCollector errors;
  const std::string urdf = testing::robot(
      "bad", link("base", kInertial) +  // line 3
                 link("heavy",
                      "<inertial><mass value=\"2e4\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" "
                      "iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>") +  // line 4
                 link("thin",
                      "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" "
                      "iyy=\"0.1\" iyz=\"0\" izz=\"0.1\"/></inertial>") +  // line 5
                 link("frame",
                      "<inertial><mass value=\"1e-9\"/><inertia ixx=\"0\" ixy=\"0\" ixz=\"0\" "
                      "iyy=\"0\" iyz=\"0\" izz=\"0\"/></inertial>") +  // 6: fine
                 joint("a", "fixed", "base", "heavy") +
                 joint("b", "planar", "base", "thin") +     // 7, 8
                 joint("c", "floating", "base", "frame"));  // line 9
  const UrdfTree tree = read(testing::fresh_dir("bad_links") / "bad.urdf", urdf, errors);
  ASSERT_EQ(errors.size(), 4u);
  EXPECT_EQ(errors.errors()[0].line(), 4);
  EXPECT_NE(errors.errors()[0].message().find("above 10 t"), std::string::npos);
  EXPECT_EQ(errors.errors()[1].line(), 5);
  EXPECT_NE(errors.errors()[1].message().find("triangle inequality"), std::string::npos);
  EXPECT_EQ(errors.errors()[2].field(), "b.type");
  EXPECT_EQ(errors.errors()[3].field(), "c.type");
  EXPECT_TRUE(tree.links[tree.link_index("frame")].is_frame_link());
}

}  // namespace
}  // namespace motoflex
