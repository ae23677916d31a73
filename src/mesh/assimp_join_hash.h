#pragma once
// Private to the library and to the mesh module: the hash table of assimp 5.2.4's
// aiProcess_JoinIdenticalVertices (JoinVerticesProcess::ProcessMesh), which both the module's join
// (mesh_libraries.cc) and the direct STL reader (stl_direct.cc) must reproduce bucket for bucket:
// a std::unordered_map reserved for the mesh's vertex count, hashed by the position.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <unordered_map>

namespace massprops::internal {

/// The bucket count of a std::unordered_map reserved for `vertices` elements, asked of one.
inline std::size_t AssimpJoinBucketsOfAMap(std::size_t vertices) {
  std::unordered_map<unsigned, unsigned> probe;
  probe.reserve(vertices);
  return probe.bucket_count();
}

/// The bucket count of assimp's table for a mesh of `vertices` vertices: what libstdc++'s
/// reserve gives (the same library's rehash policy and prime list as assimp's map). With
/// libstdc++ it is computed as its reserve computes it on an empty map, from its rehash policy
/// (bits/hashtable.h, rehash), without allocating and zeroing the buckets: a map reserved only to
/// be asked its bucket count took 1% of a first check of binary STL meshes (an 8-byte bucket per
/// corner). tests/mesh_join_test.cc compares the two. Other libraries: the map itself.
inline std::size_t AssimpJoinBuckets(std::size_t vertices) {
#if defined(__GLIBCXX__)
  std::__detail::_Prime_rehash_policy policy;  // max_load_factor 1, as a new map's
  return policy._M_next_bkt(
      std::max(policy._M_bkt_for_elements(1), policy._M_bkt_for_elements(vertices)));
#else
  return AssimpJoinBucketsOfAMap(vertices);
#endif
}

/// std::hash<float>()(v), computed inline. libstdc++ (64-bit) hashes a nonzero float's four bytes
/// with its _Hash_bytes, a MurmurHash2 (64-bit) variant with the seed 0xc70f6907, and ±0 to 0; an
/// out-of-line call per coordinate was a few percent of a first check with meshes
/// (docs/benchmarks.md, section 8). Other libraries: std::hash<float> itself.
/// tests/mesh_join_test.cc compares the two on every float class and random bit patterns.
inline std::size_t StdHashOfFloat(float v) {
#if defined(__GLIBCXX__) && SIZE_MAX == UINT64_MAX
  if (v == 0.0f) return 0;
  std::uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  constexpr std::uint64_t kMul = 0xc6a4a7935bd1e995ull;
  auto shift_mix = [](std::uint64_t h) { return h ^ (h >> 47); };
  std::uint64_t h = 0xc70f6907ull ^ (sizeof bits * kMul);
  h = (h ^ bits) * kMul;  // the 4 bytes, read as a little-endian number
  return shift_mix(shift_mix(h) * kMul);
#else
  return std::hash<float>()(v);
#endif
}

/// Assimp's hash of a vertex: boost's hash_combine of std::hash<float> of x, y, z (-0 and +0
/// alike, as std::hash<float> hashes both to 0).
inline std::size_t AssimpJoinHash(float x, float y, float z) {
  std::size_t seed = 0;
  for (const float c : {x, y, z}) {
    seed ^= StdHashOfFloat(c) + 0x9e3779b9 + (seed << 6) + (seed >> 2);
  }
  return seed;
}

}  // namespace massprops::internal
