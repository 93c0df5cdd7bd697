#pragma once

// Internal to the simulator: the box-constrained LCP that ODE's dWorldStep solves every step,
// solved by warm-started block principal pivoting on a sparse factorisation instead of ODE's
// dense Dantzig pivoting.
//
// The problem (ODE's conventions): find x and w = A·x − b with lo ≤ x ≤ hi and, per row,
// x = lo ⇒ w ≥ 0, x = hi ⇒ w ≤ 0, lo < x < hi ⇒ w = 0. A is symmetric positive definite
// (ODE adds CFM to its diagonal), so this is the optimality condition of the strictly convex
// box-constrained QP min ½xᵀAx − bᵀx, and its solution is unique: any exact method finds the
// same x up to rounding.
//
// Friction rows (findex ≥ 0) have bounds ±|hi|·x_normal. ODE fixes them once, from the normal
// forces of the sub-problem over the rows without findex (friction forces 0): its Dantzig loop
// orders the friction rows last and sets their bounds when it reaches the first of them. The
// solver keeps exactly those semantics in two phases: phase 1 solves the sub-problem over the
// non-friction rows, the friction bounds follow from its x, phase 2 solves the whole problem
// with them. Both phases have unique solutions, so the result is ODE's up to rounding.
//
// Block principal pivoting: guess which rows sit at a bound (the previous step's answer, the
// warm start), solve the free rows' linear system with the others at their bounds, and move
// every row that violates its condition to the other set; when the count of violations stops
// falling, one row at a time (Murty's rule, finite for positive definite A).
//
// The linear systems are solved by a sparse LDLᵀ factorisation. ODE's A = J M⁻¹ Jᵀ couples two
// rows only when their constraints share a body, so a robot's rows form a tree of small
// cliques, and a minimum-degree elimination order factors them with little or no fill where
// Dantzig's method works on the dense matrix. The order puts the friction rows last, so that
// phase 2 keeps phase 1's factor rows, and a pivot refactors only from the first row whose set
// changed.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace motoflex::detail {

enum class BoxRowState : std::uint8_t { kFree, kAtLower, kAtUpper };

// One box LCP in ODE's storage: A's lower triangle row-major with row stride `stride` (ODE's
// dPAD(n)); b, lo, hi of n entries `vector_stride` apart (ODE interleaves b with x and lo with
// hi: 2); findex of length n, contiguous (null: no friction rows).
struct BoxLcpView {
  unsigned n = 0;
  const double* a_lower = nullptr;
  unsigned stride = 0;
  const double* b = nullptr;
  const double* lo = nullptr;
  const double* hi = nullptr;
  std::size_t vector_stride = 1;
  const int* findex = nullptr;
};

// Scratch and warm start of one rollout's solver: owned by one rollout, used by one thread at a
// time. The warm start (the final row states of the previous problem) and the elimination order
// are reused when the next problem has the same size, friction rows and sparsity.
class BoxLcpSolver {
 public:
  // Solves `problem`; on success writes x (n entries, the view's vector_stride apart), the
  // friction bounds it used into lo_out/hi_out when they are not null (same stride; ODE
  // overwrites its friction rows' bounds the same way; they may be the view's lo and hi),
  // w = A·x − b into w_out (contiguous) when not null, and returns true. Returns false when
  // pivoting did not settle within its iteration limit or a pivot was not positive; x_out, lo_out,
  // hi_out and w_out are then untouched, and the caller falls back to ODE's own solver.
  bool solve(const BoxLcpView& problem, double* x_out, double* lo_out, double* hi_out,
             double* w_out);

  struct Counts {
    long problems = 0;      // solve() calls
    long solved = 0;        // of which solved here (the rest fell back)
    long orderings = 0;     // elimination orders computed (the others were reused)
    long factor_rows = 0;   // rows of L computed, over all factorisations
    long pivot_rounds = 0;  // linear solves, over both phases of all problems
    long rows = 0;          // size of the last problem
    long l_entries = 0;     // off-diagonal entries of L in the last elimination order
  };
  const Counts& counts() const { return counts_; }

 private:
  bool same_rows(const BoxLcpView& problem) const;
  static std::size_t count_lower_nonzeros(const BoxLcpView& problem);
  void read_structure(const BoxLcpView& problem, bool keep_known);
  void order_rows();
  void index_factor_entries();
  std::size_t read_values(const BoxLcpView& problem);
  bool factor_free_rows();
  void solve_free_rows();
  bool solve_phase(std::size_t rows);
  double a_row_times_x(std::size_t p) const;  // (A·x)_p, by position

  Counts counts_;
  // Structure, by problem index: friction flags and the pattern of A (n × n bytes).
  unsigned n_ = 0;
  std::vector<unsigned char> friction_;
  std::vector<unsigned char> adjacency_;
  // Elimination order: position → problem index, and back; friction rows take the last
  // positions, from first_friction_ on.
  std::vector<unsigned> order_;
  std::vector<unsigned> position_;
  std::size_t first_friction_ = 0;
  // Ordering scratch.
  std::vector<unsigned char> filled_;
  std::vector<unsigned> degree_;
  std::vector<unsigned char> eliminated_;
  std::vector<unsigned> neighbours_;
  // Off-diagonal nonzeros of A by position (both triangles): per position a range of
  // (position, value); and A's diagonal, b, bounds by position.
  std::vector<std::size_t> row_start_;
  std::vector<unsigned> row_column_;
  std::vector<double> row_value_;
  std::vector<double> diagonal_;
  std::vector<double> b_;
  std::vector<double> lo_;
  std::vector<double> hi_;
  // L's pattern by position (earlier positions of the filled graph, ascending), with A's value
  // at each entry (0 for fill) and L's value.
  std::vector<std::size_t> pattern_start_;
  std::vector<unsigned> pattern_;
  std::vector<double> pattern_a_;
  std::vector<double> l_;
  std::vector<double> ld_;  // L_pr · D_r per entry
  std::vector<double> d_;
  // Per entry (p, r) of L, the range in pairs_ of the entries (p, t), (r, t) with t < r.
  struct EntryPair {
    unsigned of_row;     // entry (p, t)
    unsigned of_column;  // entry (r, t)
  };
  std::vector<std::size_t> pair_start_;
  std::vector<EntryPair> pairs_;
  // The factorisation covers positions below factored_rows_, with the free set factored_free_.
  std::size_t factored_rows_ = 0;
  std::vector<unsigned char> factored_free_;
  // Pivoting state by position.
  std::vector<BoxRowState> state_;
  std::vector<unsigned char> free_;
  std::vector<double> x_;
  std::vector<double> rhs_;
  std::vector<std::size_t> violations_;
  // Warm start: the final states of the previous problem, by position.
  std::vector<BoxRowState> previous_state_;
};

}  // namespace motoflex::detail
