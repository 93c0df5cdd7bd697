#include "box_lcp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motoflex::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A row's condition counts as violated only beyond these relative margins, so that rounding on
// a degenerate row (w = 0 at a bound) cannot make the pivoting cycle; a free x inside the
// margin is clipped to its bound, which moves it by at most the margin.
constexpr double kRelativeTolerance = 1e-10;
// Block pivots allowed without fewer violations before switching one row at a time.
constexpr int kBlockPivotPatience = 3;

bool is_fixed(double lo, double hi) {
  return lo == hi;
}

// Per position p (`order`: position → problem index), the positions q adjacent to p in `graph`
// (n × n bytes by problem index), q < p only when `earlier_only`, ascending, as ranges
// [start[p], start[p + 1]) of `entries`.
void list_by_position(const std::vector<unsigned char>& graph, const std::vector<unsigned>& order,
                      bool earlier_only, std::vector<std::size_t>& start,
                      std::vector<unsigned>& entries) {
  const std::size_t n = order.size();
  start.assign(n + 1, 0);
  entries.clear();
  for (std::size_t p = 0; p < n; ++p) {
    start[p] = entries.size();
    const unsigned char* row = graph.data() + static_cast<std::size_t>(order[p]) * n;
    const std::size_t end = earlier_only ? p : n;
    for (std::size_t q = 0; q < end; ++q) {
      if (q != p && row[order[q]] != 0) entries.push_back(static_cast<unsigned>(q));
    }
  }
  start[n] = entries.size();
}

}  // namespace

bool BoxLcpSolver::solve(const BoxLcpView& problem, double* x_out, double* lo_out, double* hi_out,
                         double* w_out) {
  ++counts_.problems;
  counts_.rows = problem.n;
  // The same structure: size, friction rows, and every nonzero of A at a known place (as many
  // nonzeros as the known places hold). Then the elimination order and the warm start carry
  // over. A known place may hold an exact zero now and then (a contact normal along an axis).
  const bool same = same_rows(problem);
  const bool warm = same && read_values(problem) == count_lower_nonzeros(problem);
  if (!warm) {
    read_structure(problem, same);
    order_rows();
    read_values(problem);
  }
  const std::size_t n = n_;
  state_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    state_[p] = warm ? previous_state_[p] : BoxRowState::kFree;
  }
  x_.assign(n, 0.0);
  factored_rows_ = 0;
  factored_free_.assign(n, 0);

  // Phase 1 over the non-friction rows (the leading positions), friction forces at 0; their
  // bounds from its normal forces, as ODE sets them; phase 2 over every row.
  if (first_friction_ < n) {
    if (!solve_phase(first_friction_)) return false;
    for (std::size_t p = first_friction_; p < n; ++p) {
      const unsigned i = order_[p];
      const double normal_force = x_[position_[static_cast<unsigned>(problem.findex[i])]];
      if (normal_force == 0.0) {
        lo_[p] = hi_[p] = 0.0;
      } else {
        hi_[p] = std::fabs(problem.hi[i * problem.vector_stride] * normal_force);
        lo_[p] = -hi_[p];
      }
    }
  }
  if (!solve_phase(n)) return false;

  ++counts_.solved;
  const std::size_t stride = problem.vector_stride;
  for (std::size_t p = 0; p < n; ++p) x_out[order_[p] * stride] = x_[p];
  if (lo_out != nullptr && hi_out != nullptr) {
    for (std::size_t p = first_friction_; p < n; ++p) {
      lo_out[order_[p] * stride] = lo_[p];
      hi_out[order_[p] * stride] = hi_[p];
    }
  }
  if (w_out != nullptr) {
    for (std::size_t p = 0; p < n; ++p) w_out[order_[p]] = a_row_times_x(p) - b_[p];
  }
  previous_state_ = state_;
  return true;
}

bool BoxLcpSolver::same_rows(const BoxLcpView& problem) const {
  const unsigned n = problem.n;
  if (n != n_ || previous_state_.size() != n) return false;
  for (unsigned i = 0; i < n; ++i) {
    const bool friction = problem.findex != nullptr && problem.findex[i] >= 0;
    if (friction != (friction_[i] != 0)) return false;
  }
  return true;
}

std::size_t BoxLcpSolver::count_lower_nonzeros(const BoxLcpView& problem) {
  std::size_t count = 0;
  for (unsigned i = 0; i < problem.n; ++i) {
    const double* row = problem.a_lower + static_cast<std::size_t>(i) * problem.stride;
    for (unsigned j = 0; j < i; ++j) count += row[j] != 0.0 ? 1 : 0;
  }
  return count;
}

// A's pattern; with the same rows as before (`keep_known`), the known places stay in it, so
// that places which are zero only now and then do not make the order change back and forth.
void BoxLcpSolver::read_structure(const BoxLcpView& problem, bool keep_known) {
  const unsigned n = problem.n;
  n_ = n;
  friction_.assign(n, 0);
  for (unsigned i = 0; i < n; ++i) {
    friction_[i] = problem.findex != nullptr && problem.findex[i] >= 0 ? 1 : 0;
  }
  if (!keep_known) adjacency_.assign(static_cast<std::size_t>(n) * n, 0);
  for (unsigned i = 0; i < n; ++i) {
    const double* row = problem.a_lower + static_cast<std::size_t>(i) * problem.stride;
    for (unsigned j = 0; j < i; ++j) {
      if (row[j] != 0.0) {
        adjacency_[static_cast<std::size_t>(i) * n + j] = 1;
        adjacency_[static_cast<std::size_t>(j) * n + i] = 1;
      }
    }
  }
  previous_state_.clear();
}

// Minimum-degree elimination of A's graph, non-friction rows first; the fill it records makes
// the pattern of L.
void BoxLcpSolver::order_rows() {
  ++counts_.orderings;
  const std::size_t n = n_;
  filled_ = adjacency_;
  degree_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) degree_[i] += filled_[i * n + j];
  }
  eliminated_.assign(n, 0);
  order_.clear();
  position_.assign(n, 0);
  first_friction_ = n;
  for (std::size_t step = 0; step < n; ++step) {
    std::size_t best = n;
    for (int friction_pass = 0; friction_pass < 2 && best == n; ++friction_pass) {
      for (std::size_t i = 0; i < n; ++i) {
        if (eliminated_[i] != 0 || friction_[i] != friction_pass) continue;
        if (best == n || degree_[i] < degree_[best]) best = i;
      }
    }
    if (friction_[best] != 0 && first_friction_ == n) first_friction_ = step;
    eliminated_[best] = 1;
    position_[best] = static_cast<unsigned>(step);
    order_.push_back(static_cast<unsigned>(best));
    neighbours_.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (eliminated_[i] == 0 && filled_[best * n + i] != 0) {
        neighbours_.push_back(static_cast<unsigned>(i));
      }
    }
    for (unsigned i : neighbours_) {
      --degree_[i];
      for (unsigned j : neighbours_) {
        if (j < i && filled_[i * n + j] == 0) {
          filled_[i * n + j] = filled_[j * n + i] = 1;
          ++degree_[i];
          ++degree_[j];
        }
      }
    }
  }
  index_factor_entries();
}

// From the elimination order and its fill: L's row patterns by position, the entry pairs that
// make each entry of L, and A's nonzeros by position.
void BoxLcpSolver::index_factor_entries() {
  const std::size_t n = n_;
  list_by_position(filled_, order_, true, pattern_start_, pattern_);
  // For each entry (p, r) of L: the pairs of entries (p, t) and (r, t), t < r, whose products
  // make L_pr (the sorted patterns of rows p and r merged).
  pair_start_.assign(pattern_.size() + 1, 0);
  pairs_.clear();
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t e = pattern_start_[p]; e < pattern_start_[p + 1]; ++e) {
      pair_start_[e] = pairs_.size();
      const std::size_t r = pattern_[e];
      std::size_t fp = pattern_start_[p];
      std::size_t fr = pattern_start_[r];
      while (fp < e && fr < pattern_start_[r + 1]) {
        if (pattern_[fp] < pattern_[fr]) {
          ++fp;
        } else if (pattern_[fr] < pattern_[fp]) {
          ++fr;
        } else {
          pairs_.push_back({static_cast<unsigned>(fp), static_cast<unsigned>(fr)});
          ++fp;
          ++fr;
        }
      }
    }
  }
  pair_start_[pattern_.size()] = pairs_.size();
  counts_.l_entries = static_cast<long>(pattern_.size());
  // A's off-diagonal nonzeros by position.
  list_by_position(adjacency_, order_, false, row_start_, row_column_);
}

// A's values at the known places, by position. Returns how many of the known places in A's
// lower triangle hold a nonzero.
std::size_t BoxLcpSolver::read_values(const BoxLcpView& problem) {
  const std::size_t n = n_;
  const auto a = [&problem](std::size_t i, std::size_t j) {
    return i >= j ? problem.a_lower[i * problem.stride + j]
                  : problem.a_lower[j * problem.stride + i];
  };
  diagonal_.resize(n);
  b_.resize(n);
  lo_.resize(n);
  hi_.resize(n);
  row_value_.resize(row_column_.size());
  std::size_t nonzeros = 0;
  pattern_a_.resize(pattern_.size());
  for (std::size_t p = 0; p < n; ++p) {
    const std::size_t i = order_[p];
    diagonal_[p] = a(i, i);
    b_[p] = problem.b[i * problem.vector_stride];
    lo_[p] = problem.lo[i * problem.vector_stride];
    hi_[p] = problem.hi[i * problem.vector_stride];
    for (std::size_t e = row_start_[p]; e < row_start_[p + 1]; ++e) {
      const std::size_t j = order_[row_column_[e]];
      row_value_[e] = a(i, j);
      if (j < i && row_value_[e] != 0.0) ++nonzeros;
    }
    for (std::size_t e = pattern_start_[p]; e < pattern_start_[p + 1]; ++e) {
      pattern_a_[e] = a(i, order_[pattern_[e]]);
    }
  }
  // Sized only: every factorisation of a problem starts at row 0 and writes each row it covers.
  l_.resize(pattern_.size());
  ld_.resize(pattern_.size());
  d_.resize(n);
  return nonzeros;
}

// LDLᵀ of A restricted to the free positions below `free_.size()`, from the first position
// whose free flag differs from the last factorisation's (rows above it are unchanged).
bool BoxLcpSolver::factor_free_rows() {
  const std::size_t rows = free_.size();
  std::size_t first = 0;
  while (first < factored_rows_ && first < rows && factored_free_[first] == free_[first]) ++first;
  for (std::size_t p = first; p < rows; ++p) {
    factored_free_[p] = free_[p];
    const std::size_t begin = pattern_start_[p];
    const std::size_t end = pattern_start_[p + 1];
    if (free_[p] == 0) {
      std::fill(l_.begin() + static_cast<std::ptrdiff_t>(begin),
                l_.begin() + static_cast<std::ptrdiff_t>(end), 0.0);
      std::fill(ld_.begin() + static_cast<std::ptrdiff_t>(begin),
                ld_.begin() + static_cast<std::ptrdiff_t>(end), 0.0);
      d_[p] = 0.0;
      continue;
    }
    ++counts_.factor_rows;
    // L_pr = (A_pr − Σ_t L_pt D_t L_rt) / D_r for the free r in the pattern, in increasing r,
    // over the t in both rows' patterns (entries of a row that is not free are 0).
    double diagonal = diagonal_[p];
    for (std::size_t e = begin; e < end; ++e) {
      const std::size_t r = pattern_[e];
      double value = 0.0;
      if (free_[r] != 0) {
        double sum = pattern_a_[e];
        for (std::size_t k = pair_start_[e]; k < pair_start_[e + 1]; ++k) {
          sum -= l_[pairs_[k].of_row] * ld_[pairs_[k].of_column];
        }
        value = sum / d_[r];
        diagonal -= value * value * d_[r];
      }
      l_[e] = value;
      ld_[e] = value * d_[r];
    }
    if (!(diagonal > 0.0)) return false;
    d_[p] = diagonal;
  }
  factored_rows_ = rows;
  return true;
}

double BoxLcpSolver::a_row_times_x(std::size_t p) const {
  double ax = diagonal_[p] * x_[p];
  for (std::size_t e = row_start_[p]; e < row_start_[p + 1]; ++e) {
    ax += row_value_[e] * x_[row_column_[e]];
  }
  return ax;
}

// x_F = A_FF⁻¹ (b_F − A_F,rest x_rest) with the factorisation of factor_free_rows().
void BoxLcpSolver::solve_free_rows() {
  const std::size_t rows = free_.size();
  rhs_.assign(rows, 0.0);
  for (std::size_t p = 0; p < rows; ++p) {
    if (free_[p] == 0) continue;
    double sum = b_[p];
    for (std::size_t e = row_start_[p]; e < row_start_[p + 1]; ++e) {
      const std::size_t q = row_column_[e];
      if (q >= rows || free_[q] == 0) sum -= row_value_[e] * x_[q];
    }
    for (std::size_t e = pattern_start_[p]; e < pattern_start_[p + 1]; ++e) {
      sum -= l_[e] * rhs_[pattern_[e]];
    }
    rhs_[p] = sum;
  }
  for (std::size_t p = 0; p < rows; ++p) {
    if (free_[p] != 0) rhs_[p] /= d_[p];
  }
  for (std::size_t p = rows; p-- > 0;) {
    if (free_[p] == 0) continue;
    const double value = rhs_[p];
    for (std::size_t e = pattern_start_[p]; e < pattern_start_[p + 1]; ++e) {
      rhs_[pattern_[e]] -= l_[e] * value;
    }
  }
  for (std::size_t p = 0; p < rows; ++p) {
    if (free_[p] != 0) x_[p] = rhs_[p];
  }
}

// The box LCP over positions 0..rows−1, every later position's x held where it is (0 in
// phase 1). States of fixed rows (lo = hi) are forced; the others start from state_.
bool BoxLcpSolver::solve_phase(std::size_t rows) {
  double b_scale = 1.0;
  for (std::size_t p = 0; p < rows; ++p) {
    b_scale = std::max(b_scale, std::fabs(b_[p]));
    if (is_fixed(lo_[p], hi_[p])) state_[p] = BoxRowState::kAtLower;
    if (state_[p] == BoxRowState::kAtLower && lo_[p] == -kInfinity) state_[p] = BoxRowState::kFree;
    if (state_[p] == BoxRowState::kAtUpper && hi_[p] == kInfinity) state_[p] = BoxRowState::kFree;
  }
  const double w_tolerance = kRelativeTolerance * b_scale;
  free_.resize(rows);

  std::size_t fewest_violations = std::numeric_limits<std::size_t>::max();
  int patience = kBlockPivotPatience;
  const std::size_t max_rounds = 10 + 2 * rows;
  for (std::size_t round = 0; round < max_rounds; ++round) {
    ++counts_.pivot_rounds;
    for (std::size_t p = 0; p < rows; ++p) {
      free_[p] = state_[p] == BoxRowState::kFree ? 1 : 0;
      if (state_[p] == BoxRowState::kAtLower) x_[p] = lo_[p];
      if (state_[p] == BoxRowState::kAtUpper) x_[p] = hi_[p];
    }
    if (!factor_free_rows()) return false;
    solve_free_rows();

    violations_.clear();
    for (std::size_t p = 0; p < rows; ++p) {
      if (state_[p] == BoxRowState::kFree) {
        if (x_[p] < lo_[p] - kRelativeTolerance * (1.0 + std::fabs(lo_[p])) ||
            x_[p] > hi_[p] + kRelativeTolerance * (1.0 + std::fabs(hi_[p]))) {
          violations_.push_back(p);
        }
        continue;
      }
      if (is_fixed(lo_[p], hi_[p])) continue;
      const double w = a_row_times_x(p) - b_[p];
      if ((state_[p] == BoxRowState::kAtLower && w < -w_tolerance) ||
          (state_[p] == BoxRowState::kAtUpper && w > w_tolerance)) {
        violations_.push_back(p);
      }
    }
    if (violations_.empty()) {
      for (std::size_t p = 0; p < rows; ++p) {
        if (free_[p] != 0) x_[p] = std::clamp(x_[p], lo_[p], hi_[p]);
      }
      return true;
    }

    const auto switch_row = [this](std::size_t p) {
      if (state_[p] != BoxRowState::kFree) {
        state_[p] = BoxRowState::kFree;
      } else {
        state_[p] = x_[p] < lo_[p] ? BoxRowState::kAtLower : BoxRowState::kAtUpper;
      }
    };
    if (violations_.size() < fewest_violations) {
      fewest_violations = violations_.size();
      patience = kBlockPivotPatience;
      for (std::size_t p : violations_) switch_row(p);
    } else if (patience > 0) {
      --patience;
      for (std::size_t p : violations_) switch_row(p);
    } else {
      switch_row(violations_.back());
    }
  }
  return false;
}

}  // namespace motoflex::detail
