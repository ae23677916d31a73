#pragma once
// The pseudo-inertia J = [S h; hᵀ m] of a body's inertial parameters π (kinematic_tree.h), with
// S = ∫x·xᵀ dm = ½·tr(I)·1 − I about the body origin, and back: both linear. The identification's
// parametrizations (identify_parametrization.cc, identify_ellipsoid.cc) work on J.
#include <Eigen/Core>

#include "massprops/dynamics/kinematic_tree.h"

namespace massprops::internal {

inline Eigen::Matrix4d PseudoInertiaOf(const InertialParameters& pi) {
  Eigen::Matrix3d I;
  I << pi[4], pi[5], pi[7], pi[5], pi[6], pi[8], pi[7], pi[8], pi[9];
  Eigen::Matrix4d J;
  J.topLeftCorner<3, 3>() = 0.5 * I.trace() * Eigen::Matrix3d::Identity() - I;
  J.block<3, 1>(0, 3) = pi.segment<3>(1);
  J.block<1, 3>(3, 0) = pi.segment<3>(1).transpose();
  J(3, 3) = pi[0];
  return J;
}

// I = tr(S)·1 − S about the origin.
inline InertialParameters ParametersOfPseudoInertia(const Eigen::Matrix4d& J) {
  const Eigen::Matrix3d S = J.topLeftCorner<3, 3>();
  const Eigen::Matrix3d I = S.trace() * Eigen::Matrix3d::Identity() - S;
  InertialParameters pi;
  pi << J(3, 3), J(0, 3), J(1, 3), J(2, 3), I(0, 0), I(0, 1), I(1, 1), I(0, 2), I(1, 2), I(2, 2);
  return pi;
}

}  // namespace massprops::internal
