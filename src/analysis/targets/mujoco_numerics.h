#pragma once
// Private to analysis: MuJoCo 2.2.2's numerics (docs/targets.md, MuJoCo). Each helper computes
// what the MuJoCo function of the same purpose computes, with the same order of floating-point
// operations, so that borderline decisions agree bit for bit. MujocoEig3 (mju_eig3) is public
// (target_profile.h).
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>

#include "massprops/analysis/target_profile.h"

namespace massprops::targets {

using Quat = std::array<double, 4>;
using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major

/// Rotation matrix of a unit quaternion (mju_quat2Mat: the identity quaternion gives exactly I).
Mat3 QuatToMatrix(const Quat& q);
/// The compiler's quaternion-to-matrix (mjuu_quat2mat: no identity shortcut).
Mat3 QuatToMatrixCompiler(const Quat& q);
/// The quaternion product a·b (mju_mulQuat).
Quat QuatProduct(const Quat& a, const Quat& b);
/// Engine normalisation (mju_normalize4): multiply by the inverse norm; tiny → identity.
void NormalizeEngine(Quat* q);
/// Compiler normalisation (mjuu_normvec): divide by the norm; squared norm below mjEPS → as is.
template <std::size_t N>
void NormalizeCompiler(std::array<double, N>* vec) {
  double sum = 0;
  for (double x : *vec) sum += x * x;
  if (sum < kMujocoEps) return;
  const double norm = std::sqrt(sum);
  for (double& x : *vec) x /= norm;
}
/// The compiler's quaternion product (mjuu_mulquat), normalised.
Quat QuatProductCompiler(const Quat& a, const Quat& b);
/// aᵀ·b for 3x3, accumulated row by row as mju_mulMatTMat (a zero multiplier is skipped).
Mat3 MulTransposeLeft(const Mat3& a, const Mat3& b);
/// a·b for 3x3, accumulated row by row as mju_mulMatMat (a zero multiplier is skipped).
Mat3 Mul(const Mat3& a, const Mat3& b);
/// Diagonal inertia `local` in a frame rotated by q, as the 6 numbers {xx, yy, zz, xy, xz, yz}
/// (mjuu_globalinertia).
std::array<double, 6> RotateDiagonalInertia(const Vec3& local, const Quat& q);
/// Parallel-axis term m·(|d|²·1 − d·dᵀ) as {xx, yy, zz, xy, xz, yz} (mjuu_offcenter).
std::array<double, 6> OffCenter(double mass, const Vec3& d);
/// Pose composition: (pos, quat) ← (pos, quat) ∘ (add_pos, add_quat) (mjuu_frameaccum).
void FrameAccumulate(Vec3* pos, Quat* quat, const Vec3& add_pos, const Quat& add_quat);
/// A rotation matrix as a unit quaternion (w >= 0 branch chosen by the largest component).
Quat MatrixToQuat(const Eigen::Matrix3d& R);

}  // namespace massprops::targets
