#pragma once
/// @file
/// What `massprops fix` says about its changes, as a table (text) or a JSON document: the repairs
/// and their effect on the whole robot (analysis/fix_effect.h). Schema in docs/fix.md.

#include <string>
#include <vector>

#include "massprops/analysis/fix_effect.h"
#include "massprops/analysis/repair.h"

namespace massprops {

/// The before/after table of one model: the whole model, then each changed welded group; mass,
/// center of mass and principal moments (ascending), 6 significant digits, in the frame of the
/// body's first link (the model's root link for the whole model), as `massprops report` prints.
std::string RenderFixEffectText(const FixEffect& effect);

/// One JSON document: {"file", "changed", "repairs": [{"rule", "link", "method", "why",
/// "relative_change", "inserts_inertial", "changes": [{"element", "attribute", "line", "old",
/// "new"}]}], "effects": [{"model", "total": {"before", "after"}, "groups": [{"root_link",
/// "links", "before", "after"}]}]}; a body is {"frame", "mass", "com", "inertia_about_com",
/// "principal_moments"} as in `massprops report --format json` (numbers round-trip exactly).
std::string RenderFixJson(const std::string& file, bool changed, const std::vector<Repair>& repairs,
                          const std::vector<FixEffect>& effects);

}  // namespace massprops
