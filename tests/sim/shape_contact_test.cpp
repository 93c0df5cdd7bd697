// Every collision shape against the ground: a body dropped 2 cm comes to rest where geometry
// says it must (sphere on its radius, cylinder and capsule upright and on their side, boxes,
// mesh hulls from STL/OBJ/DAE and trimeshes), a cube's hull behaves like the box, and only
// feet and contact links may touch the ground.
//
// ODE's soft contact lets a resting body sink until each of its n contacts carries
// F/n = CFM⁻¹·ERP·δ/h, i.e. δ = CFM·m·g·h/(ERP·n) = 4.91e-6 m / n for the 1.001 kg body
// (CFM 1e-4, ERP 0.2, h = 1 ms): the rest heights below are checked to 1e-8 m against
// geometry − δ with the number of contacts each shape makes (measured: equal to 1e-10).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "motoflex/sim/rollout.hpp"
#include "robot_test_support.hpp"

namespace motoflex {
namespace {

using testing::collision;
using testing::joint;
using testing::link;

constexpr double kHalfPi = 1.5707963267948966;

// A 1 kg body carrying `shapes`, with a 1 g tag on a servo'd hinge (a robot needs an actuated
// joint); both CoMs at the body's origin, so the ODE body's position is the link origin's.
std::string drop_folder(const std::string& name, const std::string& shapes,
                        const std::string& yaml_extra = "feet: [body]\n") {
  const auto dir = testing::fresh_dir("drop_" + name);
  testing::write_file(
      dir / "drop.urdf",
      testing::robot("drop", link("body", testing::box_inertial(1.0, 0.1, 0.1, 0.1) + shapes) +
                                 link("tag", testing::box_inertial(1e-3, 0.01, 0.01, 0.01)) +
                                 joint("dummy", "revolute", "body", "tag",
                                       "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" "
                                       "effort=\"1\" velocity=\"1\"/>")));
  testing::write_file(dir / "robot.yaml",
                      "name: drop\nurdf: drop.urdf\nroot_link: body\nservo: ideal\n"
                      "actuated_joints:\n  - {joint: dummy, group: g}\n" +
                          yaml_extra + "fall: {max_tilt_rad: 10.0}\ninitial_clearance_m: 0.02\n" +
                          testing::ideal_parameters());
  return dir.string();
}

struct Drop {
  double rest_z_m = 0.0;
  double speed_m_s = 0.0;
  RolloutEnd end = RolloutEnd::kCompleted;
  std::vector<double> z_m;  // every step
};

Drop drop(const std::string& dir, double duration_s = 1.5) {
  const RobotModel model = load_robot(dir, StructureOptions{});
  const ParameterSet parameters(model.parameters);
  RolloutOptions options;
  options.servo = "ideal";
  Rollout rollout(model, parameters, options, {0.0});
  Drop out;
  const double hold = 0.0;
  const auto steps = static_cast<int>(std::lround(duration_s / options.dt_s));
  for (int k = 0; k < steps && rollout.step(&hold, &hold); ++k) {
    out.z_m.push_back(rollout.body_state(0).position_m.z());
  }
  const Rollout::BodyState body = rollout.body_state(0);
  out.rest_z_m = body.position_m.z();
  out.speed_m_s = body.velocity_m_s.norm();
  out.end = rollout.end();
  return out;
}

// The sinking of a resting 1.001 kg body on `contacts` contacts.
double sink_m(int contacts) {
  return 1e-4 * 1.001 * 9.81 * 1e-3 / (0.2 * contacts);
}

void expect_rest(const std::string& label, const std::string& shapes, double geometric_z_m,
                 int contacts, const std::string& yaml_extra = "feet: [body]\n") {
  SCOPED_TRACE(label);
  const Drop d = drop(drop_folder(label, shapes, yaml_extra));
  EXPECT_EQ(d.end, RolloutEnd::kCompleted);
  EXPECT_NEAR(d.rest_z_m, geometric_z_m - sink_m(contacts), 1e-8);
  EXPECT_LT(d.speed_m_s, 1e-9);  // measured 6e-15
}

TEST(ShapeContactTest, PrimitivesComeToRestAtTheirAnalyticHeight) {
  expect_rest("sphere", collision("<sphere radius=\"0.05\"/>"), 0.05, 1);
  expect_rest("box", collision("<box size=\"0.1 0.2 0.06\"/>"), 0.03, 4);
  expect_rest("cylinder_upright", collision("<cylinder radius=\"0.04\" length=\"0.1\"/>"), 0.05, 4);
  expect_rest("cylinder_side",
              collision("<cylinder radius=\"0.04\" length=\"0.1\"/>",
                        "rpy=\"" + testing::num(kHalfPi) + " 0 0\""),
              0.04, 2);
  // A capsule's length is its cylindrical part (SDF, Bullet, Drake): caps add the radius.
  expect_rest("capsule_upright", collision("<capsule radius=\"0.03\" length=\"0.1\"/>"), 0.08, 1);
  expect_rest("capsule_side",
              collision("<capsule radius=\"0.03\" length=\"0.1\"/>",
                        "rpy=\"0 " + testing::num(kHalfPi) + " 0\""),
              0.03, 2);
  // robot.yaml capsule_links turns a link's <cylinder>s into capsules.
  expect_rest("capsule_links", collision("<cylinder radius=\"0.03\" length=\"0.1\"/>"), 0.08, 1,
              "feet: [body]\ncapsule_links: [body]\n");
}

TEST(ShapeContactTest, MeshHullsComeToRestOnTheirLowestFace) {
  const auto mesh = [](const std::string& file, const std::string& scale = "1 1 1") {
    return collision("<mesh filename=\"" + testing::mesh_path(file) + "\" scale=\"" + scale +
                     "\"/>");
  };
  expect_rest("stl_cube", mesh("cube_100mm.stl"), 0.05, 4);
  expect_rest("obj_cube", mesh("cube_100mm.obj"), 0.05, 4);
  // Millimetres with <unit meter="0.001"> and a Z_UP axis that must not rotate it.
  expect_rest("dae_cube", mesh("cube_100mm_in_mm.dae"), 0.05, 4);
  // Millimetres scaled by the URDF, from an ASCII STL.
  expect_rest("stl_ascii_scaled", mesh("cube_mm_ascii.stl", "0.001 0.001 0.001"), 0.05, 4);
  // A non-uniform scale stretches the hull: 0.1 m × 2 high.
  expect_rest("stl_stretched", mesh("cube_100mm.stl", "1 1 2"), 0.1, 4);
  // The cone stands on its base disc, 2 cm below the link origin.
  expect_rest(
      "cone",
      collision("<mesh filename=\"" + testing::mesh_path("cone.stl") + "\"/>", "xyz=\"0 0 -0.02\""),
      0.02, 8);
  // The same cube as a trimesh.
  expect_rest("trimesh_cube", mesh("cube_100mm.stl"), 0.05, 4,
              "feet: [body]\ntrimesh_links: [body]\n");
}

TEST(ShapeContactTest, DecimatedSphereHullRestsNearItsRadius) {
  // 642 vertices cut to 64: the hull keeps the support point of −z (the bottom pole), so it
  // rests no higher than the sphere; on a face near the pole it would sit lower, down to the
  // coarse polyhedron's inradius (measured: on the pole, 0.0499951 m).
  const Drop d =
      drop(drop_folder("icosphere", collision("<mesh filename=\"" +
                                              testing::mesh_path("icosphere_642.stl") + "\"/>")));
  EXPECT_EQ(d.end, RolloutEnd::kCompleted);
  EXPECT_LE(d.rest_z_m, 0.05 + 1e-6);
  EXPECT_GT(d.rest_z_m, 0.045);
}

TEST(ShapeContactTest, CubeHullTumblesLikeTheBox) {
  // Dropped on a corner from a tilted pose, the hull of a cube and the box itself follow the
  // same path: the convex collider finds the same contacts as the box collider.
  const std::string tilt = "rpy=\"0.3 0.2 0\"";
  const Drop box = drop(drop_folder("tumble_box", collision("<box size=\"0.1 0.1 0.1\"/>", tilt)));
  const Drop hull = drop(drop_folder(
      "tumble_hull",
      collision("<mesh filename=\"" + testing::mesh_path("cube_100mm.stl") + "\"/>", tilt)));
  ASSERT_EQ(box.z_m.size(), hull.z_m.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < box.z_m.size(); ++k) {
    worst = std::max(worst, std::abs(box.z_m[k] - hull.z_m[k]));
  }
  EXPECT_LT(worst, 1e-7);  // measured 1.1e-9
  EXPECT_NEAR(box.rest_z_m, 0.05 - sink_m(4), 1e-8);
  EXPECT_NEAR(hull.rest_z_m, 0.05 - sink_m(4), 1e-8);
}

TEST(ShapeContactTest, OnlyFeetAndContactLinksMayTouchTheGround) {
  const std::string ball = collision("<sphere radius=\"0.05\"/>");
  // Not a foot: touching the ground is a fall.
  const Drop fell = drop(drop_folder("not_a_foot", ball, "feet: []\n"));
  EXPECT_EQ(fell.end, RolloutEnd::kFell);
  // A contact link rests on the ground like a foot, without a foot force sensor.
  const std::string dir = drop_folder("contact_link", ball, "feet: []\ncontact_links: [body]\n");
  const Drop rests = drop(dir);
  EXPECT_EQ(rests.end, RolloutEnd::kCompleted);
  EXPECT_NEAR(rests.rest_z_m, 0.05 - sink_m(1), 1e-8);
  const RobotModel model = load_robot(dir, StructureOptions{});
  Rollout rollout(model, ParameterSet(model.parameters), RolloutOptions{}, {0.0});
  EXPECT_EQ(rollout.foot_count(), 0u);
}

}  // namespace
}  // namespace motoflex
