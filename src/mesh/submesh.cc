// SDF <submesh>: one named part of a mesh file (submesh.h).
//
// What a part is, and what centering does, is gz-common's (github.com/gazebosim/gz-common,
// graphics/src): its loaders make one SubMesh per mesh of a node of the file's scene graph, named
// after the node (ColladaLoader and AssimpLoader: a DAE node's `name` attribute, or for a node
// without one its nearest named ancestor's; OBJLoader: the `o` object's name), and
// SubMesh::Center(c) translates a submesh's vertices by c minus the center of their bounding box.
// libsdformat only reads the name and the flag (sdf::Mesh::Submesh(), CenterSubmesh()).
#include "mesh/submesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <exception>
#include <optional>
#include <utility>

namespace massprops {

namespace internal {

namespace {

// "its parts are 'A', 'B', 'C'" of `names` in alphabetical order, at most 8 ("and N more").
std::string DescribeNames(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  if (names.empty()) return "it has no named parts";
  std::string text = names.size() == 1 ? "its one part is " : "its parts are ";
  constexpr std::size_t kShown = 8;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) {
    text += (i == 0 ? "'" : ", '") + names[i] + "'";
  }
  if (names.size() > kShown) text += " and " + std::to_string(names.size() - kShown) + " more";
  return text;
}

}  // namespace

std::vector<std::string> PartNames(const std::vector<MeshPartRange>& parts) {
  std::vector<std::string> names;
  for (const MeshPartRange& part : parts) {
    if (!part.name.empty() && std::find(names.begin(), names.end(), part.name) == names.end()) {
      names.push_back(part.name);
    }
  }
  return names;
}

bool SelectSubmesh(const TriangleMesh& whole, const std::vector<MeshPartRange>& parts,
                   const MeshSubmesh& submesh, const std::string& path, TriangleMesh* mesh,
                   std::string* error) {
  TriangleMesh selected;
  bool named = false;
  for (const MeshPartRange& part : parts) {
    if (part.name != submesh.name) continue;
    named = true;
    const auto begin = whole.vertices.begin() + static_cast<std::ptrdiff_t>(part.first_vertex);
    const auto end = begin + static_cast<std::ptrdiff_t>(part.vertex_count);
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    if (submesh.center && part.vertex_count > 0) {
      Eigen::AlignedBox3d box;
      for (auto v = begin; v != end; ++v) box.extend(*v);
      shift = -box.center();
    }
    const auto offset = static_cast<std::int64_t>(selected.vertices.size()) -
                        static_cast<std::int64_t>(part.first_vertex);
    for (auto v = begin; v != end; ++v) selected.vertices.push_back(*v + shift);
    for (std::size_t t = part.first_triangle; t < part.first_triangle + part.triangle_count; ++t) {
      std::array<std::int32_t, 3> triangle = whole.triangles[t];
      for (std::int32_t& index : triangle) index = static_cast<std::int32_t>(index + offset);
      selected.triangles.push_back(triangle);
    }
  }
  if (selected.triangles.empty()) {
    if (error) {
      *error = "mesh file '" + path + "' has no submesh '" + submesh.name + "'" +
               (named ? " with a triangle" : " (" + DescribeNames(PartNames(parts)) + ")");
    }
    return false;
  }
  *mesh = std::move(selected);
  return true;
}

std::string SubmeshKey(const MeshSubmesh& submesh) {
  if (submesh.name.empty()) return "";
  return "submesh\n" + submesh.name + (submesh.center ? "\ncentered" : "\nas placed");
}

}  // namespace internal

MeshSubmesh SubmeshOf(const Geometry& geometry) {
  return {geometry.submesh, geometry.center_submesh};
}

std::optional<std::string> UnknownSubmeshMessage(const Geometry& geometry,
                                                 const MeshResolveOptions& options) {
  if (geometry.type != Geometry::Type::kMesh || geometry.submesh.empty()) return std::nullopt;
  try {
    std::string error;
    const std::optional<std::string> path = ResolveGeometryMeshUri(geometry, options, &error);
    if (!path) return std::nullopt;
    std::optional<std::vector<std::string>> names;
    if (options.cache != nullptr) {
      names = options.cache->SubmeshNames(*path, &error);
    } else {
      TriangleMesh whole;
      std::vector<internal::MeshPartRange> parts;
      if (internal::LoadMeshFileParts(*path, &whole, &parts, &error)) {
        names = internal::PartNames(parts);
      }
    }
    if (!names) return std::nullopt;
    if (std::find(names->begin(), names->end(), geometry.submesh) != names->end()) {
      return std::nullopt;
    }
    return "mesh '" + geometry.uri + "' has no submesh '" + geometry.submesh + "'; " +
           internal::DescribeNames(*names) + "; the geometry's size is unknown to the rules";
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool LoadMeshSubmesh(const std::string& path, const MeshSubmesh& submesh, TriangleMesh* mesh,
                     std::string* error) {
  if (submesh.name.empty()) return LoadMeshFile(path, mesh, error);
  TriangleMesh whole;
  std::vector<internal::MeshPartRange> parts;
  if (!internal::LoadMeshFileParts(path, &whole, &parts, error)) return false;
  return internal::SelectSubmesh(whole, parts, submesh, path, mesh, error);
}

}  // namespace massprops
