// TITAN-VIII foot plans (seed 000 §IV-B crawl, §VI up-and-down, standing): the planned
// trajectories have the paper's stroke, swing height and leg sequence, the commanded joint
// angles reproduce them, and every posture stays reachable with margin.

#include "motoflex/motion/titan_gait.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex/model/robot_loader.hpp"

namespace motoflex {
namespace {

constexpr std::array<TitanPosture, 4> kPostures = {TitanPosture::kA, TitanPosture::kB,
                                                   TitanPosture::kC, TitanPosture::kD};

const RobotModel& titan_model() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/titan8", StructureOptions{});
  return model;
}

TitanCrawl crawl(TitanPosture posture, int periods = 1) {
  TitanCrawlOptions options;
  options.posture = posture;
  options.periods = periods;
  return TitanCrawl(options);
}

TEST(TitanGait, PostureAIsTheReadmeStandardPosture) {
  const TitanPostureSpec a = titan_posture(TitanPosture::kA);
  EXPECT_DOUBLE_EQ(a.foot_x_m, 0.25);
  EXPECT_DOUBLE_EQ(a.foot_y_m, 0.4028);
  EXPECT_EQ(parse_titan_posture("C"), TitanPosture::kC);
  EXPECT_FALSE(parse_titan_posture("E").has_value());
  EXPECT_FALSE(parse_titan_posture("a").has_value());
}

TEST(TitanGait, CrawlTimingIsThePapers) {
  const TitanCrawl gait = crawl(TitanPosture::kA);
  EXPECT_DOUBLE_EQ(gait.swing_duration_s(), 1.2);
  EXPECT_DOUBLE_EQ(gait.stance_duration_s(), 3.6);
  EXPECT_NEAR(gait.body_speed_m_s(), 0.05, 1e-15);
  // Classic crawl sequence FL → HR → FR → HL, FL first as in the paper's Fig. 8.
  EXPECT_DOUBLE_EQ(gait.swing_start_s(TitanLeg::kFL), 0.0);
  EXPECT_DOUBLE_EQ(gait.swing_start_s(TitanLeg::kHR), 1.2);
  EXPECT_DOUBLE_EQ(gait.swing_start_s(TitanLeg::kFR), 2.4);
  EXPECT_DOUBLE_EQ(gait.swing_start_s(TitanLeg::kHL), 3.6);
}

TEST(TitanGait, StanceIsAStraightStrokeAndSwingACycloidOfThePapersSize) {
  for (const TitanPosture posture : kPostures) {
    const TitanCrawl gait = crawl(posture, 2);
    for (const TitanLeg leg : kTitanLegs) {
      const double lift = gait.swing_start_s(leg) + gait.options().period_s;  // second cycle
      const double touch = lift + gait.swing_duration_s();
      const double next_lift = lift + gait.options().period_s;
      const Eigen::Vector3d centre = gait.stroke_centre_m(leg);
      const Eigen::Vector3d at_lift = gait.sole_position_m(leg, lift);
      const Eigen::Vector3d at_touch = gait.sole_position_m(leg, touch);
      const Eigen::Vector3d at_next_lift = gait.sole_position_m(leg, next_lift);
      // Stance stroke 0.18 m backward relative to the body, centred on the posture.
      EXPECT_NEAR(at_touch.x() - at_next_lift.x(), 0.18, 1e-6);
      EXPECT_NEAR(0.5 * (at_touch.x() + at_next_lift.x()), centre.x(), 1e-12);
      // Swing: forward by the stroke, apex 0.05 m above the stance height at mid-swing.
      EXPECT_NEAR(at_touch.x() - at_lift.x(), 0.18, 1e-6);
      const Eigen::Vector3d apex = gait.sole_position_m(leg, lift + 0.5 * gait.swing_duration_s());
      EXPECT_NEAR(apex.z() - centre.z(), 0.05, 1e-6);
      EXPECT_NEAR(apex.x(), centre.x(), 1e-12);
      double highest = -1.0;
      for (int k = 0; k < 1200; ++k) {
        const double t = lift + (k + 0.5) * 1e-3;
        const Eigen::Vector3d p = gait.sole_position_m(leg, t);
        highest = std::max(highest, p.z() - centre.z());
        EXPECT_EQ(gait.phase(leg, t), TitanLegPhase::kSwing);
        EXPECT_DOUBLE_EQ(p.y(), centre.y());
      }
      EXPECT_NEAR(highest, 0.05, 1e-6);
      // Stance: constant height and lateral position, constant backward speed 0.05 m/s.
      for (int k = 0; k < 3599; ++k) {
        const double t = touch + (k + 0.5) * 1e-3;
        const Eigen::Vector3d p = gait.sole_position_m(leg, t);
        const Eigen::Vector3d q = gait.sole_position_m(leg, t + 1e-3);
        EXPECT_EQ(gait.phase(leg, t), TitanLegPhase::kStance);
        EXPECT_DOUBLE_EQ(p.z(), -0.243);
        EXPECT_DOUBLE_EQ(p.y(), centre.y());
        EXPECT_NEAR((q.x() - p.x()) / 1e-3, -0.05, 1e-9);
      }
      // The cycloid lifts off and touches down with zero velocity (the paper's reason for it).
      const double h = 1e-6;
      EXPECT_LT((gait.sole_position_m(leg, lift + h) - at_lift).norm() / h, 1e-4);
      EXPECT_LT((at_touch - gait.sole_position_m(leg, touch - h)).norm() / h, 1e-4);
    }
  }
}

TEST(TitanGait, ExactlyThreeFeetSupportDuringEverySwing) {
  const TitanCrawl gait = crawl(TitanPosture::kA, 2);
  // Every millisecond, and exactly at the 100 Hz frames (the switch instants among them).
  std::vector<double> times;
  for (int k = 0; k < 9600; ++k) times.push_back(k * 1e-3);
  for (int k = 0; k <= 960; ++k) times.push_back(k / 100.0);
  for (const double t : times) {
    int stance = 0;
    for (const TitanLeg leg : kTitanLegs) {
      if (gait.phase(leg, t) == TitanLegPhase::kStance) {
        ++stance;
        EXPECT_DOUBLE_EQ(gait.sole_position_m(leg, t).z(), -0.243) << to_string(leg) << " " << t;
      }
    }
    EXPECT_EQ(stance, 3) << "t = " << t;
  }
}

TEST(TitanGait, BodyCentreStaysInsideTheSupportTriangle) {
  // Static stability of the planned crawl: the body centre (x = y = 0) on the inner side of
  // every edge of the triangle of the three stance feet (duty 0.75: margin 0 at the switches).
  const TitanCrawl gait = crawl(TitanPosture::kA);
  double least_margin_m = 1.0;
  for (double t = 0.0; t < gait.duration_s(); t += 1e-3) {
    std::vector<Eigen::Vector2d> feet;
    for (const TitanLeg leg : kTitanLegs) {
      if (gait.phase(leg, t) == TitanLegPhase::kStance) {
        feet.push_back(gait.sole_position_m(leg, t).head<2>());
      }
    }
    ASSERT_EQ(feet.size(), 3u);
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector2d a = feet[e], b = feet[(e + 1) % 3], c = feet[(e + 2) % 3];
      const Eigen::Vector2d n(-(b - a).y(), (b - a).x());
      const double side = n.dot(c - a) > 0 ? 1.0 : -1.0;
      least_margin_m = std::min(least_margin_m, side * n.dot(-a) / n.norm());
    }
  }
  EXPECT_GT(least_margin_m, -1e-9);
  EXPECT_LT(least_margin_m, 1e-3);
}

TEST(TitanGait, CommandsReproduceThePlannedSolesWithParallelSoles) {
  const TitanKinematics kinematics(titan_model());
  const TitanCrawl gait = crawl(TitanPosture::kB);
  const CommandTrajectory commands = titan_command_trajectory(kinematics, gait);
  ASSERT_EQ(commands.frames(), 481u);
  ASSERT_EQ(commands.joints(), 16u);
  EXPECT_DOUBLE_EQ(commands.time_s(120), 1.2);
  EXPECT_DOUBLE_EQ(commands.duration_s(), 4.8);
  double worst_m = 0.0;
  for (std::size_t f = 0; f < commands.frames(); ++f) {
    std::vector<double> pose(16);
    for (std::size_t j = 0; j < 16; ++j) pose[j] = commands.angle_rad(f, j);
    const auto soles = kinematics.sole_positions_m(pose);
    for (const TitanLeg leg : kTitanLegs) {
      const TitanLegAngles q = kinematics.leg_angles(leg, pose);
      EXPECT_NEAR(q.j4_rad, -(q.j2_rad + q.j3_rad), 1e-15);
      worst_m = std::max(worst_m, (soles[static_cast<std::size_t>(leg)] -
                                   gait.sole_position_m(leg, commands.time_s(f)))
                                      .norm());
    }
  }
  EXPECT_LT(worst_m, 1e-9);
}

TEST(TitanGait, ServoLeadAddsThePlannedRateOverTheGain) {
  const RobotModel& model = titan_model();
  const TitanKinematics kinematics(model);
  const TitanCrawl gait = crawl(TitanPosture::kA);
  const std::vector<double> gains =
      velocity_servo_gains_per_s(model, ParameterSet(model.parameters));
  ASSERT_EQ(gains.size(), 16u);
  EXPECT_DOUBLE_EQ(gains[0], 4.0);  // Table I: J1–J3 4 /s, J4 1 /s
  EXPECT_DOUBLE_EQ(gains[3], 1.0);
  const CommandTrajectory plain = titan_command_trajectory(kinematics, gait);
  TitanCommandOptions options;
  options.lead_gain_per_s = gains;
  const CommandTrajectory lead = titan_command_trajectory(kinematics, gait, options);
  ASSERT_EQ(lead.frames(), plain.frames());
  for (std::size_t f = 1; f + 1 < plain.frames(); ++f) {
    for (std::size_t j = 0; j < 16; ++j) {
      const double rate = (plain.angle_rad(f + 1, j) - plain.angle_rad(f - 1, j)) / 0.02;
      EXPECT_NEAR(lead.angle_rad(f, j) - plain.angle_rad(f, j), rate / gains[j], 2e-3)
          << "frame " << f << " joint " << j;
    }
  }
  options.lead_gain_per_s = {4.0};
  EXPECT_THROW(titan_command_trajectory(kinematics, gait, options), std::invalid_argument);
}

TEST(TitanGait, EveryPostureIsReachableWithMarginThroughTheWholeStroke) {
  const TitanKinematics kinematics(titan_model());
  constexpr double kJointMargin_rad = 0.3;
  for (const TitanPosture posture : kPostures) {
    const TitanCrawl gait = crawl(posture);
    double most_reach = 0.0;
    for (double t = 0.0; t < gait.duration_s(); t += 0.01) {
      for (const TitanLeg leg : kTitanLegs) {
        const TitanLegGeometry& g = kinematics.geometry(leg);
        const Eigen::Vector3d sole = gait.sole_position_m(leg, t);
        most_reach = std::max(most_reach, titan_leg_reach_fraction(g, sole));
        const TitanLegAngles q = titan_leg_ik(g, sole);
        const std::array<double, 4> a = {q.j1_rad, q.j2_rad, q.j3_rad, q.j4_rad};
        for (std::size_t i = 0; i < 4; ++i) {
          EXPECT_GT(a[i], g.lower_rad[i] + kJointMargin_rad) << to_string(posture) << " J" << i;
          EXPECT_LT(a[i], g.upper_rad[i] - kJointMargin_rad) << to_string(posture) << " J" << i;
        }
      }
    }
    EXPECT_LT(most_reach, 0.9) << to_string(posture);
  }
}

TEST(TitanGait, NonStandardPosturesTiltTheShank) {
  // The reason for B–D: at the stroke centre the shank of A is vertical (GDA), the others lean.
  const TitanKinematics kinematics(titan_model());
  const auto shank_tilt = [&](TitanPosture posture) {
    const TitanLegAngles q = titan_leg_ik(kinematics.geometry(TitanLeg::kFL),
                                          titan_stroke_centre_m(posture, TitanLeg::kFL, -0.243));
    return q.j2_rad + q.j3_rad;  // outward positive
  };
  EXPECT_NEAR(shank_tilt(TitanPosture::kA), 0.0, 1e-3);
  EXPECT_LT(shank_tilt(TitanPosture::kB), -0.2);
  EXPECT_GT(shank_tilt(TitanPosture::kC), 0.2);
  EXPECT_GT(shank_tilt(TitanPosture::kD), 0.1);
}

TEST(TitanGait, UpDownBodyHeightFollowsTheSine) {
  const TitanKinematics kinematics(titan_model());
  TitanUpDownOptions options;
  options.amplitude_m = 0.03;
  options.period_s = 4.0;
  options.periods = 2;
  const TitanUpDown motion(options);
  const CommandTrajectory commands = titan_command_trajectory(kinematics, motion);
  ASSERT_EQ(commands.frames(), 801u);
  for (std::size_t f = 0; f < commands.frames(); ++f) {
    const double t = commands.time_s(f);
    const double height = 0.243 + 0.03 * std::sin(2.0 * std::numbers::pi * t / 4.0);
    EXPECT_NEAR(motion.body_height_m(t), height, 1e-12);
    std::vector<double> pose(16);
    for (std::size_t j = 0; j < 16; ++j) pose[j] = commands.angle_rad(f, j);
    const auto soles = kinematics.sole_positions_m(pose);
    for (const TitanLeg leg : kTitanLegs) {
      EXPECT_EQ(motion.phase(leg, t), TitanLegPhase::kStance);
      const Eigen::Vector3d planted = titan_stroke_centre_m(TitanPosture::kA, leg, -height);
      EXPECT_LT((soles[static_cast<std::size_t>(leg)] - planted).norm(), 1e-9);
    }
  }
}

TEST(TitanGait, StandHoldsTheModelsStandPose) {
  const TitanKinematics kinematics(titan_model());
  const TitanStand stand(TitanPosture::kA, 2.0);
  const CommandTrajectory commands = titan_command_trajectory(kinematics, stand);
  ASSERT_EQ(commands.frames(), 201u);
  const std::vector<double> pose = titan_model().stand_pose_vector();
  for (std::size_t f = 0; f < commands.frames(); f += 50) {
    for (std::size_t j = 0; j < 16; ++j) EXPECT_NEAR(commands.angle_rad(f, j), pose[j], 3e-4);
  }
}

TEST(TitanGait, InvalidOptionsAreRejected) {
  TitanCrawlOptions options;
  options.duty_factor = 0.6;
  EXPECT_THROW(TitanCrawl{options}, std::invalid_argument);
  options = {};
  options.periods = 0;
  EXPECT_THROW(TitanCrawl{options}, std::invalid_argument);
  TitanUpDownOptions up;
  up.amplitude_m = 0.3;
  EXPECT_THROW(TitanUpDown{up}, std::invalid_argument);
  EXPECT_THROW(TitanStand(TitanPosture::kA, 0.0), std::invalid_argument);
  // A plan the legs cannot follow fails with a clear error when commands are made.
  TitanUpDownOptions deep;
  deep.mean_sole_z_m = -0.40;
  deep.amplitude_m = 0.1;
  EXPECT_THROW(titan_command_trajectory(TitanKinematics(titan_model()), TitanUpDown(deep)),
               TitanUnreachable);
}

}  // namespace
}  // namespace motoflex
