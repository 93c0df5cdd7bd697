#include "motoflex/motion/nao_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/nao_stance.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

const RobotModel& rigid_nao() {
  static const RobotModel model =
      load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao", {});
  return model;
}

struct Combination {
  double speed_mm_s;
  double step_duration_s;
};
// The walks of the MoToFlex-style reference set that the rigid Nao can make (see
// InfeasibleStepsAreRejected for 150 and 200 mm/s at 2 s).
const std::vector<Combination> kWalks = {{50, 1}, {100, 1}, {150, 1}, {200, 1}, {50, 2}, {100, 2}};

NaoWalkParams params(const Combination& c) {
  NaoWalkParams p;
  p.speed_mm_s = c.speed_mm_s;
  p.step_duration_s = c.step_duration_s;
  return p;
}

using Point = Eigen::Vector2d;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Sole rectangle around a sole point (nao.md §1.1): x −0.05…+0.10; 0.03877 inward and 0.05002
// outward of the ankle.
std::vector<Point> sole_corners(const Eigen::Vector3d& sole, bool left) {
  const double outer = left ? 0.05002 : -0.05002, inner = left ? -0.03877 : 0.03877;
  std::vector<Point> corners;
  for (const double dx : {-0.05, 0.10}) {
    for (const double dy : {inner, outer}) corners.emplace_back(sole.x() + dx, sole.y() + dy);
  }
  return corners;
}

// Andrew's monotone chain; counter-clockwise.
std::vector<Point> convex_hull(std::vector<Point> points) {
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// Signed distance inside the polygon (positive inside), as the smallest edge distance.
double inside_margin(const std::vector<Point>& hull, const Point& p) {
  double margin = 1e9;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point& a = hull[i];
    const Point& b = hull[(i + 1) % hull.size()];
    margin = std::min(margin, cross(a, b, p) / (b - a).norm());
  }
  return margin;
}

std::vector<Point> support_polygon(const NaoWalkSample& s) {
  std::vector<Point> points;
  if (s.support != NaoSupport::kRight) {
    const auto c = sole_corners(s.left_sole_m, true);
    points.insert(points.end(), c.begin(), c.end());
  }
  if (s.support != NaoSupport::kLeft) {
    const auto c = sole_corners(s.right_sole_m, false);
    points.insert(points.end(), c.begin(), c.end());
  }
  return convex_hull(points);
}

TEST(NaoWalk, PlannedZmpStaysInsideTheSupportPolygon) {
  for (const Combination& c : kWalks) {
    const NaoWalkPlan plan = plan_nao_walk(rigid_nao(), params(c));
    double worst_ref = 1e9, worst_table = 1e9;
    int single_support = 0;
    for (const NaoWalkSample& s : plan.samples) {
      const auto polygon = support_polygon(s);
      worst_ref = std::min(worst_ref, inside_margin(polygon, s.zmp_ref_m));
      worst_table = std::min(worst_table, inside_margin(polygon, s.zmp_m));
      if (s.support != NaoSupport::kDouble) {
        ++single_support;
        // The swing foot is off the ground, the support foot on it.
        const auto& support = s.support == NaoSupport::kLeft ? s.left_sole_m : s.right_sole_m;
        EXPECT_EQ(support.z(), 0.0);
      }
    }
    EXPECT_GT(worst_ref, 0.005) << c.speed_mm_s << " mm/s, " << c.step_duration_s << " s";
    EXPECT_GT(worst_table, 0.003) << c.speed_mm_s << " mm/s, " << c.step_duration_s << " s";
    EXPECT_GT(single_support, 300);
  }
}

// The CoM of the preview controller obeys the cart-table model: the ZMP computed from the
// planned CoM and its (finite-difference) acceleration equals the reference within a few mm.
TEST(NaoWalk, CoMTracksTheCartTableModel) {
  for (const Combination& c : kWalks) {
    const NaoWalkParams p = params(c);
    const NaoWalkPlan plan = plan_nao_walk(rigid_nao(), p);
    const double dt = 1.0 / p.rate_hz;
    double worst = 0.0;
    for (std::size_t f = 1; f + 1 < plan.samples.size(); ++f) {
      const Point accel =
          (plan.samples[f + 1].com_m - 2.0 * plan.samples[f].com_m + plan.samples[f - 1].com_m) /
          (dt * dt);
      const Point zmp = plan.samples[f].com_m - p.com_height_m / 9.81 * accel;
      worst = std::max(worst, (zmp - plan.samples[f].zmp_ref_m).norm());
    }
    EXPECT_LT(worst, 0.005) << c.speed_mm_s << " mm/s, " << c.step_duration_s << " s";
  }
}

// The commanded joint angles put the soles where the plan says and the whole-body CoM (all the
// model's bodies) where the preview controller wants it.
TEST(NaoWalk, CommandsRealiseTheFeetAndTheWholeBodyCoM) {
  const RobotModel& model = rigid_nao();
  NaoWalkParams p = params({100, 1});
  p.torso_offset_x_m = 0.004;
  const NaoWalkPlan plan = plan_nao_walk(model, p);
  const NaoStance stance(model);
  ASSERT_EQ(plan.commands.frames(), plan.samples.size());
  ASSERT_EQ(plan.commands.frames(), 1001u);
  for (std::size_t f = 0; f < plan.samples.size(); f += 7) {
    const NaoWalkSample& s = plan.samples[f];
    NaoStance::Legs legs;
    for (int j = 0; j < 5; ++j) {
      legs.left[j] = plan.commands.angle_rad(
          f, *model.actuator_index(std::string("L") + nao_leg::kJointNames[j]));
      legs.right[j] = plan.commands.angle_rad(
          f, *model.actuator_index(std::string("R") + nao_leg::kJointNames[j]));
    }
    const Eigen::Vector3d com = s.torso_m + stance.com_in_torso_m(legs);
    EXPECT_NEAR(com.x(), s.com_m.x() + p.torso_offset_x_m, 1e-8);
    EXPECT_NEAR(com.y(), s.com_m.y(), 1e-8);
    EXPECT_NEAR(com.z(), p.com_height_m, 1e-8);
    const NaoFootPose left = nao_leg_forward(LegSide::kLeft, legs.left);
    const NaoFootPose right = nao_leg_forward(LegSide::kRight, legs.right);
    EXPECT_NEAR((s.torso_m + left.position_m - s.left_sole_m).norm(), 0.0, 1e-9);
    EXPECT_NEAR((s.torso_m + right.position_m - s.right_sole_m).norm(), 0.0, 1e-9);
    EXPECT_NEAR(left.roll_rad, 0.0, 1e-9);
    EXPECT_NEAR(right.pitch_rad, 0.0, 1e-9);
  }
  // Footsteps: 16 steps of 0.05 m (the first half a step, the last closing the feet).
  EXPECT_EQ(plan.steps, 16);
  EXPECT_NEAR(plan.step_length_m, 0.05, 1e-12);
  EXPECT_NEAR(plan.samples.back().left_sole_m.x(), 0.05 * 14.5, 1e-12);
  EXPECT_NEAR(plan.samples.back().right_sole_m.x(), 0.05 * 14.5, 1e-12);
  EXPECT_NEAR(plan.samples.back().com_m.x(), 0.05 * 14.5 + p.zmp_offset_x_m, 2e-3);
  // The motion starts and ends at rest.
  const std::size_t n = plan.commands.joints(), last = plan.commands.frames() - 1;
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_NEAR(plan.commands.angle_rad(last, j), plan.commands.angle_rad(last - 1, j), 1e-4);
  }
}

std::string error_of(const NaoWalkParams& p) {
  try {
    plan_nao_walk(rigid_nao(), p);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(NaoWalk, InvalidParametersNameTheParameterAndTheLimit) {
  NaoWalkParams p;
  p.speed_mm_s = 400;
  const std::string too_fast = error_of(p);
  EXPECT_EQ(too_fast.rfind("speed_mm_s = 400: step length 0.200 m (speed * step_duration_s / 2) "
                           "exceeds the reachable 0.",
                           0),
            0u)
      << too_fast;
  EXPECT_NE(too_fast.find("at com_height_m 0.24, step_duration_s 1; at t = "), std::string::npos)
      << too_fast;

  p = {};
  p.com_height_m = 0.30;
  const std::string too_high = error_of(p);
  EXPECT_EQ(too_high.rfind("com_height_m = 0.3: out of reach", 0), 0u) << too_high;

  for (const auto& [field, setter] : std::vector<std::pair<std::string, void (*)(NaoWalkParams&)>>{
           {"step_duration_s = 0", [](NaoWalkParams& q) { q.step_duration_s = 0; }},
           {"duration_s = -1", [](NaoWalkParams& q) { q.duration_s = -1; }},
           {"start_s = 0", [](NaoWalkParams& q) { q.start_s = 0; }},
           {"rate_hz = 0", [](NaoWalkParams& q) { q.rate_hz = 0; }},
           {"duration_s = 2.5", [](NaoWalkParams& q) { q.duration_s = 2.5; }},
           {"foot_spacing_m = 0.05", [](NaoWalkParams& q) { q.foot_spacing_m = 0.05; }},
           {"double_support_ratio = 1", [](NaoWalkParams& q) { q.double_support_ratio = 1; }},
           {"zmp_offset_x_m = 0.2", [](NaoWalkParams& q) { q.zmp_offset_x_m = 0.2; }},
           {"speed_mm_s = -5", [](NaoWalkParams& q) { q.speed_mm_s = -5; }}}) {
    NaoWalkParams q;
    setter(q);
    const std::string message = error_of(q);
    EXPECT_EQ(message.rfind(field + ":", 0), 0u) << field << " -> " << message;
  }
}

// With 1 s per step the CoM of a LIPM at 0.24 m hovers near the support foot through single
// support, so each leg would have to reach almost a whole step length from the hip when the
// other foot lifts off and lands: 0.15 m and 0.2 m steps exceed the rear leg's hip extension
// (HipPitch ≤ 0.484 rad) and ankle dorsiflexion (AnklePitch ≥ −1.186 rad).
TEST(NaoWalk, InfeasibleStepsAreRejected) {
  for (const double speed : {150.0, 200.0}) {
    const std::string message = error_of(params({speed, 2}));
    EXPECT_EQ(message.rfind("speed_mm_s = " + std::to_string(static_cast<int>(speed)), 0), 0u)
        << message;
    EXPECT_TRUE(message.find("URDF limits") != std::string::npos ||
                message.find("leg length") != std::string::npos ||
                message.find("exceeds the reachable") != std::string::npos)
        << message;
  }
}

TEST(NaoWalk, OtherRatesAndFirstFoot) {
  NaoWalkParams p;
  p.rate_hz = 50;
  p.first_swing_left = true;
  const NaoWalkPlan plan = plan_nao_walk(rigid_nao(), p);
  EXPECT_EQ(plan.commands.frames(), 501u);
  EXPECT_NEAR(plan.commands.time_s(1), 0.02, 1e-12);
  // The left foot moves first.
  const auto moved = std::find_if(plan.samples.begin(), plan.samples.end(), [](const auto& s) {
    return s.left_sole_m.z() > 0.0 || s.right_sole_m.z() > 0.0;
  });
  ASSERT_NE(moved, plan.samples.end());
  EXPECT_GT(moved->left_sole_m.z(), 0.0);
}

TEST(NaoWalk, FastestPlannableSpeed) {
  NaoWalkParams p;
  const double fastest_1s = nao_max_walk_speed_mm_s(rigid_nao(), p);
  p.step_duration_s = 2.0;
  const double fastest_2s = nao_max_walk_speed_mm_s(rigid_nao(), p);
  std::printf("[ fastest  ] step_duration_s 1: %.0f mm/s, 2: %.0f mm/s\n", fastest_1s, fastest_2s);
  EXPECT_GE(fastest_1s, 200.0);
  EXPECT_GE(fastest_2s, 100.0);
  EXPECT_LT(fastest_2s, 150.0);
  p.speed_mm_s = fastest_2s;
  EXPECT_NO_THROW(plan_nao_walk(rigid_nao(), p));
}

// The rigid Nao on ideal servos walks every feasible combination for 10 s without falling,
// at the commanded speed (torso CoM displacement between the end of the first step and the
// start of the closing step) within 20 %.
TEST(NaoWalk, RigidNaoWalksAtTheCommandedSpeed) {
  const RobotModel& model = rigid_nao();
  const ParameterSet parameters(model.parameters);
  RolloutOptions options;
  options.servo = ServoKind::kIdeal;
  options.settle_s = 0.5;
  for (const Combination& c : kWalks) {
    const NaoWalkPlan plan = plan_nao_walk(model, params(c));
    const RolloutResult result = run_rollout(model, parameters, plan.commands, options);
    ASSERT_EQ(result.end, RolloutEnd::kCompleted)
        << c.speed_mm_s << " mm/s, " << c.step_duration_s << " s: " << result.end_detail;
    ASSERT_EQ(result.frames_completed, plan.commands.frames());
    const auto x_at = [&](double t) {
      return result.torso_position_m[3 * static_cast<std::size_t>(std::llround(t * 100.0))];
    };
    const double steady_m = x_at(plan.steady_end_s) - x_at(plan.steady_start_s);
    const double steady_mm_s = 1e3 * steady_m / (plan.steady_end_s - plan.steady_start_s);
    const double walk_m = x_at(plan.walk_end_s) - x_at(plan.walk_start_s);
    const double walk_mm_s = 1e3 * walk_m / (plan.walk_end_s - plan.walk_start_s);
    const double total_m =
        result.torso_position_m[3 * (result.frames_completed - 1)] - result.torso_position_m[0];
    std::printf(
        "[ walk     ] %3.0f mm/s, %.0f s: %2d steps, total %.3f m, steady %.1f mm/s "
        "(%.0f %%), whole walking phase %.1f mm/s\n",
        c.speed_mm_s, c.step_duration_s, plan.steps, total_m, steady_mm_s,
        100.0 * steady_mm_s / c.speed_mm_s, walk_mm_s);
    EXPECT_NEAR(steady_mm_s, c.speed_mm_s, 0.2 * c.speed_mm_s);
    // Straight: no sideways drift, no stumbling.
    const double y_drift =
        result.torso_position_m[3 * (result.frames_completed - 1) + 1] - result.torso_position_m[1];
    EXPECT_LT(std::abs(y_drift), 0.02);
    for (std::size_t f = 0; f < result.frames_completed; ++f) {
      EXPECT_LT(std::abs(result.imu_pitch_rad[f]), 0.1);
      EXPECT_LT(std::abs(result.imu_roll_rad[f]), 0.1);
    }
  }
}

}  // namespace
}  // namespace motoflex
