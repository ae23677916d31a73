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
// A welded part's center of mass left at its frame's origin (written exactly (0, 0, 0)) while
// its own geometry, known whole, lies elsewhere: a number never written, so no allowance for
// simplified geometry is due, only the margin of a whole mesh (kLeftAtOriginMargin). The origin
// often lies inside the welded neighbours' geometry, but it is no mass lumped from them when they
// carry their own (at least as much as this part): it is judged against the part's own geometry
// (LeftAtOrigin).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kComOutsideGeometry = "com-outside-geometry";

// A center of mass left at the origin is reported when the origin lies farther than this many of
// the own geometry's half-diagonals outside its box (the margin of a whole CAD mesh: an origin a
// few millimetres off a 4 cm part is a frame placed on its face), and at least kLeftAtOriginMin.
constexpr double kLeftAtOriginMargin = kMeshComMargin;
constexpr double kLeftAtOriginMin = 0.01;  // metres

// The distance from the origin to the box of the part's own geometry, when link `judged` is a
// welded part whose center of mass was left at its frame's origin (see the file comment), else
// nullopt.
std::optional<double> LeftAtOrigin(const RuleContext& ctx, const JudgedLink& judged) {
  const Link& link = *judged.link;
  if (!judged.props.p_FoScm_F.isZero(0) || !judged.bounds || judged.bounds->partial ||
      judged.bounds->marker) {
    return std::nullopt;
  }
  const WeldedGroup& group = ctx.GroupOf(judged.index);
  if (group.links.size() < 2) return std::nullopt;  // a welded part
  double others = 0;
  for (int l : group.links) {
    if (l == judged.index) continue;
    const Link& member = ctx.model.links[l];
    if (member.inertial && member.inertial->mass > 0) others += member.inertial->mass;
  }
  // A mass lumped onto this link from its neighbours (they carry less than it does) may sit
  // anywhere in their geometry.
  if (!(others >= link.inertial->mass)) return std::nullopt;
  const Eigen::AlignedBox3d& box = judged.bounds->box_B;
  const Eigen::Vector3d h = 0.5 * box.sizes();
  const double distance =
      (box.center().cwiseAbs() - h).cwiseMax(Eigen::Vector3d::Zero()).norm();
  if (!(distance > std::max(kLeftAtOriginMin, kLeftAtOriginMargin * h.norm()))) {
    return std::nullopt;
  }
  return distance;
}

void ReportLeftAtOrigin(RuleContext& ctx, const JudgedLink& judged, double distance) {
  const Link& link = *judged.link;
  const Eigen::AlignedBox3d& box = judged.bounds->box_B;
  const double allowed =
      std::max(kLeftAtOriginMin, kLeftAtOriginMargin * 0.5 * box.diagonal().norm());
  const std::string geometry = std::string(judged.bounds->from_collision ? "collision" : "visual") +
                               (judged.bounds->from_mesh ? " mesh" : "");
  ctx.Emit(kComOutsideGeometry, link, PoseLocation(link),
           judged.who + ": the center of mass is left at the link origin (0, 0, 0), " +
               Num(distance) + " m outside the bounding box " + Vec(box.min()) + " to " +
               Vec(box.max()) + " of its own " + geometry +
               " geometry (allowed " + Num(allowed) +
               " m); the welded links around it carry their own mass, so it is no mass lumped "
               "from them: the part's center of mass was never written",
           {{"com_x", 0}, {"com_y", 0}, {"com_z", 0}, {"distance", distance}, {"allowed", allowed}},
           LinkHeadline(link.name, ": center of mass left at (0, 0, 0), " +
                                       FormatLength(distance) + " outside its " + geometry),
           {{"outside_by_m", distance},
            {"allowed_m", allowed},
            {"box_center_x_m", box.center().x()},
            {"box_center_y_m", box.center().y()},
            {"box_center_z_m", box.center().z()}},
           "write the part's center of mass (from CAD) in <inertial><origin xyz>");
}

}  // namespace

const RuleInfo& ComOutsideGeometryRule() {
  static const RuleInfo kInfo{
      kComOutsideGeometry, Severity::kWarning, true,
      "The center of mass is outside the bounding box of the link's geometry."};
  return kInfo;
}

void CheckComInsideGeometry(RuleContext& ctx, const JudgedLink& judged) {
  const Link& link = *judged.link;
  if (const std::optional<double> distance = LeftAtOrigin(ctx, judged)) {
    ReportLeftAtOrigin(ctx, judged, *distance);
    return;
  }
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
