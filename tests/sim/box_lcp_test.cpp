// motoflex's box LCP solver (src/sim/box_lcp.hpp) against an exhaustive reference: every
// assignment of rows to "free / at lower / at upper" is tried, and the one whose solution meets
// the LCP conditions is the answer (unique for positive definite A). The problems are built as
// ODE builds them, A = J M⁻¹ Jᵀ + CFM, with rows on a chain of bodies, so A has ODE's zeros.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "box_lcp.hpp"

namespace motoflex::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class RowKind { kUnbounded, kLimited, kNormal, kFriction, kFixed };

struct Problem {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
  std::vector<double> lo, hi;
  std::vector<int> findex;
  // ODE's storage of A: lower triangle, row stride rounded up to a multiple of 4.
  std::vector<double> a_lower;
  unsigned stride = 0;

  BoxLcpView view() const {
    BoxLcpView v;
    v.n = static_cast<unsigned>(b.size());
    v.a_lower = a_lower.data();
    v.stride = stride;
    v.b = b.data();
    v.lo = lo.data();
    v.hi = hi.data();
    v.findex = findex.data();
    return v;
  }
};

// `kinds` rows on a chain of `bodies` bodies (6 velocities each); row r acts on body r mod
// bodies and its successor, so rows on bodies far apart have A = 0 between them.
Problem random_problem(std::mt19937& rng, const std::vector<RowKind>& kinds, int bodies) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> positive(0.5, 2.0);
  const int n = static_cast<int>(kinds.size());
  const int dof = 6 * bodies;
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n, dof);
  for (int r = 0; r < n; ++r) {
    const int first = r % bodies;
    const int second = (first + 1) % bodies;
    for (int k = 0; k < 6; ++k) {
      jacobian(r, 6 * first + k) = unit(rng);
      if (second != first && kinds[r] != RowKind::kNormal) jacobian(r, 6 * second + k) = unit(rng);
    }
  }
  Eigen::VectorXd inverse_mass(dof);
  for (int k = 0; k < dof; ++k) inverse_mass[k] = positive(rng);
  Problem p;
  p.a = jacobian * inverse_mass.asDiagonal() * jacobian.transpose();
  p.a.diagonal().array() += 1e-3;  // CFM
  p.b.resize(n);
  p.lo.assign(n, -kInf);
  p.hi.assign(n, kInf);
  p.findex.assign(n, -1);
  int last_normal = -1;
  for (int r = 0; r < n; ++r) {
    p.b[r] = 3.0 * unit(rng);
    switch (kinds[r]) {
      case RowKind::kUnbounded:
        break;
      case RowKind::kLimited:
        p.hi[r] = positive(rng);
        p.lo[r] = -p.hi[r];
        break;
      case RowKind::kNormal:
        p.lo[r] = 0.0;
        last_normal = r;
        break;
      case RowKind::kFriction:
        p.hi[r] = 0.8;  // mu; ODE passes it as the row's hi and sets lo = −hi
        p.lo[r] = -0.8;
        p.findex[r] = last_normal;
        break;
      case RowKind::kFixed:
        p.lo[r] = p.hi[r] = 0.0;
        break;
    }
  }
  p.stride = n > 1 ? (static_cast<unsigned>(n) + 3u) & ~3u : static_cast<unsigned>(n);
  p.a_lower.assign(static_cast<std::size_t>(p.stride) * n, 12345.0);  // upper part: garbage
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) p.a_lower[static_cast<std::size_t>(i) * p.stride + j] = p.a(i, j);
  }
  return p;
}

bool meets_conditions(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                      const std::vector<double>& lo, const std::vector<double>& hi,
                      const std::vector<int>& rows, const Eigen::VectorXd& x, double tolerance) {
  const Eigen::VectorXd w = a * x - b;
  for (int i : rows) {
    if (x[i] < lo[i] - tolerance || x[i] > hi[i] + tolerance) return false;
    const bool at_lower = std::abs(x[i] - lo[i]) <= tolerance;
    const bool at_upper = std::abs(x[i] - hi[i]) <= tolerance;
    if (at_lower && at_upper) continue;  // a fixed row: any w
    if (at_lower && w[i] < -tolerance) return false;
    if (at_upper && w[i] > tolerance) return false;
    if (!at_lower && !at_upper && std::abs(w[i]) > tolerance) return false;
  }
  return true;
}

// The box LCP over `rows` (the other rows' x fixed as given in `x`) by trying every assignment.
bool solve_exhaustively(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                        const std::vector<double>& lo, const std::vector<double>& hi,
                        const std::vector<int>& rows, Eigen::VectorXd& x) {
  const int m = static_cast<int>(rows.size());
  int combinations = 1;
  for (int k = 0; k < m; ++k) combinations *= 3;
  for (int code = 0; code < combinations; ++code) {
    std::vector<int> free_rows;
    Eigen::VectorXd trial = x;
    bool possible = true;
    int c = code;
    for (int k = 0; k < m; ++k, c /= 3) {
      const int i = rows[k];
      if (c % 3 == 0) {
        free_rows.push_back(i);
      } else {
        const double bound = c % 3 == 1 ? lo[i] : hi[i];
        if (!std::isfinite(bound)) possible = false;
        trial[i] = bound;
      }
    }
    if (!possible) continue;
    if (!free_rows.empty()) {
      const int f = static_cast<int>(free_rows.size());
      Eigen::MatrixXd block(f, f);
      Eigen::VectorXd rhs(f);
      for (int k = 0; k < f; ++k) {
        rhs[k] = b[free_rows[k]];
        for (int j = 0; j < a.rows(); ++j) {
          const bool free_j = std::find(free_rows.begin(), free_rows.end(), j) != free_rows.end();
          if (!free_j) rhs[k] -= a(free_rows[k], j) * trial[j];
        }
        for (int l = 0; l < f; ++l) block(k, l) = a(free_rows[k], free_rows[l]);
      }
      const Eigen::VectorXd solved = block.ldlt().solve(rhs);
      for (int k = 0; k < f; ++k) trial[free_rows[k]] = solved[k];
    }
    if (meets_conditions(a, b, lo, hi, rows, trial, 1e-9)) {
      x = trial;
      return true;
    }
  }
  return false;
}

// ODE's semantics: phase 1 without the friction rows (at 0), their bounds ±|mu|·x_normal from
// it, then phase 2 over all rows.
Eigen::VectorXd reference_solution(const Problem& p) {
  const int n = static_cast<int>(p.b.size());
  std::vector<int> non_friction, all;
  for (int i = 0; i < n; ++i) {
    all.push_back(i);
    if (p.findex[i] < 0) non_friction.push_back(i);
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<double> lo = p.lo, hi = p.hi;
  EXPECT_TRUE(solve_exhaustively(p.a, p.b, lo, hi, non_friction, x));
  for (int i = 0; i < n; ++i) {
    if (p.findex[i] < 0) continue;
    hi[i] = std::abs(p.hi[i] * x[p.findex[i]]);
    lo[i] = -hi[i];
  }
  EXPECT_TRUE(solve_exhaustively(p.a, p.b, lo, hi, all, x));
  return x;
}

std::vector<RowKind> random_kinds(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> pick(0, 9);
  std::vector<RowKind> kinds;
  while (static_cast<int>(kinds.size()) < n) {
    const int k = pick(rng);
    if (k < 4) {
      kinds.push_back(RowKind::kUnbounded);
    } else if (k < 6) {
      kinds.push_back(RowKind::kLimited);
    } else if (k < 9 && static_cast<int>(kinds.size()) + 3 <= n) {
      // A contact: normal and two friction rows.
      kinds.push_back(RowKind::kNormal);
      kinds.push_back(RowKind::kFriction);
      kinds.push_back(RowKind::kFriction);
    } else {
      kinds.push_back(RowKind::kFixed);
    }
  }
  return kinds;
}

TEST(BoxLcpTest, AgreesWithTheExhaustiveSolutionInOdesTwoPhases) {
  std::mt19937 rng(7);
  int with_friction = 0, with_clamped = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Problem p = random_problem(rng, random_kinds(rng, 8), 3);
    const Eigen::VectorXd expected = reference_solution(p);
    BoxLcpSolver solver;
    std::vector<double> x(p.b.size()), lo = p.lo, hi = p.hi, w(p.b.size());
    ASSERT_TRUE(solver.solve(p.view(), x.data(), lo.data(), hi.data(), w.data())) << trial;
    for (int i = 0; i < p.b.size(); ++i) {
      EXPECT_NEAR(x[i], expected[i], 1e-9 * (1.0 + std::abs(expected[i]))) << trial << " row " << i;
      double ax = 0.0;
      for (int j = 0; j < p.b.size(); ++j) ax += p.a(i, j) * x[j];
      EXPECT_NEAR(w[i], ax - p.b[i], 1e-12 * (1.0 + std::abs(p.b[i])));
      if (p.findex[i] >= 0) {
        ++with_friction;
        // The friction bound the solver used and reported is mu times phase 1's normal force.
        EXPECT_EQ(lo[i], -hi[i]);
        EXPECT_LE(std::abs(x[i]), hi[i] * (1.0 + 1e-12));
      }
      if (p.lo[i] != p.hi[i] && (x[i] == p.lo[i] || x[i] == p.hi[i])) ++with_clamped;
    }
  }
  // The problems exercised friction rows and rows held at a bound, not only free solves.
  EXPECT_GT(with_friction, 100);
  EXPECT_GT(with_clamped, 50);
}

TEST(BoxLcpTest, FrictionBoundsComeFromThePhaseOneNormalForce) {
  // One body, a contact whose normal force the friction rows would change in a joint solve:
  // ODE (and the solver) bound the friction by mu times the normal force solved without it.
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const Problem p = random_problem(
        rng, {RowKind::kNormal, RowKind::kFriction, RowKind::kFriction, RowKind::kUnbounded}, 1);
    std::vector<int> phase_one = {0, 3};
    Eigen::VectorXd x1 = Eigen::VectorXd::Zero(4);
    ASSERT_TRUE(solve_exhaustively(p.a, p.b, p.lo, p.hi, phase_one, x1));
    BoxLcpSolver solver;
    std::vector<double> x(4), lo = p.lo, hi = p.hi;
    ASSERT_TRUE(solver.solve(p.view(), x.data(), lo.data(), hi.data(), nullptr));
    EXPECT_NEAR(hi[1], 0.8 * x1[0], 1e-12 * (1.0 + x1[0]));
    EXPECT_NEAR(hi[2], 0.8 * x1[0], 1e-12 * (1.0 + x1[0]));
    if (x1[0] == 0.0) {
      EXPECT_EQ(x[1], 0.0);
      EXPECT_EQ(x[2], 0.0);
    }
  }
}

TEST(BoxLcpTest, LargeRobotLikeProblemsMeetTheLcpConditions) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const Problem p = random_problem(rng, random_kinds(rng, 70), 14);
    BoxLcpSolver solver;
    std::vector<double> x(p.b.size()), lo = p.lo, hi = p.hi;
    ASSERT_TRUE(solver.solve(p.view(), x.data(), lo.data(), hi.data(), nullptr)) << trial;
    const Eigen::VectorXd xv = Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
    std::vector<int> all(p.b.size());
    for (int i = 0; i < p.b.size(); ++i) all[i] = i;
    const double scale = 1.0 + p.b.cwiseAbs().maxCoeff();
    EXPECT_TRUE(meets_conditions(p.a, p.b, lo, hi, all, xv, 1e-8 * scale)) << trial;
  }
}

TEST(BoxLcpTest, WarmStartsGiveTheColdAnswerAndReuseTheOrder) {
  // A slowly changing problem, as from one physics step to the next: one solver keeps its
  // warm start and elimination order, a fresh solver per problem starts cold.
  std::mt19937 rng(5);
  const std::vector<RowKind> kinds = random_kinds(rng, 40);
  const Problem base = random_problem(rng, kinds, 8);
  BoxLcpSolver warm;
  std::normal_distribution<double> drift(0.0, 0.05);
  Problem p = base;
  for (int step = 0; step < 50; ++step) {
    for (int i = 0; i < p.b.size(); ++i) p.b[i] += drift(rng);
    std::vector<double> x_warm(p.b.size()), x_cold(p.b.size());
    std::vector<double> lo = p.lo, hi = p.hi;
    ASSERT_TRUE(warm.solve(p.view(), x_warm.data(), lo.data(), hi.data(), nullptr));
    BoxLcpSolver cold;
    lo = p.lo;
    hi = p.hi;
    ASSERT_TRUE(cold.solve(p.view(), x_cold.data(), lo.data(), hi.data(), nullptr));
    for (int i = 0; i < p.b.size(); ++i) {
      EXPECT_NEAR(x_warm[i], x_cold[i], 1e-9 * (1.0 + std::abs(x_cold[i]))) << step << " " << i;
    }
  }
  EXPECT_EQ(warm.counts().orderings, 1);
  EXPECT_EQ(warm.counts().solved, 50);
  // Warm: on average fewer pivot rounds than the two-per-problem a right guess takes plus a
  // little; cold starts need more.
  EXPECT_LT(warm.counts().pivot_rounds, 50 * 4);
}

}  // namespace
}  // namespace motoflex::detail
