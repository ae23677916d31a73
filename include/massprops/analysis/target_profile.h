#pragma once
/// @file
/// Target profiles: what a simulator decides about a model's mass properties. `--target
/// generic|mujoco|drake|gazebo` on `check`, `report` and `fix` (and `target = "..."` in
/// .massprops.toml) picks one. A profile is a layer on top of the generic checks:
///   - it adjusts the CheckOptions (validity tolerance, which rules are errors), and
///   - it adds findings of its own (rule ids `mujoco-*`, `drake-*`, `gazebo-*`), computed here by
///     emulating the simulator's model compiler.
/// docs/targets.md cites the source of every decision.
///
/// The MuJoCo profile emulates MuJoCo 2.2.2's compiler on a URDF (src/xml/xml_urdf.cc and
/// src/user/user_model.cc, user_objects.cc of google-deepmind/mujoco at tag 2.2.2): the URDF
/// defaults (fusestatic, discardvisual, inertiafromgeom="auto"), the principal moments as its
/// Jacobi eigen-solver computes them, the exact triangle test, fusion of static bodies and the
/// absolute mjMINVAL = 1e-15 floor of moving bodies. tests/target_profile_mujoco_test.cc checks
/// the prediction against the real libmujoco on the corpus.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/model/model.h"

namespace massprops {

enum class Target { kGeneric, kMujoco, kDrake, kGazebo };

/// "generic", "mujoco", "drake", "gazebo".
const char* ToString(Target target);
/// Parses one of the names above; nullopt otherwise.
std::optional<Target> ParseTarget(std::string_view text);

/// The rules only target profiles report (registered in AllRules()).
const std::vector<RuleInfo>& TargetRules();

/// What a profile changes in the generic checks, before the user's own overrides.
struct TargetProfile {
  Target target = Target::kGeneric;
  /// Tolerance of the physical-validity test (relative to the trace), or nullopt to keep the
  /// generic one.
  std::optional<double> tolerance;
  /// Rule severities the profile sets (nullopt: the rule is off for this target).
  std::map<std::string, std::optional<Severity>> overrides;
  /// Whether the simulator merges links joined by fixed joints into one body.
  bool merges_fixed_joints = false;
  std::string summary;  ///< One line: what the simulator decides and how.
};

/// The profile of `target`.
TargetProfile GetTargetProfile(Target target);

/// Applies the profile's tolerance and severities to `options` (call before applying the
/// configuration file's and the command line's overrides, which win).
void ApplyTargetProfile(Target target, CheckOptions* options);

// ------------------------------------------------------------------------------------ MuJoCo

/// MuJoCo's mjMINVAL (mjtnum.h) and mjEPS (user/user_util.h) of version 2.2.2.
inline constexpr double kMujocoMinVal = 1e-15;
inline constexpr double kMujocoEps = 1e-14;

/// The compiler settings that matter for mass properties, with MuJoCo's URDF defaults
/// (mjXURDF::Parse sets fusestatic and discardvisual; the others are mjCModel's defaults).
/// A URDF may change them in `<mujoco><compiler .../></mujoco>`.
struct MujocoCompilerOptions {
  bool fusestatic = true;
  bool discardvisual = true;
  bool balanceinertia = false;
  double boundmass = 0;
  double boundinertia = 0;
  enum class InertiaFromGeom { kFalse, kTrue, kAuto };
  InertiaFromGeom inertiafromgeom = InertiaFromGeom::kAuto;
};

/// The <mujoco><compiler> attributes of a URDF text (defaults when absent or unreadable).
/// Never throws.
MujocoCompilerOptions ReadMujocoCompilerOptions(std::string_view urdf_text);

/// The eigen-decomposition MuJoCo 2.2.2 uses for inertias (mju_eig3: Jacobi rotations on a
/// quaternion, stopping when the largest off-diagonal entry is below 1e-12 in absolute value or
/// the rotation's cosine exceeds 1 − 1e-12, at most 500 sweeps; eigenvalues in decreasing order).
/// `full` is {ixx, iyy, izz, ixy, ixz, iyz} as URDF writes them. Reimplemented (not copied) to
/// reproduce its results bit for bit on the same machine; the test compares it with libmujoco.
struct MujocoEigen {
  std::array<double, 3> values{};  ///< Decreasing (as MuJoCo sorts them).
  std::array<double, 4> quat{};    ///< w, x, y, z: the principal frame in the input frame.
};
MujocoEigen MujocoEig3(const std::array<double, 6>& full);

/// One body as MuJoCo compiles it.
struct MujocoBody {
  std::string name;  ///< The URDF link's name.
  int link = -1;     ///< Index into Model::links.
  bool moving = false;
  double mass = 0;
  std::array<double, 3> inertia{};  ///< Principal moments after MuJoCo's clamping.
  /// Links fused into this body (fusestatic), by index into Model::links.
  std::vector<int> fused_links;
};

/// One refusal MuJoCo's compiler would raise.
struct MujocoError {
  std::string rule;     ///< A TargetRules() id, e.g. "mujoco-rejects-inertia-triangle".
  std::string message;  ///< MuJoCo's own words, e.g. "inertia must satisfy A + B >= C; ...".
  std::string body;     ///< The body MuJoCo names ("" when it names none).
  int link = -1;        ///< The link behind that body (index into Model::links).
  std::array<double, 3> inertia{};  ///< MuJoCo's principal moments of that body.
  double mass = 0;
};

/// What MuJoCo 2.2.2 would decide when compiling the model (a URDF) with these options.
struct MujocoPrediction {
  /// Every refusal, in the order MuJoCo meets them; MuJoCo stops at the first (errors after it
  /// are found by continuing as if it had been accepted). Empty: MuJoCo accepts the mass
  /// properties.
  std::vector<MujocoError> errors;
  /// The bodies as MuJoCo sees them after fusing static bodies (accepted or not).
  std::vector<MujocoBody> bodies;
  /// Why the prediction is not possible or not complete (a mesh whose volume decides a body's
  /// mass, a joint type MuJoCo does not know...). Empty when the prediction is exact.
  std::vector<std::string> unsupported;
  bool accepted() const { return errors.empty(); }
};

/// Emulates MuJoCo 2.2.2's compiler on the model's mass properties. Only URDF models are
/// predicted (an SDF model gives `unsupported`). Never throws.
MujocoPrediction PredictMujoco(const Model& model, const MujocoCompilerOptions& options = {});

// ------------------------------------------------------------------------------- the layer

/// The target's own findings for `model` (empty for generic), with the severities of `options`
/// (overrides; a rule turned off is dropped; link ignore comments are honoured).
/// `mujoco` holds the file's <mujoco><compiler> settings. Never throws.
/// `text` is the file's text (for Gazebo's <gazebo> lumping tags; may be empty).
std::vector<Finding> CheckTarget(const Model& model, Target target, const CheckOptions& options,
                                 const MujocoCompilerOptions& mujoco = {},
                                 std::string_view text = {});

/// Adds to the generic `findings` what the target decides about them (e.g. "MuJoCo accepts
/// it"); appends CheckTarget's findings; keeps the order by line, then rule.
void AddTargetFindings(const Model& model, Target target, const CheckOptions& options,
                       const MujocoCompilerOptions& mujoco, std::vector<Finding>* findings,
                       std::string_view text = {});

// ------------------------------------------------------------------------------- Gazebo

/// One body as Gazebo simulates a URDF: a welded group of links joined by fixed joints that are
/// not kept by <gazebo reference="JOINT"><disableFixedJointLumping>true</...> or
/// <preserveFixedJoint>true</...> (libsdformat's URDF conversion lumps the others). SDF models
/// are not lumped (one body per link).
struct GazeboBody {
  std::string name;          ///< The body's (root link's) name.
  std::vector<int> links;    ///< Indices into Model::links, root first.
  CompositeInertia inertia;  ///< Composite in the root link's frame.
};
/// The bodies, in the order of their root links (a URDF root link named "world" is the world,
/// not a body, and is left out). `urdf_text` is the file (for the tags).
std::vector<GazeboBody> GazeboBodies(const Model& model, std::string_view urdf_text);

/// The welded groups Gazebo lumps (GazeboBodies' partition, with each member's pose in its
/// group's root): FindWeldedGroups of the model with these fixed joints kept as joints: those
/// named by <gazebo reference="JOINT"> with <disableFixedJointLumping>true or
/// <preserveFixedJoint>true, and those whose parent is a root link named "world" (libsdformat's
/// world, not a link); every joint of an SDF model. Never throws.
std::vector<WeldedGroup> GazeboLumpedGroups(const Model& model, std::string_view urdf_text);

/// Repairs that make the target accept the model, on top of `repairs` (the generic ones, which
/// are applied first): for MuJoCo, the nearest valid inertia for a triangle refusal and a floor
/// raised under the mass and principal moments of moving bodies below mjMINVAL. Returns the
/// combined list (one repair per link). Never throws.
std::vector<Repair> PlanTargetRepairs(const Model& model, Target target,
                                      const MujocoCompilerOptions& mujoco,
                                      const std::vector<Repair>& repairs);

}  // namespace massprops
