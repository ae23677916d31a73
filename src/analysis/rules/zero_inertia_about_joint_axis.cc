// zero-inertia-about-joint-axis (warning): a revolute/continuous joint's child group has zero
// moment of inertia about the axis.
//
// Evidence: the welded group's composite inertia about its root's origin, its parent joint's
// type and axis (through the joint origin, which is the child frame's origin).
// Why: the joint's diagonal entry of the mass matrix is a·I_O·a; when it is zero (within the
// tolerance, relative to the trace) a torque about the axis gives the group infinite angular
// acceleration (a point mass or a rod on the axis).

#include <Eigen/Core>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kZeroInertiaAboutJointAxis = "zero-inertia-about-joint-axis";

}  // namespace

const RuleInfo& ZeroInertiaAboutJointAxisRule() {
  static const RuleInfo kInfo{
      kZeroInertiaAboutJointAxis, Severity::kWarning, true,
      "A revolute/continuous joint's child group has zero moment of inertia about the axis."};
  return kInfo;
}

void CheckInertiaAboutJointAxis(RuleContext& ctx, const WeldedGroup& group, const std::string& who,
                                const CompositeInertia& composite) {
  if (group.parent_joint < 0 || !(composite.mass > 0)) return;
  const Link& root = ctx.model.links[group.links.front()];
  const Joint& joint = ctx.model.joints[group.parent_joint];
  if (joint.type != Joint::Type::kRevolute && joint.type != Joint::Type::kContinuous) return;
  const double norm = joint.axis.norm();
  if (!(norm > 0) || !joint.axis.allFinite()) return;
  const Eigen::Vector3d a = joint.axis / norm;
  const Eigen::Matrix3d I_Ro = composite.CalcInertiaAboutOrigin();
  const double I_axis = a.dot(I_Ro * a);
  if (I_axis <= ctx.options.tolerance * I_Ro.trace()) {
    ctx.Emit(
        kZeroInertiaAboutJointAxis, root, InertiaLocation(root),
        who + " turns on " + joint.type_name + " joint '" + joint.name +
            "' but its moment of inertia about the joint axis " + Vec(a) + " is " + Num(I_axis) +
            " kg·m² (mass " + Num(composite.mass) +
            "): a torque would give it infinite angular acceleration",
        {{"moment_about_axis", I_axis},
         {"mass", composite.mass},
         {"trace", I_Ro.trace()},
         {"group_links", static_cast<double>(group.links.size())}},
        LinkHeadline(root.name,
                     ": no inertia about the axis of its joint (" + FormatInertia(I_axis) + ")"),
        {{"moment_about_axis_kg_m2", I_axis},
         {"mass_kg", composite.mass},
         {"trace_kg_m2", I_Ro.trace()}},
        "give the body its moment about the axis (a rod or a point mass on the axis has none)");
  }
}

}  // namespace rules
}  // namespace massprops
