// The box robot of the 2011 MoToFlex program (scenarios/robots/nao_motoflex_2011): built at the
// zero pose it stands as motoflex_2011.md §2.3 says the original does (feet flat, box bottoms
// at z = 0, torso box centre 0.3775 m up), carries nao.md §3.2's boxes and masses, and has no
// joint stops (§2.10), unlike our `nao`.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

std::string robot_dir(const std::string& name) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name;
}

// World centre of the collision box of URDF link `link` and the lowest z of its corners (a box of
// a flexible link sits on the piece "<link>#k" that holds its centre).
struct BoxInWorld {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double bottom_z_m = 0.0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
};

BoxInWorld box_of(const RobotModel& model, const Rollout& rollout, const std::string& link) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const CollisionShape& box : model.bodies[b].collisions) {
      if (box.kind != ShapeKind::kBox) continue;
      if (box.link.substr(0, box.link.find('#')) != link) continue;
      const Rollout::BodyState state = rollout.body_state(b);
      BoxInWorld out;
      out.R = state.R_WB * box.X_BG.linear();
      out.centre_m = state.position_m + state.R_WB * box.X_BG.translation();
      out.bottom_z_m = INFINITY;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d local(((corner & 1) ? 0.5 : -0.5) * box.size_m.x(),
                                    ((corner & 2) ? 0.5 : -0.5) * box.size_m.y(),
                                    ((corner & 4) ? 0.5 : -0.5) * box.size_m.z());
        out.bottom_z_m = std::min(out.bottom_z_m, (out.centre_m + out.R * local).z());
      }
      return out;
    }
  }
  ADD_FAILURE() << "no box of link " << link;
  return {};
}

TEST(NaoMotoflex2011Robot, ZeroPoseIsTheOriginalsStartingPose) {
  const RobotModel model = load_robot_model(robot_dir("nao_motoflex_2011"), {2, true});
  double mass_kg = 0.0;
  for (const BodySpec& body : model.bodies) mass_kg += body.mass_kg;
  EXPECT_NEAR(mass_kg, 4.346, 1e-9);  // nao.md §3.2
  const ParameterSet params(model.parameters);
  RolloutOptions options;
  options.servo = "ideal";
  const Rollout rollout(model, params, options, std::vector<double>(model.actuators.size(), 0.0));

  // §2.3: box bottoms at z = 0 (initial_clearance_m 0), feet flat, torso box centre 0.3775 m.
  for (const char* foot : {"l_foot", "r_foot"}) {
    const BoxInWorld box = box_of(model, rollout, foot);
    EXPECT_NEAR(box.bottom_z_m, 0.0, 1e-12) << foot;
    EXPECT_TRUE(box.R.isApprox(Eigen::Matrix3d::Identity(), 1e-12)) << foot;
    EXPECT_NEAR(box.centre_m.x(), 0.025, 1e-12) << foot;
    EXPECT_NEAR(std::abs(box.centre_m.y()), 0.05, 1e-12) << foot;
  }
  const BoxInWorld torso = box_of(model, rollout, "torso");
  EXPECT_NEAR(torso.centre_m.z(), 0.331 + 0.046466, 1e-12);
  EXPECT_NEAR(torso.centre_m.z(), 0.3775, 5e-4);
  EXPECT_NEAR(torso.centre_m.x(), -0.007829, 1e-12);
  // The other boxes of the table, at the zero pose.
  EXPECT_NEAR(box_of(model, rollout, "Head").centre_m.z(), 0.331 + 0.170899, 1e-12);
  const BoxInWorld arm = box_of(model, rollout, "LArm");
  EXPECT_NEAR(arm.centre_m.y(), 0.098 + std::sin(0.35) * 0.0966, 1e-12);
  EXPECT_NEAR(arm.centre_m.z(), 0.431 - std::cos(0.35) * 0.0966, 1e-12);
  // The first of each flexible link's two boxes (flexible_split: box) is its upper half.
  EXPECT_NEAR(box_of(model, rollout, "RThigh").centre_m.z(), 0.046 + 0.100 + 0.062 + 0.019, 1e-12);
  EXPECT_NEAR(box_of(model, rollout, "RTibia").centre_m.z(), 0.046 + 0.0309 + 0.01545, 1e-12);
  // Joint anchors: hip 0.246, knee 0.146, ankle 0.046 m (nao.md §3.2).
  for (const auto& [joint, z] : {std::pair{"LHipRoll", 0.246}, std::pair{"LKneePitch", 0.146},
                                 std::pair{"RAnklePitch", 0.046}}) {
    const ActuatorSpec& a = model.actuators[*model.actuator_index(joint)];
    EXPECT_NEAR(model.joints[a.joint].anchor_W0_m.z() - model.bodies[0].com_W0_m.z() +
                    rollout.body_state(0).position_m.z(),
                z, 1e-12)
        << joint;
  }
}

// Hanging in the air with ideal servos, a RAnkleRoll command beyond the Nao's limit (0.3978 rad)
// is followed on the 2011 robot (no stops) but stopped on our nao.
TEST(NaoMotoflex2011Robot, HasNoJointStops) {
  for (const char* robot : {"nao_motoflex_2011", "nao"}) {
    SCOPED_TRACE(robot);
    const RobotModel model = load_robot_model(robot_dir(robot), {1, true});
    const std::size_t ankle = *model.actuator_index("RAnkleRoll");
    EXPECT_NEAR(model.actuators[ankle].upper_rad, 0.397761, 1e-12);  // kept for the planner
    const bool stops = std::string(robot) == "nao";
    EXPECT_EQ(std::isfinite(model.joints[model.actuators[ankle].joint].upper2_rad), stops);
    const ParameterSet params(model.parameters);
    RolloutOptions options;
    options.servo = "ideal";
    options.hold_torso = true;
    std::vector<double> pose(model.actuators.size(), 0.0);
    Rollout rollout(model, params, options, pose);
    pose[ankle] = 0.6;
    for (int step = 0; step < 300; ++step) rollout.step(pose.data(), pose.data());
    // Measured: 0.600000000 (no stops) and 0.397761999 (at the stop, 1e-6 rad beyond it).
    EXPECT_NEAR(rollout.joint_angle_rad(ankle), stops ? 0.397761 : 0.6, 1e-5);
  }
}

// flexible_split: box (motoflex_2011.md §2.9): each leg box becomes numOfSubBoxes equal boxes
// stacked along z, each with a homogeneous box's inertia, bending where their faces meet.
TEST(NaoMotoflex2011Robot, SplitsTheLegBoxesAsTheOriginal) {
  const RobotModel model = load_robot_model(robot_dir("nao_motoflex_2011"), {2, true});
  // link, mass, box height, height of the box centre above the link's own joint's anchor
  struct Leg {
    const char* link;
    double mass_kg, height_m, centre_below_joint_m;
  };
  for (const Leg& leg :
       {Leg{"LThigh", 0.533, 0.076, 0.038}, Leg{"RTibia", 0.423, 0.0618, 0.0691}}) {
    SCOPED_TRACE(leg.link);
    int pieces = 0;
    for (const BodySpec& body : model.bodies) {
      if (body.collisions.size() != 1 || body.collisions[0].link.rfind(leg.link, 0) != 0) continue;
      ++pieces;
      const double m = leg.mass_kg / 2.0, h = leg.height_m / 2.0;
      EXPECT_NEAR(body.mass_kg, m, 1e-12);
      EXPECT_NEAR(body.collisions[0].size_m.z(), h, 1e-12);
      EXPECT_NEAR(body.inertia_kg_m2(0, 0), m / 12.0 * (0.05 * 0.05 + h * h), 1e-12);
      EXPECT_NEAR(body.inertia_kg_m2(2, 2), m / 12.0 * (2 * 0.05 * 0.05), 1e-12);
    }
    EXPECT_EQ(pieces, 2);
    // The bending joint sits at the box centre, below the link's own joint.
    const std::string flex = std::string(leg.link) + "#flex1";
    const std::string own = leg.link[1] == 'T' && leg.link[2] == 'h'
                                ? std::string(1, leg.link[0]) + "HipPitch"
                                : std::string(1, leg.link[0]) + "KneePitch";
    const ActuatorSpec& a = model.actuators[*model.actuator_index(own)];
    bool found = false;
    for (const JointSpec& joint : model.joints) {
      if (joint.name != flex) continue;
      found = true;
      EXPECT_EQ(joint.kind, JointKind::kFlex);
      EXPECT_NEAR(model.joints[a.joint].anchor_W0_m.z() - joint.anchor_W0_m.z(),
                  leg.centre_below_joint_m, 1e-12);
    }
    EXPECT_TRUE(found) << flex;
  }
}

}  // namespace
}  // namespace motoflex
