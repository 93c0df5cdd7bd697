// BAM's friction family M1–M6 (bam.md §2d) as budgets: each model against its equation written
// out independently here, the structure switches of friction_model, and bit-identity of the
// laws' old friction (Coulomb + viscous + Gaussian Stribeck + K_l·|τ_m|) under the family.

#include "motoflex/sim/actuator/friction_family.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "motoflex/core/error.hpp"
#include "motoflex/model/parameters.hpp"

namespace motoflex {
namespace {

// Every coefficient non-zero and distinct, so a term in the wrong place shows.
FrictionParams all_terms(FrictionModel model) {
  FrictionParams p;
  p.model = model;
  p.coulomb_nm = 0.013;
  p.viscous_nm_s_per_rad = 0.0045;
  p.stribeck_nm = 0.0087;
  p.stribeck_velocity_rad_s = 1.7;
  p.stribeck_exponent = 1.3;
  p.load_motor = 0.29;
  p.load_external = 0.07;
  p.load_stribeck_motor = 0.11;
  p.load_stribeck_external = 0.059;
  p.quad_motor_per_nm = 0.0099;
  p.quad_external_per_nm = 0.0049;
  return p;
}

// bam.md §2d, written term by term.
double bam_equation(const FrictionParams& p, double v, double tm, double te) {
  const double s =
      std::exp(-std::pow(std::abs(v / p.stribeck_velocity_rad_s), p.stribeck_exponent));
  const double m1 = p.coulomb_nm + p.viscous_nm_s_per_rad * std::abs(v);
  const double m2 = m1 + s * p.stribeck_nm;
  switch (p.model) {
    case FrictionModel::kM1:
      return m1;
    case FrictionModel::kM2:
      return m2;
    case FrictionModel::kM3:
      return m1 + p.load_motor * std::abs(tm - te);
    case FrictionModel::kM4:
      return m2 + p.load_motor * std::abs(tm - te) + s * p.load_stribeck_motor * std::abs(tm - te);
    case FrictionModel::kM5:
    case FrictionModel::kM6: {
      double f = m2 + std::abs(p.load_motor * tm - p.load_external * te) +
                 s * std::abs(p.load_stribeck_motor * tm - p.load_stribeck_external * te);
      if (p.model == FrictionModel::kM6 && std::signbit(tm) != std::signbit(te)) {
        if (std::abs(tm) > std::abs(te)) f += s * p.quad_external_per_nm * te * te;
        if (std::abs(tm) < std::abs(te)) f += s * p.quad_motor_per_nm * tm * tm;
      }
      return f;
    }
  }
  return NAN;
}

TEST(FrictionFamilyTest, EachModelIsBamsEquation) {
  const double velocities[] = {0.0, 0.4, -1.7, 3.5, -8.0};
  // Motor and external torques of the same sign, of opposite signs with either larger.
  const double torques[][2] = {{0.3, 0.2}, {0.45, -0.2}, {-0.1, 0.48}, {0.0, -0.3}, {-0.6, -0.6}};
  for (int m = 1; m <= 6; ++m) {
    const FrictionParams p = all_terms(static_cast<FrictionModel>(m));
    for (const double v : velocities) {
      for (const auto& t : torques) {
        // Summation order differs from the reference: a few ulps.
        EXPECT_NEAR(friction_budget_nm(p, v, t[0], t[1]), bam_equation(p, v, t[0], t[1]), 1e-15)
            << "M" << m << " v " << v << " tm " << t[0] << " te " << t[1];
      }
    }
  }
}

TEST(FrictionFamilyTest, ModelsDifferWhereTheirTermsDo) {
  // At rest (s = 1) with a motor holding against gravity every term is awake.
  const double v = 0.0, tm = 0.4, te = -0.3;
  const auto budget = [&](int m) {
    return friction_budget_nm(all_terms(static_cast<FrictionModel>(m)), v, tm, te);
  };
  EXPECT_NEAR(budget(2) - budget(1), 0.0087, 1e-15);      // K_cs
  EXPECT_NEAR(budget(3) - budget(1), 0.29 * 0.7, 1e-15);  // K_l·|τ_m − τ_e|
  EXPECT_NEAR(budget(4) - budget(2), (0.29 + 0.11) * 0.7, 1e-15);
  EXPECT_NEAR(budget(5) - budget(2), (0.29 * 0.4 + 0.07 * 0.3) + (0.11 * 0.4 + 0.059 * 0.3), 1e-15);
  EXPECT_NEAR(budget(6) - budget(5), 0.0049 * 0.3 * 0.3, 1e-15);  // |τ_m| > |τ_e|: K_eq·τ_e²
  // Only M6 reads the squares, and only when the torques oppose.
  EXPECT_EQ(friction_budget_nm(all_terms(FrictionModel::kM6), v, 0.4, 0.3),
            friction_budget_nm(all_terms(FrictionModel::kM5), v, 0.4, 0.3));
}

// The laws' friction before the family (servo_stages.cpp until this change), verbatim in
// arithmetic: F_c + K_v|v|, + F_s·exp(−u·u) when F_s ≠ 0, + K_l·|τ|.
double legacy_budget(double fc, double kv, double fs, double vs, double kl, double v, double t) {
  double budget = fc + kv * std::abs(v);
  if (fs != 0.0) {
    const double u = v / vs;
    budget += fs * std::exp(-u * u);
  }
  budget += kl * std::abs(t);
  return budget;
}

TEST(FrictionFamilyTest, MotorLoadTermsAreTheOldFrictionBitForBit) {
  FrictionParams p;  // model 6 with the catalog's neutral extras: what kMotorLoad reads
  p.coulomb_nm = 0.08;
  p.viscous_nm_s_per_rad = 0.02;
  p.stribeck_nm = 0.031;
  p.stribeck_velocity_rad_s = 0.13;
  p.load_motor = 0.15;
  for (double v = -3.0; v <= 3.0; v += 0.0137) {
    for (const double t : {-1.3, -0.2, 0.0, 0.7}) {
      const double expected = legacy_budget(0.08, 0.02, 0.031, 0.13, 0.15, v, t);
      // τ_e is not computed for these laws (0): the result must not depend on it being there.
      const double actual = friction_budget_nm(p, v, t, 0.0);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(actual), std::bit_cast<std::uint64_t>(expected))
          << "v " << v << " t " << t;
    }
  }
  EXPECT_FALSE(friction_reads_external_torque(p));
  p.load_external = 0.01;
  EXPECT_TRUE(friction_reads_external_torque(p));
}

TEST(FrictionFamilyTest, LowerModelsIgnoreTheHigherCoefficients) {
  FrictionParams p = all_terms(FrictionModel::kM1);
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, -2.0, 5.0, -5.0), 0.013 + 0.0045 * 2.0);
  EXPECT_FALSE(friction_reads_external_torque(p));
  p.model = FrictionModel::kM3;  // M3 reads τ_e through K_l|τ_m − τ_e|
  EXPECT_TRUE(friction_reads_external_torque(p));
  p.load_motor = 0.0;
  EXPECT_FALSE(friction_reads_external_torque(p));
}

// The back-driving loss (not BAM's): (K_b + s·K_bs)·|τ_e| while the load drives, nothing while the
// motor does; the direction is the velocity's, or at standstill the net torque's.
TEST(FrictionFamilyTest, BackdriveLossActsOnlyWhileTheLoadDrives) {
  FrictionParams p;
  p.model = FrictionModel::kM1;  // the term is outside BAM's structure switch
  p.coulomb_nm = 0.01;
  p.stribeck_velocity_rad_s = 0.5;
  p.stribeck_exponent = 2.0;
  p.backdrive = 0.2;
  p.backdrive_static = 0.5;
  const double te = -0.4;  // gravity pulling the arm down
  // Standstill, the motor holding with less than the load: the load drives, full static loss.
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, 0.0, 0.1, te), 0.01 + 0.7 * 0.4);
  // Standstill, the motor stronger than the load: it drives, no back-driving loss.
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, 0.0, 0.5, te), 0.01);
  // Lowering at 1 rad/s against the motor: kinetic part plus the Stribeck-weighted static part.
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, -1.0, 0.1, te), 0.01 + (0.2 + 0.5 * std::exp(-4.0)) * 0.4);
  // Coasting upwards on momentum while the motor pushes up: the motor drives.
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, 1.0, 0.1, te), 0.01);
  // A released motor (τ_m = 0) is always driven.
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, 0.3, 0.0, -0.2),
                   0.01 + (0.2 + 0.5 * std::exp(-0.36)) * 0.2);
  EXPECT_TRUE(friction_reads_external_torque(p));
  p.backdrive = p.backdrive_static = 0.0;
  EXPECT_FALSE(friction_reads_external_torque(p));
  EXPECT_DOUBLE_EQ(friction_budget_nm(p, 0.0, 0.1, te), 0.01);
}

class ReadFrictionTest : public ::testing::Test {
 protected:
  ReadFrictionTest() {
    for (const std::string& name : friction_parameter_names("j", FrictionTerms::kFamily)) {
      registry_.add({name, unit_from_parameter_name(name), 0.0, -10.0, 10.0});
    }
  }
  ParameterSet values() const {
    ParameterSet set(registry_);
    set.set("joint.j.stribeck_velocity_rad_s", 0.5);
    set.set("joint.j.stribeck_exponent", 2.0);
    set.set("joint.j.friction_model", 6.0);
    return set;
  }
  ParameterRegistry registry_;
};

TEST_F(ReadFrictionTest, NamesAndModelSelection) {
  EXPECT_EQ(friction_parameter_names("j", FrictionTerms::kSpeedOnly).size(), 5u);
  EXPECT_EQ(friction_parameter_names("j", FrictionTerms::kMotorLoad).back(),
            "joint.j.load_friction");
  const auto family = friction_parameter_names("j", FrictionTerms::kFamily);
  EXPECT_EQ(family[family.size() - 3], "joint.j.friction_model");
  EXPECT_EQ(family.back(), "joint.j.backdrive_friction_static");
  ParameterSet set = values();
  set.set("joint.j.friction_model", 3.0);
  set.set("joint.j.load_friction_external", 0.2);
  const ParameterReader get(set, "test");
  const FrictionParams p = read_friction(get, "j", FrictionTerms::kFamily);
  EXPECT_EQ(p.model, FrictionModel::kM3);
  // The speed-only terms never read the load coefficients.
  set.set("joint.j.load_friction", 0.3);
  EXPECT_EQ(read_friction(get, "j", FrictionTerms::kSpeedOnly).load_motor, 0.0);
  EXPECT_EQ(read_friction(get, "j", FrictionTerms::kMotorLoad).load_motor, 0.3);
  EXPECT_EQ(read_friction(get, "j", FrictionTerms::kMotorLoad).load_external, 0.0);
}

TEST_F(ReadFrictionTest, BadValuesAreModelErrors) {
  for (const double model : {0.0, 2.5, 7.0}) {
    ParameterSet set = values();
    set.set("joint.j.friction_model", model);
    EXPECT_THROW(read_friction(ParameterReader(set, "t"), "j", FrictionTerms::kFamily), ModelError)
        << model;
  }
  for (const char* name : {"joint.j.friction_nm", "joint.j.load_friction_external_quad_per_nm",
                           "joint.j.backdrive_friction", "joint.j.backdrive_friction_static",
                           "joint.j.stribeck_velocity_rad_s", "joint.j.stribeck_exponent"}) {
    ParameterSet set = values();
    set.set(name, name == std::string("joint.j.stribeck_exponent") ? 0.0 : -0.1);
    EXPECT_THROW(read_friction(ParameterReader(set, "t"), "j", FrictionTerms::kFamily), ModelError)
        << name;
  }
}

}  // namespace
}  // namespace motoflex
