#pragma once
/// @file
/// What a link's geometry says about where its mass can be, handed to the checks and repairs
/// that compare it with the declared inertial. CheckModel and PlanRepairs never read files:
/// the primitives (box, cylinder, ...) they measure themselves; for everything else (meshes) the
/// caller may give a LinkShapeFunction, such as MakeLinkShapeFunction in geometry_checks.h,
/// which reads the meshes.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <string>

#include "massprops/model/model.h"

namespace massprops {

/// The link as a uniform solid filling its geometry (collision geometry if usable, else visual).
struct LinkShape {
  bool from_collision = true;  ///< false: the visual geometry was used.
  Eigen::AlignedBox3d box_B;   ///< Bounding box of the geometry in the link frame B (metres).
  double volume = 0;           ///< m³ (several geometries: overlaps counted twice). > 0.
  Eigen::Vector3d p_BoBcm_B = Eigen::Vector3d::Zero();  ///< Centroid in B.
  /// Inertia per unit mass about the centroid, expressed in B (m²; products as matrix entries,
  /// i.e. −∫xy dm per kg), so the solid of mass m has m·G_BBcm_B.
  Eigen::Matrix3d G_BBcm_B = Eigen::Matrix3d::Zero();
  /// "mesh" when a mesh was used, "primitive" otherwise (for messages).
  std::string kind = "primitive";
};

/// The shape of a link, or nullopt when it is not known (no geometry, a mesh that cannot be read).
/// Must not throw.
using LinkShapeFunction = std::function<std::optional<LinkShape>(const Link&)>;

}  // namespace massprops
