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

void DescribeReaderFinding(Finding& f) {
  // The readers' messages say what is wrong, then "; " and what follows from it.
  const std::size_t cut = f.message.find("; ");
  f.headline = f.message.substr(0, cut);
  // "... cannot read <inertia ixz=\"x\"> of link 'l' and loads ...": the link first, then what.
  const std::size_t read = f.headline.find(" read "), of = f.headline.find(" of link '");
  if (f.rule == kInertialUnreadable && read != std::string::npos && of != std::string::npos &&
      of > read) {
    f.headline =
        LinkHeadline(f.link, ": cannot read " + f.headline.substr(read + 6, of - read - 6));
  }
  // "<include> 'uri' cannot be resolved: where it was looked for": the why is under --explain.
  const std::size_t resolved = f.headline.find("cannot be resolved");
  if (f.rule == kIncludeUnresolved && resolved != std::string::npos) {
    f.headline.resize(resolved + std::string("cannot be resolved").size());
  }
  // "link L: <inertial auto="true"> (SDF 1.11) computed as SUMMARY": the mass is the number.
  if (f.rule == "inertial-auto") {
    for (const auto& [name, value] : f.values) {
      if (name == "mass") {
        f.headline = LinkHeadline(f.link, ": <inertial auto> computed as " + FormatMass(value));
      }
    }
  }
  // A whole sentence within the headline's length however long the names it quotes.
  const char* fallback =
      f.rule == kUrdfNotLoadable ? "ROS's URDF parser will not load the file (--explain says why)"
      : f.rule == kInertialUnreadable
          ? "a number of an <inertial> cannot be read (--explain says which)"
      : f.rule == kIncludeUnresolved ? "an <include> cannot be resolved (--explain says which)"
                                     : "the reader's full message is under --explain";
  // "ROS's URDF parser will not load this file: WHAT: DETAIL": urdfdom's WHAT is a sentence.
  const std::string refuses = "ROS's URDF parser will not load this file: ";
  if (f.rule == kUrdfNotLoadable && f.headline.rfind(refuses, 0) == 0 &&
      CountChars(f.headline) > kMaxHeadlineChars) {
    const std::string reason = f.headline.substr(refuses.size());
    const std::string shorter =
        "ROS's URDF parser refuses this file: " + reason.substr(0, reason.find(": "));
    if (CountChars(shorter) <= kMaxHeadlineChars) f.headline = shorter;
  }
  f.headline = HeadlineFromMessage(f.headline, fallback, "--explain says more");
  f.evidence.clear();
  for (const auto& [name, value] : f.values) {
    const bool moment = name.size() == 3 && name[0] == 'i';
    const std::string unit = name == "mass"               ? "_kg"
                             : name.rfind("com_", 0) == 0 ? "_m"
                             : moment                     ? "_kg_m2"
                                                          : "";
    f.evidence.emplace_back(name + unit, value);
  }
  if (!f.help.empty()) return;  // the reader's own (e.g. an MJCF mesh that cannot be used)
  if (f.rule == kUrdfNotLoadable) {
    f.help = "fix the element named so that ROS's parser loads the file (docs/urdf.md)";
  } else if (f.rule == kInertialUnreadable) {
    f.help = "write one decimal number per attribute, nothing around it";
  } else if (f.rule == kIncludeUnresolved) {
    f.help = "point massprops at the model with --model-path DIR (or download it)";
  } else {
    f.help = "nothing to fix: what SDF computed, for review (massprops explain " + f.rule + ")";
  }
}

const RuleInfo& InertialAutoRule() {
  static const RuleInfo kInfo{
      "inertial-auto", Severity::kNote, true,
      "An SDF 1.11 <inertial auto=\"true\"> was computed from the link's collisions."};
  return kInfo;
}

}  // namespace rules
}  // namespace massprops
