// mass-not-positive (error): an inertial's mass is negative, NaN or infinite.
//
// Evidence: the link's <mass> number only.
// Why: a mass is a finite number >= 0 (0 only for a massless frame welded to a body); a negative
// or non-finite one makes every quantity computed from it (composite mass, center of mass,
// kinetic energy) meaningless, and simulators reject it.

#include <cmath>
#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kMassNotPositive = "mass-not-positive";

}  // namespace

const RuleInfo& MassNotPositiveRule() {
  static const RuleInfo kInfo{kMassNotPositive, Severity::kError, true,
                              "An inertial's mass is negative, NaN or infinite."};
  return kInfo;
}

void CheckMassNotPositive(RuleContext& ctx, const Link& link, const std::string& who) {
  const double m = link.inertial->mass;
  if (!std::isfinite(m) || m < 0) {
    ctx.Emit(kMassNotPositive, link, MassLocation(link),
             who + ": mass " + Num(m) + " is " + (std::isfinite(m) ? "negative" : "not finite") +
                 " (a mass must be a finite number >= 0; 0 only for a massless frame welded to a "
                 "body)",
             {{"mass", m}},
             LinkHeadline(link.name, ": mass " + FormatMass(m) + " is " +
                                         (std::isfinite(m) ? "negative" : "not a number") +
                                         "; no body has it"),
             {{"mass_kg", m}}, "write the part's mass in kg (0 only for a frame welded to a body)");
  }
}

}  // namespace rules
}  // namespace massprops
