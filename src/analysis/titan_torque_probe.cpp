#include "motoflex/analysis/titan_torque_probe.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "motoflex/analysis/leg_jacobian_torque.hpp"

namespace motoflex {
namespace {

Eigen::Vector3d vec(const dReal* v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

TitanTorqueProbe::TitanTorqueProbe(const RobotModel& model, const TitanKinematics& kinematics,
                                   const Rollout& rollout)
    : model_(model), rollout_(rollout) {
  for (const TitanLeg leg : kTitanLegs) {
    for (std::size_t j = 0; j < 4; ++j) {
      const std::size_t actuator = kinematics.actuators(leg)[j];
      const JointSpec& spec = model.joints.at(model.actuators.at(actuator).joint);
      if (spec.kind != JointKind::kHinge) {
        throw std::invalid_argument("TITAN torque probe: " + spec.name + " is not a hinge");
      }
      JointRef& ref = joints_[index(leg)][j];
      ref.joint = rollout.joint(static_cast<std::size_t>(model.actuators[actuator].joint));
      ref.child = rollout.body(static_cast<std::size_t>(spec.child_body));
      ref.parent = rollout.body(static_cast<std::size_t>(spec.parent_body));
      ref.actuator = actuator;
      if (ref.child == nullptr || ref.parent == nullptr ||
          dJointGetBody(ref.joint, 0) != ref.child) {
        throw std::invalid_argument("TITAN torque probe: " + spec.name +
                                    " must join two moving bodies with body 1 = child");
      }
      dJointSetFeedback(ref.joint, &feedback_[index(leg)][j]);
      if (j == 3) foot_body_[index(leg)] = spec.child_body;
    }
  }
  before_step();
}

TitanTorqueProbe::~TitanTorqueProbe() {
  for (auto& leg : joints_) {
    for (JointRef& ref : leg) {
      if (ref.joint != nullptr) dJointSetFeedback(ref.joint, nullptr);
    }
  }
}

void TitanTorqueProbe::before_step() {
  for (std::size_t l = 0; l < 4; ++l) {
    for (std::size_t j = 0; j < 4; ++j) {
      const JointRef& ref = joints_[l][j];
      Geometry& g = geometry_[l][j];
      dVector3 anchor, axis;
      dJointGetHingeAnchor(ref.joint, anchor);  // the anchor as attached to body 1
      dJointGetHingeAxis(ref.joint, axis);
      g.anchor_m = vec(anchor);
      g.axis = vec(axis);
      g.child_com_m = vec(dBodyGetPosition(ref.child));
      g.parent_com_m = vec(dBodyGetPosition(ref.parent));
    }
  }
}

void TitanTorqueProbe::after_step() {
  for (std::size_t l = 0; l < 4; ++l) {
    TitanLegSample& s = samples_[l];
    for (std::size_t j = 0; j < 4; ++j) {
      const JointRef& ref = joints_[l][j];
      const Geometry& g = geometry_[l][j];
      const dJointFeedback& fb = feedback_[l][j];
      s.angle_rad[j] = rollout_.joint_angle_rad(ref.actuator);
      s.rate_rad_s[j] = rollout_.joint_rate_rad_s(ref.actuator);
      // Seed 000 eq. 4–5 on the child (body 1).
      const JointWrench on_child =
          joint_wrench_at_point(vec(fb.f1), vec(fb.t1), g.child_com_m, g.anchor_m);
      s.feedback_torque_nm[j] = joint_axis_torque_nm(on_child, g.axis);
      if (j == 2) {
        const JointWrench on_parent =
            joint_wrench_at_point(vec(fb.f2), vec(fb.t2), g.parent_com_m, g.anchor_m);
        s.knee_load = joint_load(on_child);
        s.knee_third_law_residual_n = third_law_residual(on_child, on_parent).force_n.norm();
      }
    }
    // Seed 000 eq. 7: r_a = J4 position, F = the force J4 transmits to the foot (its f1).
    s.ankle_force_n = vec(feedback_[l][3].f1);
    std::array<JointAxisFrame, 3> leg_joints;
    for (std::size_t j = 0; j < 3; ++j)
      leg_joints[j] = {geometry_[l][j].anchor_m, geometry_[l][j].axis};
    const Eigen::Vector3d tau =
        jacobian_leg_torques_nm(leg_joints, geometry_[l][3].anchor_m, s.ankle_force_n);
    for (std::size_t j = 0; j < 3; ++j) s.jacobian_torque_nm[j] = tau[static_cast<int>(j)];
  }
}

double TitanTorqueProbe::foot_clearance_m(TitanLeg leg) const {
  const int b = foot_body_[index(leg)];
  const dBodyID body = rollout_.body(static_cast<std::size_t>(b));
  const Eigen::Vector3d p = vec(dBodyGetPosition(body));
  const dReal* R = dBodyGetRotation(body);
  double lowest = std::numeric_limits<double>::infinity();
  for (const BoxGeom& box : model_.bodies[static_cast<std::size_t>(b)].boxes) {
    if (!box.is_foot) continue;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d local(((corner & 1) ? 0.5 : -0.5) * box.size_m.x(),
                                  ((corner & 2) ? 0.5 : -0.5) * box.size_m.y(),
                                  ((corner & 4) ? 0.5 : -0.5) * box.size_m.z());
      const Eigen::Vector3d c = box.X_BG * local;  // body frame
      lowest = std::min(lowest, p.z() + R[8] * c.x() + R[9] * c.y() + R[10] * c.z());
    }
  }
  return lowest;
}

double TitanTorqueProbe::potential_energy_j() const {
  dVector3 gravity;
  dWorldGetGravity(rollout_.world(), gravity);
  double energy = 0.0;
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const dBodyID body = rollout_.body(b);
    if (body == nullptr) continue;
    dMass mass;
    dBodyGetMass(body, &mass);
    energy -= mass.mass * vec(gravity).dot(vec(dBodyGetPosition(body)));
  }
  return energy;
}

double TitanTorqueProbe::kinetic_energy_j() const {
  double energy = 0.0;
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const dBodyID body = rollout_.body(b);
    if (body == nullptr) continue;
    dMass mass;
    dBodyGetMass(body, &mass);
    const Eigen::Vector3d v = vec(dBodyGetLinearVel(body));
    const Eigen::Vector3d w = vec(dBodyGetAngularVel(body));
    const dReal* R = dBodyGetRotation(body);
    Eigen::Matrix3d R_WB, I_B;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        R_WB(r, c) = R[r * 4 + c];
        I_B(r, c) = mass.I[r * 4 + c];
      }
    }
    const Eigen::Vector3d w_B = R_WB.transpose() * w;
    energy += 0.5 * mass.mass * v.squaredNorm() + 0.5 * w_B.dot(I_B * w_B);
  }
  return energy;
}

}  // namespace motoflex
