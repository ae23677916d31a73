#pragma once
/// @file
/// The fixed-base kinematic tree of a Model, as inverse dynamics sees it: the moving bodies (one
/// per revolute, continuous or prismatic joint), each with its joint, its parent body and its 10
/// inertial parameters. Links joined by fixed joints are one rigid body: a link welded to a moving
/// body adds its mass properties to that body's, and links welded to the root link form the
/// base, which does not move (floating bases are out of scope: docs/identify.md).
///
/// The inertial parameters of a body B (InertialParameters), in this order:
///   π = [m, m·cx, m·cy, m·cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]
/// m the mass, c = p_BoBcm_B the center of mass from the body origin Bo (the frame of its joint's
/// child link), and I = I_BBo_B the rotational inertia about Bo (not about the center of mass),
/// all expressed in B. Products are the matrix entries (Ixy = −∫xy dm, the convention of URDF,
/// SDF and RotationalInertia). Both the torques and the regressor are linear in π.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "massprops/core/spatial_inertia.h"
#include "massprops/model/model.h"

namespace massprops {

/// [m, m·cx, m·cy, m·cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz] of a body about its origin, in its frame.
using InertialParameters = Eigen::Matrix<double, 10, 1>;

/// The parameters of a body of mass m whose center of mass is at p_BoBcm_B and whose rotational
/// inertia about the center of mass is I_BBcm_B (matrix entries, symmetric; not checked for
/// validity). About 40 flops.
InertialParameters MakeInertialParameters(double mass, const Eigen::Vector3d& p_BoBcm_B,
                                          const Eigen::Matrix3d& I_BBcm_B);

/// The parameters of a SpatialInertia about Bo expressed in B (any mass, including 0).
InertialParameters MakeInertialParameters(const SpatialInertia<double>& M_BBo_B);

/// The parameters of a link's <inertial> in the link frame (the inertial frame Bi posed by
/// X_BBi, the tensor as written, about Bcm in Bi). About 100 flops.
InertialParameters MakeInertialParameters(const Inertial& inertial);

/// The SpatialInertia of parameters π about Bo in B. Precondition: m > 0 (the center of mass is
/// h/m). Physical validity is not checked (the result may be invalid: see IsPhysicallyValid()).
SpatialInertia<double> ToSpatialInertia(const InertialParameters& pi_BBo_B);

/// The parameters of the same body, π_CCo_C about the origin of frame C expressed in C, taken
/// about the origin of frame B and expressed in B, where X_BC is C's pose in B. Exact for any
/// parameters (linear in π: no center of mass is formed). About 80 flops.
InertialParameters ReExpressInertialParameters(const InertialParameters& pi_CCo_C,
                                               const Pose& X_BC);

/// One moving body of the tree: a link moved by its joint, with the links welded to it.
struct MovingBody {
  enum class JointType { kRevolute, kPrismatic };  ///< Continuous joints are revolute.
  std::string link;   ///< The joint's child link: the body frame B is this link's frame.
  std::string joint;  ///< The joint's name.
  JointType type = JointType::kRevolute;
  int parent = -1;  ///< Index of the parent body in KinematicTree::bodies; -1: the base.
  /// The pose of B in the parent body's frame P with the joint at zero (through the fixed joints
  /// between the parent body's link and the joint's parent link).
  Pose X_PB0;
  Eigen::Vector3d axis_B = Eigen::Vector3d::UnitX();  ///< Unit joint axis, expressed in B.
  /// The body's parameters about Bo in B: its link's and those of the links welded to it.
  InertialParameters pi_BBo_B = InertialParameters::Zero();
  std::vector<std::string> welded_links;  ///< Links fixed to this body, besides `link`.
};

/// Per-joint terms added to the joint torque (all in SI: N·m or N, per rad/s or m/s, ...):
/// τ += viscous·q̇ + coulomb·sign(q̇) + offset + armature·q̈ (sign(0) = 0). armature is the
/// rotor's reflected inertia (MuJoCo's armature, Pinocchio's rotorInertia·gear²).
struct JointFriction {
  double viscous = 0;
  double coulomb = 0;
  double offset = 0;
  double armature = 0;
};

/// A fixed-base kinematic tree. bodies are in an order where each parent comes before its
/// children; joint i of the joint vectors q, q̇, q̈, τ moves bodies[i].
struct KinematicTree {
  std::string base_link;  ///< The root link (or "world", for SDF world joints).
  std::vector<std::string> base_welded_links;  ///< Links fixed to the base, besides base_link.
  std::vector<MovingBody> bodies;
  std::vector<JointFriction> friction;  ///< One per body (all zero from MakeKinematicTree).
  Eigen::Vector3d gravity_base = Eigen::Vector3d(0, 0, -9.81);  ///< m/s², in the base frame.

  /// The number of joints (= moving bodies).
  int size() const { return static_cast<int>(bodies.size()); }
  /// Index of the body moved by the joint of that name, or -1.
  int FindJoint(const std::string& joint_name) const;
  /// The joint names, in joint order.
  std::vector<std::string> JointNames() const;
};

/// What MakeKinematicTree returns: the tree, or (tree absent) a sentence naming the joint or link
/// that keeps the model from being one.
struct KinematicTreeResult {
  std::optional<KinematicTree> tree;
  std::string error;
};

/// The fixed-base tree of `model`: its root link (Model::root_link) is the base; every revolute,
/// continuous and prismatic joint makes a moving body; fixed joints weld. An error (no tree) when
/// a joint of another type (floating, planar, ball, ...) moves a link, when a link is not attached
/// to the root (a free body), or when a link's <inertial> could not be read. A link without an
/// <inertial> adds nothing (mass 0). The joint origin, rpy and axis are used as the Model holds
/// them (an SDF or MJCF joint whose axis does not pass through its child link's origin is not
/// represented by the Model: see docs/identify.md). Cost: O(links + joints).
KinematicTreeResult MakeKinematicTree(const Model& model);

}  // namespace massprops
