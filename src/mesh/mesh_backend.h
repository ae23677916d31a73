#pragma once
// Private to the library: the code that needs the mesh libraries (assimp, with draco; qhull) is
// a separate shared object, libmassprops_meshlibs.so (src/mesh/mesh_libraries.cc),
// loaded with dlopen the first time a mesh is read or a convex hull computed. A process that
// never reads a mesh (`massprops check` without --geometry) neither maps those libraries nor
// binds their symbols: about half of the tool's start-up time (docs/benchmarks.md). Static builds
// (BUILD_SHARED_LIBS=OFF) link it into the library instead (MASSPROPS_MESH_BACKEND_STATIC).
// The same module holds yaml-cpp's reading of YAML files (src/io/yaml_scalars.h): its own entry,
// looked up (ModuleEntry, from src/io/yaml_reader.cc) the first time a xacro package's .yaml
// file is read.

#include <array>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "massprops/mesh/mesh_inertia.h"

namespace massprops::internal {

/// One part of a mesh file as loaded: the vertices and triangles that one mesh of one node of the
/// scene graph adds, contiguous in the TriangleMesh. `name` is the name gz-common gives that
/// submesh (SDF <submesh><name>): the node's name, or for a DAE node without a name that of its
/// nearest named ancestor below the scene's root; empty when there is none.
struct MeshPartRange {
  std::string name;
  std::size_t first_vertex = 0, vertex_count = 0;
  std::size_t first_triangle = 0, triangle_count = 0;
};

/// What the mesh libraries do for massprops. Version 2 (the parts); a changed layout gets a new
/// entry name.
struct MeshBackend {
  /// Reads the mesh file at `path` with assimp (triangulated, identical vertices joined, every
  /// node's transform applied, mirrored nodes re-wound); *parts (when not null) gets its parts,
  /// in the order of the mesh. Returns false and sets *error (which names the file) when assimp
  /// cannot read it or it holds no triangle. Never throws.
  bool (*load_mesh)(const char* path, TriangleMesh* mesh, std::vector<MeshPartRange>* parts,
                    std::string* error);
  /// qhull ("Qt") on `count` points (x, y, z consecutive): the hull's triangles as indices into
  /// the points, and each triangle's outward normal. Returns qhull's exit code (0 on success);
  /// *messages gets qhull's messages. Never throws.
  int (*convex_hull)(const double* points, int count, std::vector<std::array<int, 3>>* triangles,
                     std::vector<std::array<double, 3>>* normals, std::string* messages);
};

/// The mesh libraries, loaded on the first call (thread-safe); later calls return the same.
/// Returns null and sets *error (if not null) when the shared object cannot be loaded; the
/// message names it and says why (dlerror).
const MeshBackend* GetMeshBackend(std::string* error);

#ifndef MASSPROPS_MESH_BACKEND_STATIC
/// The address of the module's symbol `name` (dlsym), the module loaded on the first call
/// (thread-safe). Null, with *error (if not null) set, when the module cannot be loaded or has no
/// such symbol. For the parts above mesh that keep an entry in the module (the YAML reader of
/// src/io/yaml_scalars.h): see ModuleEntry.
void* ModuleSymbol(const char* name, std::string* error);

/// The module's entry `name`, a C function returning a const T*, called once per T
/// (thread-safe); each T has one entry. Null, with *error (if not null) set, when it is missing.
template <typename T>
const T* ModuleEntry(const char* name, std::string* error) {
  static std::once_flag once;
  static std::string failure;
  static const T* value = nullptr;
  std::call_once(once, [name] {
    using EntryFunction = const T* (*)();
    if (void* symbol = ModuleSymbol(name, &failure)) {
      value = reinterpret_cast<EntryFunction>(symbol)();
    }
  });
  if (value == nullptr && error != nullptr) *error = failure;
  return value;
}
#endif

}  // namespace massprops::internal

/// The entry point of libmassprops_meshlibs.so (C linkage: found with dlsym).
extern "C" const massprops::internal::MeshBackend* massprops_mesh_backend_v2();
