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

#include "mesh/assimp_join_hash.h"
#include "mesh/mesh_backend.h"

namespace massprops::internal {
namespace {

// Which vertices of an aiMesh assimp 5.2.4's aiProcess_JoinIdenticalVertices keeps (`kept`, in
// order) and, per vertex, the kept one it becomes (`index`). Its JoinVerticesProcess::ProcessMesh
// leaves a mesh without positions or faces as it is; else it takes the vertices some face uses in
// order and looks each up in a std::unordered_map reserved for all the vertices, hashed by the
// position (boost's hash_combine of std::hash<float> of x, y, z), whose hash is noexcept: so
// libstdc++ keeps no hash code in a node, and a lookup walks the whole bucket, newest first,
// taking the first element "equal" to the vertex: in float arithmetic, position, normal, first
// texture coordinate, tangent and bitangent each within a squared distance of 1e-10 (a missing
// channel is zero; NaN compares equal; colors are not compared). Else the vertex is kept, at the
// front of its bucket. The same buckets (the count libstdc++'s reserve gives), order and test are
// used here, so the same result, two nearby positions in one bucket included; what costs assimp
// four to five times the import of a DAE (its vertex of 16 vectors and 8 colors copied into
// every node, a second std::unordered_set of the used indices, the bucket's end found by hashing
// the next node again) is left out (docs/benchmarks.md section 8).
struct Joined {
  std::vector<unsigned> kept;
  std::vector<unsigned> index;
};

Joined JoinIdenticalVertices(const aiMesh& mesh) {
  Joined joined;
  const unsigned n = mesh.mNumVertices;
  joined.index.assign(n, 0);
  if (!mesh.HasPositions() || !mesh.HasFaces()) {
    for (unsigned v = 0; v < n; ++v) {
      joined.kept.push_back(v);
      joined.index[v] = v;
    }
    return joined;
  }
  std::vector<char> used(n, 0);
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    for (unsigned k = 0; k < face.mNumIndices; ++k) {
      if (face.mIndices[k] < n) used[face.mIndices[k]] = 1;
    }
  }
  const aiVector3D zero(0, 0, 0);
  auto attribute = [&](const aiVector3D* channel, unsigned v) {
    return channel != nullptr ? channel[v] : zero;
  };
  auto near = [](const aiVector3D& a, const aiVector3D& b) {
    return !((a - b).SquareLength() > 1e-5f * 1e-5f);
  };
  auto equal = [&](unsigned a, unsigned b) {
    return near(mesh.mVertices[a], mesh.mVertices[b]) &&
           near(attribute(mesh.mNormals, a), attribute(mesh.mNormals, b)) &&
           near(attribute(mesh.mTextureCoords[0], a), attribute(mesh.mTextureCoords[0], b)) &&
           near(attribute(mesh.mTangents, a), attribute(mesh.mTangents, b)) &&
           near(attribute(mesh.mBitangents, a), attribute(mesh.mBitangents, b));
  };
  const std::size_t buckets = AssimpJoinBuckets(n);
  // Each used vertex's bucket first (a pass over the positions), so that the bucket a few
  // vertices ahead is asked of the memory early: its first read is a cache miss.
  std::vector<std::size_t> bucket_of(n, 0);
  for (unsigned v = 0; v < n; ++v) {
    if (!used[v]) continue;
    const aiVector3D& p = mesh.mVertices[v];
    bucket_of[v] = AssimpJoinHash(p.x, p.y, p.z) % buckets;
  }
  std::vector<std::int64_t> newest(buckets, -1);  // per bucket: its newest kept vertex
  std::vector<std::int64_t> older;                // per kept vertex: the next older in its bucket
  constexpr unsigned kAhead = 16;
  for (unsigned v = 0; v < n; ++v) {
    if (v + kAhead < n) __builtin_prefetch(&newest[bucket_of[v + kAhead]]);
    if (!used[v]) continue;
    const std::size_t bucket = bucket_of[v];
    std::int64_t match = -1;
    for (std::int64_t k = newest[bucket]; k >= 0 && match < 0; k = older[k]) {
      if (equal(v, joined.kept[k])) match = k;
    }
    if (match < 0) {
      match = static_cast<std::int64_t>(joined.kept.size());
      joined.kept.push_back(v);
      older.push_back(newest[bucket]);
      newest[bucket] = match;
    }
    joined.index[v] = static_cast<unsigned>(match);
  }
  return joined;
}

// The prefix of the names assimp's Collada importer makes up for a node without one.
constexpr char kAutoName[] = "$ColladaAutoName$";

bool IsAutoName(const aiString& name) { return std::string(name.C_Str()).rfind(kAutoName, 0) == 0; }

// The name gz-common gives the submeshes of `node` (its AssimpLoader and ColladaLoader agree):
// the node's own name; for a DAE node without one, that of its nearest named ancestor below the
// root; "" when there is none (gz-common then makes up "unnamed_submesh_N").
std::string PartName(const aiNode* node, const aiNode* root) {
  if (!IsAutoName(node->mName)) return node->mName.C_Str();
  for (const aiNode* up = node->mParent; up != nullptr && up != root; up = up->mParent) {
    if (!IsAutoName(up->mName)) return up->mName.C_Str();
  }
  return "";
}

bool LoadMesh(const char* path, TriangleMesh* mesh, std::vector<MeshPartRange>* parts,
              std::string* error) {
  try {
    Assimp::Importer importer;
    // URDF and SDF use mesh coordinates as written: do not rotate a Z_UP (or X_UP) DAE to Y_UP.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    // A DAE node's name is its `name` attribute (not its `id`), as gz-common names submeshes; a
    // node without one gets kAutoName. Only names change, no geometry.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_USE_COLLADA_NAMES, true);
    const aiScene* scene =
        importer.ReadFile(path, aiProcess_Triangulate);  // and JoinIdenticalVertices, below
    if (scene == nullptr || scene->mRootNode == nullptr) {
      if (error) {
        *error =
            "mesh file '" + std::string(path) + "' cannot be read: " + importer.GetErrorString();
      }
      return false;
    }
    std::vector<Joined> joins;
    joins.reserve(scene->mNumMeshes);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
      joins.push_back(JoinIdenticalVertices(*scene->mMeshes[m]));
    }
    TriangleMesh result;
    std::vector<MeshPartRange> ranges;
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
        const std::size_t first_triangle = result.triangles.size();
        const Joined& joined = joins[node->mMeshes[m]];
        if (offset + joined.kept.size() >
            static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
          problem = "more than 2^31 vertices";
          break;
        }
        for (const unsigned v : joined.kept) {
          const aiVector3D p = X_FileNode * part->mVertices[v];
          result.vertices.emplace_back(p.x, p.y, p.z);
          if (!result.vertices.back().allFinite()) problem = "a vertex is not finite";
        }
        for (unsigned f = 0; f < part->mNumFaces; ++f) {
          const aiFace& face = part->mFaces[f];
          if (face.mNumIndices != 3) continue;  // Points and lines have no volume.
          if (face.mIndices[0] >= part->mNumVertices || face.mIndices[1] >= part->mNumVertices ||
              face.mIndices[2] >= part->mNumVertices) {
            problem = "a face names a vertex its mesh does not have";
            break;
          }
          const auto index = [&](unsigned k) {
            return static_cast<std::int32_t>(offset + joined.index[face.mIndices[k]]);
          };
          if (mirrored) {
            result.triangles.push_back({index(0), index(2), index(1)});
          } else {
            result.triangles.push_back({index(0), index(1), index(2)});
          }
        }
        if (parts != nullptr) {
          ranges.push_back({PartName(node, scene->mRootNode), offset, joined.kept.size(),
                            first_triangle, result.triangles.size() - first_triangle});
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
    if (parts != nullptr) *parts = std::move(ranges);
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

extern "C" const massprops::internal::MeshBackend* massprops_mesh_backend_v2() {
  static const massprops::internal::MeshBackend backend{&massprops::internal::LoadMesh,
                                                        &massprops::internal::ConvexHull};
  return &backend;
}
