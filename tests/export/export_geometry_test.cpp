// Exports a viewer can show: every bundled robot's MJCF export loads in MuJoCo 2.2.2 from the
// written file with its meshes, every body carries at least one visual geom (group 1, no
// collisions, no mass: the bodies' masses stay the model's), the mesh-described mini_arm draws
// its STL meshes (copied next to the file byte for byte), a DAE visual is converted to an STL
// MuJoCo reads at the right size, and the SDF export's links carry <visual> elements that
// sdformat 12 parses.

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sdf/Geometry.hh>
#include <sdf/Link.hh>
#include <sdf/Mesh.hh>
#include <sdf/Model.hh>
#include <sdf/Root.hh>
#include <sdf/Visual.hh>
#include <sdf/World.hh>

#include "export_test_support.hpp"
#include "motoflex/export/exporter.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "robot_test_support.hpp"

namespace motoflex {
namespace {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;

const char* const kBundledRobots[] = {"nao", "nao_motoflex_2011", "titan8", "servo_pendulum",
                                      "mini_arm"};

std::filesystem::path write_export(const RobotModel& model, const std::string& format,
                                   const std::string& name) {
  const ExportInput input{model, ParameterSet(model.parameters), model.default_servo, {}, 0.001};
  const Exporter* exporter = find_exporter(format);
  const ExportedFile file = exporter->write(input, {});
  EXPECT_EQ(exporter->read_back_errors(file), "") << name;
  const auto path = testing::fresh_export_dir("geometry_" + name) / (name + "." + format);
  write_exported_file(file, path.string());
  return path;
}

// Loads the written file from disk, meshes and all, as a MuJoCo user would.
ModelPtr load_from_disk(const std::filesystem::path& path) {
  char error[1000] = "";
  ModelPtr m(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  EXPECT_STREQ(error, "") << path;
  return m;
}

bool is_visual(const mjModel& m, int g) {
  return m.geom_group[g] == 1 && m.geom_contype[g] == 0 && m.geom_conaffinity[g] == 0;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ExportGeometry, EveryBundledRobotsMjcfHasVisualGeomsOnEveryBody) {
  for (const char* robot : kBundledRobots) {
    const auto model = testing::load_robot(robot);
    const ModelPtr m = load_from_disk(write_export(*model, "mjcf", robot));
    ASSERT_TRUE(m) << robot;
    const ParameterSet parameters(model->parameters);
    for (const BodySpec& body : model->bodies) {
      const int id = mj_name2id(m.get(), mjOBJ_BODY, body.name.c_str());
      ASSERT_GE(id, 0) << robot << " " << body.name;
      int visuals = 0;
      for (int g = 0; g < m->ngeom; ++g) visuals += m->geom_bodyid[g] == id && is_visual(*m, g);
      EXPECT_GE(visuals, 1) << robot << " " << body.name;
      // Visual geoms add no mass (the bench arm is the point mass bench.mass_kg).
      const bool bench_arm = std::string(robot) == "servo_pendulum" && body.name == "arm";
      EXPECT_EQ(m->body_mass[id], bench_arm ? parameters.get("bench.mass_kg") : body.mass_kg)
          << robot << " " << body.name;
    }
  }
}

TEST(ExportGeometry, MiniArmDrawsItsStlMeshesCopiedNextToTheFile) {
  const auto model = testing::load_robot("mini_arm");
  const auto path = write_export(*model, "mjcf", "mini_arm");
  const ModelPtr m = load_from_disk(path);
  ASSERT_TRUE(m);
  int mesh_visuals = 0;
  for (int g = 0; g < m->ngeom; ++g)
    mesh_visuals += is_visual(*m, g) && m->geom_type[g] == mjGEOM_MESH;
  EXPECT_EQ(mesh_visuals, 5);  // base, turntable, upper arm, forearm, gripper
  for (const char* mesh : {"base", "turntable", "upper_arm", "forearm", "gripper"}) {
    const auto copy = path.parent_path() / "mini_arm_meshes" / (std::string(mesh) + ".stl");
    ASSERT_TRUE(std::filesystem::exists(copy)) << copy;
    EXPECT_EQ(read_bytes(copy),
              read_bytes(testing::robot_dir("mini_arm") + "/meshes/" + mesh + ".stl"));
  }
}

TEST(ExportGeometry, SdfLinksCarryVisualsWithTheExportedMeshes) {
  for (const char* robot : kBundledRobots) {
    const auto model = testing::load_robot(robot);
    const auto path = write_export(*model, "sdf", robot);
    sdf::Root root;
    const sdf::Errors errors = root.Load(path.string());
    EXPECT_TRUE(errors.empty()) << robot << ": " << (errors.empty() ? "" : errors[0].Message());
    ASSERT_GE(root.WorldCount(), 1u);
    const sdf::Model* exported = root.WorldByIndex(0)->ModelByName(model->name);
    ASSERT_NE(exported, nullptr) << robot;
    ASSERT_EQ(exported->LinkCount(), model->bodies.size()) << robot;
    for (std::size_t l = 0; l < exported->LinkCount(); ++l) {
      const sdf::Link* link = exported->LinkByIndex(l);
      EXPECT_GE(link->VisualCount(), 1u) << robot << " " << link->Name();
      for (std::size_t v = 0; v < link->VisualCount(); ++v) {
        const sdf::Mesh* mesh = link->VisualByIndex(v)->Geom()->MeshShape();
        if (mesh == nullptr) continue;
        // A relative URI next to the SDF file, where the export put the mesh.
        EXPECT_TRUE(std::filesystem::exists(path.parent_path() / mesh->Uri())) << mesh->Uri();
      }
    }
  }
}

// A one-hinge robot whose cube link (1 kg, 100 mm) shows `mesh_xml` as its visual.
RobotModel mesh_visual_robot(const std::string& name, const std::string& mesh_xml) {
  const auto dir = testing::fresh_export_dir(name + "_robot");
  const std::string visual = "<visual><geometry>" + mesh_xml + "</geometry></visual>";
  testing::write_file(
      dir / (name + ".urdf"),
      testing::robot(name,
                     testing::link("base", testing::box_inertial(1.0, 0.1, 0.1, 0.1)) +
                         testing::link("cube", testing::box_inertial(1.0, 0.1, 0.1, 0.1) + visual) +
                         testing::joint("hinge", "revolute", "base", "cube",
                                        "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" "
                                        "upper=\"1\" effort=\"1\" velocity=\"1\"/>")));
  testing::write_file(dir / "robot.yaml",
                      "name: " + name + "\nurdf: " + name +
                          ".urdf\nroot_link: base\nfixed_base: true\n"
                          "servo: ideal\nactuated_joints:\n  - {joint: hinge, group: g}\n" +
                          testing::ideal_parameters());
  return load_robot_model(dir.string(), StructureOptions{});
}

// MuJoCo turns a mesh onto its principal axes (any for a cube), so the size is checked by the
// longest vertex distance: the cube's space diagonal.
double longest_vertex_distance_m(const mjModel& m, int mesh) {
  const int first = m.mesh_vertadr[mesh];
  double longest_m = 0.0;
  for (int a = first; a < first + m.mesh_vertnum[mesh]; ++a) {
    for (int b = first; b < a; ++b) {
      double squared = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double d = m.mesh_vert[3 * a + k] - m.mesh_vert[3 * b + k];
        squared += d * d;
      }
      longest_m = std::max(longest_m, std::sqrt(squared));
    }
  }
  return longest_m;
}

TEST(ExportGeometry, DaeVisualIsConvertedToAnStlMujocoReadsAtItsSize) {
  // A 100 mm cube authored in millimetres (COLLADA <unit meter="0.001">).
  const RobotModel model = mesh_visual_robot(
      "dae", "<mesh filename=\"" + testing::mesh_path("cube_100mm_in_mm.dae") + "\"/>");
  const auto path = write_export(model, "mjcf", "dae");
  EXPECT_TRUE(std::filesystem::exists(path.parent_path() / "dae_meshes/cube_100mm_in_mm.stl"));
  const ModelPtr m = load_from_disk(path);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->nmesh, 1);
  EXPECT_NEAR(longest_vertex_distance_m(*m, 0), 0.1 * std::sqrt(3.0), 1e-6);  // measured 2e-9
}

TEST(ExportGeometry, AsciiStlIsConvertedToABinaryStlMujocoReads) {
  // The same cube as an ASCII STL in millimetres with the URDF's scale 0.001: MuJoCo 2.2.2
  // rejects ASCII STL ("number of faces should be between 1 and 200000"), found on the
  // third-party desk arm's wrist mesh; the export writes it as binary STL, the scale kept.
  const RobotModel model =
      mesh_visual_robot("ascii", "<mesh filename=\"" + testing::mesh_path("cube_mm_ascii.stl") +
                                     "\" scale=\"0.001 0.001 0.001\"/>");
  const auto path = write_export(model, "mjcf", "ascii");
  const auto stl = path.parent_path() / "ascii_meshes/cube_mm_ascii.stl";
  ASSERT_TRUE(std::filesystem::exists(stl));
  EXPECT_EQ(std::filesystem::file_size(stl), 84u + 50u * 12u);  // 12 triangles, binary
  const ModelPtr m = load_from_disk(path);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->nmesh, 1);
  EXPECT_NEAR(longest_vertex_distance_m(*m, 0), 0.1 * std::sqrt(3.0), 1e-6);
}

}  // namespace
}  // namespace motoflex
