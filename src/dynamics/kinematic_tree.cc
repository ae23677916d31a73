#include "massprops/dynamics/kinematic_tree.h"

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace massprops {

namespace {

InertialParameters FromMassMomentAndTensor(double mass, const Eigen::Vector3d& h,
                                           const Eigen::Matrix3d& I) {
  InertialParameters pi;
  pi << mass, h.x(), h.y(), h.z(), I(0, 0), I(0, 1), I(1, 1), I(0, 2), I(1, 2), I(2, 2);
  return pi;
}

Eigen::Matrix3d TensorOf(const InertialParameters& pi) {
  Eigen::Matrix3d I;
  I << pi(4), pi(5), pi(7), pi(5), pi(6), pi(8), pi(7), pi(8), pi(9);
  return I;
}

// Builds the tree by a depth-first walk from the base over the Model's joints (in file order).
class TreeBuilder {
 public:
  explicit TreeBuilder(const Model& model) : model_(model) {
    for (std::size_t j = 0; j < model.joints.size(); ++j)
      children_[model.joints[j].parent].push_back(j);
  }

  KinematicTreeResult Build() {
    KinematicTree tree;
    tree.base_link = model_.root_link;
    // SDF joints to the world: the world is the base and the model's root link moves (or is
    // welded to it).
    if (model_.FindLink("world") < 0 && children_.count("world") != 0) tree.base_link = "world";
    tree_ = &tree;
    visited_.insert(tree.base_link);
    if (!AddLink(tree.base_link, -1, Pose())) return {std::nullopt, error_};
    if (!Walk(tree.base_link, -1, Pose())) return {std::nullopt, error_};
    for (const Link& link : model_.links) {
      if (visited_.count(link.name) == 0) {
        return {std::nullopt, "link '" + link.name + "' is not attached to the root link '" +
                                  tree.base_link +
                                  "' by joints (a free-floating body: floating bases are out of "
                                  "scope)"};
      }
    }
    tree.friction.assign(tree.bodies.size(), JointFriction{});
    return {std::move(tree), ""};
  }

 private:
  // Adds link `name`'s mass properties, posed by X_BL in body `body` (-1: the base).
  bool AddLink(const std::string& name, int body, const Pose& X_BL) {
    const int index = model_.FindLink(name);
    if (index < 0) return true;  // "world" of SDF: no link, no mass
    const Link& link = model_.links[static_cast<std::size_t>(index)];
    if (link.inertial_unreadable) {
      error_ = "the <inertial> of link '" + name + "' could not be read";
      return false;
    }
    if (body < 0 || !link.inertial) return true;
    MovingBody& b = tree_->bodies[static_cast<std::size_t>(body)];
    b.pi_BBo_B += ReExpressInertialParameters(MakeInertialParameters(*link.inertial), X_BL);
    return true;
  }

  bool Walk(const std::string& link, int body, const Pose& X_BL) {
    const auto found = children_.find(link);
    if (found == children_.end()) return true;
    for (std::size_t j : found->second) {
      const Joint& joint = model_.joints[j];
      if (!visited_.insert(joint.child).second) {
        error_ = "joint '" + joint.name + "' closes a loop at link '" + joint.child + "'";
        return false;
      }
      const Pose X_BC = X_BL * joint.X_PC;
      if (joint.type == Joint::Type::kFixed) {
        if (body >= 0)
          tree_->bodies[static_cast<std::size_t>(body)].welded_links.push_back(joint.child);
        if (body < 0) tree_->base_welded_links.push_back(joint.child);
        if (!AddLink(joint.child, body, X_BC) || !Walk(joint.child, body, X_BC)) return false;
        continue;
      }
      MovingBody moving;
      if (joint.type == Joint::Type::kRevolute || joint.type == Joint::Type::kContinuous) {
        moving.type = MovingBody::JointType::kRevolute;
      } else if (joint.type == Joint::Type::kPrismatic) {
        moving.type = MovingBody::JointType::kPrismatic;
      } else {
        error_ = "joint '" + joint.name + "' is of type '" + joint.type_name +
                 "': inverse dynamics handles revolute, continuous, prismatic and fixed joints";
        return false;
      }
      if (!(joint.axis.norm() > 0) || !joint.axis.allFinite()) {
        error_ = "joint '" + joint.name + "' has no axis (zero length)";
        return false;
      }
      moving.link = joint.child;
      moving.joint = joint.name;
      moving.parent = body;
      moving.X_PB0 = X_BC;
      moving.axis_B = joint.axis.normalized();
      tree_->bodies.push_back(std::move(moving));
      const int index = static_cast<int>(tree_->bodies.size()) - 1;
      if (!AddLink(joint.child, index, Pose()) || !Walk(joint.child, index, Pose())) return false;
    }
    return true;
  }

  const Model& model_;
  std::map<std::string, std::vector<std::size_t>> children_;
  std::set<std::string> visited_;
  KinematicTree* tree_ = nullptr;
  std::string error_;
};

}  // namespace

InertialParameters MakeInertialParameters(double mass, const Eigen::Vector3d& p_BoBcm_B,
                                          const Eigen::Matrix3d& I_BBcm_B) {
  const Eigen::Vector3d& c = p_BoBcm_B;
  // I_BBo = I_BBcm + m·(|c|²·1 − c·cᵀ) (parallel axis), symmetric by construction.
  Eigen::Matrix3d I = 0.5 * (I_BBcm_B + I_BBcm_B.transpose());
  I += mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  return FromMassMomentAndTensor(mass, mass * c, I);
}

InertialParameters MakeInertialParameters(const SpatialInertia<double>& M_BBo_B) {
  return FromMassMomentAndTensor(M_BBo_B.get_mass(), M_BBo_B.CalcComMoment(),
                                 M_BBo_B.CalcRotationalInertia().CopyToFullMatrix3());
}

InertialParameters MakeInertialParameters(const Inertial& inertial) {
  Eigen::Matrix3d I_BiBcm;
  I_BiBcm << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
      inertial.ixz, inertial.iyz, inertial.izz;
  const Eigen::Matrix3d& R_BBi = inertial.X_BBi.R_AB;
  return MakeInertialParameters(inertial.mass, inertial.X_BBi.p_AB,
                                R_BBi * I_BiBcm * R_BBi.transpose());
}

SpatialInertia<double> ToSpatialInertia(const InertialParameters& pi_BBo_B) {
  const double m = pi_BBo_B(0);
  const Eigen::Vector3d c = pi_BBo_B.segment<3>(1) / m;
  const Eigen::Matrix3d G = TensorOf(pi_BBo_B) / m;
  const UnitInertia<double> G_BBo_B(RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
      G(0, 0), G(1, 1), G(2, 2), G(0, 1), G(0, 2), G(1, 2), true));
  return SpatialInertia<double>(m, c, G_BBo_B, true);
}

InertialParameters ReExpressInertialParameters(const InertialParameters& pi_CCo_C,
                                               const Pose& X_BC) {
  const Eigen::Matrix3d& R = X_BC.R_AB;
  const Eigen::Vector3d& p = X_BC.p_AB;
  const double m = pi_CCo_C(0);
  const Eigen::Vector3d h_C_B = R * pi_CCo_C.segment<3>(1);  // m·c about Co, in B
  // With r = p + R·s for each particle s of the body: ∫(|r|²·1 − r·rᵀ) dm =
  // R·I_CCo·Rᵀ + m·(|p|²·1 − p·pᵀ) + 2(p·h)·1 − p·hᵀ − h·pᵀ, h = R·h_C.
  const Eigen::Matrix3d I =
      R * TensorOf(pi_CCo_C) * R.transpose() +
      m * (p.squaredNorm() * Eigen::Matrix3d::Identity() - p * p.transpose()) +
      2 * p.dot(h_C_B) * Eigen::Matrix3d::Identity() - p * h_C_B.transpose() -
      h_C_B * p.transpose();
  return FromMassMomentAndTensor(m, h_C_B + m * p, 0.5 * (I + I.transpose()));
}

int KinematicTree::FindJoint(const std::string& joint_name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].joint == joint_name) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> KinematicTree::JointNames() const {
  std::vector<std::string> names;
  names.reserve(bodies.size());
  for (const MovingBody& body : bodies) names.push_back(body.joint);
  return names;
}

KinematicTreeResult MakeKinematicTree(const Model& model) { return TreeBuilder(model).Build(); }

}  // namespace massprops
