#pragma once
// Private to the library: STL files read without assimp (src/mesh/stl_direct.cc). MeshCache reads
// each STL file once with ReadStlDirect, for its box, its hull-bound points and its mass
// properties; LoadMeshBounds (src/mesh/mesh_bounds.cc) shares the ascii scan. Loading assimp and
// its post-processing cost 5 to 7 times what the whole `massprops check` of a robot with STL meshes
// costs otherwise (docs/rules.md, docs/benchmarks.md section 8).

#include <Eigen/Core>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "massprops/mesh/mesh_inertia.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops::internal {

/// What one read of an STL file gives.
struct DirectStl {
  /// A binary STL (84 + 50·n bytes exactly, as assimp 5.2 tells it from ascii) without two
  /// nearby positions assimp's join could merge (stl_direct.cc): each distinct position once, in
  /// order of first appearance (-0 and +0 the same, written +0), and the triangles naming them. An
  /// ascii STL: every corner its own vertex, the "vertex" triples in order. Either way the same
  /// triangles, in the same order and with the same corner coordinates, as LoadMeshFile's mesh (the
  /// 32-bit floats assimp keeps; strtof for ascii), so the same integrals; not its vertex list.
  TriangleMesh mesh;
  /// The binary case above. Then `mesh`'s vertices are distinct and are the file's hull-bound
  /// points (MeshPoints::positions), and JoinedMesh() gives LoadMeshFile's mesh: assimp 5.2's
  /// importer gives each corner the facet's normal, and its aiProcess_JoinIdenticalVertices keeps
  /// a corner unless an earlier kept one has the same position and a normal within 1e-5; its
  /// vertex k is the kept corner k, at position vertex_position[k], and its triangles name them
  /// (joined_triangles).
  bool joined = false;
  std::vector<std::int32_t> vertex_position;
  std::vector<std::array<std::int32_t, 3>> joined_triangles;
};

/// LoadMeshFile's mesh of a joined DirectStl (vertex for vertex, triangle for triangle).
TriangleMesh JoinedMesh(const DirectStl& stl);

/// Reads the STL file whose bytes are `bytes` into *stl. Returns false (and leaves *stl empty)
/// when the bytes are not such an STL, hold no triangle, or a coordinate is not finite:
/// LoadMeshFile then asks assimp, which says what is wrong. Never throws.
bool ReadStlDirect(const std::string& bytes, DirectStl* stl);

class ContentHasher;  // mesh_store.h

/// ReadStlDirect of the file at `path`, which a binary STL reads in pieces of 65 500 bytes into
/// one buffer that stays in the processor's cache: copying a file into fresh memory of its whole
/// size costs about three times as much (docs/benchmarks.md, section 8). Ascii (and no STL): the
/// whole file, then ReadStlDirect. False also when the file cannot be read, or shrinks meanwhile.
/// `hasher` (if not null) is given the bytes read, in order (all of them when it returns true):
/// the cache's content hash from the same pass.
bool ReadStlDirectFile(const std::string& path, DirectStl* stl, ContentHasher* hasher = nullptr);

/// The bytes of the file at `path`, in one read (POSIX); false when it cannot be read.
bool ReadWholeFile(const std::string& path, std::string* bytes);

/// Calls take(data, n) for the bytes of the file at `path`, in order, in pieces of `piece` bytes
/// (the last one shorter, or none for an empty file) read into one buffer. Returns how many bytes
/// the file had, or -1 when it cannot be opened or read.
std::int64_t ReadFileInPieces(const std::string& path, std::size_t piece,
                              const std::function<void(const char*, std::size_t)>& take);

/// Calls visit(p) for every "vertex x y z" of an ascii STL, in order (facets and loops need not be
/// checked: their vertices are all the full loader keeps). Returns false when a vertex is not
/// three finite numbers. strtof stops at the end of the buffer's text: std::string's bytes are
/// followed by '\0'.
template <typename Visit>
bool ForEachAsciiStlVertex(const std::string& bytes, Visit visit) {
  const char* const end = bytes.data() + bytes.size();
  for (const char* at = bytes.data(); at < end;) {
    const char* found = static_cast<const char*>(std::memchr(at, 'v', end - at));
    if (found == nullptr) break;
    const bool word_start =
        found == bytes.data() || std::isspace(static_cast<unsigned char>(found[-1]));
    if (!word_start || end - found < 7 || std::strncmp(found, "vertex", 6) != 0 ||
        !std::isspace(static_cast<unsigned char>(found[6]))) {
      at = found + 1;
      continue;
    }
    float xyz[3];
    const char* cursor = found + 6;
    for (float& c : xyz) {
      char* next = nullptr;
      c = std::strtof(cursor, &next);
      if (next == cursor) return false;
      cursor = next;
    }
    const Eigen::Vector3d p(xyz[0], xyz[1], xyz[2]);
    if (!p.allFinite()) return false;
    visit(p);
    at = cursor;
  }
  return true;
}

}  // namespace massprops::internal
