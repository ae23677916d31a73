#include "massprops/dynamics/inverse_dynamics.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/body_motion.h"

namespace massprops {

namespace {

using dynamics_internal::BodyMotion;

Eigen::VectorXd Rnea(const KinematicTree& tree, const Eigen::VectorXd* pi, const Eigen::VectorXd& q,
                     const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq) {
  if (!tree.friction.empty() && tree.friction.size() != tree.bodies.size()) {
    throw std::invalid_argument("inverse dynamics: tree.friction has " +
                                std::to_string(tree.friction.size()) + " entries for " +
                                std::to_string(tree.size()) + " joints");
  }
  std::vector<BodyMotion> motions;
  dynamics_internal::CalcBodyMotions(tree, q, dq, ddq, &motions);
  const std::size_t n = tree.bodies.size();
  // Each body's spatial force (moment n about Bo, force f) in B: f = I·a + v ×f I·v.
  Eigen::Matrix<double, 6, Eigen::Dynamic> forces(6, static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const BodyMotion& m = motions[i];
    const InertialParameters p =
        pi ? InertialParameters(pi->segment<10>(static_cast<Eigen::Index>(10 * i)))
           : tree.bodies[i].pi_BBo_B;
    const double mass = p(0);
    const Eigen::Vector3d h = p.segment<3>(1);
    Eigen::Matrix3d I;
    I << p(4), p(5), p(7), p(5), p(6), p(8), p(7), p(8), p(9);
    const Eigen::Vector3d n0 = I * m.w + h.cross(m.u);  // momentum of I·v
    const Eigen::Vector3d f0 = mass * m.u - h.cross(m.w);
    forces.col(static_cast<Eigen::Index>(i)).head<3>() =
        I * m.dw + h.cross(m.du) + m.w.cross(n0) + m.u.cross(f0);
    forces.col(static_cast<Eigen::Index>(i)).tail<3>() =
        mass * m.du - h.cross(m.dw) + m.w.cross(f0);
  }
  Eigen::VectorXd tau(static_cast<Eigen::Index>(n));
  for (std::size_t k = n; k-- > 0;) {
    const MovingBody& body = tree.bodies[k];
    const Eigen::Index i = static_cast<Eigen::Index>(k);
    const Eigen::Vector3d nB = forces.col(i).head<3>();
    const Eigen::Vector3d fB = forces.col(i).tail<3>();
    const bool revolute = body.type == MovingBody::JointType::kRevolute;
    tau(i) = (revolute ? body.axis_B.dot(nB) : body.axis_B.dot(fB)) +
             dynamics_internal::FrictionTorque(tree, static_cast<int>(k), dq(i), ddq(i));
    if (body.parent < 0) continue;
    // Force transform from B to P: f_P = R·f, n_P = R·n + p × f_P.
    const BodyMotion& m = motions[k];
    const Eigen::Vector3d fP = m.R_PB * fB;
    forces.col(body.parent).head<3>() += m.R_PB * nB + m.p_PB.cross(fP);
    forces.col(body.parent).tail<3>() += fP;
  }
  return tau;
}

}  // namespace

Eigen::VectorXd CalcInverseDynamics(const KinematicTree& tree, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq) {
  return Rnea(tree, nullptr, q, dq, ddq);
}

Eigen::VectorXd CalcInverseDynamics(const KinematicTree& tree, const Eigen::VectorXd& pi,
                                    const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                                    const Eigen::VectorXd& ddq) {
  if (pi.size() != 10 * static_cast<Eigen::Index>(tree.size())) {
    throw std::invalid_argument("inverse dynamics: " + std::to_string(pi.size()) +
                                " inertial parameters for " + std::to_string(tree.size()) +
                                " bodies (10 each)");
  }
  return Rnea(tree, &pi, q, dq, ddq);
}

}  // namespace massprops
