// Micro-benchmarks of the actuator stages and of one Nao physics step, so a change to the hot
// loop can be measured stage by stage (ratios within one run; the machine is shared):
//   build/motoflex_stage_benchmarks --benchmark_repetitions=5 --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/actuator/dc_motor.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/gear_train.hpp"
#include "motoflex/sim/actuator/pid.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kDt_s = 0.001;

void BM_Pid(benchmark::State& state) {
  Pid pid({319.5, 14.19, 0.1636}, kDt_s);
  double error = 0.01;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pid.update(error));
    error = -error;
  }
}
BENCHMARK(BM_Pid);

void BM_DcMotor(benchmark::State& state) {
  DcMotor motor(DcMotorParams{}, kDt_s);
  double volts = 5.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(motor.update(volts, 10.0));
    volts = -volts;
  }
}
BENCHMARK(BM_DcMotor);

// The gear train at the Nao's sub-step count (100 per physics step, seed 001 Algorithm 2).
void BM_GearTrain(benchmark::State& state) {
  GearParams gear;
  gear.ratio = 201.3;
  gear.backlash_rad = 1.3e-5;
  gear.spring_nm_per_rad = 6.13e6;
  gear.mass_kg_m2 = 1.08e-3;
  gear.viscous_nm_s_per_rad = 84.4;
  GearTrain train(gear, kDt_s, static_cast<int>(state.range(0)));
  double torque = 0.01;
  for (auto _ : state) {
    benchmark::DoNotOptimize(train.update(torque));
    torque = -torque;
  }
}
BENCHMARK(BM_GearTrain)->Arg(1)->Arg(10)->Arg(100);

void BM_JointFriction(benchmark::State& state) {
  FrictionParams friction;
  friction.coulomb_nm = 0.3;
  friction.viscous_nm_s_per_rad = 0.1;
  friction.stribeck_nm = 0.2;
  friction.stribeck_velocity_rad_s = 0.1;
  friction.load_motor = 0.05;
  double rate = 0.5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(joint_friction(friction, rate, 1.0, 0.2));
    rate = -rate;
  }
}
BENCHMARK(BM_JointFriction);

// One physics step of the bundled Nao scenario (full pipeline, flexible links) and of the same
// robot with ideal servos: the whole step, ODE's LCP included.
void nao_step(benchmark::State& state, const std::string& servo, int flex_sub_bodies) {
  ScenarioOverrides overrides;
  overrides.servo = servo;
  overrides.flex_sub_bodies = flex_sub_bodies;
  overrides.settle_s = 0.0;
  const Scenario scenario =
      load_scenario(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/nao_default.yaml", overrides);
  const std::size_t n = scenario.model->actuators.size();
  std::vector<double> pose(n);
  for (std::size_t j = 0; j < n; ++j) pose[j] = scenario.commands.angle_rad(0, j);
  Rollout rollout(*scenario.model, scenario.parameters, scenario.rollout, pose);
  for (auto _ : state) {
    if (!rollout.step(pose.data(), pose.data())) state.SkipWithError("the rollout ended");
  }
}
void BM_NaoStepFullPipeline(benchmark::State& state) {
  nao_step(state, "motoflex", 2);
}
void BM_NaoStepIdealServos(benchmark::State& state) {
  nao_step(state, "ideal", 1);
}
BENCHMARK(BM_NaoStepFullPipeline);
BENCHMARK(BM_NaoStepIdealServos);

}  // namespace
}  // namespace motoflex

BENCHMARK_MAIN();
