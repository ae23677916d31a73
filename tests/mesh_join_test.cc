// LoadMeshFile joins identical vertices itself (src/mesh/mesh_libraries.cc) rather than with
// assimp's aiProcess_JoinIdenticalVertices, which costs four to five times the import of a DAE.
// The reference here is assimp 5.2's own step: the scene it gives with that step, walked as
// LoadMeshFile walks it (node transforms, mirrored nodes' winding), must be LoadMeshFile's mesh
// vertex for vertex, for every mesh file of testdata and ../shared/corpus (DAE, OBJ, STL, ...).
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {
namespace fs = std::filesystem;

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
  std::vector<std::string> files;
  for (const std::string& root : {std::string(MASSPROPS_TESTDATA_DIR) + "/mesh",
                                  std::string(MASSPROPS_CORPUS_DIR)}) {
    if (!fs::exists(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      std::string extension = entry.path().extension().string();
      for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (entry.is_regular_file() &&
          (extension == ".dae" || extension == ".obj" || extension == ".stl" ||
           extension == ".glb" || extension == ".gltf" || extension == ".ply")) {
        files.push_back(entry.path().string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  int compared = 0, dae = 0;
  for (const std::string& file : files) {
    TriangleMesh expected, got;
    std::string error;
    const bool assimp_read = AssimpJoined(file, &expected);
    const bool read = LoadMeshFile(file, &got, &error);
    if (!assimp_read) continue;  // an unreadable fixture: LoadMeshFile's message is tested elsewhere
    ASSERT_TRUE(read) << file << ": " << error;
    ASSERT_EQ(got.vertices.size(), expected.vertices.size()) << file;
    ASSERT_EQ(got.triangles.size(), expected.triangles.size()) << file;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < got.vertices.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        const double a = got.vertices[i][k], b = expected.vertices[i][k];
        if (!(a == b) || std::signbit(a) != std::signbit(b)) ++differing;
      }
    }
    for (std::size_t t = 0; t < got.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        if (!(got.vertices[got.triangles[t][k]] == expected.vertices[expected.triangles[t][k]])) {
          ++differing;
        }
      }
    }
    EXPECT_EQ(differing, 0u) << file;
    ++compared;
    if (file.size() > 4 && (file.substr(file.size() - 4) == ".dae" ||
                            file.substr(file.size() - 4) == ".DAE")) {
      ++dae;
    }
  }
  EXPECT_GE(compared, 10);
  EXPECT_GE(dae, 1);
}

}  // namespace
}  // namespace massprops
