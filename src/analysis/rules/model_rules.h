#pragma once
// The rules of `massprops check` judged across the whole model rather than per link or per welded
// group (private to src/analysis/): links that carry the same numbers, links that mirror each
// other. checks.cc runs them after the per-group rules (rules.h lists the others).

#include <vector>

#include "analysis/rules/rule_context.h"
#include "massprops/analysis/checks.h"
#include "massprops/model/model.h"

namespace massprops {
namespace rules {

// com-not-mirrored's RuleInfo, after com-outside-geometry in AllRules (and docs/rules.md).
const RuleInfo& ComNotMirroredRule();  // com_not_mirrored.cc
// inertia-exceeds-model's RuleInfo, after com-not-mirrored.
const RuleInfo& InertiaExceedsModelRule();  // inertia_exceeds_model.cc

// Every link's pose in the frame of its tree's root at the zero configuration, and that root
// (com_not_mirrored.cc).
struct ModelPoses {
  std::vector<Pose> X_WL;
  std::vector<int> root;
};
ModelPoses PosesOf(const RuleContext& ctx);

// units-suspect for the same typed-in inertial on three or more links, those without geometry
// of their own judged against the assembly that holds each (copied_placeholders.cc).
void CheckCopiedPlaceholders(RuleContext& ctx);
// com-not-mirrored: links that mirror each other (by name or mesh) whose centers of mass or
// products of inertia do not (com_not_mirrored.cc).
void CheckMirroredPairs(RuleContext& ctx);
// inertia-exceeds-model: a radius of gyration beyond the reach of the whole model's geometry
// from the link's center of mass (inertia_exceeds_model.cc).
void CheckInertiaWithinModel(RuleContext& ctx);

}  // namespace rules
}  // namespace massprops
