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
// vertex): far tighter than the sphere for a detailed CAD mesh. Over primitives as placed, the
// same per-axis bound, and the second moment along a direction u: Σ = ½·tr(I)·1 − I is
// ∫(x − c)(x − c)ᵀ dm, so uᵀΣu = ∫(u·(x − c))² dm <= m · max over the primitives of
// (u·(x − c))²: tight for a flat part (a wheel), where the moments are loose.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "analysis/rules/rules.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/link_measure.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaExceedsGeometry = "inertia-exceeds-geometry";

// The per-axis bound of the mesh hull (LinkGeometryPoints): a moment of inertia is flagged when
// it exceeds m · max over the hull of the squared distance to its axis by more than this factor
// (rounding of the written numbers and of float mesh vertices is far below it).
constexpr double kHullSlack = 1.1;
// The same bound over the corners of primitives: they are often simpler and smaller than the
// body (a cylinder around the motor of a longer casting), so a moment is flagged only beyond
// kGeometryMargin² times what they allow: a body reaching twice farther from every axis, the
// allowance the bounding sphere gives them too.
constexpr double kPrimitiveAxisSlack = kGeometryMargin * kGeometryMargin;
// Where the moments together fit the primitives (the trace within the sum of the three frame
// axes' bounds: the part's size is right) but one moment exceeds its axis's bound, the mass sits
// about the wrong axis: a tensor written for the part before it was turned. Then twice the bound
// is reported (a body reaching sqrt(2) times farther from that axis): a 0.4 × 0.1 × 0.1 m box
// turned 90° with the unrotated tensor has (0.4² + 0.1²)/12 against (0.05² + 0.05²), 2.83 times,
// while its trace is 1/3 of the bounds' sum.
constexpr double kTurnedAxisSlack = 2;
// A tensor whose largest principal moment is within this factor of its smallest is the same in
// every orientation (to the rounding of typed-in numbers): turning the part cannot explain it.
constexpr double kAnisotropic = 1.1;
// The second moment along a direction, ∫(u·(x − c))² dm, is flagged beyond this factor of
// m · (farthest point of the primitives from c along u)²: the primitives' allowance for a body
// that reaches twice farther (as kPrimitiveAxisSlack). It is judged for isotropic tensors only
// (all principal moments within kAnisotropic: the same number typed on every axis), the
// signature of a placeholder; docs/labels.md gives the measurement that keeps it there.
constexpr double kPrimitiveSpreadSlack = kGeometryMargin * kGeometryMargin;

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

namespace {

// The axis through the center of mass about which the moment of inertia most exceeds what the
// points allow, m · (farthest point from that axis)²: over the three principal axes and the
// three axes of the link frame.
struct WorstAxis {
  double ratio = 0, moment = 0, bound = 0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  double frame_bounds = 0;  // the sum of the bounds about the three axes of the frame
};

std::optional<WorstAxis> FindWorstAxis(const LinkGeometryPoints& points, double m,
                                       const Eigen::Vector3d& c, const Eigen::Matrix3d& I) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
  if (eig.info() != Eigen::Success) return std::nullopt;
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
  points.ForEachPoint([&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d r = p - c;
    for (int i = 0; i < 3; ++i) reach2[i] = std::max(reach2[i], r.cross(axes[i]).squaredNorm());
    const double xx = r.x() * r.x(), yy = r.y() * r.y(), zz = r.z() * r.z();
    reach2[3] = std::max(reach2[3], yy + zz);
    reach2[4] = std::max(reach2[4], xx + zz);
    reach2[5] = std::max(reach2[5], xx + yy);
  });
  WorstAxis worst;
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d& a = axes[i];
    const double moment = a.dot(I * a);
    const double bound = m * reach2[i];
    if (!(bound > 0)) continue;
    if (moment / bound > worst.ratio) worst = {moment / bound, moment, bound, a, 0};
  }
  worst.frame_bounds = m * (reach2[3] + reach2[4] + reach2[5]);
  return worst;
}

// The corners of a primitive's own box (its extent along its own axes), posed in the link frame
// by its origin: their convex hull holds the primitive whatever its orientation (a box turned
// 90° by its <origin rpy> is the box as placed). False for a mesh, an unknown type or a size
// that is not finite and non-negative.
bool AddPrimitiveCorners(const Geometry& g, std::vector<Eigen::Vector3d>* corners) {
  Eigen::Vector3d h;
  switch (g.type) {
    case Geometry::Type::kBox:
      h = 0.5 * g.size;
      break;
    case Geometry::Type::kCylinder:
      h = Eigen::Vector3d(g.radius, g.radius, 0.5 * g.length);
      break;
    case Geometry::Type::kCapsule:
      h = Eigen::Vector3d(g.radius, g.radius, 0.5 * g.length + g.radius);
      break;
    case Geometry::Type::kSphere:
      h = Eigen::Vector3d::Constant(g.radius);
      break;
    case Geometry::Type::kEllipsoid:
      h = g.radii;
      break;
    default:
      return false;
  }
  if (!h.allFinite() || (h.array() < 0).any() || !g.X_BG.p_AB.allFinite() ||
      !g.X_BG.R_AB.allFinite()) {
    return false;
  }
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d s((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
    corners->push_back(g.X_BG.p_AB + g.X_BG.R_AB * s.cwiseProduct(h));
  }
  return true;
}

// The primitives that are a link's envelope (its collision alone when the collision is its
// envelope and its visual is of unknown size), and the points whose hull holds them: nullopt
// when some of them is a mesh or of unknown size.
struct EnvelopePrimitives {
  std::vector<const Geometry*> shapes;
  LinkGeometryPoints points;
};

std::optional<EnvelopePrimitives> FindEnvelopePrimitives(const JudgedLink& judged) {
  const bool collision_only = judged.collision_envelope && judged.bounds->partial;
  EnvelopePrimitives found;
  for (const Geometry& g : judged.link->geometries) {
    if (collision_only && !g.is_collision) continue;
    if (!AddPrimitiveCorners(g, &found.points.corners_B)) return std::nullopt;
    found.shapes.push_back(&g);
  }
  if (found.shapes.empty()) return std::nullopt;
  found.points.count = found.points.corners_B.size();
  return found;
}

// The direction u along which the inertia spreads the mass farthest beyond what the primitives
// allow: ∫(u·(x − c))² dm = uᵀΣu, Σ = ½·tr(I)·1 − I, at most m · max over the primitives of
// (u·(x − c))². Over the principal axes of I (those of Σ) and each primitive's axes as placed.
struct WorstSpread {
  double ratio = 0, second_moment = 0, bound = 0, width = 0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
};

std::optional<WorstSpread> FindWorstSpread(const std::vector<const Geometry*>& shapes, double m,
                                           const Eigen::Vector3d& c, const Eigen::Matrix3d& I) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
  if (eig.info() != Eigen::Success) return std::nullopt;
  std::vector<Eigen::Vector3d> directions;
  for (int i = 0; i < 3; ++i) directions.emplace_back(eig.eigenvectors().col(i).normalized());
  for (const Geometry* g : shapes) {
    for (int i = 0; i < 3; ++i) directions.emplace_back(g->X_BG.R_AB.col(i).normalized());
  }
  WorstSpread worst;
  for (const Eigen::Vector3d& u : directions) {
    double reach = 0, low = HUGE_VAL, high = -HUGE_VAL;
    for (const Geometry* g : shapes) {
      const double middle = u.dot(g->X_BG.p_AB - c);
      const double half = HalfWidthAlong(*g, g->X_BG.R_AB.transpose() * u);
      reach = std::max(reach, std::abs(middle) + half);
      low = std::min(low, middle - half);
      high = std::max(high, middle + half);
    }
    const double second_moment = 0.5 * I.trace() - u.dot(I * u);
    const double bound = m * reach * reach;
    if (!(bound > 0)) continue;
    if (second_moment / bound > worst.ratio) {
      worst = {second_moment / bound, second_moment, bound, high - low, u};
    }
  }
  return worst;
}

// A welded part whose inertia is less than kMadeUpInertiaShare of its welded group's central
// inertia changes nothing the group does (a 15 g sensor tube on an airframe): its numbers are
// not judged axis by axis. A link alone in its group always weighs.
bool WeighsInItsGroup(const RuleContext& ctx, const JudgedLink& judged) {
  const WeldedGroup& group = ctx.GroupOf(judged.index);
  if (group.links.size() < 2) return true;
  const double total = ctx.GroupComposite(ctx.group_of[judged.index]).I_SScm_R.trace();
  if (!std::isfinite(total) || !(total > 0)) return true;
  return judged.props.I_SScm_F.trace() >= kMadeUpInertiaShare * total;
}

}  // namespace

void CheckInertiaFitsHull(RuleContext& ctx, const JudgedLink& judged) {
  if (!judged.bounds || !judged.group_bounds || judged.group_bounds->partial) return;
  // Judged against the group's geometry (a mass lumped from welded neighbours): not here.
  if (!judged.group_bounds->box_B.isApprox(judged.bounds->box_B)) return;
  if (!judged.bounds->from_mesh) {
    CheckInertiaFitsPrimitives(ctx, judged);
    return;
  }
  if (!ctx.options.points || judged.bounds->partial) return;
  const Link& link = *judged.link;
  const std::optional<LinkGeometryPoints> points = ctx.options.points(link);
  if (!points || points->unknown > 0 || points->meshes == 0 || points->empty()) return;
  const double m = link.inertial->mass;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const std::optional<WorstAxis> found = FindWorstAxis(*points, m, c, judged.props.I_SScm_F);
  if (!found || !(found->ratio > kHullSlack)) return;
  const WorstAxis& worst = *found;
  ctx.Emit(kInertiaExceedsGeometry, link, InertiaLocation(link),
           judged.who + ": no mass distribution inside the convex hull of its " +
               judged.geometry_name + " (" + std::to_string(points->meshes) + " mesh" +
               (points->meshes == 1 ? "" : "es") + ", " + std::to_string(points->count) +
               " points) has this inertia: about the axis " + Vec(worst.axis) +
               " through the center of mass " + Vec(c) + " the moment is " + Num(worst.moment) +
               " kg·m², but the hull allows at most m · (farthest point from that axis)² = " +
               Num(worst.bound) + " kg·m² (ratio " + Num(worst.ratio) +
               "): the mass was probably changed without its inertia, or the inertia comes from "
               "another part",
           {{"moment", worst.moment}, {"hull_bound", worst.bound}, {"ratio", worst.ratio}},
           LinkHeadline(link.name, ": inertia " + FormatRatio(worst.ratio) + " too large for its " +
                                       judged.geometry_name + " hull (mass changed?)"),
           {{"worst_axis_moment_kg_m2", worst.moment},
            {"max_for_its_hull_kg_m2", worst.bound},
            {"ratio", worst.ratio}},
           "recompute the inertia for this mass (from CAD, or massprops fix --from-geometry)");
}

namespace {

void EmitSpread(RuleContext& ctx, const JudgedLink& judged, const std::string& geometry,
                const WorstSpread& worst) {
  const Link& link = *judged.link;
  ctx.Emit(
      kInertiaExceedsGeometry, link, InertiaLocation(link),
      judged.who + ": along the direction " + Vec(worst.axis) +
          " the inertia spreads the mass by ∫(u·(x - c))² dm = tr(I)/2 - uᵀIu = " +
          Num(worst.second_moment) + " kg·m² about the center of mass " +
          Vec(judged.props.p_FoScm_F) + ", but the " + geometry + " primitives as placed are " +
          Num(worst.width) +
          " m wide along it, so a body inside them has at most m · (farthest point from "
          "the center of mass along it)² = " +
          Num(worst.bound) + " kg·m² (ratio " + Num(worst.ratio) + ", allowed " +
          Num(kPrimitiveSpreadSlack) +
          " for simplified geometry: a typed-in placeholder, such as the same moment on "
          "every axis of a wheel or caster)",
      {{"second_moment", worst.second_moment},
       {"width_bound", worst.bound},
       {"ratio", worst.ratio}},
      LinkHeadline(link.name, ": inertia " + FormatRatio(worst.ratio) + " too spread along its " +
                                  FormatLength(worst.width) + " width (typed-in placeholder?)"),
      {{"second_moment_kg_m2", worst.second_moment},
       {"max_for_its_width_kg_m2", worst.bound},
       {"ratio", worst.ratio},
       {"width_m", worst.width},
       {"axis_x", worst.axis.x()},
       {"axis_y", worst.axis.y()},
       {"axis_z", worst.axis.z()}},
      "recompute the inertia for this part (from CAD, or massprops fix --from-geometry)");
}

void EmitAxisMoment(RuleContext& ctx, const JudgedLink& judged, const std::string& geometry,
                    const WorstAxis& worst, bool turned, double allowed) {
  const Link& link = *judged.link;
  ctx.Emit(
      kInertiaExceedsGeometry, link, InertiaLocation(link),
      judged.who + ": about the axis " + Vec(worst.axis) + " through the center of mass " +
          Vec(judged.props.p_FoScm_F) + " the moment of inertia is " + Num(worst.moment) +
          " kg·m², but a body inside the " + geometry +
          " primitives as placed (their origins' rotations applied) has at most m · "
          "(farthest corner from that axis)² = " +
          Num(worst.bound) + " kg·m² about it (ratio " + Num(worst.ratio) + ", allowed " +
          Num(allowed) +
          (turned ? ": the moments together fit the part, so the mass sits about the wrong "
                    "axis: an inertia written for the part before it was turned)"
                  : " for simplified geometry: an inertia for a larger part, or typed in)"),
      {{"moment", worst.moment}, {"axis_bound", worst.bound}, {"ratio", worst.ratio}},
      LinkHeadline(link.name, ": axis moment " + FormatRatio(worst.ratio) + " what its " +
                                  geometry + " allows" +
                                  (turned ? " (tensor not rotated?)" : " (typed-in inertia?)")),
      {{"moment_kg_m2", worst.moment},
       {"axis_bound_kg_m2", worst.bound},
       {"ratio", worst.ratio},
       {"axis_x", worst.axis.x()},
       {"axis_y", worst.axis.y()},
       {"axis_z", worst.axis.z()}},
      turned ? "rotate the inertia as the geometry is placed (R·I·Rᵀ), or massprops fix "
               "--from-geometry"
             : "recompute the inertia for this part (from CAD, or massprops fix --from-geometry)");
}

// Whether the link belongs to the world: its welded group does not move and holds a URDF root
// link named "world" (fixed to the world by Gazebo's and PyBullet's convention, a massless base),
// an SDF link fixed to the world, or an MJCF worldbody's part. Its inertia never enters the
// dynamics (static scenery: a door's frame), so a placeholder there changes nothing.
bool PartOfTheWorld(const RuleContext& ctx, const JudgedLink& judged) {
  const WeldedGroup& group = ctx.GroupOf(judged.index);
  if (group.is_moving) return false;
  if (ctx.model.format == Model::Format::kMjcf) return true;
  if (ctx.model.format == Model::Format::kUrdf && group.root_link == "world") return true;
  return ctx.GroupWeldedToWorld(ctx.group_of[judged.index]);
}

}  // namespace

// Two bounds over the primitives as placed, one finding: the moment about an axis (a tensor
// written for the part before it was turned) and the second moment along a direction (an
// inertia spread wider than a flat part: a placeholder on a wheel); the one exceeded by more
// (its ratio over its allowance) is reported.
void CheckInertiaFitsPrimitives(RuleContext& ctx, const JudgedLink& judged) {
  if (judged.bounds->marker || (judged.bounds->partial && !judged.collision_envelope)) return;
  // A stub around one joint of a body that reaches to the next (a motor's cylinder on a link
  // whose child joint is 10 cm away) is not the body's envelope.
  if (!ctx.JointsWithin(judged.index, *judged.bounds)) return;
  if (!WeighsInItsGroup(ctx, judged)) return;
  const std::optional<EnvelopePrimitives> primitives = FindEnvelopePrimitives(judged);
  if (!primitives) return;
  const double m = judged.link->inertial->mass;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const Eigen::Matrix3d& I = judged.props.I_SScm_F;
  const std::optional<WorstAxis> axis = FindWorstAxis(primitives->points, m, c, I);
  const std::optional<WorstSpread> spread = FindWorstSpread(primitives->shapes, m, c, I);
  if (!axis || !spread) return;
  // An isotropic tensor (a typed-in 1, 1, 1) is the same in every orientation: not a turned one.
  const Validity moments = Analyze(I);
  const bool anisotropic = moments.moments(2) > kAnisotropic * moments.moments(0);
  const bool turned = anisotropic && I.trace() <= axis->frame_bounds;
  const double allowed = turned ? kTurnedAxisSlack : kPrimitiveAxisSlack;
  const double axis_excess = axis->ratio / allowed;
  // Beyond the allowance by more than the tolerance (a 5 cm box with the moment typed for a
  // body reaching 5 cm is exactly 4 times, not beyond it); isotropic tensors only, and not on
  // static scenery.
  const double spread_excess =
      anisotropic || PartOfTheWorld(ctx, judged)
          ? 0
          : spread->ratio / (kPrimitiveSpreadSlack * (1 + ctx.options.tolerance));
  if (!(axis_excess > 1) && !(spread_excess > 1)) return;
  const std::string geometry =
      judged.collision_envelope && judged.bounds->partial ? "collision" : judged.geometry_name;
  if (spread_excess > axis_excess) {
    EmitSpread(ctx, judged, geometry, *spread);
  } else {
    EmitAxisMoment(ctx, judged, geometry, *axis, turned, allowed);
  }
}

}  // namespace rules
}  // namespace massprops
