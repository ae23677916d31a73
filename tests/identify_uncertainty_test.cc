// The principal moments' first-order uncertainty (massprops/analysis/identify_uncertainty.h):
// the Jacobian against a hand-derived case and against central differences of Eigen's eigenvalues,
// the standard errors against the spread of the moments over random draws of the parameters.
#include "massprops/analysis/identify_uncertainty.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <random>

namespace massprops {
namespace {

Eigen::Vector3d Moments(const InertialParameters& pi) {
  const double m = pi[0];
  const Eigen::Vector3d h = pi.segment<3>(1);
  Eigen::Matrix3d I_O;
  I_O << pi[4], pi[5], pi[7], pi[5], pi[6], pi[8], pi[7], pi[8], pi[9];
  const Eigen::Matrix3d I_c =
      I_O - (h.squaredNorm() * Eigen::Matrix3d::Identity() - h * h.transpose()) / m;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I_c).eigenvalues();
}

// A 2 kg solid box of 0.1 × 0.2 × 0.4 m (central moments m(b² + c²)/12 ...: 0.03333, 0.02833,
// 0.00833 kg·m²), turned by 0.3 rad about (1, 2, 3) and its center of mass at (0.05, −0.02, 0.1).
InertialParameters TurnedBox() {
  const double m = 2;
  const Eigen::Vector3d c(0.05, -0.02, 0.1);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const Eigen::Matrix3d I_c =
      R *
      Eigen::Vector3d(m * (0.04 + 0.16) / 12, m * (0.01 + 0.16) / 12, m * (0.01 + 0.04) / 12)
          .asDiagonal() *
      R.transpose();
  return MakeInertialParameters(m, c, I_c);
}

// A body at its origin with I = diag(1, 2, 3): by hand, λ_k moves with the k-th diagonal entry
// alone (its eigenvector is the k-th axis), and not with m or h (∂I_c/∂m ∝ ‖h‖²·1 − h·hᵀ = 0, and
// ∂I_c/∂h_i ∝ 2h_i·1 − e_i·hᵀ − h·e_iᵀ = 0 at h = 0).
TEST(IdentifyUncertaintyTest, ADiagonalBodyAtItsOriginMovesWithItsOwnDiagonal) {
  InertialParameters pi;
  pi << 3, 0, 0, 0, 1, 0, 2, 0, 0, 3;
  const Eigen::Matrix<double, 3, 10> G = PrincipalMomentsJacobian(pi);
  Eigen::Matrix<double, 3, 10> expected = Eigen::Matrix<double, 3, 10>::Zero();
  expected(0, 4) = 1;  // Ixx
  expected(1, 6) = 1;  // Iyy
  expected(2, 9) = 1;  // Izz
  EXPECT_LT((G - expected).cwiseAbs().maxCoeff(), 1e-14) << G;
}

// Central differences of the eigenvalues (step 1e-6 of each parameter's scale; their error is
// of order step² times the third derivative): agree to 1e-7 of the moments' scale.
TEST(IdentifyUncertaintyTest, TheJacobianEqualsCentralDifferences) {
  const InertialParameters pi = TurnedBox();
  const Eigen::Matrix<double, 3, 10> G = PrincipalMomentsJacobian(pi);
  for (int j = 0; j < 10; ++j) {
    const double step = 1e-6 * std::max(std::abs(pi[j]), 1e-2);
    InertialParameters up = pi, down = pi;
    up[j] += step;
    down[j] -= step;
    const Eigen::Vector3d numeric = (Moments(up) - Moments(down)) / (2 * step);
    EXPECT_LT((G.col(j) - numeric).cwiseAbs().maxCoeff(), 1e-7 * std::max(1.0, numeric.norm()))
        << "parameter " << j << ": " << G.col(j).transpose() << " vs " << numeric.transpose();
  }
}

// 40 000 draws of π from N(π̂, Cov) with a covariance of 1e-4 of each parameter's scale (Cov =
// L·Lᵀ from a seeded random L): the sample standard deviation of each moment (its own error
// about 1/√(2·40 000) = 0.35%) equals the first-order standard error to 3%.
TEST(IdentifyUncertaintyTest, StandardErrorsMatchTheSpreadOfRandomDraws) {
  const InertialParameters pi = TurnedBox();
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0, 1);
  Eigen::Matrix<double, 10, 10> L;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) L(i, j) = normal(rng) * 1e-4 * std::max(std::abs(pi[i]), 1e-2);
  const Eigen::Matrix<double, 10, 10> cov = L * L.transpose();
  const Eigen::Vector3d reported = PrincipalMomentsStandardError(pi, cov);
  const int draws = 40000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  for (int k = 0; k < draws; ++k) {
    InertialParameters z;
    for (int i = 0; i < 10; ++i) z[i] = normal(rng);
    const Eigen::Vector3d lambda = Moments(pi + L * z);
    sum += lambda;
    sum2 += lambda.cwiseProduct(lambda);
  }
  const Eigen::Vector3d mean = sum / draws;
  const Eigen::Vector3d spread =
      ((sum2 / draws - mean.cwiseProduct(mean)) * draws / (draws - 1.0)).cwiseSqrt();
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(reported[k], 0);
    EXPECT_NEAR(reported[k] / spread[k], 1, 0.03)
        << k << ": " << reported[k] << " vs " << spread[k];
    std::cout << "moment " << k << ": reported " << reported[k] << ", spread " << spread[k] << "\n";
  }
}

}  // namespace
}  // namespace massprops
