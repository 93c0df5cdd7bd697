#include "axis_rows.hpp"

#include <Eigen/Geometry>
#include <utility>

namespace motoflex::detail {

dJointID create_axis_motor(dWorldID world, const RobotModel& model,
                           const std::vector<dBodyID>& bodies, std::size_t actuator) {
  const ActuatorSpec& spec = model.actuators[actuator];
  const JointSpec& joint = model.joints[spec.joint];
  dBodyID parent = bodies[joint.parent_body];
  dBodyID child = bodies[joint.child_body];
  const Eigen::Vector3d& axis = spec.axis == 1 ? joint.axis1_W0 : joint.axis2_W0;
  if (joint.kind == JointKind::kSlider) {
    // Along a slider a linear motor: its row acts on the child's velocity relative to the
    // parent along the axis (fixed in the parent, or global on the welded base).
    dJointID motor = dJointCreateLMotor(world, nullptr);
    dJointAttach(motor, child, parent);
    dJointSetLMotorNumAxes(motor, 1);
    const int frame = parent != nullptr ? 2 : 0;  // relative to body2 = parent, or global
    dJointSetLMotorAxis(motor, 0, frame, axis.x(), axis.y(), axis.z());
    return motor;
  }
  // The axis rides on the body that carries it: a hinge axis is fixed in both bodies, a
  // universal joint's axis 1 in the parent and axis 2 in the child; a static body is the world.
  dBodyID carrier =
      (joint.kind == JointKind::kUniversal || joint.kind == JointKind::kFlex) && spec.axis == 2
          ? child
          : parent;
  dBodyID other = carrier == parent ? child : parent;
  int frame = 1;  // axis given relative to body1 = carrier
  if (carrier == nullptr) {
    std::swap(carrier, other);
    frame = 0;  // the carrier is the static world: the axis is fixed in the global frame
  }
  dJointID motor = dJointCreateAMotor(world, nullptr);
  dJointAttach(motor, carrier, other);
  dJointSetAMotorMode(motor, dAMotorUser);
  dJointSetAMotorNumAxes(motor, 1);
  dJointSetAMotorAxis(motor, 0, frame, axis.x(), axis.y(), axis.z());
  return motor;
}

void set_axis_motor_param(dJointID motor, int parameter, dReal value) {
  if (dJointGetType(motor) == dJointTypeLMotor) {
    dJointSetLMotorParam(motor, parameter, value);
  } else {
    dJointSetAMotorParam(motor, parameter, value);
  }
}

void target_current_rate(dJointID motor) {
  // ODE's angular motor row constrains axis·ω₁ − axis·ω₂ (body 2 absent: the world at rest),
  // its linear motor row axis·v₁ − axis·v₂.
  const bool linear = dJointGetType(motor) == dJointTypeLMotor;
  dVector3 axis;
  if (linear) {
    dJointGetLMotorAxis(motor, 0, axis);
  } else {
    dJointGetAMotorAxis(motor, 0, axis);
  }
  double rate = 0.0;
  for (int k = 0; k < 2; ++k) {
    const dBodyID body = dJointGetBody(motor, k);
    if (body == nullptr) continue;
    const dReal* w = linear ? dBodyGetLinearVel(body) : dBodyGetAngularVel(body);
    rate += (k == 0 ? 1.0 : -1.0) * (axis[0] * w[0] + axis[1] * w[1] + axis[2] * w[2]);
  }
  set_axis_motor_param(motor, dParamVel, rate);
}

std::vector<int> moved_bodies(const RobotModel& model, int joint) {
  std::vector<int> moved;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (int j = model.bodies[b].parent_joint; j >= 0;
         j = model.bodies[model.joints[j].parent_body].parent_joint) {
      if (j == joint) {
        moved.push_back(static_cast<int>(b));
        break;
      }
    }
  }
  return moved;
}

double gravity_torque_nm(const OdeAxis& ode, const std::vector<dBodyID>& load_bodies,
                         const Eigen::Vector3d& gravity_m_s2) {
  dVector3 anchor, axis;
  if (ode.slider) {
    // Along a slider the external force: gravity on what it moves, along the axis (N).
    dJointGetSliderAxis(ode.joint, axis);
    double force_n = 0.0;
    for (const dBodyID body : load_bodies) {
      dMass mass;
      dBodyGetMass(body, &mass);
      force_n += mass.mass * gravity_m_s2.dot(Eigen::Vector3d(axis[0], axis[1], axis[2]));
    }
    return ode.sign * force_n;
  }
  if (!ode.universal) {
    dJointGetHingeAnchor(ode.joint, anchor);
    dJointGetHingeAxis(ode.joint, axis);
  } else {
    dJointGetUniversalAnchor(ode.joint, anchor);
    if (ode.axis == 1) {
      dJointGetUniversalAxis1(ode.joint, axis);
    } else {
      dJointGetUniversalAxis2(ode.joint, axis);
    }
  }
  const Eigen::Vector3d a(anchor[0], anchor[1], anchor[2]);
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const dBodyID body : load_bodies) {
    const dReal* p = dBodyGetPosition(body);
    dMass mass;
    dBodyGetMass(body, &mass);
    moment += (Eigen::Vector3d(p[0], p[1], p[2]) - a).cross(mass.mass * gravity_m_s2);
  }
  return moment.dot(Eigen::Vector3d(axis[0], axis[1], axis[2]));
}

}  // namespace motoflex::detail
