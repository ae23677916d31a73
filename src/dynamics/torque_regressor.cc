#include "massprops/dynamics/torque_regressor.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/body_motion.h"

namespace massprops {

namespace {

using dynamics_internal::BodyMotion;
using Block3x10 = Eigen::Matrix<double, 3, 10>;

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

// I·w as a linear map of [Ixx, Ixy, Iyy, Ixz, Iyz, Izz].
Eigen::Matrix<double, 3, 6> TensorTimes(const Eigen::Vector3d& w) {
  Eigen::Matrix<double, 3, 6> L;
  L << w.x(), w.y(), 0, w.z(), 0, 0,  //
      0, w.x(), w.y(), 0, w.z(), 0,   //
      0, 0, 0, w.x(), w.y(), w.z();
  return L;
}

// The spatial force on body B, (moment N·π about Bo, force F·π), as linear maps of its own
// parameters π: f = I·a + v ×f I·v (inverse_dynamics.cc writes the same sum out).
void BodyForceBlocks(const BodyMotion& m, Block3x10* N, Block3x10* F) {
  N->setZero();
  F->setZero();
  // mass: n gets u × (m·u) = 0; f = m·(a + ω × u).
  F->col(0) = m.du + m.w.cross(m.u);
  // h = m·c: n = h × a + ω × (h × u) + u × (ω × h), f = −h × ω̇ + ω × (ω × h).
  const Eigen::Matrix3d Sw = Skew(m.w);
  N->block<3, 3>(0, 1) = -Skew(m.du) - Sw * Skew(m.u) + Skew(m.u) * Sw;
  F->block<3, 3>(0, 1) = Skew(m.dw) + Sw * Sw;
  // I about Bo: n = I·ω̇ + ω × (I·ω).
  N->block<3, 6>(0, 4) = TensorTimes(m.dw) + Sw * TensorTimes(m.w);
}

void CheckRegressorSize(const KinematicTree& tree, const RegressorOptions& options,
                        const Eigen::Ref<Eigen::MatrixXd>& Y) {
  const Eigen::Index rows = tree.size();
  const Eigen::Index cols = CountRegressorColumns(tree, options);
  if (Y.rows() != rows || Y.cols() != cols) {
    throw std::invalid_argument("torque regressor: Y is " + std::to_string(Y.rows()) + "×" +
                                std::to_string(Y.cols()) + ", the tree needs " +
                                std::to_string(rows) + "×" + std::to_string(cols));
  }
}

}  // namespace

int CountRegressorColumns(const KinematicTree& tree, const RegressorOptions& options) {
  const int n = tree.size();
  return 10 * n + (options.friction ? 3 * n : 0) + (options.armature ? n : 0);
}

std::vector<std::string> RegressorColumnNames(const KinematicTree& tree,
                                              const RegressorOptions& options) {
  static const char* const kInertial[] = {"m",   "mx",  "my",  "mz",  "ixx",
                                          "ixy", "iyy", "ixz", "iyz", "izz"};
  std::vector<std::string> names;
  for (const MovingBody& body : tree.bodies)
    for (const char* p : kInertial) names.push_back(body.link + "." + p);
  if (options.friction) {
    for (const MovingBody& body : tree.bodies)
      for (const char* p : {"viscous", "coulomb", "offset"}) names.push_back(body.joint + "." + p);
  }
  if (options.armature)
    for (const MovingBody& body : tree.bodies) names.push_back(body.joint + ".armature");
  return names;
}

Eigen::VectorXd RegressorParameters(const KinematicTree& tree, const RegressorOptions& options) {
  const Eigen::Index n = tree.size();
  Eigen::VectorXd pi = Eigen::VectorXd::Zero(CountRegressorColumns(tree, options));
  for (Eigen::Index i = 0; i < n; ++i)
    pi.segment<10>(10 * i) = tree.bodies[static_cast<std::size_t>(i)].pi_BBo_B;
  if (tree.friction.size() != static_cast<std::size_t>(n)) return pi;
  Eigen::Index at = 10 * n;
  if (options.friction) {
    for (const JointFriction& f : tree.friction) {
      pi(at++) = f.viscous;
      pi(at++) = f.coulomb;
      pi(at++) = f.offset;
    }
  }
  if (options.armature)
    for (const JointFriction& f : tree.friction) pi(at++) = f.armature;
  return pi;
}

void CalcTorqueRegressor(const KinematicTree& tree, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq,
                         const RegressorOptions& options, Eigen::Ref<Eigen::MatrixXd> Y) {
  CheckRegressorSize(tree, options, Y);
  std::vector<BodyMotion> motions;
  dynamics_internal::CalcBodyMotions(tree, q, dq, ddq, &motions);
  Y.setZero();
  Block3x10 N, F;
  for (std::size_t i = 0; i < tree.bodies.size(); ++i) {
    BodyForceBlocks(motions[i], &N, &F);
    const Eigen::Index column = 10 * static_cast<Eigen::Index>(i);
    // Carry body i's force from joint to joint toward the base: each joint on the way takes
    // its component along its motion subspace S.
    for (int j = static_cast<int>(i);;) {
      const MovingBody& body = tree.bodies[static_cast<std::size_t>(j)];
      const bool revolute = body.type == MovingBody::JointType::kRevolute;
      Y.row(j).segment<10>(column) = body.axis_B.transpose() * (revolute ? N : F);
      if (body.parent < 0) break;
      const BodyMotion& m = motions[static_cast<std::size_t>(j)];
      F = m.R_PB * F;                     // f_P = R·f
      N = m.R_PB * N + Skew(m.p_PB) * F;  // n_P = R·n + p × f_P
      j = body.parent;
    }
  }
  const Eigen::Index n = tree.size();
  Eigen::Index at = 10 * n;
  if (options.friction) {
    for (Eigen::Index j = 0; j < n; ++j, at += 3) {
      Y(j, at) = dq(j);
      Y(j, at + 1) = dq(j) > 0 ? 1.0 : dq(j) < 0 ? -1.0 : 0.0;
      Y(j, at + 2) = 1;
    }
  }
  if (options.armature)
    for (Eigen::Index j = 0; j < n; ++j) Y(j, at + j) = ddq(j);
}

Eigen::MatrixXd CalcTorqueRegressor(const KinematicTree& tree, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq,
                                    const RegressorOptions& options) {
  Eigen::MatrixXd Y(tree.size(), CountRegressorColumns(tree, options));
  CalcTorqueRegressor(tree, q, dq, ddq, options, Y);
  return Y;
}

Eigen::MatrixXd StackTorqueRegressor(const KinematicTree& tree, const Eigen::MatrixXd& q,
                                     const Eigen::MatrixXd& dq, const Eigen::MatrixXd& ddq,
                                     const RegressorOptions& options) {
  const Eigen::Index n = tree.size();
  if (q.cols() != n || dq.cols() != n || ddq.cols() != n || dq.rows() != q.rows() ||
      ddq.rows() != q.rows()) {
    throw std::invalid_argument("stacked regressor: q, dq, ddq must be samples × " +
                                std::to_string(n) + " joints, all with the same rows");
  }
  Eigen::MatrixXd W(q.rows() * n, CountRegressorColumns(tree, options));
  for (Eigen::Index k = 0; k < q.rows(); ++k) {
    CalcTorqueRegressor(tree, q.row(k).transpose(), dq.row(k).transpose(), ddq.row(k).transpose(),
                        options, W.middleRows(k * n, n));
  }
  return W;
}

}  // namespace massprops
