#pragma once

#include <Eigen/Core>

namespace motoflex {

// Seed 000 eq. 1: converting joint rates and torques of the serial-link leg model (Fig. 2c) into
// those of TITAN-VIII's parallel-link (four-bar, wire–pulley) knee drive (Fig. 2b).
//
// Coordinates. Serial: θ_s = (θ1, θ2, θ3) with θ3 the knee angle of the shank *relative to the
// thigh*. Parallel: the knee actuator of the four-bar turns the shank relative to the hip link
// (the thigh is one side of the parallelogram), so its angle is the shank's absolute angle in the
// leg plane, θ3p = θ2 + θ3 (scenarios/robots/titan8/README.md: 0 whenever the shank is vertical).
// J2 and J3 turn about parallel axes of the same direction, so
//     θ_p = M θ_s,   M = [1 0 0; 0 1 0; 0 1 1].
//
// Jacobians. Let x = f_s(θ_s) be the foot point. The same point in parallel coordinates is
// f_p(θ_p) = f_s(M⁻¹ θ_p), so J_s = ∂f_s/∂θ_s and, by the chain rule, J_p = ∂f_p/∂θ_p = J_s M⁻¹.
//
// Eq. 1. Equal foot velocity, J_p θ̇_p = J_s θ̇_s, gives θ̇_p = J_p⁻¹ J_s θ̇_s (= M θ̇_s); equal
// static foot force F, τ = Jᵀ F in both models, gives τ_p = J_pᵀ (J_sᵀ)⁻¹ τ_s (= M⁻ᵀ τ_s):
//     θ̇1p = θ̇1,  θ̇2p = θ̇2,  θ̇3p = θ̇2 + θ̇3;    τ1p = τ1,  τ2p = τ2 − τ3,  τ3p = τ3.
// The total power is unchanged, τ_pᵀ θ̇_p = τ_sᵀ θ̇_s, but its split between J2 and J3 is not:
// the parallel J2 carries τ2 − τ3. The closed forms hold for any leg configuration (J_s cancels),
// so the study uses them; the general formulas below take the Jacobians as the paper writes them.

// M of θ_p = M θ_s.
Eigen::Matrix3d serial_to_parallel_angle_map();

// J_p = J_s M⁻¹.
Eigen::Matrix3d parallel_leg_jacobian(const Eigen::Matrix3d& serial_jacobian);

// Eq. 1 as written: θ̇_p = J_p⁻¹ J_s θ̇_s and τ_p = J_pᵀ (J_sᵀ)⁻¹ τ_s. Throws
// std::invalid_argument when J_p or J_s is singular (the leg stretched straight).
Eigen::Vector3d parallel_rates_from_jacobians(const Eigen::Matrix3d& serial_jacobian,
                                              const Eigen::Matrix3d& parallel_jacobian,
                                              const Eigen::Vector3d& serial_rates_rad_s);
Eigen::Vector3d parallel_torques_from_jacobians(const Eigen::Matrix3d& serial_jacobian,
                                                const Eigen::Matrix3d& parallel_jacobian,
                                                const Eigen::Vector3d& serial_torques_nm);

// The closed forms: (θ̇1, θ̇2, θ̇2 + θ̇3) and (τ1, τ2 − τ3, τ3).
Eigen::Vector3d parallel_knee_rates(const Eigen::Vector3d& serial_rates_rad_s);
Eigen::Vector3d parallel_knee_torques(const Eigen::Vector3d& serial_torques_nm);

}  // namespace motoflex
