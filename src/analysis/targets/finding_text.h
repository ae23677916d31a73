#pragma once
// The headline, evidence and help of the findings the target profiles add (`check --target`,
// target_profile.h; issue 32), made from the finding's rule, link, message and values, so that the
// profiles' emulation code builds only its message (private to src/analysis/).

#include "massprops/analysis/checks.h"

namespace massprops {

// Sets f.headline, f.evidence and f.help of a finding of a target rule (mujoco-*, drake-*,
// gazebo-*); leaves a finding of any other rule as it is.
void DescribeTargetFinding(Finding& f);

}  // namespace massprops
