#include "motoflex/sim/rollout.hpp"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "axis_rows.hpp"
#include "float_body_state.hpp"
#include "ground_colliders.hpp"
#include "mimic_coupling.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/model/body_kinematics.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/joint_encoder.hpp"
#include "motoflex/sim/ode_runtime.hpp"
#include "ode_axis.hpp"
#include "ode_quick_step.hpp"
#include "ode_sparse_step.hpp"
#include "resolved_parameters.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

constexpr double kMaxLinearSpeed_m_s = 50.0;  // beyond this a legged robot has diverged
constexpr double kMaxAngularSpeed_rad_s = 500.0;
constexpr double kHeldTorsoClearance_m = 0.1;  // feet above the ground when the torso is held
constexpr std::uint64_t kEncoderNoisePurpose = 0x656e636f646572ULL;  // "encoder"

void to_ode_rotation(const Eigen::Matrix3d& R, dMatrix3 out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 4 + c] = R(r, c);
    out[r * 4 + 3] = 0.0;
  }
}

Eigen::Matrix3d from_ode_rotation(const dReal* R) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out(r, c) = R[r * 4 + c];
  }
  return out;
}

// Converts limits given in our sign convention to ODE's for an axis with `sign`.
void ode_limits(double sign, double lower, double upper, double& lo, double& hi) {
  lo = sign > 0 ? lower : -upper;
  hi = sign > 0 ? upper : -lower;
}

}  // namespace

const char* to_string(RolloutEnd end) {
  switch (end) {
    case RolloutEnd::kCompleted:
      return "completed";
    case RolloutEnd::kFell:
      return "fell";
    case RolloutEnd::kDiverged:
      return "diverged";
    case RolloutEnd::kModelError:
      return "model_error";
    case RolloutEnd::kStoppedEarly:
      return "stopped_early";
  }
  return "?";
}

std::vector<const ServoLawInfo*> laws_for(const RobotModel& model, const RolloutOptions& options) {
  std::vector<const ServoLawInfo*> laws;
  for (std::size_t i = 0; i < model.actuators.size(); ++i) {
    const std::string& name = actuator_servo_name(model, options.servo, i);
    const ServoLawInfo* law = find_servo_law(name);
    if (law == nullptr) {
      throw ModelError("unknown servo '" + name + "' (" + servo_law_names() + ")");
    }
    laws.push_back(law);
  }
  return laws;
}

// The pendulum bench: the first actuator's law may carry the arm as a point mass.
bool first_law_has_point_mass_arm(const std::vector<const ServoLawInfo*>& laws) {
  return !laws.empty() && laws.front()->point_mass_arm;
}

struct Rollout::Impl {
  const RobotModel& model;
  RolloutOptions options;
  std::vector<const ServoLawInfo*> laws;  // per actuator
  bool point_mass_arm;
  detail::ResolvedParameters params;

  dWorldID world = nullptr;
  dThreadingImplementationID threading = nullptr;
  dJointGroupID contact_group = nullptr;
  dGeomID ground = nullptr;
  std::vector<dBodyID> bodies;  // nullptr for a static (welded) body
  std::vector<dJointID> joints;
  std::vector<dJointID> flex_friction_motors;
  detail::GroundColliders colliders;
  std::vector<detail::ShapeGeom> foot_geoms;     // feet: contacts and force sensors
  std::vector<detail::ShapeGeom> contact_geoms;  // contact_links: contacts, never a fall
  std::vector<detail::ShapeGeom> other_geoms;    // touching the ground is a fall
  std::vector<dJointFeedback> joint_feedback;    // per model joint (enable_joint_feedback)
  std::vector<dJointFeedback> contact_feedback;  // max_contacts per foot shape
  std::vector<std::size_t> contact_owner;        // foot shape of each used feedback slot
  std::size_t contacts_used = 0;
  std::vector<Eigen::Vector3d> foot_force_n;  // ground force on each foot shape (world frame)
  std::vector<detail::MimicCoupling> mimics;

  std::vector<detail::OdeAxis> axes;                 // per actuator
  std::vector<double> joint_torque1, joint_torque2;  // per model joint, accumulated each step
  std::vector<std::size_t> flex_joints;              // model joint indices
  double flex_velocity_gain = 0.0;                   // ERP/h of the flex springs (implicit)
  unsigned long quick_step_seed = 0;   // this rollout's dRandInt state (quick; build_world sets it)
  detail::SparseStepState sparse_lcp;  // this rollout's LCP solver (sparse)
  std::vector<std::unique_ptr<ServoLaw>> servos;  // per actuator
  // Extra rows of an actuated axis that its law asks for (null = none): the armature's inertia
  // row and a separate friction row, each an angular motor between the joint's two bodies.
  struct AxisRows {
    dJointID inertia = nullptr;
    dJointID friction = nullptr;
    std::vector<dBodyID> load_bodies;  // what the joint moves, when the law needs τ_e
    bool external_torque = false;
  };
  std::vector<AxisRows> axis_rows;  // per actuator
  Eigen::Vector3d gravity_m_s2 = Eigen::Vector3d(0.0, 0.0, -9.81);
  std::vector<JointEncoder> encoders;
  std::vector<double> applied_torque_nm;
  dContact contact_template{};
  double elapsed_s = 0.0;  // since the rollout was created (settling included)
  double logged_supply_v = std::numeric_limits<double>::quiet_NaN();  // NaN: none logged
  bool step_interrupted = false;  // an ODE error was thrown out of dWorldStep

  Impl(const RobotModel& m, const ParameterSet& values, const RolloutOptions& o)
      : model(m),
        options(o),
        laws(laws_for(m, o)),
        point_mass_arm(first_law_has_point_mass_arm(laws)),
        params(detail::resolve_parameters(m, values, point_mass_arm)) {}

  ~Impl() {
    if (world != nullptr) dWorldSetStepThreadingImplementation(world, nullptr, nullptr);
    // An ODE assertion inside a step (thrown by our handler; the rollout then ends as
    // diverged) leaves that step's jobs queued, and freeing the queue would assert again from
    // inside ODE's destructors: the queue of such a rollout is left allocated.
    if (threading != nullptr && !step_interrupted) dThreadingFreeImplementation(threading);
    if (ground != nullptr) dGeomDestroy(ground);
    if (contact_group != nullptr) dJointGroupDestroy(contact_group);
    if (world != nullptr) dWorldDestroy(world);  // also destroys bodies and joints
  }

  void build_world();
  void build_bodies();
  void build_joints();
  void build_flex_joint(std::size_t j);  // spring, damping and friction rows of flex joint j
  void build_actuators(const ParameterSet& values);
  dJointID add_axis_motor(std::size_t actuator);
  void add_damping_row(std::size_t actuator, double damping_nm_s_per_rad);
  void add_mimic_couplings();
  void add_inertia_row(std::size_t actuator, double armature);
  void update_inertia_rows();
  double external_torque_nm(std::size_t actuator) const;
  void place(const std::vector<double>& pose_rad);
  void apply_servos(const double* now_rad, const double* next_rad);
  void apply_flex_springs();
  void collide_feet();
  void read_foot_forces();
  std::optional<std::string> fall_reason(const Rollout& self) const;
  bool diverged(std::string& detail) const;
  // The joint's encoder: the angle plus its mounting offset (what the servo regulates on).
  double sensed_angle_rad(std::size_t actuator) const;
  double encoder_input(std::size_t actuator) const;  // what the logging encoder reports now
};

void Rollout::Impl::build_world() {
  world = dWorldCreate();
  // Each world gets its own threading implementation: worlds stepped in parallel must not
  // share ODE's global default one (it races; ode_and_titan8.md §2.6).
  threading = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                       threading);
  dWorldSetGravity(world, gravity_m_s2.x(), gravity_m_s2.y(), gravity_m_s2.z());
  // Set before joints are created: joints copy ERP/CFM into their limit and motor rows.
  dWorldSetERP(world, params.world_erp);
  dWorldSetCFM(world, params.world_cfm);
  dWorldSetQuickStepNumIterations(world, options.quickstep_iterations);
  dWorldSetQuickStepW(world, options.quickstep_w);
  quick_step_seed = options.quickstep_seed;
  contact_group = dJointGroupCreate(0);
  ground = dCreatePlane(nullptr, 0.0, 0.0, 1.0, 0.0);

  contact_template.surface.mode =
      dContactApprox1 | dContactSoftERP | dContactSoftCFM | dContactSlip1 | dContactSlip2;
  contact_template.surface.mu = params.contact.mu;
  contact_template.surface.soft_erp = params.contact.soft_erp;
  contact_template.surface.soft_cfm = params.contact.soft_cfm;
  contact_template.surface.slip1 = params.contact.slip;
  contact_template.surface.slip2 = params.contact.slip;
}

void Rollout::Impl::build_bodies() {
  bodies.assign(model.bodies.size(), nullptr);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const BodySpec& spec = model.bodies[b];
    Eigen::Vector3d com = spec.com_W0_m;
    if (!spec.is_static) {
      double mass = spec.mass_kg;
      Eigen::Matrix3d inertia = spec.inertia_kg_m2;
      // Bench: the arm is a point mass at bench.length_m from the axis plus the armature.
      if (point_mass_arm && spec.parent_joint >= 0 &&
          model.joints[spec.parent_joint].actuator1 == 0) {
        const JointSpec& joint = model.joints[spec.parent_joint];
        Eigen::Vector3d arm = spec.com_W0_m - joint.anchor_W0_m;
        arm -= joint.axis1_W0 * joint.axis1_W0.dot(arm);
        if (arm.norm() < 1e-9) throw ModelError("bench arm CoM lies on the joint axis");
        mass = params.bench_load.mass_kg;
        com = joint.anchor_W0_m + arm.normalized() * params.bench_load.length_m;
        inertia = Eigen::Matrix3d::Identity() * std::max(params.bench_load.armature_kg_m2, 1e-9);
      }
      dBodyID body = dBodyCreate(world);
      dMass m;
      dMassSetParameters(&m, mass, 0.0, 0.0, 0.0, inertia(0, 0), inertia(1, 1), inertia(2, 2),
                         inertia(0, 1), inertia(0, 2), inertia(1, 2));
      if (!dMassCheck(&m)) throw ModelError("body " + spec.name + " has an invalid mass");
      dBodySetMass(body, &m);
      dBodySetPosition(body, com.x(), com.y(), com.z());
      bodies[b] = body;
    }
    // Without a ground there is nothing to collide with or to fall onto.
    if (!model.ground) continue;
    for (const CollisionShape& shape : spec.collisions) {
      // On a body the offset from the ODE body's position; on the welded base a world pose.
      const Eigen::Vector3d p = shape.X_BG.translation() + spec.com_W0_m -
                                (bodies[b] != nullptr ? com : Eigen::Vector3d::Zero());
      const detail::ShapeGeom geom = colliders.add(shape, bodies[b], b, p);
      if (bodies[b] == nullptr) continue;  // the welded base never falls
      switch (shape.contact) {
        case GroundContact::kFoot: {
          // The shape's own contact limit, capped by the rollout's per-foot limit.
          detail::ShapeGeom foot = geom;
          foot.max_contacts = std::min(foot.max_contacts, options.max_contacts_per_foot);
          foot_geoms.push_back(foot);
          break;
        }
        case GroundContact::kContact:
          contact_geoms.push_back(geom);
          break;
        case GroundContact::kFall:
          other_geoms.push_back(geom);
          break;
      }
    }
  }
}

namespace {

// A slider, body1 = child: ODE's slider position is body1 relative to body2 along the axis, ours.
dJointID create_slider(dWorldID world, dBodyID parent, dBodyID child, const JointSpec& spec) {
  dJointID joint = dJointCreateSlider(world, nullptr);
  dJointAttach(joint, child, parent);
  dJointSetSliderAxis(joint, spec.axis1_W0.x(), spec.axis1_W0.y(), spec.axis1_W0.z());
  if (std::isfinite(spec.lower1_rad)) {
    dJointSetSliderParam(joint, dParamLoStop, spec.lower1_rad);
    dJointSetSliderParam(joint, dParamHiStop, spec.upper1_rad);
  }
  return joint;
}

// A hinge, body1 = child: ODE's hinge angle is body1 relative to body2, our convention.
dJointID create_hinge(dWorldID world, dBodyID parent, dBodyID child, const JointSpec& spec) {
  const Eigen::Vector3d& a = spec.anchor_W0_m;
  dJointID joint = dJointCreateHinge(world, nullptr);
  dJointAttach(joint, child, parent);
  dJointSetHingeAnchor(joint, a.x(), a.y(), a.z());
  dJointSetHingeAxis(joint, spec.axis1_W0.x(), spec.axis1_W0.y(), spec.axis1_W0.z());
  if (std::isfinite(spec.lower1_rad)) {
    dJointSetHingeParam(joint, dParamLoStop, spec.lower1_rad);
    dJointSetHingeParam(joint, dParamHiStop, spec.upper1_rad);
  }
  return joint;
}

// Universal and flex: body1 = parent carries axis 1, body2 = child carries axis 2; ODE then
// reports both angles with the opposite sign of ours (checked in tests). Stops only for a
// universal joint.
dJointID create_universal(dWorldID world, dBodyID parent, dBodyID child, const JointSpec& spec) {
  const Eigen::Vector3d& a = spec.anchor_W0_m;
  dJointID joint = dJointCreateUniversal(world, nullptr);
  dJointAttach(joint, parent, child);
  dJointSetUniversalAnchor(joint, a.x(), a.y(), a.z());
  dJointSetUniversalAxis1(joint, spec.axis1_W0.x(), spec.axis1_W0.y(), spec.axis1_W0.z());
  dJointSetUniversalAxis2(joint, spec.axis2_W0.x(), spec.axis2_W0.y(), spec.axis2_W0.z());
  if (spec.kind != JointKind::kUniversal) return joint;
  double lo = 0.0, hi = 0.0;
  if (std::isfinite(spec.lower1_rad)) {
    ode_limits(-1.0, spec.lower1_rad, spec.upper1_rad, lo, hi);
    dJointSetUniversalParam(joint, dParamLoStop, lo);
    dJointSetUniversalParam(joint, dParamHiStop, hi);
  }
  if (std::isfinite(spec.lower2_rad)) {
    ode_limits(-1.0, spec.lower2_rad, spec.upper2_rad, lo, hi);
    dJointSetUniversalParam(joint, dParamLoStop2, lo);
    dJointSetUniversalParam(joint, dParamHiStop2, hi);
  }
  return joint;
}

}  // namespace

void Rollout::Impl::build_joints() {
  joints.assign(model.joints.size(), nullptr);
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointSpec& spec = model.joints[j];
    dBodyID parent = bodies[spec.parent_body];
    dBodyID child = bodies[spec.child_body];
    if (spec.kind == JointKind::kSlider) {
      joints[j] = create_slider(world, parent, child, spec);
    } else if (spec.kind == JointKind::kHinge) {
      joints[j] = create_hinge(world, parent, child, spec);
    } else {
      joints[j] = create_universal(world, parent, child, spec);
      if (spec.kind != JointKind::kUniversal) build_flex_joint(j);
    }
  }
  joint_torque1.assign(model.joints.size(), 0.0);
  joint_torque2.assign(model.joints.size(), 0.0);
}

void Rollout::Impl::build_flex_joint(std::size_t j) {
  const JointSpec& spec = model.joints[j];
  dJointID joint = joints[j];
  const double h = options.dt_s;
  flex_joints.push_back(j);
  if (options.flex_model == FlexModel::kExplicitCfm) {
    // The 2011 program's flex rows (motoflex_2011.md §2.9): target 0 and FMax
    // flexibleFriction, with the CFM the joint copied from the world when it was created
    // (build_world sets it first), so each row is a damper 1/CFM capped at FMax; the spring
    // is an explicit torque (apply_flex_springs).
    dJointSetUniversalParam(joint, dParamFMax, params.flex.friction_nm);
    dJointSetUniversalParam(joint, dParamFMax2, params.flex.friction_nm);
    return;
  }
  // Flex joint: the spring −D_B·α and damping (seed 001 eq. 1) are integrated implicitly by
  // a motor row whose target velocity is −(ERP/h)·α with the matching CFM, i.e. ODE's
  // spring-damper equivalence ERP = h·k/(h·k + c), CFM = 1/(h·k + c). An explicit torque
  // would need h·sqrt(D_B/I) < 2, which the small sub-bodies do not meet at 1 ms.
  const double k = params.flex.spring_nm_per_rad;
  const double c = params.flex.damping_nm_s_per_rad;
  const double erp = h * k / (h * k + c);
  const double cfm = 1.0 / (h * k + c);
  flex_velocity_gain = erp / h;
  for (const auto& [fmax, cfm_param] :
       {std::pair{dParamFMax, dParamCFM}, std::pair{dParamFMax2, dParamCFM2}}) {
    dJointSetUniversalParam(joint, fmax, dInfinity);
    dJointSetUniversalParam(joint, cfm_param, cfm);
  }
  if (params.flex.friction_nm > 0.0) {
    // Coulomb damping of the flex joint: a zero-velocity angular motor on both bending axes.
    dBodyID parent = bodies[spec.parent_body];
    dBodyID child = bodies[spec.child_body];
    dJointID motor = dJointCreateAMotor(world, nullptr);
    dJointAttach(motor, parent, child);
    dJointSetAMotorMode(motor, dAMotorUser);
    dJointSetAMotorNumAxes(motor, 2);
    dJointSetAMotorAxis(motor, 0, 1, spec.axis1_W0.x(), spec.axis1_W0.y(), spec.axis1_W0.z());
    dJointSetAMotorAxis(motor, 1, 2, spec.axis2_W0.x(), spec.axis2_W0.y(), spec.axis2_W0.z());
    detail::set_axis_motor_param(motor, dParamVel, 0.0);
    detail::set_axis_motor_param(motor, dParamVel2, 0.0);
    detail::set_axis_motor_param(motor, dParamFMax, params.flex.friction_nm);
    detail::set_axis_motor_param(motor, dParamFMax2, params.flex.friction_nm);
    flex_friction_motors.push_back(motor);
  }
}

void Rollout::Impl::build_actuators(const ParameterSet& values) {
  const std::size_t n = model.actuators.size();
  applied_torque_nm.assign(n, 0.0);
  axis_rows.assign(n, AxisRows{});
  for (std::size_t i = 0; i < n; ++i) {
    const ActuatorSpec& spec = model.actuators[i];
    axes.push_back(detail::ode_axis(joints[spec.joint], model.joints[spec.joint], spec.axis));
    encoders.emplace_back(params.encoder, options.dt_s,
                          RandomStream({options.seed, kEncoderNoisePurpose, i}));
    const ParameterReader reader(values, laws[i]->name);
    servos.push_back(laws[i]->create({model, i, reader, options.dt_s, options.gear_substeps}));
    const ServoLaw& servo = *servos.back();
    const double damping_nm_s_per_rad = servo.damping_row_nm_s_per_rad();
    if (damping_nm_s_per_rad > 0.0) add_damping_row(i, damping_nm_s_per_rad);
    const double armature = servo.armature();  // kg·m², or kg on a slider
    if (armature > 0.0) add_inertia_row(i, armature);
    if (servo.has_friction_row()) {
      axis_rows[i].friction = add_axis_motor(i);
      detail::set_axis_motor_param(axis_rows[i].friction, dParamVel, 0.0);
      detail::set_axis_motor_param(axis_rows[i].friction, dParamFMax, 0.0);
    }
    if (servo.needs_external_torque() || params.torque_terms[i].uses_load()) {
      axis_rows[i].external_torque = true;
      for (const int b : detail::moved_bodies(model, spec.joint)) {
        if (bodies[b] != nullptr) axis_rows[i].load_bodies.push_back(bodies[b]);
      }
    }
  }
}

dJointID Rollout::Impl::add_axis_motor(std::size_t actuator) {
  return detail::create_axis_motor(world, model, bodies, actuator);
}

void Rollout::Impl::add_damping_row(std::size_t actuator, double damping_nm_s_per_rad) {
  // A linear damper τ = −c·ω integrated implicitly: an angular motor row driving the relative
  // rate about the actuated axis to zero with unbounded force and CFM = 1/c gives the row force
  // −c·ω at the end of the step (ODE's spring-damper equivalence with k = 0). It stays stable
  // for any c·h/I, where an explicit torque diverges once c·h/I > 2.
  dJointID motor = add_axis_motor(actuator);
  detail::set_axis_motor_param(motor, dParamVel, 0.0);
  detail::set_axis_motor_param(motor, dParamFMax, dInfinity);
  detail::set_axis_motor_param(motor, dParamCFM, 1.0 / damping_nm_s_per_rad);
}

void Rollout::Impl::add_mimic_couplings() {
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const auto& mimic = model.joints[j].mimic;
    if (!mimic) continue;
    const JointSpec& leader = model.joints[mimic->leader_joint];
    mimics.push_back({detail::ode_axis(joints[j], model.joints[j], 1),
                      detail::ode_axis(joints[mimic->leader_joint], leader, mimic->leader_axis),
                      mimic->multiplier, mimic->offset,
                      mimic->leader_axis == 1 ? leader.actuator1 : leader.actuator2});
  }
}

void Rollout::Impl::add_inertia_row(std::size_t actuator, double armature) {
  // The armature J (kg·m², or a mass in kg on a slider) as joint-space inertia (MuJoCo's armature:
  // J·q̈ on the joint's own equation, no coupling to the other joints). ODE solves a motor row to
  // J·v₁ = v_target − CFM·λ, so a row that targets the rate at the start of the step, with
  // unbounded force and CFM = h/J, applies λ = −J·(v₁ − v₀)/h: the rotor's inertial reaction,
  // implicitly, whatever J·h/I. The joint's equation becomes (I + J)·(v₁ − v₀)/h = τ, exactly as if
  // J were added to the inertia it moves (tests/sim/armature_test.cpp). The alternative, a rotor
  // body on the parent coupled 1:1 to the child by a transmission joint, costs a body and a
  // constraint per joint and couples the joint to the parent's rotation with the whole J, where a
  // real rotor (J/N² spinning at N·q̇) couples with J/N only; MuJoCo's armature, which the MJCF
  // export writes, has neither.
  axis_rows[actuator].inertia = add_axis_motor(actuator);
  dJointID motor = axis_rows[actuator].inertia;
  detail::set_axis_motor_param(motor, dParamVel, 0.0);
  detail::set_axis_motor_param(motor, dParamFMax, dInfinity);
  detail::set_axis_motor_param(motor, dParamCFM, options.dt_s / armature);
}

void Rollout::Impl::update_inertia_rows() {
  for (const AxisRows& rows : axis_rows) {
    if (rows.inertia != nullptr) detail::target_current_rate(rows.inertia);
  }
}

double Rollout::Impl::external_torque_nm(std::size_t actuator) const {
  return detail::gravity_torque_nm(axes[actuator], axis_rows[actuator].load_bodies, gravity_m_s2);
}

void Rollout::Impl::place(const std::vector<double>& pose_rad) {
  std::vector<Eigen::Isometry3d> poses = body_poses(model, pose_rad);
  if (!model.fixed_base) {
    // Feet go to the ground; a robot without feet is placed by all its shapes (held in the
    // air, or dropped onto whatever touches first).
    double lowest = lowest_foot_point_z(model, poses);
    if (!std::isfinite(lowest)) lowest = lowest_shape_point_z(model, poses);
    if (std::isfinite(lowest)) {
      const double clearance_m =
          options.hold_torso ? kHeldTorsoClearance_m : model.initial_clearance_m;
      const Eigen::Vector3d shift(0.0, 0.0, clearance_m - lowest);
      for (auto& X : poses) X.pretranslate(shift);
    }
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b] == nullptr) continue;
    Eigen::Vector3d com = poses[b].translation();
    // A bench arm's CoM was moved along the arm; keep it where build_bodies put it.
    const dReal* built = dBodyGetPosition(bodies[b]);
    const Eigen::Vector3d built_offset =
        Eigen::Vector3d(built[0], built[1], built[2]) - model.bodies[b].com_W0_m;
    com += poses[b].linear() * built_offset;
    dMatrix3 R;
    to_ode_rotation(poses[b].linear(), R);
    dBodySetPosition(bodies[b], com.x(), com.y(), com.z());
    dBodySetRotation(bodies[b], R);
    dBodySetLinearVel(bodies[b], 0.0, 0.0, 0.0);
    dBodySetAngularVel(bodies[b], 0.0, 0.0, 0.0);
  }
  for (std::size_t i = 0; i < axes.size(); ++i) axes[i].sync_turns(pose_rad[i]);
  for (auto& mimic : mimics) {
    // A passive leader starts at its build position, 0.
    const double leader = mimic.leader_actuator >= 0 ? pose_rad[mimic.leader_actuator] : 0.0;
    mimic.leader.sync_turns(leader);
    mimic.follower.sync_turns(mimic.multiplier * leader + mimic.offset);
  }
  for (std::size_t i = 0; i < encoders.size(); ++i) encoders[i].reset(encoder_input(i));
  // A held torso is a kinematic body: it does not move, and the joints act on it as on an
  // infinitely heavy one (the robot hangs from a stand).
  if (options.hold_torso && bodies[model.root_body] != nullptr) {
    dBodySetKinematic(bodies[model.root_body]);
  }
}

double Rollout::Impl::sensed_angle_rad(std::size_t i) const {
  return axes[i].angle_rad() + params.encoders[i].mounting_offset_rad;
}

double Rollout::Impl::encoder_input(std::size_t i) const {
  const detail::EncoderCalibration& calibration = params.encoders[i];
  return calibration.scale * sensed_angle_rad(i) + calibration.offset_rad;
}

void Rollout::Impl::apply_servos(const double* now_rad, const double* next_rad) {
  const std::size_t n = axes.size();
  // The robot's supply sags with the current every motor drew in the last step.
  double total_current_a = 0.0;
  for (const auto& servo : servos) total_current_a += std::abs(servo->current_a());
  std::fill(joint_torque1.begin(), joint_torque1.end(), 0.0);
  std::fill(joint_torque2.begin(), joint_torque2.end(), 0.0);
  ServoInput input;
  input.elapsed_s = elapsed_s;
  input.settle_s = options.settle_s;
  input.total_current_a = total_current_a;
  input.logged_supply_v = logged_supply_v;
  for (std::size_t i = 0; i < n; ++i) {
    const detail::OdeAxis& axis = axes[i];
    input.command_rad = now_rad[i];
    input.next_command_rad = next_rad[i];
    input.angle_rad = sensed_angle_rad(i);
    input.rate_rad_s = axis.rate_rad_s();
    input.external_torque_nm = axis_rows[i].external_torque ? external_torque_nm(i) : 0.0;
    const ServoOutput out = servos[i]->step(input);
    axis.set_motor(out.row.velocity_rad_s, out.row.fmax_nm);
    if (axis_rows[i].friction != nullptr) {
      detail::set_axis_motor_param(axis_rows[i].friction, dParamFMax, out.friction_row.fmax_nm);
    }
    applied_torque_nm[i] = out.torque_nm;
    if (std::isfinite(out.torque_nm)) {
      const ActuatorSpec& spec = model.actuators[i];
      const double explicit_nm = out.torque_nm + out.damping_offset_nm;
      (spec.axis == 1 ? joint_torque1 : joint_torque2)[spec.joint] += axis.sign * explicit_nm;
    }
    if (params.torque_terms[i].active()) {
      const TermState state{input.angle_rad, input.command_rad - input.angle_rad, input.rate_rad_s,
                            input.external_torque_nm};
      const ActuatorSpec& spec = model.actuators[i];
      (spec.axis == 1 ? joint_torque1 : joint_torque2)[spec.joint] +=
          axis.sign * params.torque_terms[i].torque_nm(state);
    }
  }
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joint_torque1[j] == 0.0 && joint_torque2[j] == 0.0) continue;
    if (model.joints[j].kind == JointKind::kHinge) {
      dJointAddHingeTorque(joints[j], joint_torque1[j]);
    } else if (model.joints[j].kind == JointKind::kSlider) {
      dJointAddSliderForce(joints[j], joint_torque1[j]);
    } else {
      dJointAddUniversalTorques(joints[j], joint_torque1[j], joint_torque2[j]);
    }
  }
}

void Rollout::Impl::apply_flex_springs() {
  if (options.flex_model == FlexModel::kExplicitCfm) {
    // seed 001 eq. 1, T_B = −D_B·α, as an explicit torque (a positive universal torque turns
    // ODE's angle positive, as for the actuators); stable only with the CFM damper of the rows.
    const double spring = params.flex.spring_nm_per_rad;
    for (const std::size_t j : flex_joints) {
      dJointID joint = joints[j];
      dJointAddUniversalTorques(joint, -spring * dJointGetUniversalAngle1(joint),
                                -spring * dJointGetUniversalAngle2(joint));
    }
    return;
  }
  for (const std::size_t j : flex_joints) {
    dJointID joint = joints[j];
    dJointSetUniversalParam(joint, dParamVel,
                            -flex_velocity_gain * dJointGetUniversalAngle1(joint));
    dJointSetUniversalParam(joint, dParamVel2,
                            -flex_velocity_gain * dJointGetUniversalAngle2(joint));
  }
}

void Rollout::Impl::collide_feet() {
  dContactGeom contacts[detail::kMaxGroundContacts];
  std::size_t used = 0;
  const auto attach = [&](const detail::ShapeGeom& shape, int k) {
    dContact contact = contact_template;
    contact.geom = contacts[k];
    dJointID joint = dJointCreateContact(world, contact_group, &contact);
    dJointAttach(joint, shape.body, nullptr);
    return joint;
  };
  for (std::size_t f = 0; f < foot_geoms.size(); ++f) {
    const int n = detail::GroundColliders::collide(foot_geoms[f], ground, contacts);
    for (int k = 0; k < n; ++k) {
      // The contact force is read back after the step (foot force sensor); the feedback
      // buffers are preallocated, one per possible contact.
      dJointSetFeedback(attach(foot_geoms[f], k), &contact_feedback[used]);
      contact_owner[used] = f;
      ++used;
    }
  }
  contacts_used = used;
  for (const detail::ShapeGeom& shape : contact_geoms) {
    const int n = detail::GroundColliders::collide(shape, ground, contacts);
    for (int k = 0; k < n; ++k) attach(shape, k);
  }
}

void Rollout::Impl::read_foot_forces() {
  for (auto& force : foot_force_n) force.setZero();
  for (std::size_t c = 0; c < contacts_used; ++c) {
    const dJointFeedback& fb = contact_feedback[c];
    foot_force_n[contact_owner[c]] += Eigen::Vector3d(fb.f1[0], fb.f1[1], fb.f1[2]);
  }
}

std::optional<std::string> Rollout::Impl::fall_reason(const Rollout& self) const {
  for (const detail::ShapeGeom& ref : other_geoms) {
    dReal aabb[6];
    dGeomGetAABB(ref.geom, aabb);
    if (aabb[4] <= 0.0) return model.bodies[ref.body_index].name + " touched the ground";
  }
  if (self.torso_tilt_rad() > model.max_tilt_rad) return std::string("torso tilted too far");
  if (model.min_torso_height_m > 0.0 && self.torso_position_m().z() < model.min_torso_height_m) {
    return std::string("torso dropped too low");
  }
  return std::nullopt;
}

bool Rollout::Impl::diverged(std::string& detail) const {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b] == nullptr) continue;
    const dReal* p = dBodyGetPosition(bodies[b]);
    const dReal* v = dBodyGetLinearVel(bodies[b]);
    const dReal* w = dBodyGetAngularVel(bodies[b]);
    const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    if (!std::isfinite(p[0] + p[1] + p[2] + v2 + w2)) {
      detail = model.bodies[b].name + " state is not finite";
      return true;
    }
    if (v2 > kMaxLinearSpeed_m_s * kMaxLinearSpeed_m_s ||
        w2 > kMaxAngularSpeed_rad_s * kMaxAngularSpeed_rad_s) {
      detail = model.bodies[b].name + " moves absurdly fast";
      return true;
    }
  }
  return false;
}

Rollout::Rollout(const RobotModel& model, const ParameterSet& parameters,
                 const RolloutOptions& options, const std::vector<double>& initial_pose_rad) {
  if (!(options.dt_s > 0.0)) throw ModelError("physics dt_s must be positive");
  if (options.max_contacts_per_foot < 1) throw ModelError("max_contacts_per_foot must be >= 1");
  if (initial_pose_rad.size() != model.actuators.size()) {
    throw ModelError("initial pose has the wrong number of joints");
  }
  ensure_ode_ready();
  if (options.solver == StepSolver::kSparseStep && !detail::ode_lcp_is_replaced()) {
    throw ModelError(
        "solver 'sparse' needs motoflex's LCP solver in place of libode's, which this process "
        "does not allow (libode is bound to its own dxSolveLCP, e.g. in a module loaded with "
        "local symbols); use solver 'step', which gives the same answers up to rounding");
  }
  impl_ = std::make_unique<Impl>(model, parameters, options);
  impl_->build_world();
  impl_->build_bodies();
  impl_->build_joints();
  impl_->build_actuators(parameters);
  impl_->add_mimic_couplings();
  std::size_t foot_contacts = 0;
  for (const auto& foot : impl_->foot_geoms) foot_contacts += foot.max_contacts;
  impl_->contact_feedback.resize(foot_contacts);
  impl_->contact_owner.resize(impl_->contact_feedback.size());
  impl_->foot_force_n.assign(impl_->foot_geoms.size(), Eigen::Vector3d::Zero());
  // The pose is given as the encoders read it; a mounting offset puts the joint off by it.
  std::vector<double> pose_rad = initial_pose_rad;
  for (std::size_t i = 0; i < pose_rad.size(); ++i) {
    pose_rad[i] -= impl_->params.encoders[i].mounting_offset_rad;
  }
  impl_->place(pose_rad);
}

Rollout::~Rollout() = default;

std::size_t Rollout::joints() const {
  return impl_->axes.size();
}

void Rollout::set_logged_supply_v(double supply_v) {
  impl_->logged_supply_v = supply_v;
}

bool Rollout::step(const double* command_now_rad, const double* command_next_rad) {
  if (end_ != RolloutEnd::kCompleted) return false;
  Impl& s = *impl_;
  try {
    s.apply_servos(command_now_rad, command_next_rad);
    for (const auto& mimic : s.mimics) mimic.drive(s.options.dt_s);
    s.update_inertia_rows();
    s.apply_flex_springs();
    s.collide_feet();
    // Our ODE error handler throws: an error inside the step interrupts it (see ~Impl).
    s.step_interrupted = true;
    int ok = 0;
    switch (s.options.solver) {
      case StepSolver::kStep:
        ok = dWorldStep(s.world, s.options.dt_s);
        break;
      case StepSolver::kSparseStep:
        ok = detail::sparse_step(s.world, s.options.dt_s, s.sparse_lcp);
        break;
      case StepSolver::kQuickStep:
        ok = detail::seeded_quick_step(s.world, s.options.dt_s, s.quick_step_seed);
        break;
    }
    s.step_interrupted = false;
    if (s.options.float_state) {
      for (dBodyID body : s.bodies) {
        if (body != nullptr) detail::round_body_state_to_float(body);
      }
    }
    s.read_foot_forces();
    dJointGroupEmpty(s.contact_group);
    if (!ok) throw ModelError("ODE ran out of memory in the step");
  } catch (const ModelError& error) {
    end_ = RolloutEnd::kDiverged;
    end_detail_ = error.what();
    dJointGroupEmpty(s.contact_group);
    return false;
  }
  time_s_ += s.options.dt_s;
  s.elapsed_s = time_s_;
  for (std::size_t i = 0; i < s.encoders.size(); ++i) s.encoders[i].push(s.encoder_input(i));
  if (s.diverged(end_detail_)) {
    end_ = RolloutEnd::kDiverged;
    return false;
  }
  if (const auto reason = s.fall_reason(*this)) {
    end_detail_ = *reason;
    if (s.options.stop_on_fall) {
      end_ = RolloutEnd::kFell;
      return false;
    }
  }
  return true;
}

double Rollout::joint_angle_rad(std::size_t actuator) const {
  return impl_->axes.at(actuator).angle_rad();
}
double Rollout::joint_rate_rad_s(std::size_t actuator) const {
  return impl_->axes.at(actuator).rate_rad_s();
}
double Rollout::encoder_rad(std::size_t actuator) {
  return impl_->encoders.at(actuator).read();
}
double Rollout::actuator_torque_nm(std::size_t actuator) const {
  return impl_->applied_torque_nm.at(actuator);
}

void Rollout::imu_roll_pitch(double& roll_rad, double& pitch_rad) const {
  const dBodyID torso = impl_->bodies[impl_->model.torso_body];
  const Eigen::Matrix3d R = (torso == nullptr ? Eigen::Matrix3d::Identity()
                                              : from_ode_rotation(dBodyGetRotation(torso))) *
                            impl_->model.R_torsoBody_torsoLink;
  // Z-Y-X (yaw-pitch-roll) angles of the torso link.
  roll_rad = std::atan2(R(2, 1), R(2, 2));
  pitch_rad = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
}

Eigen::Vector3d Rollout::torso_position_m() const {
  const dBodyID torso = impl_->bodies[impl_->model.torso_body];
  if (torso == nullptr) return impl_->model.bodies[impl_->model.torso_body].com_W0_m;
  const dReal* p = dBodyGetPosition(torso);
  return {p[0], p[1], p[2]};
}

double Rollout::torso_tilt_rad() const {
  const dBodyID torso = impl_->bodies[impl_->model.torso_body];
  if (torso == nullptr) return 0.0;
  const Eigen::Matrix3d R =
      from_ode_rotation(dBodyGetRotation(torso)) * impl_->model.R_torsoBody_torsoLink;
  return std::acos(std::clamp(R(2, 2), -1.0, 1.0));
}

std::size_t Rollout::foot_count() const {
  return impl_->foot_geoms.size();
}

Eigen::Vector3d Rollout::foot_force_n(std::size_t foot) const {
  return impl_->foot_force_n.at(foot);
}

std::string Rollout::foot_name(std::size_t foot) const {
  return impl_->model.bodies[impl_->foot_geoms.at(foot).body_index].name;
}

bool Rollout::body_is_dynamic(std::size_t index) const {
  return impl_->bodies.at(index) != nullptr;
}

Rollout::BodyState Rollout::body_state(std::size_t index) const {
  const dBodyID body = impl_->bodies.at(index);
  if (body == nullptr) throw ModelError(impl_->model.bodies[index].name + " is a static body");
  const auto vec = [](const dReal* v) { return Eigen::Vector3d(v[0], v[1], v[2]); };
  BodyState state;
  state.position_m = vec(dBodyGetPosition(body));
  state.R_WB = from_ode_rotation(dBodyGetRotation(body));
  state.velocity_m_s = vec(dBodyGetLinearVel(body));
  state.angular_velocity_rad_s = vec(dBodyGetAngularVel(body));
  dMass mass;
  dBodyGetMass(body, &mass);
  state.mass_kg = mass.mass;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) state.inertia_B_kg_m2(r, c) = mass.I[r * 4 + c];
  }
  return state;
}

Eigen::Vector3d Rollout::gravity_m_s2() const {
  dVector3 g;
  dWorldGetGravity(impl_->world, g);
  return {g[0], g[1], g[2]};
}

void Rollout::enable_joint_feedback(std::size_t joint) {
  Impl& s = *impl_;
  // Sized once: ODE keeps a pointer to each entry, so the vector must never reallocate.
  if (s.joint_feedback.empty()) s.joint_feedback.resize(s.joints.size());
  dJointSetFeedback(s.joints.at(joint), &s.joint_feedback[joint]);
}

Rollout::JointFeedback Rollout::joint_feedback(std::size_t joint) const {
  const Impl& s = *impl_;
  if (s.joint_feedback.empty() || dJointGetFeedback(s.joints.at(joint)) == nullptr) {
    throw ModelError("joint feedback of " + s.model.joints.at(joint).name + " is not enabled");
  }
  const dJointFeedback& fb = s.joint_feedback[joint];
  const auto vec = [](const dReal* v) { return Eigen::Vector3d(v[0], v[1], v[2]); };
  return {vec(fb.f1), vec(fb.t1), vec(fb.f2), vec(fb.t2)};
}

void Rollout::hinge_frame(std::size_t joint, Eigen::Vector3d& anchor_m,
                          Eigen::Vector3d& axis) const {
  const dJointID j = impl_->joints.at(joint);
  if (dJointGetType(j) != dJointTypeHinge) {
    throw ModelError(impl_->model.joints.at(joint).name + " is not a hinge");
  }
  dVector3 a, x;
  dJointGetHingeAnchor(j, a);
  dJointGetHingeAxis(j, x);
  anchor_m = {a[0], a[1], a[2]};
  axis = {x[0], x[1], x[2]};
}

const detail::SparseStepState& RolloutOdeAccess::sparse_lcp(const Rollout& rollout) {
  return rollout.impl_->sparse_lcp;
}

dWorldID RolloutOdeAccess::world(const Rollout& rollout) {
  return rollout.impl_->world;
}
dBodyID RolloutOdeAccess::body(const Rollout& rollout, std::size_t index) {
  return rollout.impl_->bodies.at(index);
}
dJointID RolloutOdeAccess::joint(const Rollout& rollout, std::size_t index) {
  return rollout.impl_->joints.at(index);
}

}  // namespace motoflex
