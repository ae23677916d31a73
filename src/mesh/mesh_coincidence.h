#pragma once
// Private to the library: CalcMeshMassProperties for a mesh whose vertices are known to sit at
// distinct positions (MeshCache's directly read binary STL: its reader found them while reading),
// so that AnalyzeMeshTopology does not hash the positions a second time.

#include "massprops/mesh/mesh_inertia.h"

namespace massprops::internal {

/// massprops::CalcMeshMassProperties(mesh, options), the same numbers. With `distinct_vertices`
/// the caller vouches that no two vertices have the same position (-0 and +0 the same): the
/// topology then takes each vertex as its own representative. A mesh scaled since that was
/// known keeps it when every scale factor s is finite with 1e-30 <= |s| <= 1e30 (distinct float
/// coordinates times such s stay distinct in double); the caller checks that.
MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options,
                                          bool distinct_vertices);

}  // namespace massprops::internal
