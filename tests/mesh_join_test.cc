// LoadMeshFile joins identical vertices itself (src/mesh/mesh_libraries.cc) rather than with
// assimp's aiProcess_JoinIdenticalVertices, which costs four to five times the import of a DAE.
// The reference here is assimp 5.2's own step: the scene it gives with that step, walked as
// LoadMeshFile walks it (node transforms, mirrored nodes' winding), must be LoadMeshFile's mesh
// vertex for vertex, for every mesh file of testdata and ../shared/corpus (DAE, OBJ, STL, ...).
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "massprops/mesh/mesh_loader.h"
#include "mesh/assimp_join_hash.h"
#include "mesh_test_support.h"
#include "shared_data.h"

namespace massprops {
namespace {
// Assimp's import with its own joining, as one mesh in the file's frame; false if it fails.
bool AssimpJoined(const std::string& path, TriangleMesh* out) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) return false;
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack = {
      {scene->mRootNode, scene->mRootNode->mTransformation}};
  while (!stack.empty()) {
    const auto [node, X] = stack.back();
    stack.pop_back();
    const bool mirrored = X.Determinant() < 0;
    for (unsigned m = 0; m < node->mNumMeshes; ++m) {
      const aiMesh* part = scene->mMeshes[node->mMeshes[m]];
      const auto offset = static_cast<std::int32_t>(out->vertices.size());
      for (unsigned v = 0; v < part->mNumVertices; ++v) {
        const aiVector3D p = X * part->mVertices[v];
        out->vertices.emplace_back(p.x, p.y, p.z);
      }
      for (unsigned f = 0; f < part->mNumFaces; ++f) {
        const aiFace& face = part->mFaces[f];
        if (face.mNumIndices != 3) continue;
        const auto at = [&](unsigned k) {
          return offset + static_cast<std::int32_t>(face.mIndices[k]);
        };
        out->triangles.push_back(mirrored ? std::array<std::int32_t, 3>{at(0), at(2), at(1)}
                                          : std::array<std::int32_t, 3>{at(0), at(1), at(2)});
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) {
      stack.emplace_back(node->mChildren[c], X * node->mChildren[c]->mTransformation);
    }
  }
  return !out->triangles.empty();
}

TEST(MeshJoinTest, LoadMeshFileIsAssimpsJoinedMesh) {
  std::vector<std::string> roots = {std::string(MASSPROPS_TESTDATA_DIR) + "/mesh"};
  const bool corpus = test_support::SharedPartPresent("corpus");
  if (corpus) roots.emplace_back(MASSPROPS_CORPUS_DIR);
  const std::vector<std::string> files =
      testing_support::MeshFilesUnder(roots, {".dae", ".obj", ".stl", ".glb", ".gltf", ".ply"});
  int compared = 0, dae = 0;
  for (const std::string& file : files) {
    TriangleMesh expected, got;
    std::string error;
    const bool assimp_read = AssimpJoined(file, &expected);
    const bool read = LoadMeshFile(file, &got, &error);
    // An unreadable fixture: LoadMeshFile's message is tested elsewhere.
    if (!assimp_read) continue;
    ASSERT_TRUE(read) << file << ": " << error;
    testing_support::ExpectSameMesh(got, expected, file);
    ++compared;
    if (file.size() > 4 &&
        (file.substr(file.size() - 4) == ".dae" || file.substr(file.size() - 4) == ".DAE")) {
      ++dae;
    }
  }
  // testdata/mesh alone: 6 meshes with triangles that assimp reads (box_ascii.stl, box_binary.stl,
  // bounds_obj_features.obj, cube_quads.obj, open_box.obj, tet_cm.dae; the others are empty,
  // broken or points only, on purpose); the corpus adds its robots' STL, OBJ and DAE files.
  EXPECT_GE(compared, corpus ? 10 : 6);
  EXPECT_GE(dae, 1);
}

// Assimp puts a vertex in a bucket by std::hash<float> of its coordinates; the joins here compute
// libstdc++'s hash inline (assimp_join_hash.h), which must agree with std::hash<float> itself
// on every float: zeros of both signs, subnormals, the extremes, infinities, NaNs and random bit
// patterns.
TEST(MeshJoinTest, TheInlineFloatHashIsStdHashOfFloat) {
  const std::hash<float> reference;
  std::vector<float> values = {0.0f,
                               -0.0f,
                               1.0f,
                               -1.0f,
                               0.5f,
                               1e-5f,
                               std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               std::numeric_limits<float>::lowest(),
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::quiet_NaN()};
  std::mt19937 random(33);
  for (int i = 0; i < 1000000; ++i) {
    const std::uint32_t bits = static_cast<std::uint32_t>(random());
    float v;
    std::memcpy(&v, &bits, sizeof v);
    values.push_back(v);
  }
  for (const float v : values) {
    ASSERT_EQ(internal::StdHashOfFloat(v), reference(v)) << v;
  }
  EXPECT_EQ(internal::AssimpJoinHash(0.0f, -0.0f, 0.0f),
            internal::AssimpJoinHash(-0.0f, 0.0f, -0.0f));
}

// The bucket count is computed from libstdc++'s rehash policy (assimp_join_hash.h) instead of
// asking a map reserved for it: the two must agree for every size, small ones (libstdc++'s table
// of the first primes) and around every prime of its list up to 2^22, then at random sizes.
TEST(MeshJoinTest, TheBucketCountIsWhatReserveGives) {
  std::vector<std::size_t> sizes;
  for (std::size_t n = 0; n <= 2000; ++n) sizes.push_back(n);
  for (std::size_t n = 2000; n < (std::size_t{1} << 22);) {
    const std::size_t buckets = internal::AssimpJoinBucketsOfAMap(n);
    for (const std::size_t k : {buckets - 1, buckets, buckets + 1}) sizes.push_back(k);
    n = buckets + 2;
  }
  std::mt19937_64 random(33);
  for (int i = 0; i < 50; ++i) sizes.push_back(random() % (std::size_t{1} << 22));
  for (const std::size_t n : sizes) {
    ASSERT_EQ(internal::AssimpJoinBuckets(n), internal::AssimpJoinBucketsOfAMap(n)) << n;
  }
}

}  // namespace
}  // namespace massprops
