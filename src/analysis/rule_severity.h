#pragma once
// The severity a rule of AllRules() reports with under CheckOptions::overrides: the override when
// one names the rule (nullopt: the rule is off), else the rule's default, or nullopt when the rule
// is off by default or unknown. One definition (checks.cc) for the rules' context, the target
// profiles and the density rules.

#include <optional>
#include <string>

#include "massprops/analysis/checks.h"

namespace massprops {

std::optional<Severity> RuleSeverity(const std::string& rule, const CheckOptions& options);

}  // namespace massprops
