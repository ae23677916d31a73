// --target drake: Drake's validity test of each inertia (RotationalInertia::CouldBePhysicallyValid)
// and the singular articulated body hinge inertia of a massless subtree (CheckDrake).
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/targets/target_layer.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops::targets {
namespace {

// Drake's validity test of a central inertia (RotationalInertia::CouldBePhysicallyValid in
// multibody/tree/rotational_inertia.h): principal moments p near non-negative and satisfying the
// triangle inequality within ε = 16·DBL_EPSILON·max(1, tr/2) — an absolute floor of 3.6e-15
// kg·m² below 1 kg·m², relative above.
bool DrakeAccepts(const Eigen::Matrix3d& I, Eigen::Vector3d* moments, double* epsilon) {
  if (!I.allFinite()) return false;
  const Eigen::Vector3d p = internal::ScaledPrincipalMoments(
      I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1), PrincipalSolver::kAccurate);
  const double eps = 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, 0.5 * I.trace());
  *moments = p;
  *epsilon = eps;
  return p.minCoeff() + eps >= 0 && p(0) + p(1) + eps >= p(2) && p(0) + p(2) + eps >= p(1) &&
         p(1) + p(2) + eps >= p(0);
}

}  // namespace

void CheckDrake(const Model& model, FindingSink* sink) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Link& link = model.links[i];
    if (!link.inertial) continue;
    const Inertial& in = *link.inertial;
    Eigen::Vector3d p = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    double eps = 0;
    if (DrakeAccepts(WrittenMatrixOf(in), &p, &eps) && std::isfinite(in.mass) && in.mass >= 0) {
      continue;
    }
    sink->Emit(kDrakeInvalid, static_cast<int>(i), InertiaLocationOf(link),
               "Drake refuses link '" + link.name +
                   "': its spatial inertia does not pass RotationalInertia::"
                   "CouldBePhysicallyValid() (mass " +
                   Num(in.mass) + ", principal moments " + Num(p(0)) + ", " + Num(p(1)) + ", " +
                   Num(p(2)) + "; Drake's tolerance 16·eps·max(1, tr/2) = " + Num(eps) +
                   " kg·m²); its parser throws when it builds the body",
               {{"mass", in.mass},
                {"principal_min", p(0)},
                {"principal_mid", p(1)},
                {"principal_max", p(2)},
                {"epsilon", eps}});
  }
  // A moving welded group whose subtree (the group and everything outboard) has no mass, or no
  // moment about its revolute axis: Drake's articulated body algorithm meets a singular hinge
  // inertia ("Encountered singular articulated body hinge inertia ... Please ensure that this
  // body has non-zero inertia along all axes of motion", multibody/tree/body_node_impl.cc).
  // A massless body with mass outboard of it is fine.
  if (model.is_static) return;
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  std::vector<bool> reachable;
  const std::vector<Pose> X_WL = CalcLinkPosesInRootFrame(model, &reachable);
  std::vector<std::vector<int>> children(model.links.size());
  for (const Joint& joint : model.joints) {
    const int p = model.FindLink(joint.parent), c = model.FindLink(joint.child);
    if (p >= 0 && c >= 0 && model.FindParentJoint(joint.child) >= 0 &&
        &model.joints[model.FindParentJoint(joint.child)] == &joint) {
      children[p].push_back(c);
    }
  }
  for (const WeldedGroup& group : groups) {
    if (!group.is_moving || group.parent_joint < 0) continue;
    const int root = group.links.front();
    if (!reachable[root]) continue;
    std::vector<MassProperties> parts;
    std::vector<int> stack = {root};
    std::vector<bool> seen(model.links.size(), false);
    while (!stack.empty()) {
      const int l = stack.back();
      stack.pop_back();
      if (seen[l]) continue;
      seen[l] = true;
      if (model.links[l].inertial_unreadable) return;
      const MassProperties local = LinkMassProperties(model.links[l], model.format);
      MassProperties in_W;
      in_W.mass = local.mass;
      in_W.p_FoScm_F = X_WL[l].p_AB + X_WL[l].R_AB * local.p_FoScm_F;
      in_W.I_SScm_F = X_WL[l].R_AB * local.I_SScm_F * X_WL[l].R_AB.transpose();
      parts.push_back(in_W);
      for (int c : children[l]) stack.push_back(c);
    }
    const CompositeInertia composite = ComposeMassProperties(parts);
    if (!std::isfinite(composite.mass) || !composite.I_SScm_R.allFinite()) continue;
    const Joint& joint = model.joints[group.parent_joint];
    const double eps =
        16 * std::numeric_limits<double>::epsilon() * std::max(1.0, composite.I_SScm_R.trace());
    std::string why;
    double value = composite.mass;
    if (!(composite.mass > 0)) {
      why = "it and everything outboard of it have no mass";
    } else if (joint.type == Joint::Type::kRevolute || joint.type == Joint::Type::kContinuous) {
      const Eigen::Vector3d a = (X_WL[root].R_AB * joint.axis).normalized();
      const Eigen::Vector3d d = composite.p_RoScm_R - X_WL[root].p_AB;
      const Eigen::Matrix3d I_o =
          composite.I_SScm_R +
          composite.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      value = a.dot(I_o * a);
      if (value <= eps) {
        why = "it and everything outboard of it have no moment of inertia about the joint axis (" +
              Num(value) + " kg·m²)";
      }
    }
    if (why.empty()) continue;
    const Link& link = model.links[root];
    sink->Emit(kDrakeMassless, root, link.location,
               "Drake cannot simulate link '" + link.name + "' on " + joint.type_name + " joint '" +
                   joint.name + "': " + why +
                   ", so its articulated body hinge inertia is singular (Drake accepts a massless "
                   "body only when mass lies outboard of it)",
               {{"subtree_mass", composite.mass}, {"value", value}});
  }
}

}  // namespace massprops::targets
