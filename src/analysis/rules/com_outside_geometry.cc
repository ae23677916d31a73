// com-outside-geometry (warning): the center of mass is outside the link's geometry.
//
// Evidence: the center of mass (in the link frame); the bounding box of the link's geometry, or
// of its welded group's known geometry when the center of mass lies outside the link's own (a
// mass lumped from welded neighbours: JudgeAgainstGeometry).
// Why: the center of mass of a body lies inside the convex hull of the body, hence inside its
// box. Simplified primitives may be smaller than the body: a center of mass is flagged only more
// than (kGeometryMargin − 1) half-diagonals outside the box; kMeshComMargin for a mesh read
// whole (a CAD envelope: a mirrored part's COM copied from its twin lies a box-width away);
// Allowance() times more where part of the geometry is of unknown size.

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kComOutsideGeometry = "com-outside-geometry";

}  // namespace

const RuleInfo& ComOutsideGeometryRule() {
  static const RuleInfo kInfo{
      kComOutsideGeometry, Severity::kWarning, true,
      "The center of mass is outside the bounding box of the link's geometry."};
  return kInfo;
}

void CheckComInsideGeometry(RuleContext& ctx, const JudgedLink& judged) {
  const Link& link = *judged.link;
  const GeometryBounds& group_bounds = *judged.group_bounds;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const double allowance = Allowance(group_bounds, /*for_inertia=*/false);
  const Eigen::Vector3d o = group_bounds.box_B.center();
  const Eigen::Vector3d h = 0.5 * group_bounds.box_B.sizes();
  const double scale2 = h.squaredNorm();
  const Eigen::Vector3d outside = ((c - o).cwiseAbs() - h).cwiseMax(Eigen::Vector3d::Zero());
  const double distance = outside.norm();
  const double margin =
      MarginOf(group_bounds) == kMeshGeometryMargin ? kMeshComMargin : kGeometryMargin - 1;
  const double allowed = allowance * margin * std::sqrt(scale2);
  if (!(distance - allowed > ctx.options.tolerance * std::sqrt(scale2))) return;
  ctx.Emit(kComOutsideGeometry, link, PoseLocation(link),
           judged.who + ": the center of mass " + Vec(c) + " is " + Num(distance) +
               " m outside the bounding box " + Vec(group_bounds.box_B.min()) + " to " +
               Vec(group_bounds.box_B.max()) + " of its " + judged.geometry_name +
               " geometry, farther than its half-diagonal " + Num(allowed) + " m",
           {{"com_x", c.x()},
            {"com_y", c.y()},
            {"com_z", c.z()},
            {"distance", distance},
            {"allowed", allowed}},
           LinkHeadline(link.name, ": center of mass " + FormatLength(distance) + " outside its " +
                                       judged.geometry_name + " (mirrored part?)"),
           {{"com_x_m", c.x()},
            {"com_y_m", c.y()},
            {"com_z_m", c.z()},
            {"outside_by_m", distance},
            {"allowed_by_m", allowed}},
           "write the part's center of mass (from CAD) in <inertial><origin xyz>");
}

}  // namespace rules
}  // namespace massprops
