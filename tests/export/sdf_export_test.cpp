// SDF 1.9 export read back by libsdformat 12 without errors: joint dynamics, limits, the flex
// springs, link masses, the ODE physics block and the contact surface arrive unchanged.

#include <gtest/gtest.h>

#include <map>
#include <sdf/Collision.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/Physics.hh>
#include <sdf/Root.hh>
#include <sdf/World.hh>

#include "export_test_support.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/parser_check.hpp"
#include "motoflex/export/sdf_export.hpp"

namespace motoflex {
namespace {

struct Loaded {
  sdf::Root root;
  const sdf::World* world = nullptr;
  const sdf::Model* model = nullptr;
};

void load(const ExportInput& input, Loaded& out) {
  const std::string text = export_sdf(input);
  EXPECT_EQ(sdformat_errors(text), "");
  const sdf::Errors errors = out.root.LoadSdfString(text);
  for (const auto& e : errors) ADD_FAILURE() << e.Message();
  ASSERT_EQ(out.root.WorldCount(), 1u);
  out.world = out.root.WorldByIndex(0);
  out.model = out.world->ModelByName(input.model.name);
  ASSERT_NE(out.model, nullptr);
}

// The SDF axis of each actuator: (joint name, axis index).
std::map<std::string, std::pair<std::string, int>> actuated_axes(const RobotModel& model) {
  std::map<std::string, std::pair<std::string, int>> out;
  for (const auto& a : model.actuators) out[a.name] = {model.joints[a.joint].name, a.axis - 1};
  return out;
}

void expect_joint_values(const ExportInput& input, const sdf::Model& model) {
  const auto axes = actuated_axes(input.model);
  for (const ActuatorExport& a : export_actuators(input)) {
    const auto& [joint_name, index] = axes.at(a.joint);
    const sdf::Joint* joint = model.JointByName(joint_name);
    ASSERT_NE(joint, nullptr) << joint_name;
    const sdf::JointAxis* axis = joint->Axis(index);
    ASSERT_NE(axis, nullptr) << a.joint;
    EXPECT_EQ(axis->Damping(), a.damping_nm_s_per_rad) << a.joint;
    EXPECT_EQ(axis->Friction(), a.friction_nm) << a.joint;
    EXPECT_EQ(axis->SpringStiffness(), 0.0) << a.joint;
    EXPECT_EQ(axis->Effort(), a.effort_nm) << a.joint;
    EXPECT_EQ(axis->MaxVelocity(), a.velocity_rad_s > 0.0 ? a.velocity_rad_s : -1.0) << a.joint;
    EXPECT_EQ(axis->Lower(), a.lower_rad) << a.joint;
    EXPECT_EQ(axis->Upper(), a.upper_rad) << a.joint;
  }
}

TEST(SdfExport, NaoLoadsWithoutErrorsAndKeepsTheFittedValues) {
  const auto f = testing::fitted_fixture("nao", "motoflex");
  Loaded loaded;
  load(*f.input, loaded);
  ASSERT_NE(loaded.model, nullptr);
  expect_joint_values(*f.input, *loaded.model);
  EXPECT_EQ(loaded.model->JointByName("LHipRoll+LHipPitch")->Type(), sdf::JointType::UNIVERSAL);
  EXPECT_EQ(loaded.model->LinkCount(), f.model->bodies.size());
  double mass = 0.0;
  for (uint64_t i = 0; i < loaded.model->LinkCount(); ++i) {
    mass += loaded.model->LinkByIndex(i)->Inertial().MassMatrix().Mass();
  }
  EXPECT_NEAR(mass, 5.00591, 1e-9);  // the whole URDF (README: 5.00591 kg)

  // World physics: ODE with the fitted ERP/CFM at the 1 ms step.
  const sdf::Physics* physics = loaded.world->PhysicsDefault();
  ASSERT_NE(physics, nullptr);
  EXPECT_EQ(physics->EngineType(), "ode");
  EXPECT_EQ(physics->MaxStepSize(), 0.001);
  const auto ode = physics->Element()->GetElement("ode");
  EXPECT_EQ(ode->GetElement("solver")->Get<std::string>("type"), "world");
  EXPECT_EQ(ode->GetElement("constraints")->Get<double>("cfm"),
            f.input->parameters.get("world.cfm"));
  EXPECT_EQ(ode->GetElement("constraints")->Get<double>("erp"),
            f.input->parameters.get("world.erp"));

  // Foot contact surface.
  std::string foot_body;
  for (const auto& body : f.model->bodies) {
    for (const auto& box : body.collisions) {
      if (box.is_foot && foot_body.empty()) foot_body = body.name;
    }
  }
  const sdf::Link* foot = loaded.model->LinkByName(foot_body);
  ASSERT_NE(foot, nullptr) << foot_body;
  bool found_foot = false;
  for (uint64_t i = 0; i < foot->CollisionCount(); ++i) {
    const auto element = foot->CollisionByIndex(i)->Element();
    if (!element->HasElement("surface")) continue;
    found_foot = true;
    const auto friction = element->GetElement("surface")->GetElement("friction")->GetElement("ode");
    EXPECT_EQ(friction->Get<double>("mu"), f.input->parameters.get("contact.mu"));
    EXPECT_EQ(friction->Get<double>("slip1"), f.input->parameters.get("contact.slip"));
    const auto contact = element->GetElement("surface")->GetElement("contact")->GetElement("ode");
    EXPECT_EQ(contact->Get<double>("soft_cfm"), f.input->parameters.get("contact.soft_cfm"));
    EXPECT_EQ(contact->Get<double>("soft_erp"), f.input->parameters.get("contact.soft_erp"));
  }
  EXPECT_TRUE(found_foot);
}

TEST(SdfExport, FlexibleLinksBecomeSpringJoints) {
  const auto f = testing::fitted_fixture("nao", "motoflex", 2);
  Loaded loaded;
  load(*f.input, loaded);
  ASSERT_NE(loaded.model, nullptr);
  expect_joint_values(*f.input, *loaded.model);
  int flex_joints = 0;
  for (const JointSpec& spec : f.model->joints) {
    if (spec.kind != JointKind::kFlex) continue;
    ++flex_joints;
    const sdf::Joint* joint = loaded.model->JointByName(spec.name);
    ASSERT_NE(joint, nullptr) << spec.name;
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(joint->Axis(k)->SpringStiffness(),
                f.input->parameters.get("flex.spring_nm_per_rad"));
      EXPECT_EQ(joint->Axis(k)->Damping(), f.input->parameters.get("flex.damping_nm_s_per_rad"));
      EXPECT_EQ(joint->Axis(k)->SpringReference(), 0.0);
    }
  }
  EXPECT_EQ(flex_joints, 4);
}

TEST(SdfExport, PendulumIsWeldedToTheWorldAndCarriesTheBenchLoad) {
  const auto f = testing::fitted_fixture("servo_pendulum", "bench");
  Loaded loaded;
  load(*f.input, loaded);
  ASSERT_NE(loaded.model, nullptr);
  expect_joint_values(*f.input, *loaded.model);
  const sdf::Joint* weld = loaded.model->JointByName("base_to_world");
  ASSERT_NE(weld, nullptr);
  EXPECT_EQ(weld->Type(), sdf::JointType::FIXED);
  const sdf::Link* arm = loaded.model->LinkByName("arm");
  ASSERT_NE(arm, nullptr);
  EXPECT_EQ(arm->Inertial().MassMatrix().Mass(), f.input->parameters.get("bench.mass_kg"));
  EXPECT_EQ(arm->Inertial().MassMatrix().Ixx(), f.input->parameters.get("bench.armature_kg_m2"));
  // The point mass hangs bench.length_m below the axis (1 m above the base origin).
  EXPECT_NEAR(arm->RawPose().Pos().Z(), 1.0 - f.input->parameters.get("bench.length_m"), 1e-12);
}

TEST(SdfExport, SdformatErrorsAreReported) {
  const std::string missing_child =
      "<sdf version=\"1.9\"><model name=\"m\"><link name=\"a\"/>"
      "<joint name=\"j\" type=\"revolute\"><parent>a</parent><child>b</child>"
      "<axis><xyz>0 0 1</xyz></axis></joint></model></sdf>";
  const std::string errors = sdformat_errors(missing_child);
  EXPECT_NE(errors.find("b"), std::string::npos) << errors;
}

}  // namespace
}  // namespace motoflex
