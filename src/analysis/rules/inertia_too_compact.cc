// inertia-too-compact (note): the inertia is smaller than any body of this mass can have.
//
// Evidence: the mass m and the trace of the inertia about the center of mass, tr(I_c).
// Why: tr(I_c) = 2·∫|x − c|² dm. Of all bodies of mass m whose density is at most ρ, the ball of
// uniform density ρ centred at c has the least ∫|x − c|² dm (each shell of radius s about c holds
// at most ρ·4πs²·ds, so filling the nearest shells first minimises it): tr(I_c) >= (6/5)·m·r²
// with r = (3m / (4πρ))^(1/3) (LeastTrace, include/massprops/analysis/link_measure.h). With
// osmium's 22 590 kg/m³, the densest element, a trace below it is impossible; with lead's
// 11 340 kg/m³ it is a body no robot part is (a mass raised without its tensor, or a tensor typed
// for a smaller part). A tensor of exactly zero (a point mass, written so on purpose) and dummy
// masses (kDummyMass) are not judged: other rules speak of them. A note: on the labelled robots the
// links below the lead ball are placeholder tensors their labellers did not count as defects
// (mini pupper's legs, 0.02-0.15 times an osmium ball; docs/labels.md), true but not worth a
// warning.

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "analysis/rules/rules.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/link_measure.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaTooCompact = "inertia-too-compact";

}  // namespace

const RuleInfo& InertiaTooCompactRule() {
  static const RuleInfo kInfo{
      kInertiaTooCompact, Severity::kNote, true,
      "The inertia is smaller than that of a ball of lead of the same mass: no robot part is so "
      "compact (below osmium's ball: no body is)."};
  return kInfo;
}

void CheckInertiaTooCompact(RuleContext& ctx, const JudgedLink& judged) {
  if (!ctx.RuleOn(kInertiaTooCompact) || !judged.valid) return;
  const Link& link = *judged.link;
  const double m = judged.props.mass;
  const double trace = judged.props.I_SScm_F.trace();
  if (!(m > kDummyMass) || !std::isfinite(m) || !std::isfinite(trace) || trace == 0) return;
  const double least_lead = LeastTrace(m, kLeadDensity);
  const double slack = 1 - ctx.options.tolerance;
  if (!(trace < slack * least_lead)) return;
  const double least_osmium = LeastTrace(m, kOsmiumDensity);
  const bool impossible = trace < slack * least_osmium;
  const double density = impossible ? kOsmiumDensity : kLeadDensity;
  const double least = impossible ? least_osmium : least_lead;
  const double radius = std::cbrt(3 * m / (4 * M_PI * density));
  const std::string material = impossible ? "osmium" : "lead";
  ctx.Emit(kInertiaTooCompact, link, InertiaLocation(link),
           judged.who + ": tr(I) = " + Num(trace) +
               " kg·m² about its center of mass, but a ball of " + material + " (" + Num(density) +
               " kg/m³" + (impossible ? ", the densest element" : "") + ") of its mass " + Num(m) +
               " kg, radius " + Num(radius) + " m, has tr(I) = (6/5)·m·r² = " + Num(least) +
               " kg·m², the least of any body of that mass and density: " +
               (impossible
                    ? "no body of this mass is so compact"
                    : "no robot part is so compact (a mass raised without its tensor, or a "
                      "tensor typed for a smaller part?); the weighed mass: massprops fix --mass " +
                          link.name + "=KG"),
           {{"trace", trace}, {"least_trace", least}, {"ratio", trace / least}, {"mass", m}},
           LinkHeadlineFirstFit(
               link.name, {": inertia " + FormatRatio(trace / least) + " that of a ball of " +
                               material + " of its mass (mass raised without its tensor?)",
                           ": inertia " + FormatRatio(trace / least) + " that of a " + material +
                               " ball of its mass"}),
           {{"trace_kg_m2", trace},
            {"least_trace_kg_m2", least},
            {"ratio", trace / least},
            {"mass_kg", m},
            {"ball_radius_m", radius}},
           "recompute the tensor for this mass (from CAD, or massprops fix --from-geometry)");
}

}  // namespace rules
}  // namespace massprops
