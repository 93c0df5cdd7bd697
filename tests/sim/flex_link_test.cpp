// The flexible-link spring (seed 001 eq. 1, integrated implicitly through an ODE motor row):
// a horizontal cantilever split in two must bend by exactly τ/k under its own load and swing
// at √(k/I) about the split.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/rollout.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;
constexpr double kSpring_nm_per_rad = 200.0;
constexpr double kTipMass_kg = 1.0;
constexpr double kBeamMass_kg = 0.2;
constexpr double kBeamLength_m = 0.4;

// A welded stand, an actuated shoulder (held at 0 by the ideal servo) and a 0.4 m beam along +x
// with a 1 kg mass welded to its end. The beam is the flexible link.
const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="cantilever">
  <link name="base">
    <inertial><origin xyz="0 0 0.5"/><mass value="1.0"/>
      <inertia ixx="1e-3" ixy="0" ixz="0" iyy="1e-3" iyz="0" izz="1e-3"/></inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="beam"/>
    <origin xyz="0 0 1.0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="100" velocity="10"/>
  </joint>
  <link name="beam">
    <inertial><origin xyz="0.2 0 0"/><mass value="0.2"/>
      <inertia ixx="1.3333333e-5" ixy="0" ixz="0" iyy="2.6733333e-3" iyz="0" izz="2.6733333e-3"/>
    </inertial>
  </link>
  <joint name="tip_weld" type="fixed">
    <parent link="beam"/><child link="tip"/><origin xyz="0.4 0 0"/>
  </joint>
  <link name="tip">
    <inertial><origin xyz="0 0 0"/><mass value="1.0"/>
      <inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
  </link>
</robot>
)";

const char* kRobotYaml = R"(name: cantilever
urdf: cantilever.urdf
root_link: base
fixed_base: true
torso_link: base
servo: ideal
actuated_joints:
  - {joint: shoulder, group: S}
held_joints: {}
universal_joints: []
flexible_links: [beam]
feet: []
fall: {max_tilt_rad: 10.0, min_torso_height_m: 0.0}
initial_clearance_m: 0.0
parameters:
  ideal.torque_max_nm: [100.0, 1.0, 1000.0]
  flex.spring_nm_per_rad: [200.0, 10.0, 50000.0]
  flex.damping_nm_s_per_rad: [0.5, 0.0001, 50.0]
  flex.friction_nm: [0.0, 0.0, 10.0]
  contact.mu: [1.0, 0.1, 2.0]
  contact.soft_erp: [0.2, 0.05, 0.9]
  contact.soft_cfm: [1.0e-4, 1.0e-7, 1.0e-2]
  contact.slip: [1.0e-3, 1.0e-5, 0.05]
  world.erp: [0.2, 0.05, 0.9]
  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]
  sensor.resolution_bits: [0, 0, 16]
  sensor.noise_rad: [0.0, 0.0, 0.01]
  sensor.delay_s: [0.0, 0.0, 0.05]
)";

class FlexLinkTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(std::filesystem::temp_directory_path() /
                                     ("motoflex_flex_link_test_" + std::to_string(getpid())));
    std::filesystem::create_directories(*dir_);
    std::ofstream(*dir_ / "cantilever.urdf") << kUrdf;
    std::ofstream(*dir_ / "robot.yaml") << kRobotYaml;
    model_ = new RobotModel(load_robot_model(dir_->string(), {2, true}));
  }
  static void TearDownTestSuite() {
    delete model_;
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }

  static int body_named(const std::string& name) {
    for (std::size_t b = 0; b < model_->bodies.size(); ++b) {
      if (model_->bodies[b].name == name) return static_cast<int>(b);
    }
    ADD_FAILURE() << "no body " << name;
    return 0;
  }

  // Bending of the outer piece relative to the inner one about +y (tip down is positive).
  static double bend_rad(const Rollout& rollout) {
    auto pitch = [&](int b) {
      const dReal* R = dBodyGetRotation(RolloutOdeAccess::body(rollout, b));
      return std::atan2(-R[8], R[0]);  // rotation about y of the body's x axis: (R20, R00)
    };
    return pitch(body_named("beam#1")) - pitch(body_named("beam"));
  }

  static std::filesystem::path* dir_;
  static RobotModel* model_;
};
std::filesystem::path* FlexLinkTest::dir_ = nullptr;
RobotModel* FlexLinkTest::model_ = nullptr;

TEST_F(FlexLinkTest, CantileverSplitsIntoTwoPiecesWithOneFlexJoint) {
  ASSERT_EQ(model_->joints.size(), 2u);
  const JointSpec& flex = model_->joints[1];
  EXPECT_EQ(flex.kind, JointKind::kFlex);
  EXPECT_LT((flex.anchor_W0_m - Eigen::Vector3d(0.2, 0.0, 1.0)).norm(), 1e-12);
  EXPECT_LT((flex.axis1_W0 - Eigen::Vector3d::UnitY()).norm(), 1e-12);
  EXPECT_LT((flex.axis2_W0 - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  // The outer piece carries the tip mass.
  EXPECT_NEAR(model_->bodies[body_named("beam#1")].mass_kg, kBeamMass_kg / 2 + kTipMass_kg, 1e-12);
}

TEST_F(FlexLinkTest, StaticDeflectionIsLoadTorqueOverSpring) {
  ParameterSet params(model_->parameters);
  params.set("flex.spring_nm_per_rad", kSpring_nm_per_rad);
  params.set("flex.damping_nm_s_per_rad", 5.0);  // about critical: settles within 0.2 s
  RolloutOptions options;
  options.servo = "ideal";
  Rollout rollout(*model_, params, options, {0.0});
  const double hold = 0.0;
  for (int k = 0; k < 1000; ++k) ASSERT_TRUE(rollout.step(&hold, &hold));
  // Load about the split (x = 0.2 m): outer beam half at its centre (lever 0.1 m) and the tip
  // (lever 0.2 m); the levers shorten by cos α once bent.
  const double torque_nm =
      kGravity_m_s2 * (kBeamMass_kg / 2 * kBeamLength_m / 4 + kTipMass_kg * kBeamLength_m / 2);
  const double bend = bend_rad(rollout);
  const double expected = torque_nm * std::cos(bend) / kSpring_nm_per_rad;
  std::printf("[ flex    ] static bend %.6f rad, τ/k %.6f rad (%+.3f %%)\n", bend, expected,
              100.0 * (bend / expected - 1.0));
  EXPECT_NEAR(bend, expected, 0.005 * expected);
  EXPECT_NEAR(rollout.joint_angle_rad(0), 0.0, 1e-6);  // the shoulder is held
}

TEST_F(FlexLinkTest, LightlyDampedBeamSwingsAtItsNaturalFrequency) {
  ParameterSet params(model_->parameters);
  params.set("flex.spring_nm_per_rad", kSpring_nm_per_rad);
  params.set("flex.damping_nm_s_per_rad", 1e-4);
  RolloutOptions options;
  options.servo = "ideal";
  Rollout rollout(*model_, params, options, {0.0});
  // Moment of inertia of the outer body (half beam + tip) about the flex axis.
  const BodySpec& outer = model_->bodies[body_named("beam#1")];
  const Eigen::Vector3d lever = outer.com_W0_m - model_->joints[1].anchor_W0_m;
  const double inertia =
      outer.inertia_kg_m2(1, 1) + outer.mass_kg * (lever.x() * lever.x() + lever.z() * lever.z());
  const double period_s = 2.0 * std::numbers::pi * std::sqrt(inertia / kSpring_nm_per_rad);
  // Released straight, it swings about the static bend; time the upward crossings of it.
  const double rest = kGravity_m_s2 *
                      (kBeamMass_kg / 2 * kBeamLength_m / 4 + kTipMass_kg * kBeamLength_m / 2) /
                      kSpring_nm_per_rad;
  const double hold = 0.0;
  double previous = bend_rad(rollout) - rest;
  std::vector<double> crossings;
  for (int k = 1; k <= 1000; ++k) {
    ASSERT_TRUE(rollout.step(&hold, &hold));
    const double now = bend_rad(rollout) - rest;
    if (previous < 0.0 && now >= 0.0)
      crossings.push_back((k - 1 + previous / (previous - now)) * 1e-3);
    previous = now;
  }
  ASSERT_GE(crossings.size(), 5u);
  const double measured_s =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  std::printf("[ flex    ] period %.6f s, 2π√(I/k) %.6f s (%+.3f %%)\n", measured_s, period_s,
              100.0 * (measured_s / period_s - 1.0));
  EXPECT_NEAR(measured_s, period_s, 0.01 * period_s);
}

}  // namespace
}  // namespace motoflex
