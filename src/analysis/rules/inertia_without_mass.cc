// inertia-without-mass (warning): an inertial has mass 0 and a non-zero inertia.
//
// Evidence: the link's <mass> and <inertia> numbers; its welded group (does it move, its
// composite mass and central inertia).
// Why: an inertia is that of a body with mass, so mass 0 with a non-zero inertia is a mass lost
// in an edit. It is judged where the inertia matters: the link's welded group has no mass at all
// (the inertia is all there is of a moving body), or the massless inertia is at least
// kMadeUpInertiaShare of the group's central inertia (numbers that change the group's dynamics).
// Not singular when other bodies give the joints inertia (so no error). A group that does not
// move (a URDF root: PyBullet's fixed base is written with mass 0; a group welded to the world)
// is left alone.

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaWithoutMass = "inertia-without-mass";

}  // namespace

const RuleInfo& InertiaWithoutMassRule() {
  static const RuleInfo kInfo{
      kInertiaWithoutMass, Severity::kWarning, true,
      "An inertial has mass 0 and a non-zero inertia: the mass was lost in an edit."};
  return kInfo;
}

void CheckInertiaWithoutMass(RuleContext& ctx, int link_index, const std::string& who) {
  const Link& link = ctx.model.links[link_index];
  const Inertial& in = *link.inertial;
  const Eigen::Matrix3d I = WrittenMatrix(in);
  const double trace = I.trace();
  if (!(trace > 0) || !std::isfinite(trace)) return;
  const WeldedGroup& group = ctx.groups[ctx.group_of[link_index]];
  if (!group.is_moving) return;
  const CompositeInertia& composite = ctx.GroupComposite(ctx.group_of[link_index]);
  const double group_trace = composite.I_SScm_R.trace();
  const double share = group_trace > 0 ? trace / group_trace : 1;
  if (composite.mass > 0 && !(share >= kMadeUpInertiaShare)) return;
  ctx.Emit(kInertiaWithoutMass, link, MassLocation(link),
           who + ": mass 0 with a non-zero inertia (ixx " + Num(in.ixx) + ", iyy " + Num(in.iyy) +
               ", izz " + Num(in.izz) + " kg·m²" +
               (composite.mass > 0 ? ", " + Format("%.3g%%", 100 * share) +
                                         " of its welded group's (" + Num(composite.mass) + " kg)"
                                   : std::string(", on a moving body that has no other mass")) +
               "): an inertia is that of a body with mass, so the mass was probably lost in an "
               "edit; give it the part's mass, or zero the inertia if the link is only a frame",
           {{"mass", 0}, {"trace", trace}, {"group_share", share}},
           LinkHeadline(link.name, ": mass 0 with inertia " + FormatInertia(trace) +
                                       " (trace; mass lost in an edit?)"),
           {{"mass_kg", 0}, {"trace_kg_m2", trace}, {"group_share_percent", 100 * share}},
           "give the link its part's mass, or zero the inertia if it is only a frame");
}

}  // namespace rules
}  // namespace massprops
