#pragma once
/// @file
/// `massprops diff A B`: the mass properties of two descriptions of the same robot (a URDF and
/// its MJCF conversion, an SDF and the URDF it was made from, two revisions of one file),
/// compared per link matched by name, per welded group matched by its root link's name, and for
/// the whole robot. Every number is compared as a relative difference:
///   - mass: |a − b| / max(|a|, |b|);
///   - center of mass: |p_a − p_b| / L, L = max(|p_a|, |p_b|, radius of gyration √(λmax/m));
///   - inertia about the center of mass: max |I_a − I_b| (entries) / max(λmax_a, λmax_b).
/// Links are compared in their own frames (the converters keep link frames); the whole robot
/// in the frame of the first link both have (the anchor), so that a different world or base
/// offset does not count.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "massprops/model/model.h"

namespace massprops {

/// The mass properties of one body (a link, a welded group or the whole robot) in one file.
struct DiffSide {
  bool present = false;
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      ///< In the body's frame.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< About the center of mass, same frame.
  SourceLocation location;
};

/// One compared body.
struct DiffEntry {
  std::string kind;  ///< "link", "group" or "total".
  std::string name;  ///< The link, the group's root link, or the anchor link for "total".
  DiffSide a, b;
  double mass_difference = 0, com_difference = 0, inertia_difference = 0;  ///< Relative.
  /// For a link only in one file: "fused" (its welded group's root is in the other file, whose
  /// group then carries its mass) or "dropped" (the other file has none of its group).
  std::string missing_how;
  bool differs = false;  ///< A difference beyond the tolerance, or present in one file only.
};

struct ModelDiff {
  std::vector<DiffEntry> entries;  ///< Links (in A's order, then B's only), groups, then total.
  double tolerance = 0;
  bool differs = false;  ///< Some entry differs.
};

/// Compares `a` and `b`. A link that is massless in both and present in one only does not count
/// as a difference (MJCF's world, URDF dummy links). Never throws. Cost: linear in the links.
ModelDiff DiffModels(const Model& a, const Model& b, double tolerance);

}  // namespace massprops
