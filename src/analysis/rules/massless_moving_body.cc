// massless-moving-body (error) and its note massless-link-with-mass-outboard.
//
// Evidence: the welded group (does it move, on which joint: its type and axis), the masses of
// its members, the composite of everything outboard of it (OutboardComposite), the joints it
// carries to groups with mass, and the model's total mass (the scale of "no mass").
// Why: a group that moves with zero mass makes the mass matrix singular when nothing outboard of
// its joint gives the joint's coordinates inertia, or when a joint it carries gets none (see
// HingeInertiaOf for each joint type): simulators reject the model or become unstable (error).
// When the outboard bodies do give the joint inertia (a multi-axis joint's intermediate link),
// the mass matrix is regular: Drake and Pinocchio accept it; MuJoCo refuses a moving body below
// mjMINVAL = 1e-15 without boundmass: the note. A URDF with no <inertial> at all is a
// kinematics-only description: one finding for the model instead of one per body.

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/rules/rules.h"
#include "massprops/core/principal_axes.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kMasslessMovingBody = "massless-moving-body";
constexpr const char* kMasslessWithMassOutboard = "massless-link-with-mass-outboard";

// massless-moving-body: a joint's generalized coordinate has zero inertia (the mass matrix is
// singular) when the inertia that its outboard bodies put on it is at most this fraction of its
// natural scale (see HingeInertiaOf). Far above the round-off of composing written numbers
// (about 1e-16 relative: a point mass written on the axis composes to 0 or ~1e-17), far below
// any real body (a 1 m, 1 kg arm would need its mass within 1 µm of the axis).
constexpr double kSingularTolerance = 1e-12;

// What the bodies outboard of a joint give its generalized coordinates (massless-moving-body).
//
// With only joint J moving, at rates q̇ (every other joint still), the bodies inboard of J stay at
// rest and the kinetic energy is that of the bodies outboard of J (its child and all their
// descendants: composite mass m, center of mass c, central inertia I_cm, all in J's frame C, whose
// origin O lies on the axis): T = ½ q̇ᵀ M_JJ q̇ with M_JJ = S_Jᵀ 𝕀_O S_J, 𝕀_O their composite spatial
// inertia about O and S_J the joint's motion subspace. M_JJ is J's diagonal block of the mass
// matrix M, and M is positive semi-definite: if vᵀ M_JJ v = 0 for some v ≠ 0, the generalized
// velocity that is v on J and 0 elsewhere has zero kinetic energy, so M·(v, 0) = 0 and M is
// singular. (The converse needs more than diagonal blocks: two coaxial revolute joints through a
// massless link make M singular with every M_JJ > 0; that case is not detected here.)
//  - revolute/continuous, unit axis a through O: S = (a; 0), M_JJ = a·I_O·a with
//    I_O = I_cm + m·(|c|²·1 − c·cᵀ); zero when everything outboard lies on the axis line (a point
//    mass on it, a rod along it). Scale: tr(I_O) = tr(I_cm) + 2·m·|c|², the outboard composite's
//    own size about O (mass × extent² + trace): singular when a·I_O·a <=
//    kSingularTolerance·tr(I_O), scale-free, and true for any tr(I_O) when a·I_O·a = 0.
//  - prismatic: S = (0; a), M_JJ = m. Scale: the model's total mass.
//  - ball: S = (1; 0), M_JJ = I_O: singular when its smallest eigenvalue is zero (scale tr(I_O)).
//  - planar (normal a): two translations ⊥ a and a turn about a; det M_JJ = m²·(a·I_cm·a) (Schur
//    complement of the translational block m·1): zero mass or a·I_cm·a = 0 (scale tr(I_cm)).
//  - floating, and a free SDF link: M_JJ is the 6×6 spatial inertia, det M_JJ = m³·det(I_cm): zero
//    mass or a singular central inertia (a point mass, a rod; scale tr(I_cm)).
//  - other types (universal, screw, unknown): judged on the mass only.
// Every type first needs m > kSingularTolerance·(the model's total mass).
struct HingeInertia {
  bool singular = false;
  double mass = 0;    // outboard mass
  double moment = 0;  // the rotational inertia judged (a·I_O·a, a smallest moment), if any
  std::string why;    // singular: what has no inertia; regular: the rotational inertia judged
};

double SmallestMoment(const Eigen::Matrix3d& I) {
  return internal::ScaledPrincipalMoments(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                          PrincipalSolver::kAccurate)(0);
}

HingeInertia HingeInertiaOf(Joint::Type type, const Eigen::Vector3d& axis_C,
                            const CompositeInertia& outboard, double total_mass) {
  HingeInertia h;
  h.mass = outboard.mass;
  if (!(outboard.mass > kSingularTolerance * total_mass)) {
    h.singular = true;
    h.why = "nothing outboard of it has mass (outboard mass " + Num(outboard.mass) + " kg)";
    return h;
  }
  const Eigen::Matrix3d I_O = outboard.CalcInertiaAboutOrigin();
  const Eigen::Matrix3d& I_cm = outboard.I_SScm_R;
  const double norm = axis_C.norm();
  const Eigen::Vector3d a = norm > 0 ? Eigen::Vector3d(axis_C / norm) : Eigen::Vector3d::UnitZ();
  double scale = 0;
  if ((type == Joint::Type::kRevolute || type == Joint::Type::kContinuous) && norm > 0) {
    h.moment = a.dot(I_O * a);
    scale = I_O.trace();
    h.why = "moment of inertia about the joint axis " + Vec(a) + " through the joint origin";
  } else if (type == Joint::Type::kBall) {
    h.moment = SmallestMoment(I_O);
    scale = I_O.trace();
    h.why = "smallest principal moment of inertia about the joint center";
  } else if (type == Joint::Type::kPlanar && norm > 0) {
    h.moment = a.dot(I_cm * a);
    scale = I_cm.trace();
    h.why = "moment of inertia about the plane's normal " + Vec(a) + " through its center of mass";
  } else if (type == Joint::Type::kFloating) {
    h.moment = SmallestMoment(I_cm);
    scale = I_cm.trace();
    h.why = "smallest principal moment of inertia about its center of mass";
  } else {
    h.why.clear();
    return h;
  }
  h.singular = h.moment <= kSingularTolerance * scale;
  h.why = h.singular ? "everything outboard of it (mass " + Num(outboard.mass) +
                           " kg) gives the joint no inertia: its " + h.why + " is " +
                           Num(h.moment) + " kg·m²"
                     : h.why + " " + Num(h.moment) + " kg·m²";
  return h;
}

// For a massless group: the first non-fixed joint from one of its links to a group with mass
// whose outboard bodies give the joint's coordinates no inertia (why, in words), or nullopt. A
// joint to a massless group is judged with that group.
std::optional<std::string> SingularCarriedJoint(const RuleContext& ctx, const WeldedGroup& group) {
  for (int l : group.links) {
    for (const auto& [c, j] : ctx.children[l]) {
      if (ctx.group_of[c] == ctx.group_of[l]) continue;  // a welded member
      bool child_massless = true;
      ctx.CountContributingMembers(ctx.groups[ctx.group_of[c]], &child_massless);
      if (child_massless) continue;
      const Joint& joint = ctx.model.joints[j];
      const std::optional<CompositeInertia> outboard = ctx.OutboardComposite(c);
      if (!outboard || !std::isfinite(outboard->mass) || !outboard->I_SScm_R.allFinite()) continue;
      const HingeInertia h = HingeInertiaOf(joint.type, joint.axis, *outboard, ctx.total_mass);
      if (h.singular) {
        return "carries " + joint.type_name + " joint '" + joint.name + "', where " + h.why;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

const RuleInfo& MasslessMovingBodyRule() {
  static const RuleInfo kInfo{
      kMasslessMovingBody, Severity::kError, true,
      "A welded group that moves relative to its parent has zero mass, and nothing outboard "
      "gives its joint (or a joint it carries) inertia: the mass matrix is singular."};
  return kInfo;
}

const RuleInfo& MasslessWithMassOutboardRule() {
  static const RuleInfo kInfo{
      kMasslessWithMassOutboard, Severity::kNote, true,
      "A massless moving welded group with mass outboard of it (a multi-axis joint's "
      "intermediate link): physics accepts it, MuJoCo does not without boundmass."};
  return kInfo;
}

void CheckKinematicOnlyModel(RuleContext& ctx) {
  int moving = 0;
  const WeldedGroup* first = nullptr;
  for (const WeldedGroup& group : ctx.groups) {
    if (!group.is_moving) continue;
    ++moving;
    if (first == nullptr) first = &group;
  }
  if (first == nullptr) return;
  const Link& root = ctx.model.links[first->links.front()];
  ctx.Emit(kMasslessMovingBody, root, root.location,
           "the model has no <inertial> at all (a kinematics-only description): its " +
               std::to_string(moving) + " moving bod" + (moving == 1 ? "y is" : "ies are") +
               " massless, starting with link '" + root.name + "'; a simulator cannot use it",
           {{"mass", 0}, {"moving_groups", static_cast<double>(moving)}},
           "no <inertial> anywhere: " + std::to_string(moving) + " moving bod" +
               (moving == 1 ? "y is" : "ies are") + " massless (kinematics-only model)",
           {{"moving_bodies_count", static_cast<double>(moving)}},
           "add each link's <inertial>, or massprops fix --from-geometry to compute them");
}

MasslessVerdict CheckMasslessMovingGroup(RuleContext& ctx, const WeldedGroup& group,
                                         const std::string& who, bool all_massless) {
  if (!group.is_moving || !all_massless) return MasslessVerdict::kNone;
  const int root_index = group.links.front();
  const Link& root = ctx.model.links[root_index];
  Joint free;  // a free-floating SDF link moves as on a floating joint
  free.type = Joint::Type::kFloating;
  const Joint& joint = group.parent_joint >= 0 ? ctx.model.joints[group.parent_joint] : free;
  const std::string how = group.parent_joint >= 0
                              ? "moves on " + joint.type_name + " joint '" + joint.name + "'"
                              : "is free-floating";
  const std::optional<CompositeInertia> outboard = ctx.OutboardComposite(root_index);
  // An outboard <inertial> unreadable or not finite: its own finding says so; nothing to judge.
  if (!outboard || !std::isfinite(outboard->mass) || !outboard->I_SScm_R.allFinite()) {
    return MasslessVerdict::kSingular;
  }
  const HingeInertia hinge = HingeInertiaOf(joint.type, joint.axis, *outboard, ctx.total_mass);
  const std::vector<std::pair<std::string, double>> values = {
      {"mass", 0},
      {"outboard_mass", hinge.mass},
      {"moment_outboard", hinge.moment},
      {"group_links", static_cast<double>(group.links.size())}};
  const std::vector<std::pair<std::string, double>> evidence = {
      {"mass_kg", 0},
      {"outboard_mass_kg", hinge.mass},
      {"outboard_moment_kg_m2", hinge.moment},
      {"links_count", static_cast<double>(group.links.size())}};
  const std::string help =
      "give the link its mass and inertia (massprops fix --apply massless-moving-body)";
  const std::string singular =
      ": the mass matrix is singular (a joint coordinate has zero inertia), so simulators reject "
      "the model or become unstable";
  if (hinge.singular) {
    ctx.Emit(kMasslessMovingBody, root, MassLocation(root),
             who + " " + how + " but has zero mass, and " + hinge.why + singular, values,
             LinkHeadline(root.name, ": massless, and nothing outboard has mass (singular)"),
             evidence, help);
    return MasslessVerdict::kSingular;
  }
  if (const std::optional<std::string> carried = SingularCarriedJoint(ctx, group)) {
    ctx.Emit(kMasslessMovingBody, root, MassLocation(root),
             who + " " + how + " but has zero mass, and " + *carried + singular, values,
             LinkHeadline(root.name, ": massless; a joint it carries gets no inertia (singular)"),
             evidence, help);
    return MasslessVerdict::kSingular;
  }
  ctx.Emit(kMasslessWithMassOutboard, root, MassLocation(root),
           who + " " + how + " with zero mass, but " + Num(hinge.mass) + " kg lies outboard of it" +
               (hinge.why.empty() ? "" : " (" + hinge.why + ")") +
               ": the mass matrix is regular, so Drake and Pinocchio accept it; MuJoCo refuses a "
               "moving body whose mass is below mjMINVAL = 1e-15 unless its compiler options "
               "boundmass/boundinertia raise it (see `massprops check --target mujoco`)",
           values,
           LinkHeadline(root.name,
                        ": massless, " + FormatMass(hinge.mass) + " outboard (MuJoCo refuses it)"),
           evidence,
           "check with --target mujoco; a multi-axis joint's cross link may stay massless");
  return MasslessVerdict::kMassOutboard;
}

}  // namespace rules
}  // namespace massprops
