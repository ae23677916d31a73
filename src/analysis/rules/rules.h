#pragma once
// The rules of `massprops check`, one file each in src/analysis/rules/ (private to
// src/analysis/). Each file holds its rule's RuleInfo (id, default severity, whether on by
// default, one-line summary), a comment naming the evidence it reads and the physics behind it,
// and its logic. src/analysis/checks.cc runs them in order (CheckModel) and lists their RuleInfo
// (AllRules); docs/rules.md has one section per rule, in the same order (tests/rules_docs_test.py).

#include <Eigen/Core>
#include <string>

#include "analysis/rules/rule_context.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/model/model.h"

namespace massprops {
namespace rules {

// ---- Each rule's RuleInfo, in the order of AllRules (and of docs/rules.md).
const RuleInfo& MassNotPositiveRule();            // mass_not_positive.cc
const RuleInfo& InertiaNotFiniteRule();           // inertia_not_finite.cc
const RuleInfo& InertiaNotPhysicalRule();         // inertia_not_physical.cc
const RuleInfo& MasslessMovingBodyRule();         // massless_moving_body.cc
const RuleInfo& MasslessWithMassOutboardRule();   // massless_moving_body.cc (its note)
const RuleInfo& ZeroInertiaAboutJointAxisRule();  // zero_inertia_about_joint_axis.cc
const RuleInfo& InertiaWithoutMassRule();         // inertia_without_mass.cc
const RuleInfo& InertialMissingRule();            // inertial_missing.cc
const RuleInfo& ModelWithoutInertialsRule();      // model_without_inertials.cc
const RuleInfo& ProductsSignSuspectRule();        // products_sign_suspect.cc
const RuleInfo& UnitsSuspectRule();               // units_suspect.cc
const RuleInfo& InertiaAboutOriginSuspectRule();  // inertia_about_origin_suspect.cc
const RuleInfo& InertiaExceedsGeometryRule();     // inertia_exceeds_geometry.cc
const RuleInfo& InertiaBeyondHullRule();          // density_realizable.cc
const RuleInfo& InertiaTooCompactRule();          // inertia_too_compact.cc
const RuleInfo& ComOutsideGeometryRule();         // com_outside_geometry.cc
const RuleInfo& InertiaNearBoundaryRule();        // inertia_not_physical.cc (its note)
// Only with `check --data LOG`; listed last (after the geometry rules): data_contradiction.cc.
const RuleInfo& InertiaContradictsDataRule();
// The rules whose findings the readers make (ReadResult::findings): reader_rules.cc.
const RuleInfo& UrdfNotLoadableRule();
const RuleInfo& InertialUnreadableRule();
const RuleInfo& IncludeUnresolvedRule();
const RuleInfo& InertialAutoRule();
// Sets the headline (the reader's message up to its first "; "), the evidence (its values, with
// their units in the names) and the help of a finding of one of these rules.
void DescribeReaderFinding(Finding& finding);

// ---- Per-link rules (CheckModel runs them on each link with an <inertial>, in this order).

// mass-not-positive: a negative, NaN or infinite mass.
void CheckMassNotPositive(RuleContext& ctx, const Link& link, const std::string& who);
// inertia-not-finite; returns whether the inertia and the inertial's pose are all finite.
bool CheckInertiaNotFinite(RuleContext& ctx, const Link& link, const std::string& who);
// inertia-not-physical (and products-sign-suspect when negating the products makes it valid),
// or inertia-near-boundary; returns whether the written inertia is valid within the tolerance.
bool CheckInertiaValidity(RuleContext& ctx, int link_index, const std::string& who);
// inertia-without-mass (a link of mass 0, on a model that is not static).
void CheckInertiaWithoutMass(RuleContext& ctx, int link_index, const std::string& who);
// products-sign-suspect for an invalid inertia: valid with the products of inertia negated.
void CheckProductsSignWhenInvalid(RuleContext& ctx, const Link& link, const std::string& who);
// products-sign-suspect for an inertia valid both ways: the geometry decides.
void CheckProductsSignAgainstGeometry(RuleContext& ctx, const JudgedLink& judged);
// units-suspect against the geometry or the kinematic tree; returns whether it was flagged.
bool CheckUnits(RuleContext& ctx, const JudgedLink& judged);
// units-suspect for a typed-in inertia on a link with nothing to judge it by; returns whether it
// was flagged.
bool CheckMadeUpInertia(RuleContext& ctx, const JudgedLink& judged);
// inertia-exceeds-geometry by the bounding sphere of the geometry's box, or
// inertia-about-origin-suspect where the numbers fit as the inertia about the link origin;
// returns whether either was flagged.
bool CheckInertiaFitsGeometry(RuleContext& ctx, const JudgedLink& judged);
// inertia-exceeds-geometry by the convex hull of the link's meshes, or, for a link whose geometry
// is all primitives, axis by axis by the corners of the primitives as placed and direction by
// direction by their widths (CheckInertiaFitsPrimitives).
void CheckInertiaFitsHull(RuleContext& ctx, const JudgedLink& judged);
void CheckInertiaFitsPrimitives(RuleContext& ctx, const JudgedLink& judged);
// inertia-beyond-hull by the bounds a density inside the convex hull of the link's whole geometry
// puts on its inertia (direction by direction, and the bounding ellipsoid), and
// density-implausible by its mass over the hull's volume (density_realizable.cc).
void CheckDensityRealizable(RuleContext& ctx, const JudgedLink& judged);
// inertia-too-compact: a trace below that of a ball of the densest material of its mass.
void CheckInertiaTooCompact(RuleContext& ctx, const JudgedLink& judged);
// com-outside-geometry.
void CheckComInsideGeometry(RuleContext& ctx, const JudgedLink& judged);

// What CheckInertiaFitsGeometry found too large: the inertia's spread about the center o of the
// geometry's box, tr(Σ_o) = ½·tr(I) + m·|c − o|², and the bound m·r² it exceeds.
struct GeometryRoom {
  double spread = 0;     // kg·m²
  double bound = 0;      // m·r², kg·m²
  double r2 = 0;         // r², m²
  double allowance = 1;  // Allowance() of the geometry (1 for a collision envelope)
  double margin = 0;     // MarginOf() of the geometry
  Eigen::Vector3d d = Eigen::Vector3d::Zero();  // c − o
};
// inertia-about-origin-suspect: the inertia that does not fit `room` fits when taken as the
// inertia about the link origin; returns whether it was flagged.
bool CheckInertiaAboutOrigin(RuleContext& ctx, const JudgedLink& judged, const GeometryRoom& room);

// ---- Per-model and per-group rules.

// massless-moving-body for a URDF without any <inertial> (one finding for the whole model).
void CheckKinematicOnlyModel(RuleContext& ctx);
// massless-moving-body (error) or massless-link-with-mass-outboard (note) for a moving welded
// group without mass. Returns kNone unless the group moves and has no mass; kSingular when the
// error was given (or an outboard inertial cannot be judged), kMassOutboard when the note was.
enum class MasslessVerdict { kNone, kSingular, kMassOutboard };
MasslessVerdict CheckMasslessMovingGroup(RuleContext& ctx, const WeldedGroup& group,
                                         const std::string& who, bool all_massless);
// inertial-missing (or, for an SDF model without any <inertial>, model-without-inertials).
void CheckInertialMissing(RuleContext& ctx, const WeldedGroup& group, bool mass_outboard);
// model-without-inertials, once per model, on the first link with collision geometry.
void NoteModelWithoutInertials(RuleContext& ctx, const WeldedGroup& group);
// inertia-not-physical for the group as one rigid body (when more than one member contributes).
void CheckCompositeValidity(RuleContext& ctx, const WeldedGroup& group, const std::string& who,
                            const CompositeInertia& composite, int contributing);
// zero-inertia-about-joint-axis: a group turning on a revolute or continuous joint.
void CheckInertiaAboutJointAxis(RuleContext& ctx, const WeldedGroup& group, const std::string& who,
                                const CompositeInertia& composite);

}  // namespace rules
}  // namespace massprops
