#pragma once
/// @file
/// The joint-torque regressor: inverse dynamics (inverse_dynamics.h) is linear in the bodies'
/// inertial parameters and the joints' friction terms, τ = Y(q, q̇, q̈)·π (Atkeson, An and
/// Hollerbach, "Estimation of inertial parameters of manipulator loads and links", IJRR 1986;
/// Khalil and Dombre, "Modeling, Identification and Control of Robots", 2002, ch. 12). Each row
/// of Y is a joint, each column a parameter:
///   - 10 per moving body, in body order, as kinematic_tree.h lays them out:
///     [m, m·cx, m·cy, m·cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz] about the body origin Bo, in B;
///   - with RegressorOptions::friction, 3 per joint, in joint order: viscous (q̇), Coulomb
///     (sign q̇) and offset (1), each only in its own joint's row;
///   - with RegressorOptions::armature, 1 per joint, in joint order: the armature (q̈).
/// Body i's columns are zero in the rows of joints that are not on its path to the base.
/// Cost, per sample: the RNEA's outward pass (about 150 flops per body) and, per body, a 6×10
/// force block carried to each joint on its path to the base (about 290 flops per joint
/// passed): O(n·depth), 7 joints in a chain about 10 000 flops against the RNEA's 2 000
/// (bench/dynamics_bench.cc measures both: docs/benchmarks.md).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "massprops/dynamics/kinematic_tree.h"

namespace massprops {

/// Which columns besides the inertial ones.
struct RegressorOptions {
  bool friction = true;   ///< viscous, Coulomb and offset, 3 per joint
  bool armature = false;  ///< 1 per joint
};

/// The number of columns: 10·bodies + 3·joints (friction) + joints (armature).
int CountRegressorColumns(const KinematicTree& tree, const RegressorOptions& options = {});

/// A name per column: "LINK.m", "LINK.mx", "LINK.my", "LINK.mz", "LINK.ixx", "LINK.ixy",
/// "LINK.iyy", "LINK.ixz", "LINK.iyz", "LINK.izz" (LINK the body's link), then "JOINT.viscous",
/// "JOINT.coulomb", "JOINT.offset", then "JOINT.armature".
std::vector<std::string> RegressorColumnNames(const KinematicTree& tree,
                                              const RegressorOptions& options = {});

/// The tree's own parameter vector in the column order: each body's pi_BBo_B, then the friction
/// terms of tree.friction (zeros when it is empty). τ = Y·π equals CalcInverseDynamics(tree, ...)
/// to round-off when the options include every non-zero term of tree.friction.
Eigen::VectorXd RegressorParameters(const KinematicTree& tree,
                                    const RegressorOptions& options = {});

/// Writes Y(q, q̇, q̈) into `Y`, which must be tree.size() × CountRegressorColumns(tree, options)
/// (a block of a stacked regressor will do). Gravity is tree.gravity_base. Throws
/// std::invalid_argument when a size is wrong.
void CalcTorqueRegressor(const KinematicTree& tree, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq,
                         const RegressorOptions& options, Eigen::Ref<Eigen::MatrixXd> Y);

/// The regressor as a new matrix (see above).
Eigen::MatrixXd CalcTorqueRegressor(const KinematicTree& tree, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& dq, const Eigen::VectorXd& ddq,
                                    const RegressorOptions& options = {});

/// The stacked regressor of N samples: q, dq and ddq are N × tree.size() (one sample per row, in
/// joint order); the result is (N·tree.size()) × CountRegressorColumns, sample k's joint j in row
/// k·tree.size() + j. Throws std::invalid_argument when the shapes disagree.
Eigen::MatrixXd StackTorqueRegressor(const KinematicTree& tree, const Eigen::MatrixXd& q,
                                     const Eigen::MatrixXd& dq, const Eigen::MatrixXd& ddq,
                                     const RegressorOptions& options = {});

}  // namespace massprops
