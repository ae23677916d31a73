#pragma once
// Private to the library: STL files read without assimp (src/mesh/mesh_bounds.cc holds the
// readers, shared with LoadMeshBounds). MeshCache::MassProperties uses it when
// MeshInertiaOptions::read_stl_directly is set (the density rules): loading assimp and its
// post-processing cost 5 to 7 times what the whole `massprops check` of a robot with STL meshes
// costs otherwise (docs/rules.md).

#include <string>

#include "massprops/mesh/mesh_inertia.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops::internal {

/// The triangles of the STL file at `path` (binary: 84 + 50·n bytes exactly, as assimp 5.2 tells
/// it from ascii; ascii: starts with "solid", every facet a "vertex" triple), each triangle with
/// its own three vertices in file order, coordinates as the 32-bit floats assimp keeps (strtof
/// for ascii). The same triangles, in the same order and with the same coordinates, as assimp
/// gives (it joins identical vertices, which the mass properties do not depend on). Returns false
/// (and leaves *mesh empty) when the file is not such an STL, has no triangle or a coordinate is
/// not finite: LoadMeshFile then asks assimp, which says what is wrong. When `points` is not null,
/// the same read also gives a binary STL's hull-bound points (*has_points true; see
/// BinaryStlPoints in mesh_bounds.cc: the distinct positions, and the vertex count LoadMeshFile
/// gives); not an ascii STL's, nor a file of colored facets ("COLOR=" in its header): then
/// *has_points is false. Never throws.
bool ReadStlDirect(const std::string& path, TriangleMesh* mesh, MeshPoints* points = nullptr,
                   bool* has_points = nullptr);

}  // namespace massprops::internal
