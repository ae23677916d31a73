// What a mass can do inside its own geometry (issue 49): the bounds that any non-negative density
// inside the convex hull K of a link's whole geometry (collision and visual, primitives and
// meshes as placed) puts on its mass m, center of mass c and inertia, judged from one
// measurement of K (MeasureLink, include/massprops/analysis/link_measure.h).
//
// density-implausible: m <= ρ·volume(K), with ρ osmium's (the densest element: above it no body of
// that mass fits inside K) or, where K is drawn by meshes (the part as exported), 1.1 × lead's
// (no robot part is that dense: a mass typed for more than the drawn part). Primitives are
// simplified envelopes: K grown kGeometryMargin times (8 times its volume), osmium only.
//
// inertia-beyond-hull (off by default: docs/rules.md gives the labelled robots' figures), two
// bounds, the larger excess reported:
// - per direction u (Bhatia–Davis): ∫(u·(x − c))² dm <= m·(h_K(u) − u·c)·(u·c + h_K(−u)), over
//   the principal axes, the frame's and the primitives' axes, the hull's face normals and 128
//   directions covering the sphere (WorstDirection);
// - the bounding ellipsoid E ⊇ K (Wensing, Kim, Slotine, IEEE RA-L 2018): tr(J·Q̃) >= 0, i.e.
//   tr(Q⁻¹(Σ + m(c − x0)(c − x0)ᵀ)) <= m (EllipsoidRatio);
// K grown kMeshGeometryMargin times about its box's center for meshes (a decimated mesh lies
// inside the part), kGeometryMargin times for primitives.
//
// Judged where the geometry is the link's own body: every geometry known, not a marker or a
// placeholder, the center of mass within the link's own geometry (not a mass lumped from welded
// neighbours, whose box is their group's), a real mass. The bounds are necessary conditions:
// any density inside K meets them (tests/link_measure_test.cc, random point masses in random
// convex bodies).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/rules/rules.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/link_measure.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaBeyondHull = "inertia-beyond-hull";
constexpr const char* kDensityImplausible = "density-implausible";
// Where the center of mass is within this share of K's width of a face along u, the help says it
// sits on that face (the bound there is near 0 whatever the spread).
constexpr double kOnFaceShare = 0.05;

// "x", "y" or "z" for a direction within 0.1° of a frame axis; else its components to two
// digits: a headline's direction, read at a glance.
std::string AxisName(const Eigen::Vector3d& u) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(u(i)) > 0.999998) return std::string(1, static_cast<char>('x' + i));
  }
  return "(" + FormatSignificant(u.x(), 2) + ", " + FormatSignificant(u.y(), 2) + ", " +
         FormatSignificant(u.z(), 2) + ")";
}

// Whether the center of mass sits on a face of K along d.u: within kOnFaceShare of K's width.
bool OnFace(const DirectionBound& d) {
  const double width = d.ahead_in_K + d.behind_in_K;
  return width > 0 && std::min(d.ahead_in_K, d.behind_in_K) <= kOnFaceShare * width;
}

void EmitDirection(RuleContext& ctx, const JudgedLink& judged, const LinkMeasure& measure,
                   const DirectionBound& d, double scale) {
  const Link& link = *judged.link;
  const std::string geometry = measure.has_mesh ? "geometry" : "primitives";
  ctx.Emit(
      kInertiaBeyondHull, link, InertiaLocation(link),
      judged.who + ": along " + Vec(d.u) + " the mass spreads ∫(u·(x - c))² dm = " +
          Num(d.second_moment) + " kg·m² about the center of mass " + Vec(judged.props.p_FoScm_F) +
          ", but its " + geometry + (scale > 1 ? " (grown " + Num(scale) + " times)" : "") +
          " reach " + Num(d.ahead) + " m ahead of it and " + Num(d.behind) +
          " m behind it, so a mass inside has at most m·" + Num(d.ahead) + "·" + Num(d.behind) +
          " = " + Num(d.bound) + " kg·m² (Bhatia–Davis; ratio " + Num(d.ratio) + ")",
      {{"second_moment", d.second_moment}, {"direction_bound", d.bound}, {"ratio", d.ratio}},
      LinkHeadlineFirstFit(
          link.name,
          {": spread " + FormatSignificant(d.second_moment, 2) + " kg·m² along " + AxisName(d.u) +
               ", at most " + FormatSignificant(d.bound, 2) + " inside its " + geometry,
           ": inertia " + FormatRatio(d.ratio) + " the spread its " + geometry + " allows"}),
      {{"spread_kg_m2", d.second_moment},
       {"max_inside_geometry_kg_m2", d.bound},
       {"ratio", d.ratio},
       {"room_ahead_m", d.ahead_in_K},
       {"room_behind_m", d.behind_in_K}},
      OnFace(d) ? "COM on the part's face, tensor about its middle: recompute both from CAD"
                : "recompute the inertia for this part (from CAD, or massprops fix "
                  "--from-geometry)");
}

void EmitEllipsoid(RuleContext& ctx, const JudgedLink& judged, double ratio, double scale) {
  const Link& link = *judged.link;
  ctx.Emit(kInertiaBeyondHull, link, InertiaLocation(link),
           judged.who + ": no mass inside the least ellipsoid around its geometry" +
               (scale > 1 ? " (grown " + Num(scale) + " times)" : "") +
               " has this inertia: tr(Q⁻¹(Σ + m(c - x0)(c - x0)ᵀ))/m = " + Num(ratio) +
               ", at most 1 inside it (Wensing, Kim, Slotine 2018, tr(J·Q) >= 0)",
           {{"ellipsoid_ratio", ratio}},
           LinkHeadline(link.name, ": inertia " + FormatRatio(ratio) +
                                       " what its geometry's bounding ellipsoid allows"),
           {{"ratio", ratio}},
           "recompute the inertia for this part (from CAD, or massprops fix --from-geometry)");
}

// density-implausible over the hull's volume; returns whether it was flagged.
bool CheckMassFitsVolume(RuleContext& ctx, const JudgedLink& judged, const LinkMeasure& measure) {
  const Link& link = *judged.link;
  const double m = link.inertial->mass;
  // Primitives may stand for a body reaching kGeometryMargin times farther (a 1 cm box for a
  // camera): their hull grown so, and only osmium's bound.
  const double growth = measure.has_mesh ? 1 : kGeometryMargin * kGeometryMargin * kGeometryMargin;
  const double volume = growth * measure.volume;
  if (!(volume > 0) || !ctx.RuleOn(kDensityImplausible)) return false;
  const double rho = m / volume;
  const bool impossible = rho > kOsmiumDensity;
  if (!impossible && !(measure.has_mesh && rho > kDenseMargin * kLeadDensity)) return false;
  const std::string what = impossible ? "osmium's 22590 kg/m³, the densest element"
                                      : Num(kDenseMargin) + " times lead's 11340 kg/m³";
  ctx.Emit(
      kDensityImplausible, link, MassLocation(link),
      judged.who + ": mass " + Num(m) + " kg over the volume " + Num(volume) +
          " m³ of the convex hull of its whole geometry" +
          (measure.has_mesh ? "" : " (its primitives grown " + Num(kGeometryMargin) + " times)") +
          " is " + Num(rho) + " kg/m³, above " + what +
          (impossible ? ": no body of this mass fits inside it"
                      : ": no robot part is that dense (a mass typed for more than the "
                        "drawn part, or in the wrong unit?)"),
      {{"mass", m}, {"hull_volume", volume}, {"density", rho}},
      LinkHeadlineFirstFit(link.name,
                           {": " + FormatSignificant(rho) + " kg/m³ over its geometry's hull, " +
                                (impossible ? "denser than osmium" : "denser than lead"),
                            std::string(": denser than ") + (impossible ? "osmium" : "lead")}),
      {{"mass_kg", m},
       {"hull_volume_m3", volume},
       {"density_kg_m3", rho},
       {"mass_if_steel_kg", 7850 * volume}},
      "write the weighed mass, or run massprops fix --material LINK=NAME");
  return true;
}

// Whether the mass over the hull of the link's geometry may exceed CheckMassFitsVolume's
// thresholds: false when it does not even over a volume inside the hull (InnerVolume), so that
// the hull itself is built only for the few links that may be too dense.
bool MayBeTooDense(const Link& link, const std::optional<LinkGeometryPoints>& points) {
  const bool has_mesh =
      std::any_of(link.geometries.begin(), link.geometries.end(),
                  [](const Geometry& g) { return g.type == Geometry::Type::kMesh; });
  const double growth = has_mesh ? 1 : kGeometryMargin * kGeometryMargin * kGeometryMargin;
  const double threshold = has_mesh ? kDenseMargin * kLeadDensity : kOsmiumDensity;
  const double inner = growth * InnerVolume(link, points);
  return !(inner > 0) || link.inertial->mass / inner > threshold;
}

}  // namespace

void CheckDensityRealizable(RuleContext& ctx, const JudgedLink& judged) {
  const bool inertia_on = ctx.RuleOn(kInertiaBeyondHull);
  if (!inertia_on && !ctx.RuleOn(kDensityImplausible)) return;
  if (!judged.bounds || !judged.group_bounds || judged.bounds->partial || judged.bounds->marker) {
    return;
  }
  // A mass lumped from welded neighbours is judged against their group's geometry: not here.
  if (!judged.group_bounds->box_B.isApprox(judged.bounds->box_B)) return;
  // A tensor of exactly zero is a point mass written so on purpose: its geometry is a marker (a
  // 5 mm cylinder at a tool frame).
  if (judged.props.I_SScm_F.isZero(0)) return;
  const Link& link = *judged.link;
  std::optional<LinkGeometryPoints> points;
  if (ctx.options.points) points = ctx.options.points(link);
  if (!inertia_on && !MayBeTooDense(link, points)) return;
  const LinkMeasure measure = MeasureLink(link, points, /*ellipsoid=*/inertia_on);
  if (!measure.whole) return;
  ++ctx.stats.link_measures;
  if (CheckMassFitsVolume(ctx, judged, measure) || !inertia_on || !judged.valid) return;
  const double m = link.inertial->mass;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const Eigen::Matrix3d& I = judged.props.I_SScm_F;
  const Eigen::Matrix3d Sigma = 0.5 * I.trace() * Eigen::Matrix3d::Identity() - I;
  const double scale = measure.has_mesh ? kMeshGeometryMargin : kGeometryMargin;
  const double slack = 1 + ctx.options.tolerance;
  const DirectionBound direction = WorstDirection(measure, m, c, Sigma, scale);
  const double ellipsoid = EllipsoidRatio(measure, m, c, Sigma, scale);
  const double direction_excess = direction.ratio / slack;
  const double ellipsoid_excess = std::isfinite(ellipsoid) ? ellipsoid / slack : 0;
  if (!(direction_excess > 1) && !(ellipsoid_excess > 1)) return;
  if (direction_excess >= ellipsoid_excess) {
    EmitDirection(ctx, judged, measure, direction, scale);
  } else {
    EmitEllipsoid(ctx, judged, ellipsoid, scale);
  }
}

const RuleInfo& InertiaBeyondHullRule() {
  static const RuleInfo kInfo{
      kInertiaBeyondHull, Severity::kWarning, false,
      "No density inside the convex hull of the link's geometry has this inertia: along some "
      "direction, or by the hull's bounding ellipsoid (off by default: --severity "
      "inertia-beyond-hull=warning)."};
  return kInfo;
}

}  // namespace rules
}  // namespace massprops
