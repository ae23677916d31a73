#pragma once
/// @file
/// The uncertainty of a body's principal moments from that of its inertial parameters, to first
/// order: what `massprops identify` reports beside each link's principal moments (issue 51).

#include <Eigen/Core>

#include "massprops/dynamics/kinematic_tree.h"

namespace massprops {

/// dλ/dπ (3 × 10): how the principal moments λ (ascending) of the central inertia I_c of
/// π = [m, h, I_O] move with π, to first order. With v_k the unit
/// eigenvectors of I_c, dλ_k = v_kᵀ·dI_c·v_k (the first-order perturbation of a simple
/// eigenvalue), and I_c = I_O − (‖h‖²·1 − h·hᵀ)/m. Where two moments are equal (an axisymmetric
/// body) each of them is not differentiable; the rows then give the derivative along the
/// eigenvectors the solver picked, and their sum stays exact. Requires m > 0.
Eigen::Matrix<double, 3, 10> PrincipalMomentsJacobian(const InertialParameters& pi);

/// The standard errors of the principal moments (ascending, kg·m²) from the covariance of π
/// (10 × 10): the square roots of the diagonal of G·Cov·Gᵀ, G = PrincipalMomentsJacobian(pi).
Eigen::Vector3d PrincipalMomentsStandardError(const InertialParameters& pi,
                                              const Eigen::Matrix<double, 10, 10>& cov_pi);

}  // namespace massprops
