#include "dynamics/body_motion.h"

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

namespace massprops {

namespace dynamics_internal {

void CalcBodyMotions(const KinematicTree& tree, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                     const Eigen::VectorXd& ddq, std::vector<BodyMotion>* motions) {
  CheckStateSizes(tree, q, dq, ddq);
  motions->resize(tree.bodies.size());
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d up = -tree.gravity_base;  // the base accelerates at −g
  for (std::size_t i = 0; i < tree.bodies.size(); ++i) {
    const MovingBody& body = tree.bodies[i];
    BodyMotion& m = (*motions)[i];
    const Eigen::Index j = static_cast<Eigen::Index>(i);
    const Eigen::Vector3d& s = body.axis_B;
    const bool revolute = body.type == MovingBody::JointType::kRevolute;
    // X_PB = X_PB0 · X_joint(q): a rotation about s, or a translation along s (s in B, which is
    // the joint frame, so s is the same in the joint frame before and after the motion).
    if (revolute) {
      m.R_PB = body.X_PB0.R_AB * Eigen::AngleAxisd(q(j), s).toRotationMatrix();
      m.p_PB = body.X_PB0.p_AB;
    } else {
      m.R_PB = body.X_PB0.R_AB;
      m.p_PB = body.X_PB0.p_AB + body.X_PB0.R_AB * (s * q(j));
    }
    const bool base = body.parent < 0;
    const BodyMotion* parent = base ? nullptr : &(*motions)[static_cast<std::size_t>(body.parent)];
    const Eigen::Vector3d& w_P = base ? zero : parent->w;
    const Eigen::Vector3d& u_P = base ? zero : parent->u;
    const Eigen::Vector3d& dw_P = base ? zero : parent->dw;
    const Eigen::Vector3d& du_P = base ? up : parent->du;
    // Motion transform from P to B: ω_B = Rᵀω, u_B = Rᵀ(u + ω × p).
    const Eigen::Matrix3d Rt = m.R_PB.transpose();
    m.w = Rt * w_P;
    m.u = Rt * (u_P + w_P.cross(m.p_PB));
    m.dw = Rt * dw_P;
    m.du = Rt * (du_P + dw_P.cross(m.p_PB));
    // v += S·q̇; a += S·q̈ + v ×ₘ S·q̇ (Featherstone's crm).
    const Eigen::Vector3d sdq = s * dq(j);
    if (revolute) {
      m.w += sdq;
      m.dw += s * ddq(j) + m.w.cross(sdq);
      m.du += m.u.cross(sdq);
    } else {
      m.u += sdq;
      m.du += s * ddq(j) + m.w.cross(sdq);
    }
  }
}

double FrictionTorque(const KinematicTree& tree, int joint, double dq, double ddq) {
  if (tree.friction.empty()) return 0;
  const JointFriction& f = tree.friction[static_cast<std::size_t>(joint)];
  const double sign = dq > 0 ? 1.0 : dq < 0 ? -1.0 : 0.0;
  return f.viscous * dq + f.coulomb * sign + f.offset + f.armature * ddq;
}

}  // namespace dynamics_internal

}  // namespace massprops
