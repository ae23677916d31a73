#pragma once
// Private to the library: CalcMeshMassProperties for a mesh whose vertices are known to sit at
// distinct positions (MeshCache's directly read binary STL: its reader found them while reading),
// so that AnalyzeMeshTopology does not hash the positions a second time; and in two steps, so that
// MeshCache analyzes a mesh once for all the options it is asked with.

#include "massprops/mesh/mesh_inertia.h"

namespace massprops::internal {

/// massprops::CalcMeshMassProperties(mesh, options), the same numbers. With `distinct_vertices`
/// the caller vouches for what the direct binary STL reader knows of its mesh: no two vertices
/// have the same position (-0 and +0 the same), every vertex is finite and used by a triangle,
/// and every index names a vertex. The topology then takes each vertex as its own
/// representative, the mesh is not validated again, and its box is that of its vertices. A mesh
/// scaled since that was known keeps it when every scale factor s is finite with
/// 1e-30 <= |s| <= 1e30 (distinct float coordinates times such s stay distinct, and finite, in
/// double); the caller checks that.
MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options,
                                          bool distinct_vertices);

/// What CalcMeshMassProperties finds of a mesh before its options matter: the topology, the box
/// of the used vertices, the signed integral about the box's center and, for a mesh that is not a
/// closed manifold, how much that integral depends on the reference point (the diagnostics'
/// reference_point_sensitivity). An open mesh is asked for twice in one `check` (the density rules
/// model it as a closed solid, the hull bound as a thin shell): MeshCache keeps this between them.
struct MeshSolidAnalysis {
  MeshDiagnostics diagnostics;
  double diagonal = 0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  MeshMassProperties signed_result;
};

/// Throws std::invalid_argument, as CalcMeshMassProperties does, when the options' density or
/// shell thickness is negative or not finite.
void CheckMeshInertiaOptions(const MeshInertiaOptions& options);

/// The analysis above (validates the mesh: throws std::invalid_argument as
/// CalcMeshMassProperties does). `distinct_vertices` as above.
MeshSolidAnalysis AnalyzeMeshSolid(const TriangleMesh& mesh, bool distinct_vertices);

/// CalcMeshMassProperties(mesh, options, distinct_vertices) from `analysis`, which must be
/// AnalyzeMeshSolid(mesh, distinct_vertices): the same numbers, bit for bit.
MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options,
                                          const MeshSolidAnalysis& analysis);

}  // namespace massprops::internal
