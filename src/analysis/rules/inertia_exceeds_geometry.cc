// inertia-exceeds-geometry (warning): no mass distribution inside the link's geometry has this
// inertia.
//
// Evidence: the mass, center of mass c and inertia (in the link frame); the bounding box of the
// link's geometry (its welded group's when the center of mass lies outside its own: a mass
// lumped from welded neighbours), with the margins of rule_context.h (kGeometryMargin for
// simplified primitives, kMeshGeometryMargin for a mesh from CAD, more where part of the geometry
// is of unknown size); for a link whose own geometry is meshes read whole, the convex hull of
// their vertices (CheckOptions::points).
// Why: a body inside the box lies inside the box's circumscribed sphere (center o, radius r =
// half-diagonal), so ∫|x − o|² dm = tr(Σ_o) = ½·tr(I) + m·|c − o|² <= m·r² (Wensing, Kim, Slotine
// 2017, with the ellipsoid Q = r²·1). Where the numbers fit as the inertia about the link origin
// instead, inertia-about-origin-suspect is said (inertia_about_origin_suspect.cc). The hull bound:
// for each axis a through c, a body inside the hull of points P has I_a <= m · max_{p in P}
// |(p − c) × a|² (the squared distance to an axis is convex, so its maximum over the hull is at a
// vertex): far tighter than the sphere for a detailed CAD mesh.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaExceedsGeometry = "inertia-exceeds-geometry";

// The per-axis bound of the mesh hull (LinkGeometryPoints): a moment of inertia is flagged when
// it exceeds m · max over the hull of the squared distance to its axis by more than this factor
// (rounding of the written numbers and of float mesh vertices is far below it).
constexpr double kHullSlack = 1.1;

}  // namespace

const RuleInfo& InertiaExceedsGeometryRule() {
  static const RuleInfo kInfo{
      kInertiaExceedsGeometry, Severity::kWarning, true,
      "No mass distribution inside the link's geometry bounding box has this inertia."};
  return kInfo;
}

bool CheckInertiaFitsGeometry(RuleContext& ctx, const JudgedLink& judged) {
  const Link& link = *judged.link;
  const double m = link.inertial->mass;
  const double tol = ctx.options.tolerance;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const Eigen::Matrix3d& I_B = judged.props.I_SScm_F;
  GeometryRoom room;
  room.allowance =
      judged.collision_envelope ? 1.0 : Allowance(*judged.group_bounds, /*for_inertia=*/true);
  const Eigen::Vector3d o = judged.group_bounds->box_B.center();
  const Eigen::Vector3d h = 0.5 * judged.group_bounds->box_B.sizes();
  const double scale2 = h.squaredNorm();
  const std::string& geometry_kind = judged.geometry_name;
  room.margin = MarginOf(*judged.group_bounds);
  const double allowance = room.allowance, margin = room.margin;
  room.r2 = allowance * allowance * margin * margin * scale2;
  const double r2 = room.r2;
  room.d = c - o;
  // tr(Σ_o) = tr(Σ_cm) + m·|d|² = ½·tr(I) + m·|d|².
  room.spread = 0.5 * I_B.trace() + m * room.d.squaredNorm();
  room.bound = m * r2;
  const double spread = room.spread, bound = room.bound;
  if (!(spread - bound > tol * bound)) return false;
  if (CheckInertiaAboutOrigin(ctx, judged, room)) return true;
  ctx.Emit(kInertiaExceedsGeometry, link, InertiaLocation(link),
           judged.who + ": no mass distribution inside the bounding box of the " + geometry_kind +
               " geometry (center " + Vec(o) + ", half-sizes " + Vec(h) +
               " m) has this inertia: ∫|x - o|² dm = tr(I)/2 + m·|c - o|² = " + Num(spread) +
               " kg·m² exceeds m·r² = " + Num(bound) + " kg·m² (r = " + Num(allowance * margin) +
               " × half-diagonal = " + Num(std::sqrt(r2)) + " m, " +
               (margin == kMeshGeometryMargin ? "the mesh being the part's envelope"
                                              : "allowing for simplified geometry") +
               "; ratio " + Num(spread / bound) + ")",
           {{"spread", spread},
            {"bound", bound},
            {"ratio", spread / bound},
            {"half_diagonal", std::sqrt(r2)}},
           LinkHeadline(link.name, ": inertia " + FormatRatio(spread / bound) +
                                       " too large for its size (mass changed?)"),
           {{"polar_moment_kg_m2", spread},
            {"max_for_its_size_kg_m2", bound},
            {"ratio", spread / bound},
            {"allowed_radius_m", std::sqrt(r2)}},
           "recompute the inertia for this mass (from CAD, or massprops fix --from-geometry)");
  return true;
}

void CheckInertiaFitsHull(RuleContext& ctx, const JudgedLink& judged) {
  if (!ctx.options.points || !judged.bounds || !judged.bounds->from_mesh ||
      judged.bounds->partial || !judged.group_bounds || judged.group_bounds->partial) {
    return;
  }
  // Judged against the group's geometry (a mass lumped from welded neighbours): not here.
  if (!judged.group_bounds->box_B.isApprox(judged.bounds->box_B)) return;
  const Link& link = *judged.link;
  const std::optional<LinkGeometryPoints> points = ctx.options.points(link);
  if (!points || points->unknown > 0 || points->meshes == 0 || points->empty()) return;
  const double m = link.inertial->mass;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const Eigen::Matrix3d& I = judged.props.I_SScm_F;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
  if (eig.info() != Eigen::Success) return;
  // The six axes: the principal axes and those of the frame. The farthest point from each is
  // found in one pass over the points (the points of a robot's meshes are many; one pass reads
  // them from memory once, not six times).
  std::array<Eigen::Vector3d, 6> axes;
  for (int i = 0; i < 6; ++i) {
    axes[i] = i < 3 ? Eigen::Vector3d(eig.eigenvectors().col(i).normalized())
                    : Eigen::Vector3d(Eigen::Vector3d::Unit(i - 3));
  }
  // About a frame axis the squared distance is the sum of two squared coordinates: r × x̂ is
  // (±0, r_z, -r_y) exactly, so |r × x̂|² = r_z² + r_y², the same number in fewer operations.
  std::array<double, 6> reach2{};
  points->ForEachPoint([&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d r = p - c;
    for (int i = 0; i < 3; ++i) reach2[i] = std::max(reach2[i], r.cross(axes[i]).squaredNorm());
    const double xx = r.x() * r.x(), yy = r.y() * r.y(), zz = r.z() * r.z();
    reach2[3] = std::max(reach2[3], yy + zz);
    reach2[4] = std::max(reach2[4], xx + zz);
    reach2[5] = std::max(reach2[5], xx + yy);
  });
  double worst = 0, worst_moment = 0, worst_bound = 0;
  Eigen::Vector3d worst_axis = Eigen::Vector3d::UnitX();
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d& a = axes[i];
    const double moment = a.dot(I * a);
    const double bound = m * reach2[i];
    if (!(bound > 0)) continue;
    if (moment / bound > worst) {
      worst = moment / bound;
      worst_moment = moment;
      worst_bound = bound;
      worst_axis = a;
    }
  }
  if (!(worst > kHullSlack)) return;
  ctx.Emit(kInertiaExceedsGeometry, link, InertiaLocation(link),
           judged.who + ": no mass distribution inside the convex hull of its " +
               judged.geometry_name + " (" + std::to_string(points->meshes) + " mesh" +
               (points->meshes == 1 ? "" : "es") + ", " + std::to_string(points->count) +
               " points) has this inertia: about the axis " + Vec(worst_axis) +
               " through the center of mass " + Vec(c) + " the moment is " + Num(worst_moment) +
               " kg·m², but the hull allows at most m · (farthest point from that axis)² = " +
               Num(worst_bound) + " kg·m² (ratio " + Num(worst) +
               "): the mass was probably changed without its inertia, or the inertia comes from "
               "another part",
           {{"moment", worst_moment}, {"hull_bound", worst_bound}, {"ratio", worst}},
           LinkHeadline(link.name, ": inertia " + FormatRatio(worst) + " too large for its " +
                                       judged.geometry_name + " hull (mass changed?)"),
           {{"worst_axis_moment_kg_m2", worst_moment},
            {"max_for_its_hull_kg_m2", worst_bound},
            {"ratio", worst}},
           "recompute the inertia for this mass (from CAD, or massprops fix --from-geometry)");
}

}  // namespace rules
}  // namespace massprops
