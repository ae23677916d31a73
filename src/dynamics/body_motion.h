#pragma once
// The outward pass that inverse dynamics and its regressor share: each moving body's pose in its
// parent, its spatial velocity and its spatial acceleration (gravity folded in as an upward
// acceleration of the base, Featherstone 2008, §5.3), all in body coordinates.

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

#include "massprops/dynamics/kinematic_tree.h"

namespace massprops::dynamics_internal {

/// Body B's motion: X_PB its pose in the parent body P; ω (w) and the velocity u of the
/// body-fixed point at Bo, both in B; the spatial acceleration (dw, du) = (ω̇, a_Bo − ω × u) in B,
/// with the base accelerating at −g.
struct BodyMotion {
  Eigen::Matrix3d R_PB;
  Eigen::Vector3d p_PB;
  Eigen::Vector3d w, u, dw, du;
};

/// Throws std::invalid_argument unless q, dq and ddq have tree.size() entries.
inline void CheckStateSizes(const KinematicTree& tree, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq) {
  const Eigen::Index n = tree.size();
  if (q.size() != n || dq.size() != n || ddq.size() != n) {
    throw std::invalid_argument("inverse dynamics: the tree has " + std::to_string(n) +
                                " joints but q, dq, ddq have " + std::to_string(q.size()) + ", " +
                                std::to_string(dq.size()) + ", " + std::to_string(ddq.size()) +
                                " entries");
  }
}

/// The motion of every body (resized to tree.size()). About 150 flops per body.
void CalcBodyMotions(const KinematicTree& tree, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                     const Eigen::VectorXd& ddq, std::vector<BodyMotion>* motions);

/// Each joint's friction and armature torque (0 when tree.friction is empty).
double FrictionTorque(const KinematicTree& tree, int joint, double dq, double ddq);

}  // namespace massprops::dynamics_internal
