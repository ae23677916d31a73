// The rules whose findings the readers make (ReadResult::findings; ReaderFindings in checks.cc
// applies the severity overrides and the rules ignored per link): urdf-not-loadable and
// inertial-unreadable (docs/urdf.md), include-unresolved and inertial-auto (docs/sdf.md).
//
// Evidence: what the URDF and SDF readers (src/io/) could not read or had to decide.

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kUrdfNotLoadable = "urdf-not-loadable";
constexpr const char* kInertialUnreadable = "inertial-unreadable";
constexpr const char* kIncludeUnresolved = "include-unresolved";

}  // namespace

const RuleInfo& UrdfNotLoadableRule() {
  static const RuleInfo kInfo{
      kUrdfNotLoadable, Severity::kError, true,
      "urdfdom (ROS's URDF parser) refuses the file; its mass properties are checked from a "
      "lenient reading."};
  return kInfo;
}

const RuleInfo& InertialUnreadableRule() {
  static const RuleInfo kInfo{
      kInertialUnreadable, Severity::kError, true,
      "A number of a link's <inertial> cannot be read; the other links are still checked."};
  return kInfo;
}

const RuleInfo& IncludeUnresolvedRule() {
  static const RuleInfo kInfo{
      kIncludeUnresolved, Severity::kWarning, true,
      "An SDF <include> cannot be resolved; the rest of the file is still checked."};
  return kInfo;
}

const RuleInfo& InertialAutoRule() {
  static const RuleInfo kInfo{
      "inertial-auto", Severity::kNote, true,
      "An SDF 1.11 <inertial auto=\"true\"> was computed from the link's collisions."};
  return kInfo;
}

}  // namespace rules
}  // namespace massprops
