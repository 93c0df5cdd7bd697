#pragma once

// A one-joint robot written for a test: a welded base and an arm on the revolute joint `hinge`
// (group `hinge`, so a law's own parameters are servo.hinge.*), with a point-like mass at
// `length_m` from the axis. A horizontal axis (y) makes a pendulum, q = 0 hanging down and
// τ_g = −m·g·l·sin q; a vertical axis (z) makes a turntable with no gravity torque at all, the
// plant of the analytic servo responses. robot.yaml declares the globals every law needs
// (velocity, ideal, motoflex, bench), and add_servo_law_defaults adds the own parameters of the
// law under test, so any registered law can drive it.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex::testing {

struct OneJointRobot {
  double mass_kg = 0.5;
  double length_m = 0.1;
  double com_inertia_kg_m2 = 1e-7;  // each principal inertia about the CoM
  bool vertical_axis = false;       // false: pendulum about y, true: turntable about z
  double limit_rad = 3.14159;       // joint stops ± (ODE's hinge angle wraps at ±π anyway)
};

constexpr double kTestGravity_m_s2 = 9.81;  // the rollout's world gravity

// A number as text that reads back exactly.
inline std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// Inertia about the joint axis (kg·m²).
inline double axis_inertia_kg_m2(const OneJointRobot& robot) {
  return robot.mass_kg * robot.length_m * robot.length_m + robot.com_inertia_kg_m2;
}

// Writes the robot into a fresh folder `name`, loads it (model layer: no parameter check) and
// adds the defaults of `law`'s own parameters; every actuator then runs `law`.
inline RobotModel make_one_joint_robot(const std::string& name, const OneJointRobot& robot,
                                       const std::string& law) {
  const std::filesystem::path dir = fresh_dir(name);
  const std::string com =
      robot.vertical_axis ? number(robot.length_m) + " 0 0" : "0 0 " + number(-robot.length_m);
  const std::string axis = robot.vertical_axis ? "0 0 1" : "0 1 0";
  const std::string inertia = number(robot.com_inertia_kg_m2);
  write_text(dir / "one_joint.urdf",
             "<?xml version=\"1.0\"?>\n<robot name=\"one_joint\">\n"
             "  <link name=\"base\"><inertial><origin xyz=\"0 0 0.5\"/><mass value=\"1\"/>"
             "<inertia ixx=\"1e-3\" ixy=\"0\" ixz=\"0\" iyy=\"1e-3\" iyz=\"0\" izz=\"1e-3\"/>"
             "</inertial></link>\n"
             "  <joint name=\"hinge\" type=\"revolute\"><parent link=\"base\"/>"
             "<child link=\"arm\"/><origin xyz=\"0 0 1\"/><axis xyz=\"" +
                 axis + "\"/><limit lower=\"" + number(-robot.limit_rad) + "\" upper=\"" +
                 number(robot.limit_rad) +
                 "\" effort=\"10\" velocity=\"50\"/></joint>\n"
                 "  <link name=\"arm\"><inertial><origin xyz=\"" +
                 com + "\"/><mass value=\"" + number(robot.mass_kg) + "\"/><inertia ixx=\"" +
                 inertia + "\" ixy=\"0\" ixz=\"0\" iyy=\"" + inertia + "\" iyz=\"0\" izz=\"" +
                 inertia +
                 "\"/></inertial></link>\n"
                 "</robot>\n");
  write_text(dir / "robot.yaml",
             "name: one_joint\nurdf: one_joint.urdf\nroot_link: base\nfixed_base: true\n"
             "torso_link: base\nservo: " +
                 law +
                 "\nactuated_joints:\n  - {joint: hinge, group: hinge}\n"
                 "held_joints: {}\nuniversal_joints: []\nflexible_links: []\nfeet: []\n"
                 "fall: {max_tilt_rad: 10.0, min_torso_height_m: 0.0}\n"
                 "initial_clearance_m: 0.0\nparameters:\n"
                 "  joint.hinge.gain_per_s: [4.0, 0.1, 100.0]\n"
                 "  joint.hinge.torque_max_nm: [1.0, 0.01, 100.0]\n"
                 "  ideal.torque_max_nm: [100.0, 1.0, 1000.0]\n"
                 "  pid.kp_v_per_rad: [0.0, 0.0, 3000.0]\n"
                 "  pid.ki_v_per_rad_s: [0.0, 0.0, 100.0]\n"
                 "  pid.kd_v_s_per_rad: [0.0, 0.0, 100.0]\n"
                 "  motor.supply_v: [7.4, 1.0, 30.0]\n"
                 "  motor.R_ohm: [2.6, 0.1, 10.0]\n"
                 "  motor.L_h: [1.0e-4, 1.0e-6, 1.0e-2]\n"
                 "  motor.Kt_nm_per_a: [0.01, 0.001, 1.0]\n"
                 "  motor.stiffness: [1.0, 0.1, 10.0]\n"
                 "  gear.hinge.ratio: [100.0, 1.0, 1000.0]\n"
                 "  gear.hinge.motor_viscous_nm_s_per_rad: [0.0, 0.0, 1.0e-3]\n"
                 "  gear.hinge.backlash_rad: [0.0, 0.0, 0.05]\n"
                 "  gear.hinge.spring_nm_per_rad: [1000.0, 1.0, 1.0e5]\n"
                 "  gear.hinge.mass_kg_m2: [1.0e-4, 1.0e-6, 1.0e-2]\n"
                 "  gear.hinge.viscous_nm_s_per_rad: [0.0, 0.0, 10.0]\n"
                 "  bench.kp: [400.0, 1.0, 2000.0]\n"
                 "  bench.error_gain: [0.0028774, 0.00284, 0.00292]\n"
                 "  bench.max_duty: [1.0, 0.5, 1.0]\n"
                 "  bench.supply_v: [7.4, 5.0, 13.0]\n"
                 "  bench.Kt_nm_per_a: [0.6, 0.0, 3.0]\n"
                 "  bench.R_ohm: [2.6, 1.0, 6.0]\n"
                 "  bench.armature_kg_m2: [1.0e-4, 1.0e-7, 0.05]\n"
                 "  bench.mass_kg: [" +
                 number(robot.mass_kg) +
                 ", 0.01, 5.0]\n"
                 "  bench.length_m: [" +
                 number(std::max(robot.length_m, 0.01)) +
                 ", 0.01, 0.5]\n"
                 "  bench.torque_off_s: [1.0e9, 0.0, 1.0e9]\n"
                 "  bench.logged_supply: [1, 0, 1]\n"
                 "  contact.mu: [1.0, 0.1, 2.0]\n  contact.soft_erp: [0.2, 0.05, 0.9]\n"
                 "  contact.soft_cfm: [1.0e-4, 1.0e-7, 1.0e-2]\n"
                 "  contact.slip: [1.0e-3, 1.0e-5, 0.05]\n"
                 "  world.erp: [0.2, 0.05, 0.9]\n  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]\n"
                 "  sensor.resolution_bits: [0, 0, 16]\n  sensor.noise_rad: [0.0, 0.0, 0.01]\n"
                 "  sensor.delay_s: [0.0, 0.0, 0.05]\n");
  RobotModel model = load_robot_model(dir.string(), StructureOptions{});
  add_servo_law_defaults(model, law);
  return model;
}

// The true joint angle, rate and actuator torque after every physics step of a rollout that
// starts at rest at q0_rad and follows command_rad(t).
struct StepTrace {
  std::vector<double> t_s, q_rad, w_rad_s, torque_nm;
};

inline StepTrace run_steps(const RobotModel& model, const ParameterSet& parameters,
                           const std::string& law, double q0_rad,
                           const std::function<double(double)>& command_rad, double duration_s,
                           double dt_s = 1e-3) {
  RolloutOptions options;
  options.dt_s = dt_s;
  options.servo = law;
  Rollout rollout(model, parameters, options, {q0_rad});
  StepTrace trace;
  const auto steps = static_cast<long>(std::lround(duration_s / dt_s));
  for (long k = 0; k < steps; ++k) {
    const double now = command_rad(rollout.time_s());
    const double next = command_rad(rollout.time_s() + dt_s);
    if (!rollout.step(&now, &next)) break;
    trace.t_s.push_back(rollout.time_s());
    trace.q_rad.push_back(rollout.joint_angle_rad(0));
    trace.w_rad_s.push_back(rollout.joint_rate_rad_s(0));
    trace.torque_nm.push_back(rollout.actuator_torque_nm(0));
  }
  return trace;
}

}  // namespace motoflex::testing
