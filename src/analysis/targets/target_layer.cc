// The target layer (docs/targets.md): what the simulator files share, and CheckTarget and
// AddTargetFindings, which call the simulator the target names.
#include "analysis/targets/target_layer.h"

#include <algorithm>
#include <cstdio>

#include "analysis/rule_severity.h"
#include "analysis/targets/finding_text.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {
namespace targets {

std::string Num(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", x);
  return buffer;
}

std::string Moments(const std::array<double, 3>& m) {
  return Num(m[0]) + ", " + Num(m[1]) + ", " + Num(m[2]);
}

bool Ignored(const Link& link, const std::string& rule) {
  for (const std::string& ignored : link.ignored_rules) {
    if (ignored == "all" || ignored == rule) return true;
  }
  return false;
}

const SourceLocation& InertiaLocationOf(const Link& link) {
  if (link.inertial) {
    if (link.inertial->inertia_location.line > 0) return link.inertial->inertia_location;
    if (link.inertial->location.line > 0) return link.inertial->location;
  }
  return link.location;
}

Eigen::Matrix3d WrittenMatrixOf(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

bool PhysicallyValid(const Eigen::Matrix3d& I, double tolerance) {
  return internal::IsPhysicallyValidInertia(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                            tolerance);
}

bool HasCollision(const Link& link) {
  for (const Geometry& g : link.geometries) {
    if (g.is_collision) return true;
  }
  return false;
}

void FindingSink::Emit(const std::string& rule, int link_index, const SourceLocation& location,
                       std::string message, std::vector<std::pair<std::string, double>> values) {
  const std::optional<Severity> severity = RuleSeverity(rule, options_);
  if (!severity) return;
  Finding f;
  if (link_index >= 0) {
    const Link& link = model_.links[link_index];
    if (Ignored(link, rule)) return;
    f.link = link.name;
  }
  f.rule = rule;
  f.severity = *severity;
  f.model = model_.name;
  f.location = location;
  f.message = std::move(message);
  f.values = std::move(values);
  DescribeTargetFinding(f);
  findings_.push_back(std::move(f));
}

}  // namespace targets

std::vector<Finding> CheckTarget(const Model& model, Target target, const CheckOptions& options,
                                 const MujocoCompilerOptions& mujoco, std::string_view text) {
  targets::FindingSink sink(model, options);
  if (target == Target::kDrake) targets::CheckDrake(model, &sink);
  if (target == Target::kGazebo) targets::CheckGazebo(model, options, text, &sink);
  if (target == Target::kMujoco) targets::CheckMujoco(model, options, mujoco, &sink);
  return sink.Take();
}

void AddTargetFindings(const Model& model, Target target, const CheckOptions& options,
                       const MujocoCompilerOptions& mujoco, std::vector<Finding>* findings,
                       std::string_view text) {
  if (target == Target::kGeneric) return;
  if (target == Target::kMujoco) targets::AnnotateMujoco(model, mujoco, findings);
  if (target == Target::kGazebo) targets::AnnotateGazebo(model, options, text, findings);
  std::vector<Finding> own = CheckTarget(model, target, options, mujoco, text);
  findings->insert(findings->end(), own.begin(), own.end());
  std::stable_sort(findings->begin(), findings->end(), [](const Finding& a, const Finding& b) {
    if (a.location.line != b.location.line) return a.location.line < b.location.line;
    return a.rule < b.rule;
  });
}

}  // namespace massprops
