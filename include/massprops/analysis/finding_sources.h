#pragma once
/// @file
/// Findings of an expanded xacro package, pointed at the sources: each finding gets the place
/// where the numbers it is about were written (io/xacro_trace.h).

#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/io/xacro_trace.h"

namespace massprops {

/// Sets Finding::source of each finding that names a link to one traced number of that link:
/// the rule's own (products-sign-suspect: the first non-zero of ixy, ixz, iyz; the mass rules:
/// the mass; com-outside-geometry: the origin xyz), else the first on the finding's line (the
/// <inertia>, <mass> or <origin> element), else the link's first traced inertia number, then
/// mass, then origin. `generated_name` names the expansion in FindingSource::generated. Findings
/// with no traced number are left as they are. Cost: O(findings × numbers).
void AttachXacroSources(const XacroTrace& trace, const std::string& generated_name,
                        std::vector<Finding>* findings);

}  // namespace massprops
