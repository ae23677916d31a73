#pragma once
// Shared by the mesh-reading tests (stl_one_read_test.cc, mesh_join_test.cc): the mesh files of a
// folder tree, and an exact comparison of two meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "massprops/mesh/mesh_inertia.h"

namespace massprops::testing_support {

/// The regular files under the existing folders of `roots` whose extension, lower-cased, is one
/// of `extensions` (".stl", ".dae", ...), sorted.
inline std::vector<std::string> MeshFilesUnder(const std::vector<std::string>& roots,
                                               const std::vector<std::string>& extensions) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const std::string& root : roots) {
    if (!fs::exists(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      std::string extension = entry.path().extension().string();
      for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (entry.is_regular_file() &&
          std::find(extensions.begin(), extensions.end(), extension) != extensions.end()) {
        files.push_back(entry.path().string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Exactly the same vertices (value and sign of zero) in the same order, and the same triangles.
/// Where assimp could join a corner to either of two kept vertices at one position, the index may
/// differ but not the position: the triangles are compared by their corners' positions.
inline void ExpectSameMesh(const TriangleMesh& got, const TriangleMesh& expected,
                           const std::string& what) {
  ASSERT_EQ(got.vertices.size(), expected.vertices.size()) << what;
  ASSERT_EQ(got.triangles.size(), expected.triangles.size()) << what;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < got.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double a = got.vertices[i][k], b = expected.vertices[i][k];
      if (!(a == b) || std::signbit(a) != std::signbit(b)) ++differing;
    }
  }
  EXPECT_EQ(differing, 0u) << what;
  std::size_t moved = 0;
  for (std::size_t t = 0; t < got.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!(got.vertices[got.triangles[t][k]] == expected.vertices[expected.triangles[t][k]])) {
        ++moved;
      }
    }
  }
  EXPECT_EQ(moved, 0u) << what;
}

}  // namespace massprops::testing_support
