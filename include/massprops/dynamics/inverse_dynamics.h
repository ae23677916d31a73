#pragma once
/// @file
/// Inverse dynamics of a fixed-base kinematic tree by the recursive Newton–Euler algorithm
/// (Featherstone, "Rigid Body Dynamics Algorithms", 2008, §5.3, in body coordinates): the joint
/// torques (N·m for revolute joints, N for prismatic ones) that give the tree the accelerations
/// q̈ at the state (q, q̇) under gravity, plus each joint's friction and armature terms:
///   τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + viscous·q̇ + coulomb·sign(q̇) + offset + armature·q̈.
/// q of a revolute joint in rad, of a prismatic joint in m; the joint frame is the child link's
/// frame at q = 0, rotated about (or moved along) the joint axis by q, as URDF defines it.

#include <Eigen/Core>
#include <vector>

#include "massprops/dynamics/kinematic_tree.h"

namespace massprops {

/// The joint torques τ (size tree.size()) at positions q, velocities q̇ = dq and accelerations
/// q̈ = ddq (each of size tree.size(), in joint order), with the bodies' inertial parameters
/// tree.bodies[i].pi_BBo_B, the friction terms tree.friction (when it has one entry per joint;
/// none when empty) and gravity tree.gravity_base. Throws std::invalid_argument when a vector's
/// size is not tree.size(). Cost: about 260 flops per joint (one pass out, one pass in), no
/// allocation but the result and one work array.
Eigen::VectorXd CalcInverseDynamics(const KinematicTree& tree, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq);

/// As CalcInverseDynamics with the inertial parameters `pi` (10 per body, in body order: the
/// layout of kinematic_tree.h) in place of those of tree.bodies. Throws std::invalid_argument
/// when pi.size() != 10·tree.size().
Eigen::VectorXd CalcInverseDynamics(const KinematicTree& tree, const Eigen::VectorXd& pi,
                                    const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                                    const Eigen::VectorXd& ddq);

}  // namespace massprops
