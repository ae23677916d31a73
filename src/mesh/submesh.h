#pragma once
// Private to mesh: SDF <submesh>, one named part of a loaded mesh file (LoadMeshSubmesh and
// MeshCache in mesh_loader.h; docs/meshes.md, "Submeshes").
#include <string>
#include <vector>

#include "massprops/mesh/mesh_loader.h"
#include "mesh/mesh_backend.h"

namespace massprops::internal {

/// LoadMeshFile's mesh and, in *parts (when not null), its parts (MeshPartRange) in order.
/// Returns false and sets *error as LoadMeshFile does.
bool LoadMeshFileParts(const std::string& path, TriangleMesh* mesh,
                       std::vector<MeshPartRange>* parts, std::string* error);

/// The parts of `whole` (whose parts are `parts`) named submesh.name, in order, as one mesh: each
/// part's vertices and triangles, and with submesh.center each part moved so that the center of
/// its vertices' bounding box is the origin (gz-common's SubMesh::Center(0)). Returns false and
/// sets *error (naming `path`, the submesh and up to 8 of the names the file has) when no part
/// has that name or those that have it hold no triangle. Precondition: the parts' ranges lie in
/// `whole` (LoadMeshFileParts gives such). Cost: one pass over the selected parts.
bool SelectSubmesh(const TriangleMesh& whole, const std::vector<MeshPartRange>& parts,
                   const MeshSubmesh& submesh, const std::string& path, TriangleMesh* mesh,
                   std::string* error);

/// The distinct non-empty names of `parts`, in order.
std::vector<std::string> PartNames(const std::vector<MeshPartRange>& parts);

/// The text that tells a part's cached numbers from the whole file's and the other parts' (the
/// persistent cache's entry names, FileKey::part): "" for the whole file.
std::string SubmeshKey(const MeshSubmesh& submesh);

}  // namespace massprops::internal
