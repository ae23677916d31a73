// MuJoCo 2.2.2's numerics (mujoco_numerics.h), and its eigen-solver mju_eig3 (MujocoEig3).
#include "analysis/targets/mujoco_numerics.h"

#include <Eigen/Geometry>

namespace massprops {
namespace targets {

// Rotation matrix of a unit quaternion (mju_quat2Mat: the identity quaternion gives exactly I).
Mat3 QuatToMatrix(const Quat& q) {
  if (q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double q00 = q[0] * q[0], q01 = q[0] * q[1], q02 = q[0] * q[2], q03 = q[0] * q[3];
  const double q11 = q[1] * q[1], q12 = q[1] * q[2], q13 = q[1] * q[3];
  const double q22 = q[2] * q[2], q23 = q[2] * q[3], q33 = q[3] * q[3];
  Mat3 r;
  r[0] = q00 + q11 - q22 - q33;
  r[4] = q00 - q11 + q22 - q33;
  r[8] = q00 - q11 - q22 + q33;
  r[1] = 2 * (q12 - q03);
  r[2] = 2 * (q13 + q02);
  r[3] = 2 * (q12 + q03);
  r[5] = 2 * (q23 - q01);
  r[6] = 2 * (q13 - q02);
  r[7] = 2 * (q23 + q01);
  return r;
}

// The compiler's quaternion-to-matrix (mjuu_quat2mat: no identity shortcut).
Mat3 QuatToMatrixCompiler(const Quat& q) {
  const double q00 = q[0] * q[0], q11 = q[1] * q[1], q22 = q[2] * q[2], q33 = q[3] * q[3];
  Mat3 r;
  r[0] = q00 + q11 - q22 - q33;
  r[4] = q00 - q11 + q22 - q33;
  r[8] = q00 - q11 - q22 + q33;
  r[1] = 2 * (q[1] * q[2] - q[0] * q[3]);
  r[2] = 2 * (q[1] * q[3] + q[0] * q[2]);
  r[3] = 2 * (q[1] * q[2] + q[0] * q[3]);
  r[5] = 2 * (q[2] * q[3] - q[0] * q[1]);
  r[6] = 2 * (q[1] * q[3] - q[0] * q[2]);
  r[7] = 2 * (q[2] * q[3] + q[0] * q[1]);
  return r;
}

Quat QuatProduct(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// Engine normalisation (mju_normalize4): multiply by the inverse norm; tiny → identity.
void NormalizeEngine(Quat* q) {
  Quat& v = *q;
  const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
  if (norm < kMujocoMinVal) {
    v = {1, 0, 0, 0};
    return;
  }
  const double inverse = 1 / norm;
  for (double& x : v) x *= inverse;
}

// The compiler's quaternion product (mjuu_mulquat), normalised.
Quat QuatProductCompiler(const Quat& a, const Quat& b) {
  Quat r = QuatProduct(a, b);
  NormalizeCompiler(&r);
  return r;
}

// res = mat1ᵀ·mat2 and res = mat1·mat2 for 3x3, accumulated row by row as mju_mulMatTMat and
// mju_mulMatMat do (a zero multiplier is skipped).
Mat3 MulTransposeLeft(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double s = a[i * 3 + j];
      if (s == 0) continue;
      for (int k = 0; k < 3; ++k) r[j * 3 + k] += b[i * 3 + k] * s;
    }
  }
  return r;
}

Mat3 Mul(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double s = a[i * 3 + k];
      if (s == 0) continue;
      for (int j = 0; j < 3; ++j) r[i * 3 + j] += b[k * 3 + j] * s;
    }
  }
  return r;
}

// Diagonal inertia `local` in a frame rotated by q, as the 6 numbers {xx, yy, zz, xy, xz, yz}
// (mjuu_globalinertia).
std::array<double, 6> RotateDiagonalInertia(const Vec3& local, const Quat& q) {
  const Mat3 m = QuatToMatrixCompiler(q);
  const Mat3 t = {m[0] * local[0], m[3] * local[0], m[6] * local[0],
                  m[1] * local[1], m[4] * local[1], m[7] * local[1],
                  m[2] * local[2], m[5] * local[2], m[8] * local[2]};
  return {m[0] * t[0] + m[1] * t[3] + m[2] * t[6], m[3] * t[1] + m[4] * t[4] + m[5] * t[7],
          m[6] * t[2] + m[7] * t[5] + m[8] * t[8], m[0] * t[1] + m[1] * t[4] + m[2] * t[7],
          m[0] * t[2] + m[1] * t[5] + m[2] * t[8], m[3] * t[2] + m[4] * t[5] + m[5] * t[8]};
}

// Parallel-axis term m·(|d|²·1 − d·dᵀ) as {xx, yy, zz, xy, xz, yz} (mjuu_offcenter).
std::array<double, 6> OffCenter(double mass, const Vec3& d) {
  return {mass * (d[1] * d[1] + d[2] * d[2]),
          mass * (d[0] * d[0] + d[2] * d[2]),
          mass * (d[0] * d[0] + d[1] * d[1]),
          -mass * d[0] * d[1],
          -mass * d[0] * d[2],
          -mass * d[1] * d[2]};
}

// Pose composition: (pos, quat) ← (pos, quat) ∘ (add_pos, add_quat) (mjuu_frameaccum).
void FrameAccumulate(Vec3* pos, Quat* quat, const Vec3& add_pos, const Quat& add_quat) {
  const Mat3 m = QuatToMatrixCompiler(*quat);
  for (int i = 0; i < 3; ++i) {
    (*pos)[i] += m[i * 3] * add_pos[0] + m[i * 3 + 1] * add_pos[1] + m[i * 3 + 2] * add_pos[2];
  }
  *quat = QuatProductCompiler(*quat, add_quat);
}

// A rotation matrix as a unit quaternion (w >= 0 branch chosen by the largest component).
Quat MatrixToQuat(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  q.normalize();
  Quat out = {q.w(), q.x(), q.y(), q.z()};
  if (R.isIdentity(0)) out = {1, 0, 0, 0};
  return out;
}

}  // namespace targets

using namespace targets;

MujocoEigen MujocoEig3(const std::array<double, 6>& full) {
  const Mat3 mat = {full[0], full[3], full[4], full[3], full[1],
                    full[5], full[4], full[5], full[2]};
  constexpr double kEigEps = 1e-12;
  MujocoEigen out;
  Quat quat = {1, 0, 0, 0};
  std::array<double, 3>& eigval = out.values;
  for (int iter = 0; iter < 500; ++iter) {
    const Mat3 v = QuatToMatrix(quat);
    const Mat3 d = Mul(MulTransposeLeft(v, mat), v);
    eigval = {d[0], d[4], d[8]};
    // The largest off-diagonal entry (row r, column c) and the axis of the rotation that
    // annihilates it.
    int r = 0, c = 0, axis = 0;
    if (std::fabs(d[1]) > std::fabs(d[2]) && std::fabs(d[1]) > std::fabs(d[5])) {
      r = 0, c = 1, axis = 2;
    } else if (std::fabs(d[2]) > std::fabs(d[5])) {
      r = 0, c = 2, axis = 1;
    } else {
      r = 1, c = 2, axis = 0;
    }
    if (std::fabs(d[3 * r + c]) < kEigEps) break;
    // Symmetric 2x2 Schur rotation (Golub & Van Loan, Algorithm 8.4.1).
    const double tau = (d[4 * c] - d[4 * r]) / (2 * d[3 * r + c]);
    const double t = tau >= 0 ? 1.0 / (tau + std::sqrt(1 + tau * tau))
                              : -1.0 / (-tau + std::sqrt(1 + tau * tau));
    const double cosine = 1.0 / std::sqrt(1 + t * t);
    if (cosine > 1.0 - kEigEps) break;
    Quat rotation = {0, 0, 0, 0};
    double half_sine = std::sqrt(0.5 - 0.5 * cosine);
    if (tau >= 0) half_sine = -half_sine;
    if (axis == 1) half_sine = -half_sine;
    rotation[axis + 1] = half_sine;
    rotation[0] = std::sqrt(1.0 - half_sine * half_sine);
    NormalizeEngine(&rotation);
    quat = QuatProduct(quat, rotation);
    NormalizeEngine(&quat);
  }
  // Decreasing order by three compare-and-swap steps (pairs 0-1, 1-2, 0-1), each swap turning the
  // frame by 90° about the third axis.
  for (int j = 0; j < 3; ++j) {
    const int lead = j % 2;
    if (eigval[lead] < eigval[lead + 1]) {
      std::swap(eigval[lead], eigval[lead + 1]);
      Quat turn = {0.707106781186548, 0, 0, 0};
      turn[(lead + 2) % 3 + 1] = turn[0];
      quat = QuatProduct(quat, turn);
      NormalizeEngine(&quat);
    }
  }
  out.quat = quat;
  return out;
}

}  // namespace massprops
