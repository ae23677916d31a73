#pragma once
/// @file
/// Check rules that read a link's geometry (meshes included): `inertia-disagrees-with-geometry`
/// and `mesh-unreadable`. Both are off unless asked for (`massprops check --geometry`), since
/// they read mesh files. They live apart from checks.h's CheckModel, which never reads files.

#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/link_shape.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"

namespace massprops {

inline constexpr const char* kInertiaDisagreesWithGeometryRule = "inertia-disagrees-with-geometry";
inline constexpr const char* kMeshUnreadableRule = "mesh-unreadable";

/// What the geometry rules need.
struct GeometryCheckOptions {
  /// Run the rules at all (`--geometry`); when false CheckModelGeometry returns nothing.
  bool enabled = false;
  /// `inertia-disagrees-with-geometry` fires when, for some k, the declared and the
  /// geometry-implied principal moments (both ascending) differ by more than this factor:
  /// max(d_k/g_k, g_k/d_k) > factor. Must be > 1.
  double factor = 2;
  /// Where meshes are found, and the cache that reads each file once (model_file is set per
  /// model by CheckModelGeometry from Model::file).
  MeshResolveOptions resolve;
  /// Severity overrides and disabling (CheckOptions::overrides) for these two rules.
  CheckOptions check;
};

/// The LinkShapeFunction that reads meshes: for a link, CalcLinkGeometryInertia at unit mass
/// (collision geometry if all of it can be computed, else visual; meshes resolved by `resolve`,
/// whose model_file should be the model's file and whose cache should be set so that each mesh
/// is read once), as a LinkShape with the box of the geometries used. nullopt when the link has
/// no usable geometry. Give it to CheckOptions::shape and RepairOptions::shape so that the
/// units, products-sign and about-origin rules and `fix --from-geometry` use meshes.
/// The returned function holds a copy of `resolve` (the cache by pointer: it must outlive it).
LinkShapeFunction MakeLinkShapeFunction(const MeshResolveOptions& resolve);

/// The LinkBoxFunction that reads only the meshes' bounding boxes (CalcGeometryBounds: STL and
/// OBJ without assimp, other formats through it), each file once per `resolve.cache`, which should
/// be set and outlive the function. `resolve.model_file` is the model's file (relative URIs); a
/// geometry from an included SDF file is resolved relative to that file. For every geometry of
/// the link, collision and visual. Never throws.
LinkBoxFunction MakeLinkBoxFunction(const MeshResolveOptions& resolve);

/// The LinkPointsFunction that reads the meshes' vertices (through `resolve.cache`, which should
/// be set and outlive the function: each file is loaded once) and the corners of the primitives'
/// posed boxes, for every geometry of the link, collision and visual. Never throws.
LinkPointsFunction MakeLinkPointsFunction(const MeshResolveOptions& resolve);

/// The LinkShapeFunction of a link's closed meshes: the first of its visual geometries, then its
/// collision geometries, that consists of meshes only, each of which resolves, reads and is
/// watertight after its scale (MeshDiagnostics::IsClosedManifold: every edge shared by exactly
/// two triangles wound in opposite directions; or a surface that encloses its volume despite
/// T-junctions or cracks of no area: reference_point_sensitivity <= closure_tolerance, 1e-6, as
/// the STL files of CAD exports are), as one uniform solid (volumes summed, overlaps
/// counted twice; LinkShape::kind "mesh", box_B left empty). The visual set comes first: a CAD
/// export's visual mesh is the part's own surface (the solid its mass was computed from), where
/// collision meshes are often simplified. nullopt when neither set qualifies (a primitive, an open
/// mesh, a mesh that does not resolve). For the density rules (CheckOptions::closed_mesh) and `fix
/// --density LINK=RHO` / `--material`. Meshes are integrated as closed solids (no convex hull is
/// computed for an open mesh: it is refused). Each file is read once per `resolve.cache`, which
/// should be set and outlive the function. Never throws.
LinkShapeFunction MakeClosedMeshShapeFunction(const MeshResolveOptions& resolve);

/// Reads, on `threads` threads (the calling one included), what the functions above will ask
/// resolve.cache for about the meshes of `model`: each file's box (MakeLinkBoxFunction; a binary
/// STL's hull-bound points come with it) and its closed-solid mass properties per scale
/// (MakeClosedMeshShapeFunction). Changes no result: the cache computes each number once, the
/// same way, whichever thread asks first. Nothing without a cache, with fewer than 2 threads or
/// fewer than 2 mesh files. Never throws.
void PrefetchModelMeshes(const Model& model, const MeshResolveOptions& resolve, int threads);

/// The two rules above, as RuleInfo (both warnings, both off by default).
const std::vector<RuleInfo>& GeometryRules();

/// Runs the geometry rules on every link of `model` that has geometry and a positive mass:
/// `mesh-unreadable` for each mesh that cannot be resolved or read (its uri and the reason), and
/// `inertia-disagrees-with-geometry` when the declared central inertia's principal moments and
/// those the geometry implies for the declared mass (CalcLinkGeometryInertia) differ by more
/// than options.factor. Honours options.check.overrides and Link::ignored_rules. Returns
/// findings in link order. Never throws for bad input. Cost: loads each mesh once per cache.
std::vector<Finding> CheckModelGeometry(const Model& model, const GeometryCheckOptions& options);

}  // namespace massprops
