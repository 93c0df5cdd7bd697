#include "motoflex/motion/zmp_preview.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace motoflex {

Eigen::MatrixXd solve_discrete_riccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                       const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R) {
  const Eigen::Index n = A.rows();
  if (A.cols() != n || B.rows() != n || Q.rows() != n || Q.cols() != n || R.rows() != B.cols() ||
      R.cols() != B.cols()) {
    throw std::invalid_argument("solve_discrete_riccati: inconsistent matrix sizes");
  }
  // Structure-preserving doubling (Chu, Fan & Lin 2005): A_k → 0, G_k → controllability
  // Gramian-like term, H_k → P, each iteration doubling the horizon of the Riccati recursion.
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd Ak = A;
  Eigen::MatrixXd Gk = B * R.ldlt().solve(B.transpose());
  Eigen::MatrixXd Hk = Q;
  bool converged = false;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> W(I + Gk * Hk);
    const Eigen::MatrixXd W_A = W.solve(Ak);
    const Eigen::MatrixXd W_G = W.solve(Gk);
    const Eigen::MatrixXd H_next = Hk + Ak.transpose() * Hk * W_A;
    const Eigen::MatrixXd G_next = Gk + Ak * W_G * Ak.transpose();
    const Eigen::MatrixXd A_next = Ak * W_A;
    const double change = (H_next - Hk).norm();
    Ak = A_next;
    Gk = G_next;
    Hk = H_next;
    if (change <= 1e-13 * std::max(1.0, Hk.norm())) {
      converged = true;
      break;
    }
  }
  const Eigen::MatrixXd P = 0.5 * (Hk + Hk.transpose());
  const Eigen::MatrixXd S = R + B.transpose() * P * B;
  const Eigen::MatrixXd residual =
      Q + A.transpose() * P * A - A.transpose() * P * B * S.ldlt().solve(B.transpose() * P * A) - P;
  if (!converged || !(residual.norm() <= 1e-8 * std::max(1.0, P.norm()))) {
    throw std::runtime_error("discrete Riccati equation did not converge (residual " +
                             std::to_string(residual.norm()) + ")");
  }
  return P;
}

ZmpPreviewController::ZmpPreviewController(const ZmpPreviewOptions& options) : options_(options) {
  const double T = options.dt_s;
  if (!(T > 0.0)) throw std::invalid_argument("ZMP preview: dt_s must be positive");
  if (!(options.com_height_m > 0.0)) {
    throw std::invalid_argument("ZMP preview: com_height_m must be positive");
  }
  if (!(options.gravity_m_s2 > 0.0)) {
    throw std::invalid_argument("ZMP preview: gravity must be positive");
  }
  if (!(options.preview_s >= T)) {
    throw std::invalid_argument("ZMP preview: preview_s must cover at least one period");
  }
  if (!(options.jerk_weight > 0.0) || options.tracking_weight < 0.0 || options.state_weight < 0.0) {
    throw std::invalid_argument("ZMP preview: weights must be >= 0 and the jerk weight > 0");
  }
  // Cart-table model, Kajita 2003 eq. 7.
  A_ << 1.0, T, T * T / 2.0, 0.0, 1.0, T, 0.0, 0.0, 1.0;
  B_ << T * T * T / 6.0, T * T / 2.0, T;
  C_ << 1.0, 0.0, -options.com_height_m / options.gravity_m_s2;

  // Incremental (servo) system on (e, Δx): Ã = [1 CA; 0 A], B̃ = [CB; B] (Katayama 1985).
  Eigen::Matrix4d At = Eigen::Matrix4d::Zero();
  At(0, 0) = 1.0;
  At.block<1, 3>(0, 1) = C_ * A_;
  At.block<3, 3>(1, 1) = A_;
  Eigen::Vector4d Bt;
  Bt(0) = C_ * B_;
  Bt.tail<3>() = B_;
  Eigen::Matrix4d Qt = Eigen::Matrix4d::Zero();
  Qt(0, 0) = options.tracking_weight;
  Qt.block<3, 3>(1, 1) = options.state_weight * Eigen::Matrix3d::Identity();
  Eigen::MatrixXd R(1, 1);
  R(0, 0) = options.jerk_weight;
  const Eigen::Matrix4d P = solve_discrete_riccati(At, Bt, Qt, R);

  const double S = options.jerk_weight + Bt.dot(P * Bt);
  const Eigen::Vector4d It(1.0, 0.0, 0.0, 0.0);
  Eigen::Matrix<double, 4, 3> Ft;
  Ft.row(0) = C_ * A_;
  Ft.block<3, 3>(1, 0) = A_;
  gain_integral_ = Bt.dot(P * It) / S;
  gain_state_ = (Bt.transpose() * P * Ft) / S;
  // Preview gains: G_p(1) = −G_I, G_p(j) = S⁻¹B̃ᵀX(j−1), X(1) = −ÃcᵀPĨ, X(j) = ÃcᵀX(j−1).
  const Eigen::Matrix4d Ac = At - Bt * (Bt.transpose() * P * At) / S;
  const auto N = static_cast<std::size_t>(std::llround(options.preview_s / T));
  gain_preview_.resize(N);
  gain_preview_[0] = -gain_integral_;
  Eigen::Vector4d X = -Ac.transpose() * P * It;
  for (std::size_t j = 1; j < N; ++j) {
    gain_preview_[j] = Bt.dot(X) / S;
    X = Ac.transpose() * X;
  }
}

ZmpPreviewController::Track ZmpPreviewController::track(const std::vector<double>& ref) const {
  Track out;
  const std::size_t K = ref.size();
  if (K == 0) return out;
  out.com_m.reserve(K);
  out.velocity_m_s.reserve(K);
  out.accel_m_s2.reserve(K);
  out.zmp_m.reserve(K);
  Eigen::Vector3d x(ref[0], 0.0, 0.0);
  double error_sum = 0.0;
  for (std::size_t k = 0; k < K; ++k) {
    const double zmp = C_ * x;
    out.com_m.push_back(x(0));
    out.velocity_m_s.push_back(x(1));
    out.accel_m_s2.push_back(x(2));
    out.zmp_m.push_back(zmp);
    error_sum += zmp - ref[k];
    double preview = 0.0;
    for (std::size_t j = 0; j < gain_preview_.size(); ++j) {
      preview += gain_preview_[j] * ref[std::min(k + j + 1, K - 1)];
    }
    const double u = -gain_integral_ * error_sum - gain_state_ * x - preview;
    x = A_ * x + B_ * u;
  }
  return out;
}

}  // namespace motoflex
