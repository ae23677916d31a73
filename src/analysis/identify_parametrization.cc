// The log-Cholesky parametrization of a body's inertial parameters (Rucker and Wensing, "Smooth
// Parameterizations of Rigid-Body Inertia", RA-L 2022) and the consistency test of a body's
// parameters (identify.h).
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "analysis/pseudo_inertia.h"
#include "massprops/analysis/identify.h"
#include "massprops/core/spatial_inertia.h"

namespace massprops {

namespace {

using PseudoMatrix = Eigen::Matrix4d;

// U(θ) = e^α·[[e^d1, s12, s13, t1], [0, e^d2, s23, t2], [0, 0, e^d3, t3], [0, 0, 0, 1]].
PseudoMatrix UpperFactor(const LogCholeskyParameters& t) {
  PseudoMatrix U = PseudoMatrix::Zero();
  U(0, 0) = std::exp(t[1]);
  U(1, 1) = std::exp(t[2]);
  U(2, 2) = std::exp(t[3]);
  U(0, 1) = t[4];
  U(1, 2) = t[5];
  U(0, 2) = t[6];
  U(0, 3) = t[7];
  U(1, 3) = t[8];
  U(2, 3) = t[9];
  U(3, 3) = 1;
  return std::exp(t[0]) * U;
}

}  // namespace

InertialParameters InertialParametersFromLogCholesky(const LogCholeskyParameters& theta) {
  const PseudoMatrix U = UpperFactor(theta);
  return internal::ParametersOfPseudoInertia(U * U.transpose());
}

Eigen::Matrix<double, 10, 10> InertialParametersFromLogCholeskyJacobian(
    const LogCholeskyParameters& theta) {
  const PseudoMatrix U = UpperFactor(theta);
  const double scale = std::exp(theta[0]);
  // The entry of U that each of θ[1..9] moves (its derivative: U's entry for d_i, e^α for the
  // others); θ[0] = α scales all of U.
  static const int kRow[10] = {0, 0, 1, 2, 0, 1, 0, 0, 1, 2};
  static const int kCol[10] = {0, 0, 1, 2, 1, 2, 2, 3, 3, 3};
  Eigen::Matrix<double, 10, 10> D;
  for (int k = 0; k < 10; ++k) {
    PseudoMatrix dU = PseudoMatrix::Zero();
    if (k == 0) {
      dU = U;
    } else {
      dU(kRow[k], kCol[k]) = k <= 3 ? U(kRow[k], kCol[k]) : scale;
    }
    D.col(k) = internal::ParametersOfPseudoInertia(dU * U.transpose() + U * dU.transpose());
  }
  return D;
}

LogCholeskyParameters LogCholeskyFromInertialParameters(const InertialParameters& pi,
                                                        double floor) {
  PseudoMatrix J = internal::PseudoInertiaOf(pi);
  const Eigen::SelfAdjointEigenSolver<PseudoMatrix> eig(J);
  const Eigen::Vector4d& lambda = eig.eigenvalues();
  const double smallest = std::max(floor * std::max(lambda.maxCoeff(), 0.0), 1e-12);
  if (!(lambda.minCoeff() >= smallest)) {
    J = eig.eigenvectors() * lambda.cwiseMax(smallest).asDiagonal() *
        eig.eigenvectors().transpose();
  }
  // J = U·Uᵀ with U upper triangular: the lower Cholesky factor of J with rows and columns
  // reversed (P·J·P = L·Lᵀ, U = P·L·P).
  const PseudoMatrix reversed = J.reverse();
  const PseudoMatrix L = reversed.llt().matrixL();
  const PseudoMatrix U = L.reverse();
  LogCholeskyParameters t;
  const double e = U(3, 3);
  t[0] = std::log(e);
  t[1] = std::log(U(0, 0) / e);
  t[2] = std::log(U(1, 1) / e);
  t[3] = std::log(U(2, 2) / e);
  t[4] = U(0, 1) / e;
  t[5] = U(1, 2) / e;
  t[6] = U(0, 2) / e;
  t[7] = U(0, 3) / e;
  t[8] = U(1, 3) / e;
  t[9] = U(2, 3) / e;
  return t;
}

bool IsConsistentBody(const InertialParameters& pi, double relative_tolerance) {
  if (!pi.allFinite() || !(pi[0] > 0)) return false;
  return ToSpatialInertia(pi).IsPhysicallyValid(relative_tolerance);
}

}  // namespace massprops
