#include "analysis/targets/finding_text.h"

#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/finding_text.h"

namespace massprops {
namespace {

// The value named `name` of the finding, or `fallback`.
double ValueOf(const Finding& f, const std::string& name, double fallback = 0) {
  for (const auto& [key, value] : f.values) {
    if (key == name) return value;
  }
  return fallback;
}

// The finding's values under names that carry their units.
std::vector<std::pair<std::string, double>> EvidenceOf(const Finding& f) {
  std::vector<std::pair<std::string, double>> evidence;
  for (const auto& [name, value] : f.values) {
    if (name == "first") continue;  // which refusal MuJoCo reports: said in the headline
    // Each name in words, with the unit it is in.
    std::string key = name;
    if (name == "mass" || name == "subtree_mass") {
      key += "_kg";
    } else if (name == "principal_min" || name == "principal_1") {
      key = "smallest_moment_kg_m2";
    } else if (name == "principal_mid" || name == "principal_2") {
      key = "middle_moment_kg_m2";
    } else if (name == "principal_max" || name == "principal_3") {
      key = "largest_moment_kg_m2";
    } else if (name == "epsilon") {
      key = "drake_tolerance_kg_m2";
    } else if (name == "value") {
      key = "moment_about_axis_kg_m2";
    } else if (name == "lumped_links") {
      key += "_count";
    }
    evidence.emplace_back(key, value);
  }
  return evidence;
}

// The sentence without its trailing relative clause (", whose ..." or ", which ...": detail that
// the sentence is whole without) when the whole message is too long for a headline.
std::string WithoutRelativeClause(const std::string& text) {
  if (CountChars(text) <= kMaxHeadlineChars) return text;
  for (const char* clause : {", whose ", ", which "}) {
    const std::size_t at = text.find(clause);
    if (at != std::string::npos) return text.substr(0, at);
  }
  return text;
}

}  // namespace

void DescribeTargetFinding(Finding& f) {
  // `before` + "link 'NAME'" (or "this link", or "the model") + `after`: a whole headline.
  auto about = [&f](const std::string& before, const std::string& after) {
    return f.link.empty() ? before + "the model" + after : LinkHeadline(f.link, after, before);
  };
  const bool first = ValueOf(f, "first") != 0;
  const std::string mujoco = "MuJoCo 2.2.2 refuses ";
  const std::string reported = first ? " (the refusal it reports)" : "";
  const std::string fix_mujoco = "massprops fix --target mujoco";
  if (f.rule == "mujoco-rejects-inertia-triangle") {
    f.headline = about(mujoco, ": principal moments break A + B >= C exactly" + reported);
    f.help = fix_mujoco + ", or <compiler balanceinertia=\"true\"/>";
  } else if (f.rule == "mujoco-rejects-below-minval") {
    f.headline = about(mujoco, ": moving body with mass or a moment below 1e-15" + reported);
    f.help = fix_mujoco + ", or <compiler boundmass=... boundinertia=.../>";
  } else if (f.rule == "mujoco-rejects-fused-inertia") {
    f.headline = about(mujoco, ": fused static bodies give a moment below 1e-14" + reported);
    f.help = fix_mujoco + ", or <compiler fusestatic=\"false\"/>";
  } else if (f.rule == "mujoco-rejects-geom-inertia") {
    f.headline = about(mujoco, ": its geoms give too little mass or inertia" + reported);
    f.help = "give the link an <inertial> (massprops fix --apply inertial-missing)";
  } else if (f.rule == "mujoco-rejects-negative") {
    f.headline = about(mujoco, ": negative mass or principal moment" + reported);
    f.help = "write the part's mass and inertia (massprops fix projects an invalid inertia)";
  } else if (f.rule == "mujoco-not-predicted") {
    f.headline = HeadlineFromMessage(
        WithoutRelativeClause(f.message),
        "MuJoCo's decision cannot be fully predicted (--explain says why)",
        "--explain says more");
    f.help = "load the model in MuJoCo to know (massprops explain mujoco-not-predicted)";
  } else if (f.rule == "drake-rejects-invalid-inertia") {
    f.headline = about("Drake refuses ", ": inertia fails CouldBePhysicallyValid() (mass " +
                                             FormatMass(ValueOf(f, "mass")) + ")");
    f.help = "massprops fix (the nearest valid inertia)";
  } else if (f.rule == "drake-rejects-massless-body") {
    f.headline = about("Drake cannot simulate ",
                       ": no mass or inertia on the axis of its joint, singular hinge inertia");
    f.help =
        "give the body its part's mass and inertia (massprops fix --apply "
        "massless-moving-body)";
  } else if (f.rule == "gazebo-lumps-fixed-joint") {
    const bool valid = f.message.find("NOT physically valid") == std::string::npos;
    f.headline = about("Gazebo lumps " + FormatSignificant(ValueOf(f, "lumped_links")) +
                           " fixed-joint links into ",
                       " (" + FormatMass(ValueOf(f, "mass")) + ", inertia " +
                           (valid ? "valid" : "NOT valid") + ")");
    f.help =
        "to keep a link: <preserveFixedJoint>true</preserveFixedJoint> in its joint's <gazebo>";
  } else {
    return;
  }
  f.evidence = EvidenceOf(f);
}

}  // namespace massprops
