// libmassprops_meshlibs.so: the code of massprops that needs assimp (and through it draco) and
// qhull, loaded on demand by src/mesh/mesh_backend.cc (see src/mesh/mesh_backend.h for why). It
// depends on the mesh libraries and Eigen only, not on libmassprops.
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <assimp/Importer.hpp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <utility>
#include <vector>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "mesh/mesh_backend.h"

namespace massprops::internal {
namespace {

bool LoadMesh(const char* path, TriangleMesh* mesh, std::string* error) {
  try {
    Assimp::Importer importer;
    // URDF and SDF use mesh coordinates as written: do not rotate a Z_UP (or X_UP) DAE to Y_UP.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    const aiScene* scene =
        importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || scene->mRootNode == nullptr) {
      if (error) {
        *error =
            "mesh file '" + std::string(path) + "' cannot be read: " + importer.GetErrorString();
      }
      return false;
    }
    TriangleMesh result;
    std::string problem;
    // Depth-first walk of the scene graph, carrying the node-to-file transform.
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack = {
        {scene->mRootNode, scene->mRootNode->mTransformation}};
    while (!stack.empty() && problem.empty()) {
      const auto [node, X_FileNode] = stack.back();
      stack.pop_back();
      const bool mirrored = X_FileNode.Determinant() < 0;
      for (unsigned m = 0; m < node->mNumMeshes; ++m) {
        if (node->mMeshes[m] >= scene->mNumMeshes) continue;
        const aiMesh* part = scene->mMeshes[node->mMeshes[m]];
        const std::size_t offset = result.vertices.size();
        if (offset + part->mNumVertices >
            static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
          problem = "more than 2^31 vertices";
          break;
        }
        for (unsigned v = 0; v < part->mNumVertices; ++v) {
          const aiVector3D p = X_FileNode * part->mVertices[v];
          result.vertices.emplace_back(p.x, p.y, p.z);
          if (!result.vertices.back().allFinite()) problem = "a vertex is not finite";
        }
        for (unsigned f = 0; f < part->mNumFaces; ++f) {
          const aiFace& face = part->mFaces[f];
          if (face.mNumIndices != 3) continue;  // Points and lines have no volume.
          const auto index = [&](unsigned k) {
            return static_cast<std::int32_t>(offset + face.mIndices[k]);
          };
          if (mirrored) {
            result.triangles.push_back({index(0), index(2), index(1)});
          } else {
            result.triangles.push_back({index(0), index(1), index(2)});
          }
        }
      }
      for (unsigned c = 0; c < node->mNumChildren; ++c) {
        stack.emplace_back(node->mChildren[c], X_FileNode * node->mChildren[c]->mTransformation);
      }
    }
    if (problem.empty() && result.triangles.empty()) problem = "it holds no triangle";
    if (!problem.empty()) {
      if (error) *error = "mesh file '" + std::string(path) + "' cannot be used: " + problem;
      return false;
    }
    *mesh = std::move(result);
    return true;
  } catch (const std::exception& e) {  // e.g. std::bad_alloc on a huge file
    if (error) *error = "mesh file '" + std::string(path) + "' cannot be read: " + e.what();
    return false;
  }
}

int ConvexHull(const double* points, int count, std::vector<std::array<int, 3>>* triangles,
               std::vector<std::array<double, 3>>* normals, std::string* messages) {
  // qhull writes its messages to a FILE: collect them in memory.
  char* message_buffer = nullptr;
  std::size_t message_size = 0;
  FILE* stream = open_memstream(&message_buffer, &message_size);
  if (stream == nullptr) {
    *messages = "cannot open a stream for qhull's messages";
    return -1;
  }
  std::vector<coordT> coordinates(points, points + 3 * static_cast<std::size_t>(count));
  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, stream);
  char command[] = "qhull Qt";
  const int exit_code =
      qh_new_qhull(qh, 3, count, coordinates.data(), False, command, stream, stream);
  if (exit_code == 0) {
    facetT* facet;
    vertexT* vertex;
    vertexT** vertexp;
    FORALLfacets {
      std::array<int, 3> triangle{};
      int k = 0;
      FOREACHvertex_(facet->vertices) {
        if (k >= 3) break;
        triangle[k++] = qh_pointid(qh, vertex->point);
      }
      if (k != 3) continue;
      triangles->push_back(triangle);
      normals->push_back({facet->normal[0], facet->normal[1], facet->normal[2]});
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int still_long = 0, total_long = 0;
  qh_memfreeshort(qh, &still_long, &total_long);
  std::fclose(stream);
  *messages = message_buffer ? std::string(message_buffer, message_size) : std::string();
  std::free(message_buffer);
  return exit_code;
}

}  // namespace
}  // namespace massprops::internal

extern "C" const massprops::internal::MeshBackend* massprops_mesh_backend_v1() {
  static const massprops::internal::MeshBackend backend{&massprops::internal::LoadMesh,
                                                        &massprops::internal::ConvexHull};
  return &backend;
}
