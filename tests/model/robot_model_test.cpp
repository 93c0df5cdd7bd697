// Structure of the loaded robots: lumping welded links into bodies, merging hinge pairs into
// universal joints and splitting flexible links must not change the robot's mass distribution.

#include "motoflex/model/robot_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "motoflex/model/robot_loader.hpp"

namespace motoflex {
namespace {

std::string robot_dir(const std::string& name) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name;
}

// Sum of the <mass value="..."/> entries of a URDF, read from the text independently of the
// loader.
double urdf_total_mass_kg(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::regex mass(R"(<mass\s+value\s*=\s*"([^"]+)\")");
  double total = 0.0;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), mass); it != std::sregex_iterator();
       ++it) {
    total += std::stod((*it)[1].str());
  }
  return total;
}

struct MassProperties {
  double mass_kg = 0.0;
  Eigen::Vector3d com_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about com_m
};

// Whole-robot mass, CoM and inertia about that CoM in the build configuration, from the bodies.
MassProperties whole_robot(const RobotModel& model) {
  MassProperties out;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  for (const BodySpec& body : model.bodies) {
    out.mass_kg += body.mass_kg;
    first_moment += body.mass_kg * body.com_W0_m;
  }
  out.com_m = first_moment / out.mass_kg;
  for (const BodySpec& body : model.bodies) {
    const Eigen::Vector3d d = body.com_W0_m - out.com_m;
    out.inertia_kg_m2 +=
        body.inertia_kg_m2 +
        body.mass_kg * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return out;
}

struct Variant {
  int flex_sub_bodies;
  bool universal_joints;
};
const Variant kVariants[] = {{1, true}, {1, false}, {2, true}, {3, true}, {3, false}};

TEST(RobotModelTest, LumpingAndSplittingConserveMassComAndInertia) {
  for (const std::string robot : {"nao", "titan8", "servo_pendulum"}) {
    const RobotModel reference = load_robot_model(robot_dir(robot), {1, true});
    const MassProperties ref = whole_robot(reference);
    EXPECT_NEAR(ref.mass_kg, urdf_total_mass_kg(reference.urdf_path), 1e-12) << robot;
    for (const Variant& v : kVariants) {
      const RobotModel model =
          load_robot_model(robot_dir(robot), {v.flex_sub_bodies, v.universal_joints});
      const MassProperties props = whole_robot(model);
      const std::string label = robot + " flex " + std::to_string(v.flex_sub_bodies) +
                                (v.universal_joints ? " universal" : " hinges");
      EXPECT_NEAR(props.mass_kg, ref.mass_kg, 1e-9) << label;
      EXPECT_LT((props.com_m - ref.com_m).norm(), 1e-9) << label;
      EXPECT_LT((props.inertia_kg_m2 - ref.inertia_kg_m2).cwiseAbs().maxCoeff(), 1e-9)
          << label << "\n"
          << props.inertia_kg_m2 << "\nvs\n"
          << ref.inertia_kg_m2;
      for (const BodySpec& body : model.bodies) {
        if (body.is_static) continue;
        EXPECT_GT(body.mass_kg, 0.0) << label << " " << body.name;
        const Eigen::Matrix3d& I = body.inertia_kg_m2;
        EXPECT_LT((I - I.transpose()).cwiseAbs().maxCoeff(), 1e-15) << label << " " << body.name;
        const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
        EXPECT_GT(eig.minCoeff(), 0.0) << label << " " << body.name;
        EXPECT_GE(eig(0) + eig(1), eig(2) * (1.0 - 1e-9)) << label << " " << body.name;
      }
    }
  }
}

TEST(RobotModelTest, WholeBodyComMatchesTheReadmes) {
  // nao/README.md: 5.00591 kg, CoM (0.0023, 0, −0.0623) m in the torso frame (= the build
  // frame, whose origin is the torso link's), given to 0.1 mm.
  const RobotModel nao = load_robot_model(robot_dir("nao"), {});
  const MassProperties n = whole_robot(nao);
  EXPECT_NEAR(n.mass_kg, 5.00591, 1e-9);
  EXPECT_NEAR(n.com_m.x(), 0.0023, 0.5e-4);
  EXPECT_NEAR(n.com_m.y(), 0.0, 1e-9);  // mirror-symmetric body, symmetric held arm pose
  EXPECT_NEAR(n.com_m.z(), -0.0623, 0.5e-4);
  // titan8/README.md: 22.000 kg, symmetric, whole CoM 0.231 m above the ground with the body
  // origin at 0.243 m.
  const RobotModel titan = load_robot_model(robot_dir("titan8"), {});
  const MassProperties t = whole_robot(titan);
  EXPECT_NEAR(t.mass_kg, 22.0, 1e-9);
  EXPECT_NEAR(t.com_m.x(), 0.0, 1e-12);
  EXPECT_NEAR(t.com_m.y(), 0.0, 1e-12);
  EXPECT_NEAR(t.com_m.z(), 0.231 - 0.243, 0.5e-3);
}

TEST(RobotModelTest, NaoActuatorsAreTheTenLegJointsInLogOrder) {
  const RobotModel nao = load_robot_model(robot_dir("nao"), {});
  const std::vector<std::string> expected = {
      "LHipRoll", "LHipPitch", "LKneePitch", "LAnklePitch", "LAnkleRoll",
      "RHipRoll", "RHipPitch", "RKneePitch", "RAnklePitch", "RAnkleRoll"};
  EXPECT_EQ(nao.actuator_names(), expected);
  EXPECT_EQ(nao.default_servo, "motoflex");
  EXPECT_FALSE(nao.fixed_base);
  // Stand pose of robot.yaml in actuator order.
  const std::vector<double> stand = {0.0, -0.3, 0.6, -0.3, 0.0, 0.0, -0.3, 0.6, -0.3, 0.0};
  EXPECT_EQ(nao.stand_pose_vector(), stand);
}

TEST(RobotModelTest, NaoHipsAndAnklesBecomeUniversalJoints) {
  const RobotModel merged = load_robot_model(robot_dir("nao"), {1, true});
  // (first, second) of each declared pair share one universal joint, as axis 1 and axis 2.
  const std::pair<const char*, const char*> pairs[] = {{"LHipRoll", "LHipPitch"},
                                                       {"LAnklePitch", "LAnkleRoll"},
                                                       {"RHipRoll", "RHipPitch"},
                                                       {"RAnklePitch", "RAnkleRoll"}};
  for (const auto& [first, second] : pairs) {
    const ActuatorSpec& a = merged.actuators.at(*merged.actuator_index(first));
    const ActuatorSpec& b = merged.actuators.at(*merged.actuator_index(second));
    EXPECT_EQ(a.joint, b.joint) << first;
    EXPECT_EQ(a.axis, 1) << first;
    EXPECT_EQ(b.axis, 2) << second;
    const JointSpec& joint = merged.joints.at(a.joint);
    EXPECT_EQ(joint.kind, JointKind::kUniversal) << first;
    EXPECT_NEAR(joint.axis1_W0.dot(joint.axis2_W0), 0.0, 1e-12) << first;
    EXPECT_EQ(joint.actuator1, static_cast<int>(*merged.actuator_index(first)));
    EXPECT_EQ(joint.actuator2, static_cast<int>(*merged.actuator_index(second)));
  }
  for (const char* knee : {"LKneePitch", "RKneePitch"}) {
    EXPECT_EQ(merged.joints.at(merged.actuators.at(*merged.actuator_index(knee)).joint).kind,
              JointKind::kHinge);
  }
  // Without merging, every actuator has its own hinge and the two intermediate links (hip,
  // ankle-pitch) are bodies of their own: 4 bodies and 4 joints more.
  const RobotModel hinges = load_robot_model(robot_dir("nao"), {1, false});
  for (const ActuatorSpec& a : hinges.actuators) {
    EXPECT_EQ(hinges.joints.at(a.joint).kind, JointKind::kHinge) << a.name;
    EXPECT_EQ(a.axis, 1) << a.name;
  }
  EXPECT_EQ(hinges.bodies.size(), merged.bodies.size() + 4);
  EXPECT_EQ(hinges.joints.size(), merged.joints.size() + 4);
}

TEST(RobotModelTest, FlexibleLinksSplitIntoSubBodiesJoinedByFlexJoints) {
  const RobotModel rigid = load_robot_model(robot_dir("nao"), {1, true});
  for (const JointSpec& joint : rigid.joints) EXPECT_NE(joint.kind, JointKind::kFlex);
  for (const int pieces : {2, 3}) {
    const RobotModel flex = load_robot_model(robot_dir("nao"), {pieces, true});
    int flex_joints = 0;
    for (const JointSpec& joint : flex.joints) {
      if (joint.kind != JointKind::kFlex) continue;
      ++flex_joints;
      EXPECT_EQ(joint.actuator1, -1);
      EXPECT_EQ(joint.actuator2, -1);
      EXPECT_NEAR(joint.axis1_W0.norm(), 1.0, 1e-12);
      EXPECT_NEAR(joint.axis2_W0.norm(), 1.0, 1e-12);
      EXPECT_NEAR(joint.axis1_W0.dot(joint.axis2_W0), 0.0, 1e-12);
      // The bending axes are orthogonal to the link, i.e. to the line from the joint that
      // carries the link to the joint at its far end; the flex joints divide that line evenly.
      const JointSpec* start = &joint;
      int piece = 1;  // this joint's index along the link
      while (start->kind == JointKind::kFlex) {
        start = &flex.joints.at(flex.bodies.at(start->parent_body).parent_joint);
        if (start->kind == JointKind::kFlex) ++piece;
      }
      const JointSpec* end = &joint;
      while (end->kind == JointKind::kFlex) {
        const int body = end->child_body;
        const auto next = std::find_if(flex.joints.begin(), flex.joints.end(),
                                       [&](const JointSpec& j) { return j.parent_body == body; });
        ASSERT_NE(next, flex.joints.end()) << joint.name;
        end = &*next;
      }
      const Eigen::Vector3d span = end->anchor_W0_m - start->anchor_W0_m;
      EXPECT_NEAR(joint.axis1_W0.dot(span.normalized()), 0.0, 1e-9) << joint.name;
      EXPECT_NEAR(joint.axis2_W0.dot(span.normalized()), 0.0, 1e-9) << joint.name;
      const Eigen::Vector3d expected_anchor =
          start->anchor_W0_m + (static_cast<double>(piece) / pieces) * span;
      EXPECT_LT((joint.anchor_W0_m - expected_anchor).norm(), 1e-12)
          << joint.name << " from " << start->name << " to " << end->name;
    }
    // 4 flexible links (thighs, tibias), pieces − 1 joints each.
    EXPECT_EQ(flex_joints, 4 * (pieces - 1));
    EXPECT_EQ(flex.bodies.size(), rigid.bodies.size() + 4 * (pieces - 1));
    EXPECT_EQ(flex.actuators.size(), rigid.actuators.size());
  }
}

TEST(RobotModelTest, JointsArePlacedParentsFirst) {
  for (const std::string robot : {"nao", "titan8", "servo_pendulum"}) {
    for (const Variant& v : kVariants) {
      const RobotModel model =
          load_robot_model(robot_dir(robot), {v.flex_sub_bodies, v.universal_joints});
      std::vector<bool> reached(model.bodies.size(), false);
      reached[model.root_body] = true;
      for (std::size_t j = 0; j < model.joints.size(); ++j) {
        const JointSpec& joint = model.joints[j];
        EXPECT_TRUE(reached.at(joint.parent_body)) << robot << " " << joint.name;
        EXPECT_FALSE(reached.at(joint.child_body)) << robot << " " << joint.name;
        reached[joint.child_body] = true;
        EXPECT_EQ(model.bodies[joint.child_body].parent_joint, static_cast<int>(j));
      }
      for (std::size_t b = 0; b < reached.size(); ++b) EXPECT_TRUE(reached[b]) << robot << b;
    }
  }
}

}  // namespace
}  // namespace motoflex
