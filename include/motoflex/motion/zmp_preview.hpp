#pragma once

#include <Eigen/Core>
#include <vector>

namespace motoflex {

// Stabilising solution P of the discrete algebraic Riccati equation
//   P = Q + AᵀPA − AᵀPB (R + BᵀPB)⁻¹ BᵀPA
// by the structure-preserving doubling algorithm (quadratic convergence). Requires R positive
// definite, (A, B) stabilisable and (A, Q^½) detectable; throws std::runtime_error when the
// iteration does not converge or the result does not satisfy the equation.
Eigen::MatrixXd solve_discrete_riccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                       const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R);

// Weights and timing of the ZMP preview controller. The defaults are Kajita et al.'s (2003):
// only the integrated ZMP tracking error is penalised (Q_e = 1, Q_x = 0) against the squared
// change of CoM jerk (R = 1e-6); the preview covers 1.6 s.
struct ZmpPreviewOptions {
  double dt_s = 0.01;          // control period
  double com_height_m = 0.26;  // cart height z_c
  double gravity_m_s2 = 9.81;
  double preview_s = 1.6;        // look-ahead of the reference ZMP
  double tracking_weight = 1.0;  // Q_e: integrated ZMP error
  double state_weight = 0.0;     // Q_x: increments of (c, ċ, c̈), all three equally
  double jerk_weight = 1e-6;     // R: increment of the jerk input
};

// One horizontal axis of the cart-table model (Kajita et al. 2003, "Biped walking pattern
// generation by using preview control of zero-moment point"): a cart of constant height z_c
// with state x = (c, ċ, c̈), jerk input u, and table ZMP p = c − (z_c/g)·c̈. The controller is
// Katayama's optimal preview servo on the incremental system (Kajita eqs. 7–13):
//   u(k) = −G_I Σ_{i≤k} (p(i) − p_ref(i)) − G_x x(k) − Σ_{j=1..N} G_p(j) p_ref(k+j).
// Throws std::invalid_argument for non-positive dt, height, gravity, preview or R.
class ZmpPreviewController {
 public:
  explicit ZmpPreviewController(const ZmpPreviewOptions& options);

  struct Track {
    std::vector<double> com_m;         // c(k)
    std::vector<double> velocity_m_s;  // ċ(k)
    std::vector<double> accel_m_s2;    // c̈(k)
    std::vector<double> zmp_m;         // cart-table ZMP c − (z_c/g)·c̈
  };
  // Runs the controller over a reference sampled every dt_s, starting at rest at c = ref[0];
  // the reference is held at its last value beyond its end.
  Track track(const std::vector<double>& zmp_ref_m) const;

  const ZmpPreviewOptions& options() const { return options_; }
  double integral_gain() const { return gain_integral_; }
  const Eigen::RowVector3d& state_gain() const { return gain_state_; }
  const std::vector<double>& preview_gains() const { return gain_preview_; }  // G_p(1..N)

 private:
  ZmpPreviewOptions options_;
  Eigen::Matrix3d A_;
  Eigen::Vector3d B_;
  Eigen::RowVector3d C_;
  double gain_integral_ = 0.0;
  Eigen::RowVector3d gain_state_;
  std::vector<double> gain_preview_;
};

}  // namespace motoflex
