#pragma once
/// @file
/// SDFormat 1.11 `<inertial auto="true">`: a link's mass properties computed from its collision
/// geometries, as the SDFormat 1.11 specification (sdf/1.11/inertial.sdf, collision.sdf) says and
/// libsdformat 14 implements (Link::ResolveAutoInertials, Collision::CalculateInertial):
///   - each <collision>'s geometry is a uniform solid of its <density> (kg/m³); a collision
///     without one takes the link's <inertial><density>, else the default 1000 kg/m³;
///   - each solid's inertia is placed at its collision pose in the link frame, and the solids
///     are summed (overlaps count twice), about their common center of mass, in link axes;
///   - a <mass> beside auto="true" scales the sum to that mass (same center, inertia × ratio);
///   - the inertial frame is at the center of mass with the link's axes.
/// Shapes: box, cylinder, sphere, capsule, ellipsoid from unit_inertia.h, meshes from
/// mesh_inertia.h (through CalcGeometryMassProperties of mesh_loader.h).

#include <optional>
#include <string>
#include <vector>

#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"

namespace massprops {

/// libsdformat's DensityDefault(): water, kg/m³ (sdf/1.11/collision.sdf <density> default).
inline constexpr double kSdfDefaultDensity = 1000.0;

/// One collision of an auto-inertial link.
struct AutoInertiaCollision {
  std::string name;            ///< The <collision> name attribute (for messages).
  Geometry geometry;           ///< With X_BG, its pose in the link frame B.
  double density = 0;          ///< kg/m³, already chosen (collision, link, or default).
  std::string density_source;  ///< "collision", "inertial" or "default" (for messages).
};

/// The computed inertial: Inertial::X_BBi is (center of mass, identity rotation), the six
/// numbers are the inertia about the center of mass in the link axes (products as SDF writes
/// them: matrix entries). `summary` says what was computed from which collisions, e.g.
/// "6 kg from 1 collision: 'c' box 1 × 1 × 1 m at 6 kg/m³ (collision <density>)".
struct AutoInertiaResult {
  Inertial inertial;
  std::string summary;
};

/// Computes the auto inertial of a link from `collisions`. `mass` (the <mass> written beside
/// auto="true") scales the result to it. Returns nullopt and sets *error when there is no
/// collision, a geometry cannot be computed (an unsupported shape, a mesh that cannot be read,
/// a zero volume), a density is not positive and finite, or the total mass is zero. Never
/// throws. Cost: about 100 flops per primitive; meshes linear in their triangles.
std::optional<AutoInertiaResult> CalcAutoInertial(
    const std::vector<AutoInertiaCollision>& collisions, std::optional<double> mass,
    const MeshResolveOptions& mesh_options, std::string* error);

}  // namespace massprops
