// inertia-not-physical (error), per link and per welded group, and its note
// inertia-near-boundary.
//
// Evidence: the link's written inertia (about its center of mass, in the inertial frame: validity
// does not depend on the frame, so the numbers are judged as written, free of rotation
// round-off); for a welded group, the composite inertia of its members about the group's center
// of mass (a simulator that merges fixed joints sees only that).
// Why: the inertia of any mass distribution about its center of mass has non-negative principal
// moments that satisfy the triangle inequality λ1 + λ2 >= λ3 (each is ∫ of a sum of two squared
// coordinates). An inertia that fails them by more than the tolerance (relative to the trace) is
// no body's: error. One that holds only within the tolerance (a thin shape written with rounded
// numbers) gets the note inertia-near-boundary. An invalid inertia that becomes valid with its
// products negated also gets products-sign-suspect (products_sign_suspect.cc).

#include <string>
#include <utility>
#include <vector>

#include "analysis/rules/rules.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaNotPhysical = "inertia-not-physical";
constexpr const char* kInertiaNearBoundary = "inertia-near-boundary";

}  // namespace

const RuleInfo& InertiaNotPhysicalRule() {
  static const RuleInfo kInfo{
      kInertiaNotPhysical, Severity::kError, true,
      "At the center of mass, a principal moment is negative or the triangle inequality fails "
      "(per link and per welded group)."};
  return kInfo;
}

const RuleInfo& InertiaNearBoundaryRule() {
  static const RuleInfo kInfo{kInertiaNearBoundary, Severity::kNote, true,
                              "The inertia is physically valid only within the tolerance."};
  return kInfo;
}

namespace {

// The evidence of an invalid inertia: its principal moments and how far the triangle
// inequality fails, as a percentage of the trace ("excess 2.58%"), or in kg·m² when the
// trace is not positive (negative moments), where a share of it means nothing.
std::vector<std::pair<std::string, double>> ViolationEvidence(const Validity& v) {
  // First, the deciding number: by how much moment 3 exceeds moments 1 + 2 (the triangle
  // inequality every body obeys); then the moments (the headline quotes them too).
  std::vector<std::pair<std::string, double>> evidence;
  if (v.trace > 0) {
    evidence.emplace_back("triangle_excess_percent", 100 * v.excess / v.trace);
  } else {
    evidence.emplace_back("triangle_excess_kg_m2", v.excess);
  }
  evidence.insert(evidence.end(), {{"moment_1_kg_m2", v.moments(0)},
                                   {"moment_2_kg_m2", v.moments(1)},
                                   {"moment_3_kg_m2", v.moments(2)}});
  return evidence;
}

}  // namespace

bool CheckInertiaValidity(RuleContext& ctx, int link_index, const std::string& who) {
  const Link& link = ctx.model.links[link_index];
  const Eigen::Matrix3d I_written = WrittenMatrix(*link.inertial);
  // Validity does not depend on the frame the inertia is expressed in: judge the numbers as
  // written (about the center of mass, in the inertial frame), free of rotation round-off.
  const double tol = ctx.options.tolerance;
  const bool valid = IsValid(I_written, tol);
  if (!valid) {
    const Validity v = Analyze(I_written);
    ctx.Emit(
        kInertiaNotPhysical, link, InertiaLocation(link),
        who + ": the inertia about the center of mass is not physically valid: " +
            DescribeViolation(v) + ctx.GroupNote(link_index),
        ValidityValues(v, tol),
        LinkHeadline(link.name, ": impossible inertia (moments " + FormatSignificant(v.moments(0)) +
                                    " + " + FormatSignificant(v.moments(1)) + " < " +
                                    FormatSignificant(v.moments(2)) + ")"),
        ViolationEvidence(v),
        "recompute it from CAD or geometry; massprops fix projects it to the nearest valid one");
    CheckProductsSignWhenInvalid(ctx, link, who);
  } else if (!IsValid(I_written, internal::DefaultInertiaValidityTolerance<double>())) {
    const Validity v = Analyze(I_written);
    ctx.Emit(
        kInertiaNearBoundary, link, InertiaLocation(link),
        who + ": the inertia is valid only within the tolerance " + Num(tol) + " of the trace: " +
            DescribeViolation(v) + " (the body is a thin shape, written with rounded numbers?)",
        ValidityValues(v, tol),
        LinkHeadline(link.name, ": inertia valid only within tolerance (thin shape, rounded?)"),
        ViolationEvidence(v), "write the moments with more digits, or leave it: it is a note");
  }
  return valid;
}

void CheckCompositeValidity(RuleContext& ctx, const WeldedGroup& group, const std::string& who,
                            const CompositeInertia& composite, int contributing) {
  if (contributing <= 1 || IsValid(composite.I_SScm_R, ctx.options.tolerance)) return;
  const Link& root = ctx.model.links[group.links.front()];
  const Validity v = Analyze(composite.I_SScm_R);
  std::vector<std::pair<std::string, double>> values = ValidityValues(v, ctx.options.tolerance);
  values.emplace_back("group_links", static_cast<double>(group.links.size()));
  ctx.Emit(
      kInertiaNotPhysical, root, InertiaLocation(root),
      who + ": the composite inertia about the composite center of mass " +
          Vec(composite.p_RoScm_R) + " (mass " + Num(composite.mass) +
          ") is not physically valid: " + DescribeViolation(v),
      std::move(values),
      LinkHeadline(root.name, ": impossible composite inertia of its welded group of " +
                                  std::to_string(group.links.size())),
      [&] {
        std::vector<std::pair<std::string, double>> evidence = ViolationEvidence(v);
        evidence.emplace_back("links_count", static_cast<double>(group.links.size()));
        evidence.emplace_back("mass_kg", composite.mass);
        return evidence;
      }(),
      "fix the members' inertias first (massprops check names them)");
}

}  // namespace rules
}  // namespace massprops
