// The principal moments' first-order uncertainty (massprops/analysis/identify_uncertainty.h).
#include "massprops/analysis/identify_uncertainty.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace massprops {

namespace {

// The symmetric 3 × 3 matrix that π's inertia entry k (4..9: Ixx, Ixy, Iyy, Ixz, Iyz, Izz) adds
// to I_O per unit.
Eigen::Matrix3d InertiaEntryUnit(int k) {
  static const int kRow[6] = {0, 0, 1, 0, 1, 2};
  static const int kCol[6] = {0, 1, 1, 2, 2, 2};
  Eigen::Matrix3d E = Eigen::Matrix3d::Zero();
  E(kRow[k - 4], kCol[k - 4]) = 1;
  E(kCol[k - 4], kRow[k - 4]) = 1;
  return E;
}

}  // namespace

Eigen::Matrix<double, 3, 10> PrincipalMomentsJacobian(const InertialParameters& pi) {
  const double m = pi[0];
  const Eigen::Vector3d h = pi.segment<3>(1);
  Eigen::Matrix3d I_O;
  I_O << pi[4], pi[5], pi[7], pi[5], pi[6], pi[8], pi[7], pi[8], pi[9];
  const Eigen::Matrix3d shift = h.squaredNorm() * Eigen::Matrix3d::Identity() - h * h.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I_O - shift / m);
  const Eigen::Matrix3d& V = eig.eigenvectors();
  Eigen::Matrix<double, 3, 10> G;
  for (int j = 0; j < 10; ++j) {
    Eigen::Matrix3d dI;  // ∂I_c/∂π_j
    if (j == 0) {
      dI = shift / (m * m);
    } else if (j <= 3) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(j - 1);
      dI =
          -(2 * h[j - 1] * Eigen::Matrix3d::Identity() - e * h.transpose() - h * e.transpose()) / m;
    } else {
      dI = InertiaEntryUnit(j);
    }
    for (int k = 0; k < 3; ++k) G(k, j) = V.col(k).dot(dI * V.col(k));
  }
  return G;
}

Eigen::Vector3d PrincipalMomentsStandardError(const InertialParameters& pi,
                                              const Eigen::Matrix<double, 10, 10>& cov_pi) {
  const Eigen::Matrix<double, 3, 10> G = PrincipalMomentsJacobian(pi);
  return (G * cov_pi * G.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace massprops
