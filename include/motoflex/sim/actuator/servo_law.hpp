#pragma once

// The servo law of one actuated joint axis: what turns the commanded angle into a joint torque
// and/or an ODE motor row each physics step. Every law (motoflex, velocity, ideal, bench, ...)
// is one file in src/sim/actuator/ behind this interface, listed once in
// servo_law_registry.cpp under the name a scenario's `servo:` key uses.
//
// Model vs state: a ServoLawInfo is immutable and shared; a ServoLaw instance belongs to one
// actuator of one rollout and is touched by that rollout's thread only.

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// A velocity-controlled ODE motor row on the actuated axis: ODE drives the axis rate toward
// velocity_rad_s with a force of at most fmax_nm, solved implicitly inside the step. With
// fmax_nm = 0 the row does nothing. (Dry friction is such a row with velocity 0.)
struct MotorCommand {
  double velocity_rad_s = 0.0;
  double fmax_nm = 0.0;
};

// What a law sees of its joint at the start of a physics step (our sign convention).
struct ServoInput {
  double command_rad = 0.0;       // commanded angle now (what the servo regulates to)
  double next_command_rad = 0.0;  // commanded angle at the end of the step
  double angle_rad = 0.0;         // true joint angle
  double rate_rad_s = 0.0;        // true joint rate
  double elapsed_s = 0.0;         // since the rollout was created (settling included)
  double settle_s = 0.0;          // the settling time before the motion's t = 0
  // Σ|I| of every law of the robot after the previous step (A): a shared battery sags with it.
  double total_current_a = 0.0;
  // The gravity torque on everything the joint moves, about its axis (N·m, our sign): the
  // external torque τ_e of BAM's load-dependent friction (friction_family.hpp). Computed only
  // for a law whose needs_external_torque() is true; 0 otherwise.
  double external_torque_nm = 0.0;
  // The supply voltage the robot logged at this time (V, smoothed: CommandTrajectory), NaN when
  // the motion has none. A law with a supply input drives from it instead of its nominal supply.
  double logged_supply_v = std::numeric_limits<double>::quiet_NaN();
};

// What a law applies to its joint during the step.
struct ServoOutput {
  // Explicit torque on the axis (N·m); NaN when the law acts only through the motor row (then
  // the rollout reports the actuator torque as unknown).
  double torque_nm = std::numeric_limits<double>::quiet_NaN();
  MotorCommand row;  // the axis's motor row for this step
  // Joint friction for a law whose `row` drives the joint (has_friction_row()): a second,
  // zero-velocity row on the axis with this budget.
  MotorCommand friction_row;
  // For a law with an implicit damping row (damping_row_nm_s_per_rad() = c > 0) whose torque_nm
  // already contains that damping evaluated at the start-of-step rate, −c·θ̇₀ (a DC motor's
  // back-EMF term inside a current limit): the explicit torque +c·θ̇₀ that the rollout adds to
  // cancel it, so the damping acts through the row at the end-of-step rate instead. Applied:
  // torque_nm + c·θ̇₀ − c·θ̇₁, stable for any c·h/I; reported: torque_nm. 0 for other laws.
  double damping_offset_nm = 0.0;
};

// One actuator's servo in one rollout.
class ServoLaw {
 public:
  virtual ~ServoLaw() = default;
  // Advances the law by one physics step. Throws ModelError when the state cannot go on (the
  // rollout then ends as diverged).
  virtual ServoOutput step(const ServoInput& input) = 0;
  // A linear damper on the axis that the rollout integrates implicitly as its own motor row
  // (N·m·s/rad; 0 = none). Asked once, when the rollout is built.
  virtual double damping_row_nm_s_per_rad() const { return 0.0; }
  // The current the law draws from the robot's supply (A), for supply effects.
  virtual double current_a() const { return 0.0; }
  // Reflected rotor inertia on the axis (kg·m² on a hinge, kg on a slider; 0 = none), which the
  // rollout adds as a joint-space inertia row (rollout.cpp, add_inertia_row). Asked once, when
  // the rollout is built.
  virtual double armature() const { return 0.0; }
  // Whether step() reads ServoInput::external_torque_nm. Asked once, when the rollout is built.
  virtual bool needs_external_torque() const { return false; }
  // Whether the rollout must give the axis a second motor row for ServoOutput::friction_row.
  // Asked once, when the rollout is built.
  virtual bool has_friction_row() const { return false; }
};

// Reads parameter values by name for a law being set up. A name the robot does not declare is
// a ModelError naming it and the law.
class ParameterReader {
 public:
  ParameterReader(const ParameterSet& values, std::string law)
      : values_(values), law_(std::move(law)) {}
  double operator()(const std::string& name) const;

 private:
  const ParameterSet& values_;
  std::string law_;
};

// Everything a law needs to build one actuator's instance.
struct ServoLawSetup {
  const RobotModel& model;
  std::size_t actuator;  // index into model.actuators
  const ParameterReader& get;
  double dt_s = 0.001;    // physics step
  int gear_substeps = 1;  // gear sub-steps per physics step (laws with a gear train)
};

// What the URDF says about one actuated joint, for starting values (NaN where it says nothing
// or only a placeholder; init-robot screens them). Units are the joint's: N·m or N, rad/s or
// m/s, N·m·s/rad or N·s/m.
struct JointHints {
  double effort = std::numeric_limits<double>::quiet_NaN();    // <limit effort>
  double velocity = std::numeric_limits<double>::quiet_NaN();  // <limit velocity>
  double damping = std::numeric_limits<double>::quiet_NaN();   // <dynamics damping>
  double friction = std::numeric_limits<double>::quiet_NaN();  // <dynamics friction>
};

// A parameter's starting value and search bounds for a new robot folder, and where they come
// from (shown in init-robot's table of assumptions).
struct ParameterDefault {
  std::string name;
  double value = 0.0;
  double lower = 0.0;
  double upper = 1.0;
  std::string source;  // e.g. "URDF effort 3 N·m", "Nao (scenarios/robots/nao)"
};

// A servo law as the registry knows it.
struct ServoLawInfo {
  std::string name;     // the scenario's `servo:` value
  std::string summary;  // one line for help texts and reports
  // Every parameter name the law reads for one actuator (per joint, per group and robot-wide
  // names alike), in a stable order; the robot must declare each.
  std::vector<std::string> (*parameter_names)(const RobotModel& model, std::size_t actuator);
  // Builds the law's state for one actuator. Throws ModelError for values it cannot simulate.
  std::unique_ptr<ServoLaw> (*create)(const ServoLawSetup& setup);
  // The pendulum bench: the first actuated joint's child is replaced by a point mass
  // (bench.mass_kg at bench.length_m along the arm, inertia bench.armature_kg_m2).
  bool point_mass_arm = false;
  // Whether the law can drive a prismatic joint (its parameters then in m and N).
  bool drives_prismatic = false;
  // Starting value and bounds of every name `parameter_names` lists for one actuator (laws
  // without it fall back on default_parameters, else init-robot flags each name). Names shared with
  // other laws (joint friction, ...) may be left out: joint_friction_defaults (servo_stages.hpp)
  // and the rollout's own table (robot_parameter_defaults.hpp) give them.
  std::vector<ParameterDefault> (*init_defaults)(const RobotModel& model, std::size_t actuator,
                                                 const JointHints& hints) = nullptr;
  // Default value and search bounds of the law's own parameters for one actuator (the
  // `servo.<scope>.*` names; joint.* names have theirs in the model's parameter catalog), for
  // robots that do not declare them. nullptr = the law has no defaults: the robot declares all.
  std::vector<ParameterSpec> (*default_parameters)(const RobotModel& model,
                                                   std::size_t actuator) = nullptr;
};

// Every law, in registration order.
const std::vector<ServoLawInfo>& servo_laws();
// The law registered under `name`, or nullptr.
const ServoLawInfo* find_servo_law(const std::string& name);
// Like find_servo_law, but throws std::invalid_argument naming the known laws.
const ServoLawInfo& servo_law(const std::string& name);
// "motoflex|velocity|..." for messages.
std::string servo_law_names();
// The name of the law that drives `actuator`: `override_servo` when not empty (a scenario's or
// the command line's `servo:`), else the joint's own (ActuatorSpec::servo), else the robot's
// default (robot.yaml `servo:`).
const std::string& actuator_servo_name(const RobotModel& model, const std::string& override_servo,
                                       std::size_t actuator);
// Adds to `model` the default of every parameter that the law of each actuator (as
// actuator_servo_name resolves it with `override_servo`) lists in default_parameters and the
// model does not declare. Returns the names added. Throws std::invalid_argument for an unknown
// law. (For robots built in code and for tests; robot.yaml files declare their parameters.)
std::vector<std::string> add_servo_law_defaults(RobotModel& model,
                                                const std::string& override_servo = "");

}  // namespace motoflex
