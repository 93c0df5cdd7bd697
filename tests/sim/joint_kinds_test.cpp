// Joints beyond the hinge: a prismatic joint slides under gravity with the analytic
// acceleration and stops at its limits, a continuous joint turns past ±π without wrapping,
// a <mimic> follower holds multiplier·leader + offset, and massless frame links change
// nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "motoflex/sim/rollout.hpp"
#include "robot_test_support.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

using testing::box_inertial;
using testing::joint;
using testing::link;

constexpr double kGravity_m_s2 = 9.81;

std::string folder(const std::string& name, const std::string& urdf_body,
                   const std::string& yaml_body) {
  const auto dir = testing::fresh_dir("joints_" + name);
  testing::write_file(dir / "r.urdf", testing::robot(name, urdf_body));
  testing::write_file(
      dir / "robot.yaml",
      "name: " + name + "\nurdf: r.urdf\nfixed_base: true\nground: false\n" + yaml_body);
  return dir.string();
}

// A block on a slider inclined 30° above the x axis, free (force limit 0): it slides down with
// a = −g·sin 30° along the axis.
std::string slider_folder(const std::string& name, const std::string& limits,
                          const std::string& servo = "velocity") {
  const double s = std::sin(std::numbers::pi / 6), c = std::cos(std::numbers::pi / 6);
  return folder(name,
                link("base", box_inertial(1.0, 0.1, 0.1, 0.1)) +
                    link("block", box_inertial(0.5, 0.05, 0.05, 0.05)) +
                    joint("slide", "prismatic", "base", "block",
                          "<axis xyz=\"" + testing::num(c) + " 0 " + testing::num(s) +
                              "\"/><limit " + limits + " effort=\"50\" velocity=\"2\"/>"),
                "servo: " + servo +
                    "\nactuated_joints:\n  - {joint: slide, group: s}\nparameters:\n"
                    "  joint.slide.gain_per_s: [4.0, 0.4, 40.0]\n"
                    "  joint.slide.force_max_n: [0.0, 0.0, 100.0]\n"
                    "  world.erp: [0.2, 0.05, 0.9]\n  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]\n");
}

// Free slide from rest for `duration_s`; the slider position after every step.
std::vector<double> slide(const RobotModel& model, double duration_s) {
  RolloutOptions options;
  options.servo.clear();
  Rollout rollout(model, ParameterSet(model.parameters), options, {0.0});
  std::vector<double> q;
  const double hold = 0.0;
  for (int k = 0; k < static_cast<int>(std::lround(duration_s / options.dt_s)); ++k) {
    EXPECT_TRUE(rollout.step(&hold, &hold));
    q.push_back(rollout.joint_angle_rad(0));
  }
  return q;
}

TEST(JointKindsTest, PrismaticJointSlidesWithTheAnalyticAcceleration) {
  const RobotModel model = load_robot(slider_folder("slide", "lower=\"-5\" upper=\"5\""), {});
  ASSERT_EQ(model.joints.size(), 1u);
  EXPECT_EQ(model.joints[0].kind, JointKind::kSlider);
  EXPECT_TRUE(model.actuators[0].prismatic);
  const std::vector<double> q = slide(model, 0.5);
  // Semi-implicit Euler: q_n = −a·h²·n(n+1)/2 exactly for a constant acceleration a.
  const double a = kGravity_m_s2 * 0.5;
  const double n = static_cast<double>(q.size());
  const double h = 1e-3;
  EXPECT_NEAR(q.back(), -a * h * h * n * (n + 1) / 2, 1e-12);  // measured 5.6e-16
  // ½at² at 0.5 s, less the Euler scheme's offset a·h·t/2 = 1.2e-3 m.
  EXPECT_NEAR(q.back(), -0.5 * a * 0.25, 2e-3);
}

// A slider's friction is read in N (joint.<J>.friction_n, friction_family.hpp) and acts as a
// budget: 1 N of the 2.4525 N of gravity along the incline leaves a = 1.4525 N / 0.5 kg, and
// 3 N holds the block.
TEST(JointKindsTest, PrismaticJointFrictionInNewtonsSlowsAndHoldsTheSlide) {
  const RobotModel model =
      load_robot(slider_folder("slide_friction", "lower=\"-5\" upper=\"5\""), {});
  ASSERT_TRUE(model.parameters.contains("joint.slide.friction_n"));
  EXPECT_FALSE(model.parameters.contains("joint.slide.friction_nm"));
  const auto slide_with = [&](double friction_n) {
    ParameterSet values(model.parameters);
    values.set("joint.slide.friction_n", friction_n);
    RolloutOptions options;
    options.servo.clear();
    Rollout rollout(model, values, options, {0.0});
    const double hold = 0.0;
    for (int k = 0; k < 500; ++k) EXPECT_TRUE(rollout.step(&hold, &hold));
    return rollout.joint_angle_rad(0);
  };
  const double a = (0.5 * 0.5 * kGravity_m_s2 - 1.0) / 0.5;
  const double n = 500.0, h = 1e-3;
  EXPECT_NEAR(slide_with(1.0), -a * h * h * n * (n + 1) / 2, 1e-9);
  EXPECT_NEAR(slide_with(3.0), 0.0, 1e-9);
}

// A slider's armature is a reflected mass, joint.<J>.armature_kg (not kg·m²): with m_a kg of
// it the 0.5 kg block under the 2.4525 N of gravity along the incline accelerates at
// F/(m_link + m_a), exactly (the inertia row is implicit: (m + m_a)·(v₁ − v₀)/h = F).
TEST(JointKindsTest, PrismaticArmatureIsAMassThatScalesTheAcceleration) {
  const RobotModel model =
      load_robot(slider_folder("slide_armature", "lower=\"-5\" upper=\"5\""), {});
  ASSERT_TRUE(model.parameters.contains("joint.slide.armature_kg"));
  EXPECT_FALSE(model.parameters.contains("joint.slide.armature_kg_m2"));
  const double force_n = 0.5 * kGravity_m_s2 * 0.5;  // m·g·sin 30°
  const double n = 500.0, h = 1e-3;
  for (const double armature_kg : {0.0, 0.5, 2.0}) {
    ParameterSet values(model.parameters);
    values.set("joint.slide.armature_kg", armature_kg);
    RolloutOptions options;
    options.servo.clear();
    Rollout rollout(model, values, options, {0.0});
    const double hold = 0.0;
    for (int k = 0; k < 500; ++k) EXPECT_TRUE(rollout.step(&hold, &hold));
    const double a = force_n / (0.5 + armature_kg);
    // Measured: |error| < 1e-15 m for each (semi-implicit Euler, q_n = −a·h²·n(n+1)/2).
    EXPECT_NEAR(rollout.joint_angle_rad(0), -a * h * h * n * (n + 1) / 2, 1e-12) << armature_kg;
  }
}

TEST(JointKindsTest, PrismaticJointStopsAtItsLimitUnlessStopsAreOff) {
  const RobotModel stopped = load_robot(slider_folder("stop", "lower=\"-0.2\" upper=\"0.2\""), {});
  EXPECT_NEAR(slide(stopped, 1.0).back(), -0.2, 1e-9);  // measured 1.2e-12
  const std::string dir = slider_folder("no_stop", "lower=\"-0.2\" upper=\"0.2\"");
  testing::write_file(std::filesystem::path(dir) / "robot.yaml", [&] {
    std::ifstream in(std::filesystem::path(dir) / "robot.yaml");
    std::stringstream text;
    text << in.rdbuf();
    return "joint_stops: false\n" + text.str();
  }());
  const RobotModel free = load_robot(dir, {});
  EXPECT_LT(slide(free, 1.0).back(), -2.0);      // ½·4.9·1² = 2.45 m
  EXPECT_EQ(free.actuators[0].lower_rad, -0.2);  // the URDF limits are kept for the motion
}

TEST(JointKindsTest, LawsForRevoluteJointsRejectAPrismaticOne) {
  try {
    load_robot(slider_folder("wrong_law", "lower=\"-1\" upper=\"1\"", "bench"), {});
    FAIL() << "a prismatic joint under the bench law must be rejected";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("joint 'slide' is prismatic"), std::string::npos)
        << error.what();
  }
}

// A 1 kg pendulum on a hinge about y (continuous, or revolute with `limits`), driven by the
// ideal servo.
std::string pendulum_urdf(const std::string& type, const std::string& extra_links = "") {
  return link("base", box_inertial(1.0, 0.1, 0.1, 0.1)) +
         link("arm", box_inertial(1.0, 0.02, 0.02, 0.2, "0 0 -0.1")) +
         joint("swing", type, "base", "arm",
               "<axis xyz=\"0 1 0\"/>" +
                   std::string(type == "revolute" ? "<limit lower=\"-1\" upper=\"1\" effort=\"10\" "
                                                    "velocity=\"5\"/>"
                                                  : "")) +
         extra_links;
}

const std::string kIdealPendulumYaml =
    "servo: ideal\nactuated_joints:\n  - {joint: swing, group: p}\nparameters:\n"
    "  ideal.torque_max_nm: [100.0, 1.0, 1000.0]\n"
    "  world.erp: [0.2, 0.05, 0.9]\n  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]\n";

TEST(JointKindsTest, ContinuousJointTurnsPastHalfATurnWithoutWrapping) {
  const RobotModel model =
      load_robot(folder("continuous", pendulum_urdf("continuous"), kIdealPendulumYaml), {});
  EXPECT_FALSE(std::isfinite(model.joints[0].lower1_rad));
  // Two and a half turns at 5 rad/s, from a start beyond π.
  Rollout rollout(model, ParameterSet(model.parameters), RolloutOptions{}, {4.0});
  EXPECT_NEAR(rollout.joint_angle_rad(0), 4.0, 1e-9);
  const double h = 1e-3;
  double worst = 0.0;
  for (int k = 1; k <= 3000; ++k) {
    const double now = 4.0 + 5.0 * h * (k - 1), next = 4.0 + 5.0 * h * k;
    ASSERT_TRUE(rollout.step(&now, &next));
    worst = std::max(worst, std::abs(rollout.joint_angle_rad(0) - next));
  }
  EXPECT_NEAR(rollout.joint_angle_rad(0), 19.0, 1e-6);
  EXPECT_LT(worst, 1e-6);  // the ideal servo reaches each command; measured 2e-13
}

TEST(JointKindsTest, MimicFollowerHoldsMultiplierTimesLeaderPlusOffset) {
  // A second pendulum on the same base follows the first at −0.5·q + 0.1 (URDF <mimic>); it
  // is not actuated and its own weight pulls on it the whole time.
  const std::string follower =
      link("arm2", box_inertial(2.0, 0.02, 0.02, 0.3, "0 0 -0.15")) +
      joint("swing2", "revolute", "base", "arm2",
            "<origin xyz=\"0.2 0 0\"/><axis xyz=\"0 1 0\"/><limit lower=\"-2\" upper=\"2\" "
            "effort=\"10\" velocity=\"5\"/><mimic joint=\"swing\" multiplier=\"-0.5\" "
            "offset=\"0.1\"/>");
  const RobotModel model =
      load_robot(folder("mimic", pendulum_urdf("revolute", follower), kIdealPendulumYaml), {});
  ASSERT_EQ(model.joints.size(), 2u);
  ASSERT_EQ(model.actuators.size(), 1u);
  const JointSpec& coupled = model.joints[1].mimic ? model.joints[1] : model.joints[0];
  ASSERT_TRUE(coupled.mimic.has_value());
  EXPECT_EQ(coupled.mimic->multiplier, -0.5);
  EXPECT_EQ(coupled.mimic->offset, 0.1);
  const std::size_t f = model.joints[1].mimic ? 1 : 0;

  Rollout rollout(model, ParameterSet(model.parameters), RolloutOptions{}, {0.3});
  const auto follower_angle = [&] {
    return dJointGetHingeAngle(RolloutOdeAccess::joint(rollout, f));
  };
  EXPECT_NEAR(follower_angle(), -0.5 * 0.3 + 0.1, 1e-12);  // placed on the coupling
  double worst = 0.0;
  // The leader swings 0.3 → 0.9 rad and back, from rest (6 rad/s, up to 10.8 rad/s²).
  const auto command = [](double t) { return 0.3 + 0.3 * (1.0 - std::cos(6.0 * t)); };
  for (int k = 1; k <= 2000; ++k) {
    const double t = 1e-3 * k;
    const double now = command(t - 1e-3), next = command(t);
    ASSERT_TRUE(rollout.step(&now, &next));
    worst = std::max(worst, std::abs(follower_angle() - (-0.5 * rollout.joint_angle_rad(0) + 0.1)));
  }
  // The coupling follows the leader's rate at the start of each step, so it lags by
  // |m·q̈|·h²/ERP ≈ 0.5 · 10.8 · 1e-6 / 0.2 = 2.7e-5 rad at most; measured 2.7e-5.
  EXPECT_LT(worst, 1e-4);
}

TEST(JointKindsTest, MasslessFrameLinksChangeNothing) {
  // The same pendulum with frame links welded everywhere (no <inertial>, or 1e-9 kg with a
  // zero inertia): same bodies, bit-identical motion.
  const std::string frames =
      link("tool0", "") +
      joint("tool0_fixed", "fixed", "arm", "tool0", "<origin xyz=\"0 0 -0.2\"/>") +
      link("imu",
           "<inertial><mass value=\"1e-9\"/><inertia ixx=\"0\" ixy=\"0\" ixz=\"0\" "
           "iyy=\"0\" iyz=\"0\" izz=\"0\"/></inertial>") +
      joint("imu_fixed", "fixed", "base", "imu");
  const RobotModel plain =
      load_robot(folder("plain", pendulum_urdf("revolute"), kIdealPendulumYaml), {});
  const RobotModel framed =
      load_robot(folder("framed", pendulum_urdf("revolute", frames), kIdealPendulumYaml), {});
  ASSERT_EQ(plain.bodies.size(), framed.bodies.size());
  for (std::size_t b = 0; b < plain.bodies.size(); ++b) {
    EXPECT_EQ(plain.bodies[b].mass_kg, framed.bodies[b].mass_kg);
    EXPECT_EQ(plain.bodies[b].inertia_kg_m2, framed.bodies[b].inertia_kg_m2);
    EXPECT_EQ(plain.bodies[b].com_W0_m, framed.bodies[b].com_W0_m);
  }
  EXPECT_EQ(framed.bodies[1].links.size(), 2u);  // arm + tool0
  // Released at 0.8 rad with a weak servo (0.3 N·m; gravity pulls with 1 kg · g · 0.1 m ·
  // sin 0.8 = 0.70 N·m) that cannot hold it.
  const auto swing = [](const RobotModel& model) {
    ParameterSet parameters(model.parameters);
    parameters.set("ideal.torque_max_nm", 0.3);
    Rollout rollout(model, parameters, RolloutOptions{}, {0.8});
    const double command = 0.8;
    for (int k = 0; k < 1000; ++k) rollout.step(&command, &command);
    return rollout.joint_angle_rad(0);
  };
  EXPECT_EQ(swing(plain), swing(framed));
  EXPECT_GT(std::abs(swing(plain) - 0.8), 0.1);  // it did swing
}

}  // namespace
}  // namespace motoflex
