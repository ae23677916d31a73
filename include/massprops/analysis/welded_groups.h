#pragma once
/// @file
/// Welded groups (links joined by fixed joints move as one rigid body) and composite inertias:
/// per link, per welded group, and for the whole model at the zero configuration.
///
/// Composition follows DESIGN.md's stable order: the composite center of mass is found first
/// (mass-weighted average of the members' centers of mass), then each member's central inertia is
/// re-expressed in the common frame and shifted AWAY from its own center of mass to the composite
/// one (only additions of positive semi-definite terms m·(|d|²·1 − d·dᵀ)). Nothing is ever
/// shifted toward a center of mass.
///
/// Numbers are kept as plain Eigen matrices (inertia matrix entries, so the off-diagonal entries
/// are the negated products −∫xy dm, the same numbers URDF/SDF write as ixy), because the
/// composite of invalid file inertias must still be computable in order to be checked.

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "massprops/core/spatial_inertia.h"
#include "massprops/model/model.h"

namespace massprops {

/// Links joined by fixed joints: one rigid body.
struct WeldedGroup {
  std::string root_link;  ///< Name of the group's root link (the member nearest the model root).
  /// Indices into Model::links, root first, then the other members in file order.
  std::vector<int> links;
  /// Pose X_RL of each member link's frame L in the root link frame R, parallel to `links`
  /// (identity for the root).
  std::vector<Pose> X_RL;
  /// Index into Model::joints of the non-fixed joint attaching the group to its parent, -1 for
  /// the model root or a free-floating link.
  int parent_joint = -1;
  /// True when the group can move relative to its parent: attached through a non-fixed joint, or
  /// a free-floating link (an SDF link with no joint that is not the model's root link). The
  /// model's root group is not moving (URDF convention: fixed to the world or a floating base
  /// decided by the user of the file).
  bool is_moving = false;
};

/// Mass properties of a body S in some frame F: its mass, the position of its center of mass from
/// F's origin, and its inertia about its center of mass, all expressed in F.
struct MassProperties {
  double mass = 0;
  Eigen::Vector3d p_FoScm_F = Eigen::Vector3d::Zero();
  /// Inertia matrix about Scm expressed in F (symmetric; off-diagonals are −∫xy dm).
  Eigen::Matrix3d I_SScm_F = Eigen::Matrix3d::Zero();
};

/// A composite rigid body S (a welded group, or the whole model) in its reference frame R.
struct CompositeInertia {
  double mass = 0;
  /// Composite center of mass from R's origin, expressed in R. Zero when the mass is zero.
  Eigen::Vector3d p_RoScm_R = Eigen::Vector3d::Zero();
  /// Composite inertia about Scm, expressed in R (symmetric matrix).
  Eigen::Matrix3d I_SScm_R = Eigen::Matrix3d::Zero();

  /// The inertia about R's origin Ro, expressed in R: I_SScm_R + m·(|p|²·1 − p·pᵀ), p = p_RoScm_R
  /// (shifting away from the center of mass). About 20 flops.
  Eigen::Matrix3d CalcInertiaAboutOrigin() const;
  /// The central inertia as the core class. Precondition (checked by the core in debug builds:
  /// throws std::logic_error): the inertia is physically valid.
  RotationalInertia<double> CalcRotationalInertia() const;
  /// The spatial inertia about R's origin expressed in R. Precondition as for
  /// CalcRotationalInertia(), and mass > 0 when the core requires it.
  SpatialInertia<double> CalcSpatialInertia() const;
};

/// Partitions the model's links into welded groups, ordered by the file order of their root
/// links. Every link is in exactly one group. A link that is the child of several joints (a
/// closed chain in SDF) keeps the first of them, in file order, as its tree parent. A fixed-joint
/// cycle (malformed input) is cut at the link where it is detected. Joints whose parent link is
/// not in the model (e.g. SDF "world") attach their child group to the world: fixed → not moving,
/// otherwise moving. Never throws for well-formed Model values.
/// Cost: linear in the number of links and joints (iterative, no recursion).
std::vector<WeldedGroup> FindWeldedGroups(const Model& model);

/// The mass properties of a link in its own frame B, from its <inertial>: mass, p_BoBcm_B =
/// X_BBi.p, I_BBcm_B = R_BBi·I_Bi·R_BBiᵀ. A link without inertial has zero mass and inertia in
/// URDF, and the SDF defaults (mass 1, inertia diag(1, 1, 1) at the link origin) in SDF. A link
/// whose <inertial> could not be read wholly has what the loader loaded of it
/// (Link::loaded_inertial; UnknownInertialNumbers says which numbers are not the author's).
/// Non-finite numbers propagate. Never throws.
MassProperties LinkMassProperties(const Link& link, Model::Format format = Model::Format::kUrdf);

/// The link's spatial inertia about its origin Bo, expressed in its frame B (for a link without
/// inertial: zero in URDF, the SDF defaults in SDF; see LinkMassProperties). Precondition (checked
/// by the core in debug builds: throws std::logic_error): the link's inertial is finite and
/// physically valid.
SpatialInertia<double> LinkSpatialInertia(const Link& link,
                                          Model::Format format = Model::Format::kUrdf);

/// Composes bodies whose mass properties are given in one common frame R, in the stable order
/// (composite center of mass first, then shifts away from each member's center of mass).
/// With total mass zero, the center of mass is R's origin and the inertia is the sum of the
/// members' central inertias. Cost: two passes over the parts, about 60 flops per part.
CompositeInertia ComposeMassProperties(const std::vector<MassProperties>& parts_in_R);

/// The composite inertia of a welded group about its root link's frame R (center of mass and
/// central inertia expressed in R). Precondition: `group` came from FindWeldedGroups(model).
CompositeInertia CalcCompositeInertia(const Model& model, const WeldedGroup& group);

/// The whole model's composite at the zero configuration (every joint at 0), expressed in the
/// root link's frame. Links that cannot be reached from the root link through joints (free SDF
/// links) are left out and listed in `unreachable_links` (indices into Model::links).
struct ModelCompositeInertia {
  CompositeInertia inertia;
  std::vector<int> unreachable_links;
};

/// Computes the ModelCompositeInertia. A model without links, or whose root_link is not found,
/// gives zero mass and every link unreachable. Cost: linear in links and joints (iterative).
ModelCompositeInertia CalcModelCompositeInertia(const Model& model);

namespace internal {
// Not part of the API: shared by the library's welded_groups.cc and mass_report.cc.

// m·(|d|²·1 − d·dᵀ): the inertia of a point mass m at d about the origin (PSD for m >= 0).
inline Eigen::Matrix3d PointMassInertia(double mass, const Eigen::Vector3d& d) {
  return mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

// ComposeMassProperties on parts 0 .. count − 1 made on demand instead of stored: pass 1 asks
// only for each part's mass and center of mass (mass_and_com(k, &m, &p_RoPcm_R), false: not a
// part), pass 2 for the whole part (part(k, &props), false: not a part, or one of zero mass and
// zero inertia, which composition leaves out). Both passes do ComposeMassProperties' arithmetic
// on the same numbers, so the results are bit for bit those of composing the stored parts; a
// part of zero mass adds nothing in pass 1 (the sum of masses starts at +0 and cannot become
// −0), so pass 1 need not know which parts pass 2 leaves out. Storing the parts cost 104 bytes
// per link written and read back, out of cache at 10^5–10^6 links (docs/benchmarks.md).
template <typename MassAndCom, typename Part>
CompositeInertia ComposeMassPropertiesOnDemand(std::size_t count, MassAndCom mass_and_com,
                                               Part part) {
  CompositeInertia result;
  // Pass 1: total mass and the mass-weighted sum of the centers of mass.
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < count; ++k) {
    double mass = 0;
    Eigen::Vector3d p_RoPcm_R;
    if (!mass_and_com(k, &mass, &p_RoPcm_R)) continue;
    result.mass += mass;
    if (mass != 0) weighted += mass * p_RoPcm_R;
  }
  if (result.mass != 0) result.p_RoScm_R = weighted / result.mass;
  // Pass 2: each central inertia shifted away from its own center of mass to the composite one.
  MassProperties props;
  for (std::size_t k = 0; k < count; ++k) {
    if (!part(k, &props)) continue;
    result.I_SScm_R += props.I_SScm_F;
    if (props.mass != 0) {
      result.I_SScm_R += PointMassInertia(props.mass, props.p_FoScm_F - result.p_RoScm_R);
    }
  }
  return result;
}

// The link's mass, and its center of mass p_BoBcm_B, exactly as LinkMassProperties gives them,
// without computing the inertia.
double LinkMassAndCom(const Link& link, Model::Format format, Eigen::Vector3d* p_BoBcm_B);

// FindWeldedGroups(model) for a model whose tree is already known: parent_joint[i] and
// parent_link[i] for each link i as FindWeldedGroups finds them (-1: none). With `with_poses`
// false every group's X_RL is left empty (CalcGroupPoses makes one group's when needed), which
// spares 96 bytes per link of memory that is fresh on every call at 10^5-10^6 links.
std::vector<WeldedGroup> FindWeldedGroups(const Model& model, const std::vector<int>& parent_joint,
                                          const std::vector<int>& parent_link,
                                          bool with_poses = true);

// The X_RL that FindWeldedGroups gives `group` (same arithmetic, bit for bit), into *X_RL, for a
// group made without them; parent_joint and parent_link as given to FindWeldedGroups.
void CalcGroupPoses(const Model& model, const WeldedGroup& group,
                    const std::vector<int>& parent_joint, const std::vector<int>& parent_link,
                    std::vector<Pose>* X_RL);

// CalcCompositeInertia(model, group) from the members' poses (`X_RL`, parallel to group.links)
// and mass properties already computed: props_by_link[i] = LinkMassProperties(model.links[i],
// model.format) for every member i. The same arithmetic on the same numbers, so bit for bit the
// same result; the report (mass_report.cc) computes each link's once instead of reading the Link
// again for its group.
CompositeInertia CalcCompositeInertia(const WeldedGroup& group, const std::vector<Pose>& X_RL,
                                      const std::vector<MassProperties>& props_by_link);

}  // namespace internal

/// The pose X_WL of every link L in the root link frame W at the zero configuration, indexed like
/// Model::links; `reachable[i]` is false (and the pose identity) for links not reachable from the
/// root. Cost: linear in links and joints.
std::vector<Pose> CalcLinkPosesInRootFrame(const Model& model, std::vector<bool>* reachable);

}  // namespace massprops
