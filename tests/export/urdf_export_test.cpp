// URDF export read back by urdfdom: the fitted damping, friction, effort and velocity arrive
// bit-identically; the transmissions carry the gear ratio; urdfdom ignores the <motoflex:model>
// extension, which holds every parameter.

#include <gtest/gtest.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <filesystem>
#include <map>

#include "export_test_support.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/parser_check.hpp"
#include "motoflex/export/urdf_export.hpp"
#include "motoflex/model/robot_loader.hpp"

namespace motoflex {
namespace {

void expect_round_trip(const ExportInput& input) {
  const std::string text = export_urdf(input);
  EXPECT_EQ(urdfdom_errors(text), "");
  const urdf::ModelInterfaceSharedPtr exported = urdf::parseURDF(text);
  ASSERT_TRUE(exported);
  const urdf::ModelInterfaceSharedPtr source = urdf::parseURDFFile(input.model.urdf_path);
  ASSERT_TRUE(source);
  // Nothing of the robot itself changed.
  EXPECT_EQ(exported->links_.size(), source->links_.size());
  EXPECT_EQ(exported->joints_.size(), source->joints_.size());
  for (const auto& [name, link] : source->links_) {
    ASSERT_TRUE(exported->getLink(name)) << name;
    if (link->inertial) {
      EXPECT_EQ(exported->getLink(name)->inertial->mass, link->inertial->mass);
    }
  }

  // The fitted values, exactly.
  TiXmlDocument document;
  document.Parse(text.c_str());
  ASSERT_FALSE(document.Error()) << document.ErrorDesc();
  std::map<std::string, double> reductions;
  for (const TiXmlElement* t = document.RootElement()->FirstChildElement("transmission");
       t != nullptr; t = t->NextSiblingElement("transmission")) {
    const std::string joint = t->FirstChildElement("joint")->Attribute("name");
    reductions[joint] = std::stod(
        t->FirstChildElement("actuator")->FirstChildElement("mechanicalReduction")->GetText());
  }
  for (const ActuatorExport& a : export_actuators(input)) {
    const auto joint = exported->getJoint(a.joint);
    ASSERT_TRUE(joint && joint->dynamics && joint->limits) << a.joint;
    EXPECT_EQ(joint->dynamics->damping, a.damping_nm_s_per_rad) << a.joint;
    EXPECT_EQ(joint->dynamics->friction, a.friction_nm) << a.joint;
    EXPECT_EQ(joint->limits->effort, a.effort_nm) << a.joint;
    if (a.velocity_rad_s > 0.0) {
      EXPECT_EQ(joint->limits->velocity, a.velocity_rad_s) << a.joint;
    }
    EXPECT_EQ(joint->limits->lower, source->getJoint(a.joint)->limits->lower);
    EXPECT_EQ(joint->limits->upper, source->getJoint(a.joint)->limits->upper);
    ASSERT_TRUE(reductions.count(a.joint)) << a.joint;
    EXPECT_EQ(reductions[a.joint], a.reduction) << a.joint;
  }

  // The extension carries every parameter, exactly, and the provenance.
  const TiXmlElement* extension = document.RootElement()->FirstChildElement("motoflex:model");
  ASSERT_NE(extension, nullptr);
  std::size_t count = 0;
  for (const TiXmlElement* p = extension->FirstChildElement("motoflex:parameter"); p != nullptr;
       p = p->NextSiblingElement("motoflex:parameter")) {
    EXPECT_EQ(std::stod(p->Attribute("value")), input.parameters.get(p->Attribute("name")))
        << p->Attribute("name");
    ++count;
  }
  EXPECT_EQ(count, input.parameters.registry().size());
  const TiXmlElement* provenance = extension->FirstChildElement("motoflex:provenance");
  ASSERT_NE(provenance, nullptr);
  EXPECT_STREQ(provenance->Attribute("config_hash"), "abc123");
}

TEST(UrdfExport, NaoMotoflexServoRoundTripsThroughUrdfdom) {
  const auto f = testing::fitted_fixture("nao", "motoflex");
  expect_round_trip(*f.input);
  // Spot check against the parameter names: LKneePitch uses gear B.
  const urdf::ModelInterfaceSharedPtr exported = urdf::parseURDF(export_urdf(*f.input));
  const ParameterSet& p = f.input->parameters;
  const double sigma = p.get("gear.B.ratio");
  EXPECT_NEAR(exported->getJoint("LKneePitch")->dynamics->damping,
              p.get("joint.LKneePitch.viscous_nm_s_per_rad") +
                  p.get("gear.B.motor_viscous_nm_s_per_rad") * sigma * sigma,
              1e-12);
  EXPECT_EQ(exported->getJoint("LKneePitch")->dynamics->friction,
            p.get("joint.LKneePitch.friction_nm"));
}

TEST(UrdfExport, PendulumBenchServoRoundTripsThroughUrdfdom) {
  const auto f = testing::fitted_fixture("servo_pendulum", "bench");
  expect_round_trip(*f.input);
}

TEST(UrdfExport, IdealServoKeepsTheUrdfVelocityLimit) {
  const auto f = testing::fitted_fixture("nao", "ideal");
  expect_round_trip(*f.input);
  const auto source = urdf::parseURDFFile(f.model->urdf_path);
  const auto exported = urdf::parseURDF(export_urdf(*f.input));
  EXPECT_EQ(exported->getJoint("LHipRoll")->limits->velocity,
            source->getJoint("LHipRoll")->limits->velocity);
  EXPECT_EQ(exported->getJoint("LHipRoll")->limits->effort,
            f.input->parameters.get("ideal.torque_max_nm"));
}

TEST(UrdfExport, UrdfdomErrorsAreReported) {
  EXPECT_NE(urdfdom_errors("<robot name=\"x\"><joint name=\"j\" type=\"revolute\"/></robot>"), "");
}

// MuJoCo 2.2.2 reads URDF too (damping → damping, friction → frictionloss) and skips the
// transmissions and the extension.
TEST(UrdfExport, MujocosUrdfReaderAcceptsTheExport) {
  const auto f = testing::fitted_fixture("servo_pendulum", "bench");
  EXPECT_EQ(mujoco_errors(export_urdf(*f.input)), "");
}

// A URDF from a ROS package often has its own <transmission> per joint: the export replaces the
// actuated joints' ones (one each, with the fitted reduction) and keeps the others.
TEST(UrdfExport, TheFilesOwnTransmissionsAreReplacedNotDuplicated) {
  const auto dir = testing::fresh_export_dir("transmissions");
  std::filesystem::copy(testing::robot_dir("servo_pendulum"), dir / "robot",
                        std::filesystem::copy_options::recursive);
  std::string urdf_path;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "robot")) {
    if (entry.path().extension() == ".urdf") urdf_path = entry.path().string();
  }
  ASSERT_FALSE(urdf_path.empty());
  TiXmlDocument source;
  ASSERT_TRUE(source.LoadFile(urdf_path.c_str()));
  const std::string own =
      "<transmission name=\"own_pendulum\"><type>transmission_interface/SimpleTransmission</type>"
      "<joint name=\"pendulum\"><hardwareInterface>x</hardwareInterface></joint>"
      "<actuator name=\"m\"><mechanicalReduction>7</mechanicalReduction></actuator>"
      "</transmission>";
  const std::string other =
      "<transmission name=\"unrelated\"><joint name=\"not_actuated\"/></transmission>";
  for (const std::string& xml : {own, other}) {
    TiXmlDocument fragment;
    fragment.Parse(xml.c_str());
    source.RootElement()->InsertEndChild(*fragment.RootElement());
  }
  ASSERT_TRUE(source.SaveFile(urdf_path.c_str()));

  StructureOptions structure;
  const RobotModel model = load_robot_model((dir / "robot").string(), structure);
  ExportInput input{model, ParameterSet(model.parameters), "bench", {}, 0.001};
  TiXmlDocument document;
  document.Parse(export_urdf(input).c_str());
  ASSERT_FALSE(document.Error());
  int pendulum = 0;
  int unrelated = 0;
  for (const TiXmlElement* t = document.RootElement()->FirstChildElement("transmission");
       t != nullptr; t = t->NextSiblingElement("transmission")) {
    const std::string joint = t->FirstChildElement("joint")->Attribute("name");
    pendulum += joint == "pendulum" ? 1 : 0;
    unrelated += joint == "not_actuated" ? 1 : 0;
    if (joint == "pendulum") {
      EXPECT_STREQ(t->Attribute("name"), "pendulum_transmission");
    }
  }
  EXPECT_EQ(pendulum, 1);
  EXPECT_EQ(unrelated, 1);
}

}  // namespace
}  // namespace motoflex
