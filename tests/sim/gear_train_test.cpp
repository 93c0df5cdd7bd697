#include "motoflex/sim/actuator/gear_train.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

constexpr double kDt = 1e-3;

// MoToFlex-like values: ω = sqrt(D/m) = 1.28e5 rad/s (ω·dt = 128 for a 1 ms step).
GearParams motoflex_gear() {
  return GearParams{.ratio = 130.85,
                    .backlash_rad = 1.05e-5,
                    .spring_nm_per_rad = 1.8e7,
                    .mass_kg_m2 = 1.1e-3,
                    .viscous_nm_s_per_rad = 0.11};
}

// Joint-side outputs of `steps` physics steps after settling at `start_nm` and holding
// `joint_nm` (both joint side).
std::vector<double> step_response(const GearParams& params, int substeps, double start_nm,
                                  double joint_nm, int steps) {
  GearTrain gear(params, kDt, substeps);
  gear.settle_at(start_nm);
  std::vector<double> outputs;
  for (int k = 0; k < steps; ++k) outputs.push_back(gear.update(joint_nm / params.ratio));
  return outputs;
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// A small constant torque on a mass at rest at the lower side of the hull, without friction.
struct BacklashCrossing {
  GearParams params = [] {
    GearParams p = motoflex_gear();
    p.viscous_nm_s_per_rad = 0.0;
    return p;
  }();
  double joint_nm = 1e-5;  // small, so the crossing takes many physics steps
  // Free flight from rest under constant torque: l_h = ½·a·t².
  double accel_rad_s2 = joint_nm / params.mass_kg_m2;
  double crossing_s = std::sqrt(2.0 * params.backlash_rad * params.mass_kg_m2 / joint_nm);
  double crossing_speed_rad_s = accel_rad_s2 * crossing_s;
  int crossing_step = static_cast<int>(crossing_s / kDt);  // 48 (t = 48.06 ms)
};

TEST(GearTrainTest, NoTorquePassesWhileTheMassCrossesTheBacklash) {
  const BacklashCrossing crossing;
  const GearParams& params = crossing.params;
  ASSERT_GT(crossing.crossing_s / kDt - crossing.crossing_step, 0.05)
      << "crossing too close to a step boundary";
  for (int substeps : {100, 1000}) {
    GearTrain gear(params, kDt, substeps);
    gear.set_state(0.0, 0.0);
    const double substep_s = kDt / substeps;
    for (int k = 0; k < crossing.crossing_step; ++k) {
      ASSERT_EQ(gear.update(crossing.joint_nm / params.ratio), 0.0) << "step " << k;
      // Symplectic Euler from rest: p after n substeps is a·Δt²·n(n+1)/2 (→ a·t²/2).
      const double n = (k + 1.0) * substeps;
      ASSERT_NEAR(gear.mass_position_rad(),
                  crossing.accel_rad_s2 * substep_s * substep_s * n * (n + 1) / 2,
                  1e-12 * params.backlash_rad);
      ASSERT_LE(gear.mass_position_rad(), params.backlash_rad);
    }
    // The step containing t_cross passes torque: the mass reaches the spring.
    EXPECT_GT(gear.update(crossing.joint_nm / params.ratio), 0.0) << substeps << " substeps";
  }
}

TEST(GearTrainTest, BounceOffTheHullIsElasticWithFineSubsteps) {
  // Without friction the stiff spring (contact ≈ π/ω = 25 µs) throws the mass back with the
  // speed it arrived with, and the step carries the bounce's impulse 2·m_g·v. The implicit
  // contact spring loses about (ω·Δt_g)² of the energy per substep in contact, so the bounce
  // is elastic only once the contact is resolved finely: N = 400000 gives ω·Δt_g = 3.2e-4.
  const BacklashCrossing crossing;
  const GearParams& params = crossing.params;
  GearTrain gear(params, kDt, 400000);
  gear.set_state(0.0, 0.0);
  for (int k = 0; k < crossing.crossing_step; ++k) gear.update(crossing.joint_nm / params.ratio);
  const double bounce_output_nm = gear.update(crossing.joint_nm / params.ratio);
  const double v = crossing.crossing_speed_rad_s;
  EXPECT_LT(gear.mass_position_rad(), params.backlash_rad);  // back inside the hull
  EXPECT_NEAR(gear.mass_velocity_rad_s(), -v, 0.02 * v);
  EXPECT_NEAR(bounce_output_nm * kDt, 2.0 * params.mass_kg_m2 * v,
              0.02 * 2.0 * params.mass_kg_m2 * v);
}

TEST(GearTrainTest, CoarseSubstepsMakeImpactsInelasticNotEnergetic) {
  // With 100 substeps a contact lasts 2.5 substeps; the implicit spring must never return the
  // mass faster than it arrived (no numerical energy gain).
  const BacklashCrossing crossing;
  const GearParams& params = crossing.params;
  GearTrain gear(params, kDt, 100);
  gear.set_state(0.0, 0.0);
  for (int k = 0; k <= crossing.crossing_step; ++k) gear.update(crossing.joint_nm / params.ratio);
  EXPECT_LE(std::abs(gear.mass_velocity_rad_s()), crossing.crossing_speed_rad_s * 1.001);
}

TEST(GearTrainTest, OutputIsTheSpringTorqueAtTheNewPosition) {
  // With one substep the output is the spring torque where the substep ends: D·(p − l_h) above
  // the hull, D·p below it, zero inside.
  const GearParams params = motoflex_gear();
  const double dt_s = 1e-5;
  GearTrain gear(params, dt_s, 1);
  const double l_h = params.backlash_rad;
  const double d_g = params.spring_nm_per_rad;
  for (double position_rad : {l_h + 2e-7, l_h + 1e-9, -3e-7, -1e-9, 0.0, 0.3 * l_h, l_h}) {
    for (double motor_nm : {0.0, 5.0 / params.ratio, -5.0 / params.ratio}) {
      gear.set_state(position_rad, 0.0);
      const double output_nm = gear.update(motor_nm);
      const double p = gear.mass_position_rad();
      const double expected_nm = p > l_h ? d_g * (p - l_h) : p < 0.0 ? d_g * p : 0.0;
      EXPECT_NEAR(output_nm, expected_nm, 1e-9 * std::max(1.0, std::abs(expected_nm)))
          << "p0 = " << position_rad << ", T_M = " << motor_nm;
    }
  }
  // Inside the hull with no drive nothing moves and nothing passes.
  gear.set_state(0.3 * l_h, 0.0);
  EXPECT_EQ(gear.update(0.0), 0.0);
  EXPECT_EQ(gear.mass_position_rad(), 0.3 * l_h);
}

TEST(GearTrainTest, SettledGearPassesTheHeldTorque) {
  const GearParams params = motoflex_gear();
  for (double joint_nm : {3.0, -1.5, 1e-3}) {
    GearTrain gear(params, kDt, 100);
    gear.settle_at(joint_nm);
    const double contact_side_rad = joint_nm > 0 ? params.backlash_rad : 0.0;
    EXPECT_NEAR(gear.mass_position_rad(), contact_side_rad + joint_nm / params.spring_nm_per_rad,
                1e-20);
    for (int k = 0; k < 100; ++k) {
      ASSERT_NEAR(gear.update(joint_nm / params.ratio), joint_nm,
                  1e-12 * std::max(1.0, std::abs(joint_nm)))
          << "T = " << joint_nm << ", step " << k;
    }
  }
  GearTrain idle(params, kDt, 100);
  idle.settle_at(0.0);
  EXPECT_EQ(idle.mass_position_rad(), 0.5 * params.backlash_rad);
  EXPECT_EQ(idle.update(0.0), 0.0);
}

TEST(GearTrainTest, DampedStepResponseConvergesToRatioTimesMotorTorque) {
  // B_g/m_g = 100/s: the rattle in the backlash and the spring ringing die out within ~0.3 s,
  // for fine and coarse substep counts alike (the implicit contact spring cannot pump energy).
  const GearParams params = motoflex_gear();
  struct Case {
    int substeps;
    double start_nm;
    double joint_nm;
  };
  for (const Case& c :
       {Case{1000, 0.0, 1.96}, Case{1000, -2.0, 2.0}, Case{1000, 0.0, -0.3}, Case{100, 0.0, 1.96},
        Case{100, -2.0, 2.0}, Case{100, 1.5, 2.0}, Case{100, -1.5, -2.0}, Case{10, 0.0, 1.96}}) {
    GearTrain gear(params, kDt, c.substeps);
    gear.settle_at(c.start_nm);
    double output_nm = 0.0;
    for (int k = 0; k < 1000; ++k) output_nm = gear.update(c.joint_nm / params.ratio);
    EXPECT_NEAR(output_nm, c.joint_nm, 1e-9 * std::abs(c.joint_nm))
        << c.substeps << " substeps, " << c.start_nm << " -> " << c.joint_nm << " N·m";
    EXPECT_NEAR(gear.mass_velocity_rad_s(), 0.0, 1e-9);
  }
}

TEST(GearTrainTest, RattleDiesOutForEveryTorqueAtTheDefaultSubsteps) {
  // Physically the rattle must die out: the viscous friction only removes energy. With a
  // symplectic (energy-conserving) substep, N = 100 kept about 30 of these 48 cases rattling
  // forever (±3 N·m); the implicit contact spring settles all of them, at N = 100 and N = 600.
  const GearParams params = motoflex_gear();
  for (int substeps : {100, 600}) {
    for (int i = 0; i < 16; ++i) {
      const double joint_nm = 0.03 * std::pow(1.45, i);  // 0.03 … 7.5 N·m
      for (double start_fraction : {0.0, -1.0, 0.5}) {
        GearTrain gear(params, kDt, substeps);
        gear.settle_at(start_fraction * joint_nm);
        double output_nm = 0.0;
        for (int k = 0; k < 1000; ++k) output_nm = gear.update(joint_nm / params.ratio);
        EXPECT_NEAR(output_nm, joint_nm, 1e-6 * joint_nm)
            << substeps << " substeps, " << start_fraction * joint_nm << " -> " << joint_nm;
      }
    }
  }
}

TEST(GearTrainTest, TorqueOverATransientBalancesTheMassMomentum) {
  // Summing m·(v' − v) = (σT_M − T_s − B·v')·Δt over a run gives
  //   Σ T_j·dt = σT_M·t − m·Δv − B·Δp,
  // exact while the mass stays in contact; at each release the implicit force differs from
  // the output one by at most one substep's worth, so the balance holds to a small fraction.
  const GearParams params = motoflex_gear();
  for (int substeps : {20, 100, 400}) {
    GearTrain gear(params, kDt, substeps);
    gear.settle_at(0.0);
    const double start_rad = gear.mass_position_rad();
    const double motor_nm = 0.02;
    double impulse_nm_s = 0.0;
    const int steps = 20;
    for (int k = 0; k < steps; ++k) impulse_nm_s += gear.update(motor_nm) * kDt;
    const double expected_nm_s =
        params.ratio * motor_nm * steps * kDt - params.mass_kg_m2 * gear.mass_velocity_rad_s() -
        params.viscous_nm_s_per_rad * (gear.mass_position_rad() - start_rad);
    EXPECT_NEAR(impulse_nm_s, expected_nm_s, 0.01 * params.ratio * motor_nm * steps * kDt)
        << substeps << " substeps";
  }
}

TEST(GearTrainTest, MeanTorqueOfABacklashTransientAgreesAcrossSubstepCounts) {
  // The torque reversal case: settled at 0 (mass mid-hull), then 2 N·m at the joint. The mass
  // crosses the hull and rattles against the stiff spring (contact ≈ π/ω = 25 µs, flight
  // ≈ 0.3 ms) for tens of ms. N = 50 is below the stability limit with these values.
  const GearParams params = motoflex_gear();
  const double joint_nm = 2.0;
  std::vector<double> means;
  for (int substeps : {100, 200, 400, 800}) {
    means.push_back(mean(step_response(params, substeps, 0.0, joint_nm, 20)));
  }
  // The 20 ms mean is fixed by the momentum balance above up to m·v_end/t, so it agrees to
  // < 1 % even while the individual bounces are not resolved.
  EXPECT_LT(std::abs(means[1] - means[2]), 0.01 * joint_nm);
  for (double m : means) EXPECT_NEAR(m, joint_nm, 0.01 * joint_nm);
}

TEST(GearTrainTest, PerStepTorqueConvergesInTheSubstepCount) {
  // MoToFlex's gear type A (201.3; ζ = 0.52): a torque reversal from −1 to +2 N·m crosses the
  // hull and lands on the spring. The implicit scheme is first order, so the per-step torques
  // converge toward a fine-substep reference as the substep count grows.
  const GearParams params{.ratio = 201.3,
                          .backlash_rad = 1.301e-5,
                          .spring_nm_per_rad = 6.131e6,
                          .mass_kg_m2 = 1.0808e-3,
                          .viscous_nm_s_per_rad = 84.37};
  const std::vector<double> reference = step_response(params, 6400, -1.0, 2.0, 20);
  auto error_nm = [&](int substeps) {
    const std::vector<double> outputs = step_response(params, substeps, -1.0, 2.0, 20);
    double largest = 0.0;
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      largest = std::max(largest, std::abs(outputs[k] - reference[k]));
    }
    return largest;
  };
  // Measured: 0.043, 0.0058 and 0.000095 N·m for N = 25, 100, 800 (the crossing instant falls
  // between substeps, so single doublings are not monotone, but the trend is first order).
  const double coarse = error_nm(25), nominal = error_nm(100), fine = error_nm(800);
  EXPECT_LT(nominal, 0.01 * 3.0);  // N = 100: within 1 % of the 3 N·m reversal
  EXPECT_LT(nominal, coarse / 3.0);
  EXPECT_LT(fine, nominal / 4.0);
}

TEST(GearTrainTest, AnySubstepCountIsStable) {
  // ω·Δt_g = 128 with a single substep: explicit schemes explode, the implicit spring settles.
  const GearParams params = motoflex_gear();
  for (int substeps : {1, 3, 50}) {
    GearTrain gear(params, kDt, substeps);
    gear.settle_at(0.0);
    double output_nm = 0.0;
    for (int k = 0; k < 2000; ++k) {
      output_nm = gear.update(2.0 / params.ratio);
      ASSERT_TRUE(std::isfinite(output_nm));
      ASSERT_LT(std::abs(output_nm), 100.0);
    }
    EXPECT_NEAR(output_nm, 2.0, 1e-6) << substeps << " substeps";
  }
}

TEST(GearTrainTest, RejectsInvalidParameters) {
  const GearParams good = motoflex_gear();
  EXPECT_THROW(GearTrain(good, 0.0, 100), std::invalid_argument);
  EXPECT_THROW(GearTrain(good, kDt, 0), std::invalid_argument);
  GearParams bad = good;
  bad.mass_kg_m2 = 0.0;
  EXPECT_THROW(GearTrain(bad, kDt, 100), std::invalid_argument);
  bad = good;
  bad.backlash_rad = -1e-6;
  EXPECT_THROW(GearTrain(bad, kDt, 100), std::invalid_argument);
  bad = good;
  bad.spring_nm_per_rad = -1.0;
  EXPECT_THROW(GearTrain(bad, kDt, 100), std::invalid_argument);
  bad = good;
  bad.viscous_nm_s_per_rad = -0.1;
  EXPECT_THROW(GearTrain(bad, kDt, 100), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
