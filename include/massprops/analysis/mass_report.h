#pragma once
/// @file
/// The mass report (`massprops report`): mass, center of mass, inertia about the center of mass,
/// principal moments and axes, and the equivalent uniform box, for every link, every welded group
/// and the whole model, at the zero configuration or at given joint values, each expressed in a
/// frame the report names. Composition itself is welded_groups.h's (stable order of DESIGN.md);
/// this file adds joint configurations, frames and restriction of the work to what is asked.
/// The text / JSON / CSV renderings are output/report_format.h's (schema in docs/report.md).

#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "massprops/analysis/welded_groups.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"

namespace massprops {

/// What to compute. Link and joint names are those of Model (SDF: scoped "nested::link").
struct MassReportOptions {
  /// Joint values (radians for revolute/continuous, meters for prismatic); joints not named are
  /// at 0. A name that is not a joint of the model, a fixed joint, or a joint of another type
  /// (floating, planar, ball, ...) is an error.
  std::map<std::string, double> joint_values;
  /// When not empty, every result is re-expressed in this link's frame (at the configuration).
  std::string frame;
  /// When not empty: report only these links and the welded groups they belong to (no total).
  std::vector<std::string> only;
  /// When not empty: report only this link and its descendants (through any joint): their links,
  /// their welded groups (the group containing `subtree` is cut at it and rooted at it), and as
  /// total the composite of the whole subtree, expressed in the subtree link's frame.
  std::string subtree;
  /// A body whose estimated digits lost (BodyMassProperties::digits_lost) exceed this many gets
  /// a note in the text output.
  double digits_lost_threshold = 6;
  /// When not null (`report --geometry`): every reported link also gets the inertia its geometry
  /// implies for its declared mass (LinkMassReport::geometry), meshes resolved and cached as
  /// these options say. Not owned; must outlive ComputeMassReport.
  const MeshResolveOptions* geometry = nullptr;
};

/// Bits of BodyMassProperties::unknown.
inline constexpr unsigned kUnknownMass = 1u << 0;
inline constexpr unsigned kUnknownCom = 1u << 1;
/// The inertia about the center of mass, and so the principal moments and axes, the equivalent
/// box and the digits lost.
inline constexpr unsigned kUnknownInertia = 1u << 2;

/// What of a body is unknown (kUnknown* bits) when a part of it has the Inertial::unknown numbers
/// `inertial_unknown`: its mass if the part's mass; its center of mass if the part's mass or
/// position; its inertia if any of the part's numbers.
unsigned BodyUnknownOf(unsigned inertial_unknown);

/// The mass properties of one body (a link, a welded group, or a whole model or subtree),
/// expressed in the frame named `frame` (a link frame; its origin is the reference point).
struct BodyMassProperties {
  std::string frame;  ///< Name of the link whose frame F expresses everything below.
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();  ///< p_FoScm_F.
  /// Inertia matrix about Scm expressed in F (off-diagonals are −∫xy dm, as URDF's ixy).
  Eigen::Matrix3d inertia_about_com = Eigen::Matrix3d::Zero();
  /// Eigenvalues of inertia_about_com, ascending.
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();
  /// Rotation R_FP whose columns are the principal axes (unit, right-handed), in F, matching
  /// principal_moments.
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
  /// Sides of the uniform box of the same mass with the same principal moments, the side k along
  /// principal axis k: s_k² = 6·(I_i + I_j − I_k)/m. nullopt when the mass is not positive or the
  /// moments violate the triangle inequality (beyond round-off), where no such box exists.
  std::optional<Eigen::Vector3d> equivalent_box;
  /// Estimated significant digits lost to cancellation by a shift between the frame origin and
  /// the center of mass: log10(m·|com|² / max(tr(I_com), tiny)), at least 0. A tool that stores
  /// the inertia about the frame origin and shifts it back to the center of mass loses this many.
  double digits_lost = 0;
  /// Which numbers above are unknown (kUnknown* bits): a link whose <inertial> could not be read
  /// wholly (inertial-unreadable) holds what the loader of record loads, and a composite holding
  /// it is incomplete. The renderings print those numbers as unknown, never as measured.
  unsigned unknown = 0;
};

/// A link's declared central inertia beside the one its geometry implies for the same mass,
/// everything in the link's own frame B (whatever MassReportOptions::frame says).
struct LinkGeometryComparison {
  /// Why there is no comparison (a mesh not found or unreadable, no geometry, no positive
  /// declared mass); the fields below are then unset. Empty on success.
  std::string error;
  bool from_collision = true;  ///< false when the visual geometries were used.
  /// The geometry-implied body: center of mass p_BoBcm_B, inertia about it expressed in B,
  /// principal moments (ascending) and axes.
  BodyMassProperties geometry;
  /// The declared central inertia's principal moments (ascending).
  Eigen::Vector3d declared_moments = Eigen::Vector3d::Zero();
  /// Per principal moment k (both sorted ascending): (declared_k − geometry_k) / geometry_k;
  /// NaN where geometry_k is 0.
  Eigen::Vector3d moment_rel_diff = Eigen::Vector3d::Zero();
  /// The angle (degrees, in [0, 90] per axis, [0, 180] for frames) between the declared and the
  /// geometry-implied principal axes; nullopt when the axes are not defined (see
  /// CalcPrincipalAxisAngle).
  std::optional<double> axis_angle_deg;
  /// The meshes among the geometries used, in file order, with what their triangles looked like
  /// (the model used — closed solid, convex hull, thin shell —, an inverted winding, open or
  /// non-manifold edges; see DescribeMeshDiagnostics).
  struct Mesh {
    std::string uri;   ///< As written in the model file.
    std::string path;  ///< As resolved.
    MeshDiagnostics diagnostics;
    MeshFoundBy found_by = MeshFoundBy::kNone;  ///< How `path` was found (JSON "found_by").
  };
  std::vector<Mesh> meshes;
};

/// The angle in degrees between two sets of principal axes, given by the principal moments
/// (ascending) and the axes (columns, right-handed) of two inertias A and B. Moments closer than
/// `rel_gap` × the largest moment count as equal. When every moment of both is distinct: the
/// smallest rotation angle taking A's axes to B's, over the four sign choices of the axes that
/// keep them right-handed. When both have exactly one pair of equal moments and the distinct one
/// has the same rank: the angle between the two distinct axes (0..90). Otherwise nullopt (a
/// sphere-like inertia has no axes). Never throws.
std::optional<double> CalcPrincipalAxisAngle(const Eigen::Vector3d& moments_A,
                                             const Eigen::Matrix3d& axes_A,
                                             const Eigen::Vector3d& moments_B,
                                             const Eigen::Matrix3d& axes_B, double rel_gap = 1e-3);

/// Compares `link`'s declared central inertia (re-expressed in the link frame B) with the one
/// CalcLinkGeometryInertia gives for the declared mass. Failures are values (error set). Cost:
/// that of CalcLinkGeometryInertia (meshes loaded once per options.cache).
LinkGeometryComparison CompareLinkWithGeometry(const Link& link, const MeshResolveOptions& options);

/// One link's entry.
struct LinkMassReport {
  std::string name;
  BodyMassProperties properties;
  /// With MassReportOptions::geometry only (else null). Held apart, not in the entry: as an
  /// optional member the 400-byte comparison made every entry 712 bytes instead of 320 (g++ 12,
  /// x86-64), written for every link of every report (docs/benchmarks.md, section 2).
  std::shared_ptr<const LinkGeometryComparison> geometry;
};

/// One welded group's entry.
struct GroupMassReport {
  std::string root_link;
  std::vector<std::string> links;  ///< Root first, then the others in file order.
  BodyMassProperties properties;
  /// The members whose numbers are partly unknown (properties.unknown says what that leaves
  /// unknown of the group); empty when the composite is complete.
  std::vector<std::string> incomplete_links;
};

/// The report of one model.
struct ModelMassReport {
  std::string name;
  std::string file;
  std::vector<LinkMassReport> links;
  std::vector<GroupMassReport> welded_groups;
  /// The whole model (or the subtree); absent with MassReportOptions::only.
  std::optional<BodyMassProperties> total;
  /// Links left out of the total: not reachable from the model's root link (free SDF links).
  std::vector<std::string> unreachable_links;
  /// The links of the total whose numbers are partly unknown (total->unknown says what).
  std::vector<std::string> total_incomplete_links;
};

/// Computes the mass properties of a body given in frame F: principal moments and axes, the
/// equivalent box and the digits-lost estimate. Never throws (non-finite input gives non-finite
/// output and no box). Cost: about 200 ns.
BodyMassProperties MakeBodyMassProperties(const std::string& frame, double mass,
                                          const Eigen::Vector3d& p_FoScm_F,
                                          const Eigen::Matrix3d& I_SScm_F);

/// The sides of the uniform box of mass `mass` whose principal moments are `moments` (ascending):
/// s_k = sqrt(6·(I_i + I_j − I_k)/m). nullopt when mass <= 0, a moment is negative or the
/// triangle inequality fails by more than 32·eps·trace (smaller violations give a side of 0).
std::optional<Eigen::Vector3d> CalcEquivalentBox(double mass, const Eigen::Vector3d& moments);

/// The pose of joint's child frame C in its parent frame P at joint value q: X_PC(0)·Rot(axis, q)
/// for revolute and continuous joints, X_PC(0)·Trans(axis·q) for prismatic ones, X_PC(0) for any
/// joint at q = 0. Throws std::invalid_argument for a nonzero q on another joint type.
Pose CalcJointPose(const Joint& joint, double q);

/// Computes the report of `model` as `options` asks. Returns false and sets *error (a sentence
/// naming the joint or link) when an option names a joint or link the model does not have, gives
/// a value to a fixed or unsupported joint, or `only` and `subtree` are both given; *report is
/// then unspecified. Never throws for such input.
/// Cost: an index of the link and joint names (linear, hashing only), then work proportional to
/// what is asked: every link for a full report; for `only`, the listed links, their groups and
/// (with `frame`) their paths to the root; for `subtree`, the links of the subtree.
bool ComputeMassReport(const Model& model, const MassReportOptions& options,
                       ModelMassReport* report, std::string* error);

}  // namespace massprops
