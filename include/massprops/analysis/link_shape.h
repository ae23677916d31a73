#pragma once
/// @file
/// What a link's geometry says about where its mass can be, handed to the checks and repairs
/// that compare it with the declared inertial. CheckModel and PlanRepairs never read files:
/// the primitives (box, cylinder, ...) they measure themselves; for everything else (meshes) the
/// caller may give a LinkShapeFunction, such as MakeLinkShapeFunction in geometry_checks.h,
/// which reads the meshes' mass properties, and a LinkBoxFunction (MakeLinkBoxFunction), which
/// reads only their bounding boxes.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

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

/// The extent of a link's geometry without its mass properties: the union of the bounding boxes
/// of all its geometries, collision and visual, meshes included (a mesh's box is read from its
/// vertices alone, which is cheap: MakeLinkBoxFunction in geometry_checks.h). This is what
/// `massprops check` uses by default for links whose geometry includes meshes, so that the rules
/// that compare an inertia or a center of mass with the size of the body (units-suspect,
/// inertia-exceeds-geometry, inertia-about-origin-suspect, com-outside-geometry, and the
/// welded-group union of inertial-missing) see those links. It says nothing of how the mass is
/// spread inside the box, so it never feeds a rule that needs the solid's inertia or volume
/// (products-sign-suspect, the repairs from geometry): those need a LinkShape (`--geometry`).
struct LinkGeometryBox {
  Eigen::AlignedBox3d box_B;  ///< In the link frame B (metres); empty when known == 0.
  int known = 0;              ///< Geometries in the box.
  int meshes = 0;             ///< Of which meshes.
  /// Geometries whose extent could not be told (a mesh that does not resolve or cannot be read,
  /// an unknown geometry type): the body may reach beyond the box.
  int unknown = 0;
  bool from_collision = false;  ///< Some collision geometry is in the box.
  /// The first mesh that could not be used (its URI) and why; empty when none.
  std::string unresolved_uri;
  std::string unresolved_reason;
};

/// The LinkGeometryBox of a link, or nullopt when it has no geometry. Must not throw.
using LinkBoxFunction = std::function<std::optional<LinkGeometryBox>(const Link&)>;

/// Points whose convex hull holds a link's geometry, in the link frame B: the vertices of its
/// meshes (scaled and posed) and the corners of its primitives' posed boxes, for every geometry,
/// collision and visual. A body inside the geometry lies inside their convex hull, so for any
/// axis through its center of mass c, its moment of inertia is at most m · max over the points of
/// the squared distance to that axis (the squared distance to a line is convex, so its maximum
/// over the hull is at a vertex). Used by inertia-exceeds-geometry for links whose geometry
/// includes meshes (a CAD mesh is the part's envelope: far tighter than its bounding box).
struct LinkGeometryPoints {
  /// The corners of the primitives' boxes, in B (metres).
  std::vector<Eigen::Vector3d> corners_B;
  /// A mesh's distinct positions (its file's frame and unit, as MeshPoints holds them: shared,
  /// not copied) and how they are scaled and posed in B.
  struct PosedPositions {
    std::shared_ptr<const std::vector<Eigen::Vector3d>> positions;
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();
    Pose X_BG;
  };
  std::vector<PosedPositions> posed;
  /// How many points the geometries have: 8 per primitive's box, and each mesh's vertex count as
  /// LoadMeshFile gives it (the points visited are each mesh's distinct positions, which bound
  /// the same hull).
  std::size_t count = 0;
  int meshes = 0;   ///< Meshes read.
  int unknown = 0;  ///< Geometries that could not be read (then the hull is not the body's).

  /// Calls visit(p_B) for every point in B: the boxes' corners, then each mesh's positions, each
  /// computed as X_BG.p_AB + X_BG.R_AB · (v ∘ scale) when it is visited. A robot's meshes have
  /// hundreds of thousands of positions: they are not copied into B first.
  template <typename Visit>
  void ForEachPoint(Visit visit) const {
    for (const Eigen::Vector3d& p : corners_B) visit(p);
    for (const PosedPositions& mesh : posed) {
      for (const Eigen::Vector3d& v : *mesh.positions) {
        visit(Eigen::Vector3d(mesh.X_BG.p_AB + mesh.X_BG.R_AB * v.cwiseProduct(mesh.scale)));
      }
    }
  }
  /// Whether there is no point at all.
  bool empty() const {
    if (!corners_B.empty()) return false;
    for (const PosedPositions& mesh : posed) {
      if (!mesh.positions->empty()) return false;
    }
    return true;
  }
};

/// The LinkGeometryPoints of a link, or nullopt when it has no geometry. Must not throw.
using LinkPointsFunction = std::function<std::optional<LinkGeometryPoints>(const Link&)>;

}  // namespace massprops
