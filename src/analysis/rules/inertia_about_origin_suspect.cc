// inertia-about-origin-suspect (warning): the inertia looks like it is about the link origin
// rather than the center of mass.
//
// Evidence: the mass, center of mass c and inertia as CheckInertiaFitsGeometry
// (inertia_exceeds_geometry.cc) found them too large for the link's geometry, and that
// geometry's room (the sphere about its box center).
// Why: URDF and SDF want the inertia about the center of mass; an inertia written about the link
// origin Bo carries the extra m·(|c|²·1 − c·cᵀ) of the parallel-axis theorem, so it needs more
// room than the body has. When the numbers, taken as the inertia about Bo and shifted to the
// center of mass (I_Bcm = I − m·(|c|²·1 − c·cᵀ)), are valid and fit the room, that is the
// likelier reading than a body too large for its geometry (inertia-exceeds-geometry).

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaAboutOriginSuspect = "inertia-about-origin-suspect";

}  // namespace

const RuleInfo& InertiaAboutOriginSuspectRule() {
  static const RuleInfo kInfo{
      kInertiaAboutOriginSuspect, Severity::kWarning, true,
      "The inertia looks like it is about the link origin rather than the center of mass."};
  return kInfo;
}

bool CheckInertiaAboutOrigin(RuleContext& ctx, const JudgedLink& judged, const GeometryRoom& room) {
  const Link& link = *judged.link;
  const double m = link.inertial->mass;
  const double tol = ctx.options.tolerance;
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  const Eigen::Matrix3d& I_B = judged.props.I_SScm_F;
  const std::string& geometry_kind = judged.geometry_name;
  const double spread = room.spread, bound = room.bound, r2 = room.r2;
  const double allowance = room.allowance, margin = room.margin;
  const Eigen::Vector3d& d = room.d;
  // Would the numbers fit as the inertia about the link origin Bo? Then I_Bcm = I − m·(|c|²1
  // − c·cᵀ) must be valid and fit the sphere.
  const Eigen::Matrix3d I_shifted =
      I_B - m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  const double shifted_spread = 0.5 * I_shifted.trace() + m * d.squaredNorm();
  const bool shifted_fits =
      !c.isZero(0) && IsValid(I_shifted, tol) && shifted_spread - bound <= tol * bound;
  if (!shifted_fits) return false;
  const Validity vs = Analyze(I_shifted);
  ctx.Emit(
      kInertiaAboutOriginSuspect, link, InertiaLocation(link),
      judged.who + ": the inertia needs more room than the " + geometry_kind +
          " geometry gives (∫|x - o|² dm = " + Num(spread) + " > m·r² = " + Num(bound) +
          " kg·m² about the center o of its bounding box, r = " + Num(allowance * margin) +
          " × half-diagonal = " + Num(std::sqrt(r2)) +
          " m), but taken as the inertia about the link origin and shifted to the center "
          "of mass " +
          Vec(c) + " it is valid and fits (principal moments " + Num(vs.moments(0)) + ", " +
          Num(vs.moments(1)) + ", " + Num(vs.moments(2)) +
          "): it was probably written about the link origin",
      {{"spread", spread},
       {"bound", bound},
       {"shifted_spread", shifted_spread},
       {"shifted_principal_min", vs.moments(0)},
       {"shifted_principal_mid", vs.moments(1)},
       {"shifted_principal_max", vs.moments(2)}},
      LinkHeadline(link.name, ": inertia " + FormatRatio(spread / bound) + " too spread for its " +
                                  geometry_kind + "; fits as about the link origin"),
      {{"polar_moment_kg_m2", spread},
       {"max_for_its_size_kg_m2", bound},
       {"polar_moment_if_about_origin_kg_m2", shifted_spread},
       {"com_from_origin_m", c.norm()}},
      "shift it to the center of mass: massprops fix --apply inertia-about-origin-suspect");
  return true;
}

}  // namespace rules
}  // namespace massprops
