#pragma once
/// @file
/// Mass properties (volume, center of volume, inertia) of a body bounded by a triangle mesh.
///
/// A closed, consistently oriented mesh is treated as the boundary of a uniform solid and
/// integrated exactly by the divergence theorem in the signed-tetrahedron (covariance) form of
/// Kallay, "Computing the moment of inertia of a solid defined by a triangle mesh", Journal of
/// Graphics Tools 11(2), 2006: every triangle (a, b, c) spans with a reference point R a
/// tetrahedron of signed volume det[a b c]/6 whose covariance about R is
/// det[a b c]/120·(a·aᵀ + b·bᵀ + c·cᵀ + s·sᵀ), s = a + b + c (positions from R); summed over the
/// triangles these give the solid's volume, first moment and covariance exactly. R is the center
/// of the mesh's bounding box, so a mesh far from the origin loses no digits to cancellation.
///
/// Real meshes are not always closed: the topology (boundary, non-manifold and inconsistently
/// oriented edges, degenerate triangles, duplicated vertices) is measured. A mesh with such edges
/// whose integral does not depend on the reference point (T-junctions, zero-area cracks) is still
/// a closed solid; any other is replaced by its convex hull (computed with qhull) or by a thin
/// shell of its triangles, as MeshInertiaOptions says. MeshDiagnostics tells what was found and
/// which model was used. Every cost is linear in the number of triangles (the hull: n log n).

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "massprops/core/rotational_inertia.h"

namespace massprops {

/// A triangle soup or mesh: vertex positions and triangles as triples of indices into them.
/// The frame of the positions is the mesh's own (a geometry frame G, before any scale).
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::int32_t, 3>> triangles;
};

/// How the mass properties were modelled.
enum class MeshSolidModel {
  kClosedSolid,  ///< The mesh bounds a solid: divergence theorem on its own triangles.
  kConvexHull,   ///< The mesh is open or non-manifold: the solid convex hull of its vertices.
  kThinShell,    ///< The triangles as a thin shell of uniform thickness (area × thickness).
};

/// "closed solid", "convex hull" or "thin shell".
const char* ToString(MeshSolidModel model);

/// What to do with a mesh that does not bound a solid (open, non-manifold, inconsistently
/// oriented, or of zero volume).
struct MeshInertiaOptions {
  /// kConvexHull (the default) or kThinShell; kClosedSolid means "integrate anyway" (the result
  /// is then only as good as the mesh). When the hull cannot be built (fewer than 4 points not
  /// in a plane) the thin shell is used.
  MeshSolidModel open_mesh_model = MeshSolidModel::kConvexHull;
  /// Wall thickness of the thin-shell model, in the mesh's length unit (1 mm for meshes in m).
  double shell_thickness = 1e-3;
  /// A mesh with boundary, non-manifold or inconsistent edges is still integrated as a closed
  /// solid when its signed integral does not depend on the reference point to this relative
  /// tolerance (see MeshDiagnostics::reference_point_sensitivity): CAD exports often have
  /// T-junctions or float-rounding cracks whose area is nil. 0 disables this.
  double closure_tolerance = 1e-6;
  /// Density of the material: mass = density × volume.
  double density = 1.0;
  /// MeshCache::MassProperties only, kept for the cache's key: MeshCache reads an STL file's
  /// triangles directly, without assimp, whatever it says (the same triangles, floats and order,
  /// so the same volume, center and inertia; num_vertices and duplicate_vertices_merged may then
  /// count the file's distinct positions or every corner rather than LoadMeshFile's vertices).
  /// The density rules, which run by default, set it (docs/rules.md).
  bool read_stl_directly = false;
};

/// What the mesh looked like and what was done with it.
struct MeshDiagnostics {
  std::int64_t num_vertices = 0;   ///< As given.
  std::int64_t num_triangles = 0;  ///< As given.
  /// Vertices at exactly the same position as an earlier one, merged for the topology (an STL
  /// file repeats every vertex in each triangle). The integrals do not depend on merging.
  std::int64_t duplicate_vertices_merged = 0;
  /// Triangles with a repeated vertex (after merging) or an area below 1e-12 × (longest edge)²;
  /// they add nothing to the integrals. Those with a repeated vertex are left out of the
  /// topology (they have no edges); slivers are kept (they may close a T-junction).
  std::int64_t degenerate_triangles = 0;
  std::int64_t edges = 0;               ///< Distinct undirected edges.
  std::int64_t boundary_edges = 0;      ///< Used by one triangle: the mesh is open.
  std::int64_t non_manifold_edges = 0;  ///< Used by three or more triangles.
  /// Used by two triangles in the same direction: their windings disagree.
  std::int64_t inconsistent_edges = 0;
  /// The signed volume of the closed mesh was negative (triangles wound clockwise seen from
  /// outside): the result is that of the solid, the sign was flipped.
  bool winding_inverted = false;
  /// For a mesh that is not a closed manifold: the largest relative change of volume, center
  /// (relative to the bounding-box diagonal) and central inertia of the signed integral when the
  /// reference point moves by about half the mesh's size. Zero (to round-off) when the surface
  /// encloses a volume despite its edges (T-junctions); about (hole area)/(size)² otherwise.
  /// 0 for a closed manifold (not computed).
  double reference_point_sensitivity = 0;
  MeshSolidModel model = MeshSolidModel::kClosedSolid;
  /// Why a fallback model was used ("3 boundary edges", "qhull: ...", ...); empty if none.
  std::string fallback_reason;

  /// True if every edge is shared by exactly two triangles in opposite directions.
  bool IsClosedManifold() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0;
  }
};

/// Mass properties of the body a mesh describes, in the mesh's frame G and length unit.
struct MeshMassProperties {
  double volume = 0;  ///< Of the model used (thin shell: area × shell_thickness).
  double area = 0;    ///< Surface area of the mesh's triangles (not of the hull).
  double mass = 0;    ///< density × volume.
  Eigen::Vector3d p_GoGcm_G = Eigen::Vector3d::Zero();  ///< Center of mass (uniform density).
  /// Inertia about the center of mass for `mass` (negated products: these are matrix entries).
  RotationalInertia<double> I_GGcm_G;
  MeshDiagnostics diagnostics;
};

/// One sentence on what was notable about a mesh and what was done about it, for users: the
/// winding was inverted (flipped), it is open / non-manifold / inconsistently oriented (with the
/// counts) and which model was used (closed solid despite T-junctions, convex hull, thin shell,
/// and why), degenerate triangles. Empty for a clean closed manifold integrated as it is.
std::string DescribeMeshDiagnostics(const MeshDiagnostics& diagnostics);

/// The topology of a mesh: fills every count of MeshDiagnostics except winding_inverted, model
/// and fallback_reason. Throws std::invalid_argument if a triangle's index is out of range or a
/// vertex is not finite. Cost: linear in vertices + triangles (a hash of the positions and a
/// bucket sort of the edges by their smaller vertex).
MeshDiagnostics AnalyzeMeshTopology(const TriangleMesh& mesh);

/// Volume, center of mass and central inertia of the body bounded by `mesh` (see the file
/// comment for the method and the fallbacks). An empty mesh, or one whose every model has zero
/// volume (e.g. a single flat triangle with shell_thickness 0), gives volume 0 and a zero
/// inertia with the center at the area centroid (or the origin when there is no area).
/// The inertia is not checked for validity (a mesh integrated with kClosedSolid despite defects
/// may give an invalid one). Throws std::invalid_argument if an index is out of range, a vertex
/// is not finite, or density or shell_thickness is negative or not finite.
/// Cost: about 100 flops per triangle plus AnalyzeMeshTopology (1e6 triangles: see
/// bench/mesh_inertia_bench.cc and docs/meshes.md); the hull fallback adds qhull's n log n.
MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options = {});

/// Volume, center and inertia of the solid bounded by `mesh` integrated by the divergence
/// theorem with no topology analysis and no fallback: the signed result (negative volume for an
/// inward winding). Meaningful only for a closed, consistently oriented mesh. Throws
/// std::invalid_argument as CalcMeshMassProperties. Cost: about 100 flops per triangle.
MeshMassProperties CalcClosedMeshMassPropertiesSigned(const TriangleMesh& mesh);

/// The convex hull of the mesh's vertices as a closed, outward-wound triangle mesh (qhull,
/// options "Qt"). Returns false and sets *error (qhull's message) when the hull cannot be
/// built (fewer than 4 points, or all points in a plane). Cost: n log n in the vertices.
bool CalcConvexHull(const TriangleMesh& mesh, TriangleMesh* hull, std::string* error);

/// The same body with mass `mass` (volume, center unchanged; inertia scaled by mass/this mass).
/// Precondition: properties.mass > 0 and mass >= 0 (throws std::invalid_argument otherwise).
MeshMassProperties ScaleToMass(const MeshMassProperties& properties, double mass);

}  // namespace massprops
