// The profiles of --target (docs/targets.md): each target's name, its rules, and which generic
// rules it turns into warnings or off.
#include "analysis/targets/target_layer.h"

namespace massprops {

using namespace targets;  // the rule ids

const char* ToString(Target target) {
  switch (target) {
    case Target::kGeneric:
      return "generic";
    case Target::kMujoco:
      return "mujoco";
    case Target::kDrake:
      return "drake";
    case Target::kGazebo:
      return "gazebo";
  }
  return "generic";
}

std::optional<Target> ParseTarget(std::string_view text) {
  for (Target t : {Target::kGeneric, Target::kMujoco, Target::kDrake, Target::kGazebo}) {
    if (text == ToString(t)) return t;
  }
  return std::nullopt;
}

const std::vector<RuleInfo>& TargetRules() {
  static const std::vector<RuleInfo> kRules = {
      {kMujocoTriangle, Severity::kError, true,
       "--target mujoco: MuJoCo refuses a body whose principal moments (as it computes them) "
       "break A + B >= C exactly ('balanceinertia' accepts it)."},
      {kMujocoMinValRule, Severity::kError, true,
       "--target mujoco: MuJoCo refuses a moving body whose mass or a principal moment is below "
       "mjMINVAL = 1e-15 ('boundmass'/'boundinertia' accept it)."},
      {kMujocoFusedInertia, Severity::kError, true,
       "--target mujoco: fusing static bodies (fusestatic) gives an inertia with a principal "
       "moment below 1e-14, which MuJoCo refuses."},
      {kMujocoGeomMass, Severity::kError, true,
       "--target mujoco: a body without <inertial> gets its inertia from its geoms, and they "
       "have too little mass (or a degenerate inertia) for MuJoCo."},
      {kMujocoNegative, Severity::kError, true,
       "--target mujoco: a negative mass or principal moment survives 'boundmass'/'boundinertia'."},
      {kMujocoUnpredicted, Severity::kNote, true,
       "--target mujoco: part of MuJoCo's decision cannot be predicted from the file (mesh "
       "volumes, joint types MuJoCo does not know)."},
      {kDrakeMassless, Severity::kError, true,
       "--target drake: a massless body with no mass outboard of it (Drake cannot invert the "
       "articulated inertia)."},
      {kDrakeInvalid, Severity::kError, true,
       "--target drake: Drake's RotationalInertia::CouldBePhysicallyValid refuses the inertia."},
      {kGazeboLumped, Severity::kNote, true,
       "--target gazebo: links joined by fixed joints are lumped into one body (no "
       "<disableFixedJointLumping>/<preserveFixedJoint>)."},
  };
  return kRules;
}

TargetProfile GetTargetProfile(Target target) {
  TargetProfile p;
  p.target = target;
  switch (target) {
    case Target::kGeneric:
      p.summary = "massprops' own physics test (scale-free tolerance 1e-6 of the trace)";
      break;
    case Target::kMujoco:
      // MuJoCo judges each body on its own (triangle test before fusion) and each moving body
      // after fusion (mjMINVAL): its own findings are the errors; the physics rules say when
      // physics disagrees.
      p.overrides["inertia-not-physical"] = Severity::kWarning;
      p.overrides["massless-moving-body"] = Severity::kWarning;
      p.overrides["zero-inertia-about-joint-axis"] = Severity::kWarning;
      p.overrides[kDrakeMassless] = std::nullopt;
      p.overrides[kDrakeInvalid] = std::nullopt;
      p.overrides[kGazeboLumped] = std::nullopt;
      p.merges_fixed_joints = true;
      p.summary =
          "MuJoCo 2.2.2 compiler on URDF: fusestatic, exact A + B >= C on its own eigenvalues, "
          "mjMINVAL = 1e-15 on moving bodies";
      break;
    case Target::kDrake:
      // Drake's own test (drake-rejects-invalid-inertia) decides; the physics rules say when
      // physics disagrees.
      p.overrides["massless-moving-body"] = std::nullopt;  // drake-rejects-massless-body decides
      p.overrides["inertia-not-physical"] = Severity::kWarning;
      p.overrides[kMujocoUnpredicted] = std::nullopt;
      p.overrides[kGazeboLumped] = std::nullopt;
      p.summary =
          "Drake: CouldBePhysicallyValid (tolerance 16 eps times max(1, tr/2)); a massless "
          "body is accepted when mass lies outboard of it";
      break;
    case Target::kGazebo:
      p.merges_fixed_joints = true;
      p.overrides[kMujocoUnpredicted] = std::nullopt;
      p.overrides[kDrakeMassless] = std::nullopt;
      p.overrides[kDrakeInvalid] = std::nullopt;
      p.summary =
          "Gazebo (libsdformat 12 URDF conversion): fixed joints lumped unless "
          "disableFixedJointLumping/preserveFixedJoint; the lumped bodies are judged";
      break;
  }
  return p;
}

void ApplyTargetProfile(Target target, CheckOptions* options) {
  const TargetProfile p = GetTargetProfile(target);
  if (p.tolerance) options->tolerance = *p.tolerance;
  for (const auto& [rule, level] : p.overrides) options->overrides[rule] = level;
}

}  // namespace massprops
