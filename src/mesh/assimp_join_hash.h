#pragma once
// Private to the library and to the mesh module: the hash table of assimp 5.2.4's
// aiProcess_JoinIdenticalVertices (JoinVerticesProcess::ProcessMesh), which both the module's join
// (mesh_libraries.cc) and the direct STL reader (stl_direct.cc) must reproduce bucket for bucket:
// a std::unordered_map reserved for the mesh's vertex count, hashed by the position.

#include <cstddef>
#include <functional>
#include <unordered_map>

namespace massprops::internal {

/// The bucket count of assimp's table for a mesh of `vertices` vertices: what libstdc++'s
/// reserve gives (the same library's rehash policy and prime list as assimp's map).
inline std::size_t AssimpJoinBuckets(std::size_t vertices) {
  std::unordered_map<unsigned, unsigned> probe;
  probe.reserve(vertices);
  return probe.bucket_count();
}

/// Assimp's hash of a vertex: boost's hash_combine of std::hash<float> of x, y, z (-0 and +0
/// alike, as std::hash<float> hashes both to 0).
inline std::size_t AssimpJoinHash(float x, float y, float z) {
  std::size_t seed = 0;
  for (const float c : {x, y, z}) {
    seed ^= std::hash<float>()(c) + 0x9e3779b9 + (seed << 6) + (seed >> 2);
  }
  return seed;
}

}  // namespace massprops::internal
