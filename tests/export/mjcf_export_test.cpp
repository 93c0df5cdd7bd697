// MJCF export compiled by Debian's MuJoCo 2.2.2 (mj_loadXML, empty error buffer): armature,
// damping, frictionloss, ranges, servo gains and force limits, masses and the parameters in
// <custom> arrive unchanged in mjModel.

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "export_test_support.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/mjcf_export.hpp"
#include "motoflex/export/parser_check.hpp"

namespace motoflex {
namespace {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;

// Loads through a real file, the way a MuJoCo user would.
ModelPtr load(const std::string& text, const std::string& name) {
  const auto path = testing::fresh_export_dir("mjcf_" + name) / (name + ".xml");
  std::ofstream(path) << text;
  char error[1000] = "";
  ModelPtr m(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  EXPECT_STREQ(error, "");
  return m;
}

void expect_actuated_values(const ExportInput& input, const mjModel& m) {
  const auto actuators = export_actuators(input);
  ASSERT_EQ(m.nu, static_cast<int>(actuators.size()));
  for (std::size_t i = 0; i < actuators.size(); ++i) {
    const ActuatorExport& a = actuators[i];
    const int joint = mj_name2id(&m, mjOBJ_JOINT, a.joint.c_str());
    ASSERT_GE(joint, 0) << a.joint;
    const int dof = m.jnt_dofadr[joint];
    EXPECT_EQ(m.dof_armature[dof], a.armature) << a.joint;
    EXPECT_EQ(m.dof_damping[dof], a.damping_nm_s_per_rad) << a.joint;
    EXPECT_EQ(m.dof_frictionloss[dof], a.friction_nm) << a.joint;
    EXPECT_EQ(m.jnt_limited[joint], a.limited ? 1 : 0) << a.joint;
    // qpos is the encoder's reading: the written pose is qpos = the mounting offset (the
    // fixture's is −0.08 rad), and the stops on the joint angle move with it.
    EXPECT_NE(a.mounting_offset_rad, 0.0) << a.joint;
    EXPECT_EQ(m.qpos0[m.jnt_qposadr[joint]], a.mounting_offset_rad) << a.joint;
    if (a.limited) {
      EXPECT_EQ(m.jnt_range[2 * joint], a.lower_rad + a.mounting_offset_rad) << a.joint;
      EXPECT_EQ(m.jnt_range[2 * joint + 1], a.upper_rad + a.mounting_offset_rad) << a.joint;
    }
    // Actuators in model (log column) order, each on its joint.
    const int u = static_cast<int>(i);
    EXPECT_EQ(m.actuator_trnid[2 * u], joint) << a.joint;
    EXPECT_EQ(m.actuator_gainprm[u * mjNGAIN], a.kp_nm_per_rad) << a.joint;
    EXPECT_EQ(m.actuator_biasprm[u * mjNBIAS + 1], -a.kp_nm_per_rad) << a.joint;
    EXPECT_EQ(m.actuator_biasprm[u * mjNBIAS + 2], -a.kv_nm_s_per_rad) << a.joint;
    EXPECT_EQ(m.actuator_forcelimited[u], 1);
    EXPECT_EQ(m.actuator_forcerange[2 * u], -a.effort_nm) << a.joint;
    EXPECT_EQ(m.actuator_forcerange[2 * u + 1], a.effort_nm) << a.joint;
  }
}

double numeric(const mjModel& m, const std::string& name) {
  const int id = mj_name2id(&m, mjOBJ_NUMERIC, name.c_str());
  EXPECT_GE(id, 0) << name;
  return id < 0 ? NAN : m.numeric_data[m.numeric_adr[id]];
}

TEST(MjcfExport, NaoIsFreeFloatingWithTheFittedJointValues) {
  const auto f = testing::fitted_fixture("nao", "motoflex");
  const std::string text = export_mjcf(*f.input);
  EXPECT_EQ(mujoco_errors(text), "");
  const ModelPtr m = load(text, "nao");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->nq, 7 + 10);  // free joint + 10 actuated hinges; held joints are welded
  EXPECT_EQ(m->nv, 6 + 10);
  EXPECT_EQ(m->jnt_type[0], mjJNT_FREE);
  EXPECT_EQ(m->opt.timestep, 0.001);
  EXPECT_EQ(m->opt.integrator, mjINT_IMPLICIT);
  expect_actuated_values(*f.input, *m);
  // Armature of the motoflex servo = the gear's small mass m_g of the joint's group plus the
  // joint's reflected rotor inertia.
  const int knee = mj_name2id(m.get(), mjOBJ_JOINT, "LKneePitch");
  EXPECT_GT(f.input->parameters.get("joint.LKneePitch.armature_kg_m2"), 0.0);
  EXPECT_EQ(m->dof_armature[m->jnt_dofadr[knee]],
            f.input->parameters.get("gear.B.mass_kg_m2") +
                f.input->parameters.get("joint.LKneePitch.armature_kg_m2"));
  double mass = 0.0;
  for (int b = 1; b < m->nbody; ++b) mass += m->body_mass[b];
  EXPECT_NEAR(mass, 5.00591, 1e-9);
  // Every parameter travels in <custom>.
  for (const auto& spec : f.model->parameters.specs()) {
    EXPECT_EQ(numeric(*m, "motoflex:" + spec.name), f.input->parameters.get(spec.name));
  }
  EXPECT_GE(mj_name2id(m.get(), mjOBJ_TEXT, "motoflex:provenance"), 0);
}

TEST(MjcfExport, NaoStandsOnTheFloorAtItsInitialClearance) {
  const auto f = testing::fitted_fixture("nao", "ideal");
  const ModelPtr m = load(export_mjcf(*f.input), "nao_stand");
  ASSERT_TRUE(m);
  mjData* d = mj_makeData(m.get());
  mj_forward(m.get(), d);
  // Lowest foot-box corner 1 mm above the floor (robot.yaml initial_clearance_m).
  double lowest = 1e9;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] != mjGEOM_BOX || m->geom_contype[g] == 0) continue;
    for (int corner = 0; corner < 8; ++corner) {
      double local[3], world[3];
      for (int k = 0; k < 3; ++k) local[k] = ((corner >> k) & 1 ? 1 : -1) * m->geom_size[3 * g + k];
      mju_rotVecMat(world, local, d->geom_xmat + 9 * g);
      lowest = std::min(lowest, world[2] + d->geom_xpos[3 * g + 2]);
    }
  }
  EXPECT_NEAR(lowest, f.model->initial_clearance_m, 1e-9);
  mj_deleteData(d);
}

TEST(MjcfExport, PendulumIsAFixedBaseBenchWithThePointMassAndArmature) {
  const auto f = testing::fitted_fixture("servo_pendulum", "bench");
  const ModelPtr m = load(export_mjcf(*f.input), "pendulum");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->nq, 1);
  expect_actuated_values(*f.input, *m);
  const int arm = mj_name2id(m.get(), mjOBJ_BODY, "arm");
  ASSERT_GE(arm, 0);
  EXPECT_EQ(m->body_mass[arm], f.input->parameters.get("bench.mass_kg"));
  EXPECT_EQ(m->dof_armature[0], f.input->parameters.get("bench.armature_kg_m2"));
  // The arm's CoM is bench.length_m from the joint axis.
  mjData* d = mj_makeData(m.get());
  mj_forward(m.get(), d);
  const double* com = d->xipos + 3 * arm;
  const double* anchor = d->xanchor;
  EXPECT_NEAR(std::hypot(com[0] - anchor[0], com[2] - anchor[2]),
              f.input->parameters.get("bench.length_m"), 1e-12);
  // Static check of gravity and the servo: at rest with the encoder reading q, the actuator
  // balances m·g·l·sin(q − m_offset), the joint angle being the reading less the mounting offset
  // (MuJoCo's gravity torque about +y is −m·g·l·sin θ for our arm).
  const double q = 0.3;
  const double offset = f.input->parameters.get("joint.pendulum.mounting_offset_rad");
  d->qpos[0] = q;
  mj_forward(m.get(), d);
  const double l = f.input->parameters.get("bench.length_m");
  const double mass = f.input->parameters.get("bench.mass_kg");
  EXPECT_NEAR(d->qfrc_bias[0], mass * 9.81 * l * std::sin(q - offset), 1e-9);
  mj_deleteData(d);
}

TEST(MjcfExport, FlexibleLinksAndHeldTorsoCompile) {
  const auto f = testing::fitted_fixture("nao", "motoflex", 2);
  MjcfOptions options;
  options.weld_root = true;
  options.clearance_m = 0.1;
  const ModelPtr m = load(export_mjcf(*f.input, options), "nao_flex");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->nq, 10 + 4 * 2);  // no free joint; two hinges per flex joint
  int springs = 0;
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_stiffness[j] > 0.0) {
      ++springs;
      EXPECT_EQ(m->jnt_stiffness[j], f.input->parameters.get("flex.spring_nm_per_rad"));
      EXPECT_EQ(m->dof_damping[m->jnt_dofadr[j]],
                f.input->parameters.get("flex.damping_nm_s_per_rad"));
    }
  }
  EXPECT_EQ(springs, 8);
}

TEST(MjcfExport, MujocoErrorsAreReported) {
  EXPECT_NE(mujoco_errors("<mujoco><worldbody><body><joint type=\"hinge\" kv=\"1\"/></body>"
                          "</worldbody></mujoco>"),
            "");
}

}  // namespace
}  // namespace motoflex
