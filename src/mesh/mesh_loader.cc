#include "massprops/mesh/mesh_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <limits>
#include <sstream>
#include <utility>

#include "massprops/core/unit_inertia.h"
#include "mesh/mesh_backend.h"
#include "mesh/submesh.h"

namespace massprops {
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

bool IsRegularFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool IsDirectory(const fs::path& path) {
  std::error_code ec;
  return fs::is_directory(path, ec);
}

// The folders of a ':'-separated environment variable (empty entries skipped).
std::vector<std::string> SplitEnvironmentPath(const char* variable, const std::string& suffix) {
  std::vector<std::string> folders;
  const char* value = std::getenv(variable);
  if (value == nullptr) return folders;
  std::string text(value);
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(':', begin), text.size());
    if (end > begin) folders.push_back(text.substr(begin, end - begin) + suffix);
    begin = end + 1;
  }
  return folders;
}

// Folders that are the package `name` under search folder P: P/name, P itself or a child of P
// whose package.xml names it.
std::vector<fs::path> PackageRootsIn(const fs::path& folder, const std::string& name) {
  std::vector<fs::path> roots;
  if (!IsDirectory(folder)) return roots;
  if (IsDirectory(folder / name)) roots.push_back(folder / name);
  if (PackageXmlName(folder.string()) == name) roots.push_back(folder);
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code entry_ec;
    if (!it->is_directory(entry_ec) || it->path().filename() == name) continue;
    if (PackageXmlName(it->path().string()) == name) roots.push_back(it->path());
  }
  return roots;
}

fs::path BaseFolder(const MeshResolveOptions& options) {
  if (options.model_file.empty() || options.model_file == "-") return fs::current_path();
  fs::path folder = fs::path(options.model_file).parent_path();
  return folder.empty() ? fs::path(".") : folder;
}

std::string JoinList(const std::vector<std::string>& items) {
  if (items.empty()) return "(no search path)";
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::optional<std::string> CheckFile(const fs::path& path, const std::string& uri,
                                     std::string* error) {
  if (IsRegularFile(path)) return path.lexically_normal().string();
  if (error) {
    *error = "mesh '" + uri + "': " + (IsDirectory(path) ? "is a directory: " : "no such file: ") +
             path.string();
  }
  return std::nullopt;
}

// `rest` of "SCHEME://NAME/rest" split into NAME and the path after it.
std::pair<std::string, std::string> SplitNameAndPath(const std::string& rest) {
  const std::size_t slash = rest.find('/');
  if (slash == std::string::npos) return {rest, ""};
  return {rest.substr(0, slash), rest.substr(slash + 1)};
}

std::string Describe(const Geometry& geometry) {
  std::ostringstream out;
  out << (geometry.is_collision ? "collision" : "visual");
  if (geometry.location.line > 0) out << " at line " << geometry.location.line;
  if (geometry.type == Geometry::Type::kMesh) {
    out << " (mesh '" << geometry.uri << "'";
    if (!geometry.submesh.empty()) out << ", submesh '" << geometry.submesh << "'";
    out << ")";
  }
  return out.str();
}

}  // namespace

namespace {

// "the packages under R (N folders listed[, stopped at the limit of M])" for a message.
std::string DescribeRepositorySearch(const std::string& base, RepositoryPackages& packages) {
  std::string text = "the packages under " + packages.SearchRoot(base) + " (" +
                     std::to_string(packages.folders_listed()) + " folders listed";
  if (packages.truncated()) {
    text += ", stopped at the limit of " + std::to_string(packages.max_folders());
  }
  return text + ")";
}

// A package:// or model:// URI: NAME looked up where options say, the first package or model
// that holds `rest` wins.
std::optional<std::string> ResolveSearchedUri(const std::string& uri, bool is_package,
                                              const std::string& name, const std::string& rest,
                                              const MeshResolveOptions& options, std::string* error,
                                              MeshFoundBy* found_by) {
  const char* kind = is_package ? "package" : "model";
  std::vector<std::string> searched;
  std::vector<std::string> found_without_file;
  // Returns true when `root`/rest is a file (then *path is set).
  auto holds = [&](const fs::path& root, MeshFoundBy how, std::optional<std::string>* path) {
    const fs::path candidate = root / rest;
    if (IsRegularFile(candidate)) {
      *path = candidate.lexically_normal().string();
      if (found_by) *found_by = how;
      return true;
    }
    found_without_file.push_back(candidate.string());
    return false;
  };
  auto in_folders = [&](const std::vector<std::string>& folders, MeshFoundBy how,
                        std::optional<std::string>* path) {
    for (const auto& folder : folders) {
      searched.push_back(folder);
      std::vector<fs::path> roots;
      if (is_package) {
        roots = PackageRootsIn(folder, name);
      } else if (IsDirectory(fs::path(folder) / name)) {
        roots.push_back(fs::path(folder) / name);
      }
      for (const auto& root : roots) {
        if (holds(root, how, path)) return true;
      }
    }
    return false;
  };
  std::optional<std::string> path;
  if (in_folders(is_package ? options.package_paths : options.model_paths, MeshFoundBy::kFlag,
                 &path)) {
    return path;
  }
  if (is_package && options.search_repository) {
    const std::string base = BaseFolder(options).string();
    RepositoryPackages local;
    RepositoryPackages& packages = options.cache ? options.cache->packages() : local;
    const std::optional<std::string> package = packages.Find(base, name);
    if (package && holds(*package, MeshFoundBy::kRepositoryPackage, &path)) return path;
    searched.push_back(DescribeRepositorySearch(base, packages));
    const std::optional<std::string> ancestor = packages.FindAncestor(base, name);
    if (ancestor && ancestor != package && holds(*ancestor, MeshFoundBy::kAncestor, &path)) {
      return path;
    }
    searched.push_back("its ancestor folders named '" + name + "'");
  }
  if (options.use_environment) {
    const std::vector<std::pair<const char*, const char*>> variables =
        is_package
            ? std::vector<std::pair<const char*, const char*>>{{"ROS_PACKAGE_PATH", ""},
                                                               {"AMENT_PREFIX_PATH", "/share"}}
            : std::vector<std::pair<const char*, const char*>>{{"SDF_PATH", ""},
                                                               {"GZ_SIM_RESOURCE_PATH", ""},
                                                               {"IGN_GAZEBO_RESOURCE_PATH", ""},
                                                               {"GAZEBO_MODEL_PATH", ""}};
    std::vector<std::string> folders;
    for (const auto& [variable, suffix] : variables) {
      for (auto& folder : SplitEnvironmentPath(variable, suffix)) folders.push_back(folder);
    }
    if (in_folders(folders, MeshFoundBy::kEnvironment, &path)) return path;
  }
  if (error) {
    if (!found_without_file.empty()) {
      *error = "mesh '" + uri + "': " + kind + " '" + name +
               "' found but the file is not there: " + JoinList(found_without_file);
    } else {
      *error = "mesh '" + uri + "': " + kind + " '" + name + "' not found in " + JoinList(searched);
    }
  }
  return std::nullopt;
}

}  // namespace

const char* ToString(MeshFoundBy found_by) {
  switch (found_by) {
    case MeshFoundBy::kNone:
      return "none";
    case MeshFoundBy::kFlag:
      return "flag";
    case MeshFoundBy::kRepositoryPackage:
      return "repository-package";
    case MeshFoundBy::kAncestor:
      return "ancestor";
    case MeshFoundBy::kEnvironment:
      return "environment";
    case MeshFoundBy::kBesideFile:
      return "beside-file";
    case MeshFoundBy::kRelative:
      return "relative";
    case MeshFoundBy::kAbsolute:
      return "absolute";
  }
  return "none";
}

std::optional<std::string> ResolveMeshUri(const std::string& uri, const MeshResolveOptions& options,
                                          std::string* error, MeshFoundBy* found_by) {
  if (found_by) *found_by = MeshFoundBy::kNone;
  if (uri.empty()) {
    if (error) *error = "mesh with an empty filename";
    return std::nullopt;
  }
  const bool is_package = StartsWith(uri, "package://");
  const bool is_model = StartsWith(uri, "model://");
  if (is_package || is_model) {
    const auto [name, rest] = SplitNameAndPath(uri.substr(is_package ? 10 : 8));
    if (name.empty() && !is_package) {
      if (error) *error = "mesh '" + uri + "': no model name";
      return std::nullopt;
    }
    // "package://x/../../etc/passwd" names no file of package x: refused, never looked up.
    const fs::path inside = fs::path(std::string(rest)).lexically_normal();
    if (inside.is_absolute() || (!inside.empty() && *inside.begin() == "..")) {
      if (error) {
        *error = "mesh '" + uri + "': the path leaves the " +
                 std::string(is_package ? "package" : "model") + " folder ('..'); not read";
      }
      return std::nullopt;
    }
    if (name.empty()) {  // package:///rest (onshape-to-robot): beside the description file
      std::optional<std::string> path =
          CheckFile(BaseFolder(options) / std::string(rest), uri, error);
      if (path && found_by) *found_by = MeshFoundBy::kBesideFile;
      if (!path && error) *error += " (package:/// names a file beside the description)";
      return path;
    }
    return ResolveSearchedUri(uri, is_package, name, rest, options, error, found_by);
  }
  if (StartsWith(uri, "file://")) {
    fs::path path(uri.substr(7));
    const bool relative = path.is_relative();
    if (relative) path = BaseFolder(options) / path;
    std::optional<std::string> found = CheckFile(path, uri, error);
    if (found && found_by) *found_by = relative ? MeshFoundBy::kRelative : MeshFoundBy::kAbsolute;
    return found;
  }
  const std::size_t scheme_end = uri.find("://");
  if (scheme_end != std::string::npos && scheme_end > 0 &&
      uri.find('/') > scheme_end) {  // "http://...", not "dir/a://b"
    if (error) {
      *error = "mesh '" + uri + "': the URI scheme '" + uri.substr(0, scheme_end) +
               "' is not supported (package://, model://, file:// and paths are)";
    }
    return std::nullopt;
  }
  fs::path path(uri);
  const bool relative = path.is_relative();
  if (relative) path = BaseFolder(options) / path;
  std::optional<std::string> found = CheckFile(path, uri, error);
  if (found && found_by) *found_by = relative ? MeshFoundBy::kRelative : MeshFoundBy::kAbsolute;
  return found;
}

std::optional<std::string> ResolveGeometryMeshUri(const Geometry& geometry,
                                                  const MeshResolveOptions& options,
                                                  std::string* error, MeshFoundBy* found_by) {
  MeshResolveOptions where = options;
  const std::string& holder = geometry.location.file;
  if (!holder.empty() && holder != "-" && holder != "<stdin>" && holder != "<input>") {
    where.model_file = holder;
  }
  if (where.cache != nullptr) return where.cache->Resolve(geometry.uri, where, error, found_by);
  return ResolveMeshUri(geometry.uri, where, error, found_by);
}

bool LoadMeshFile(const std::string& path, TriangleMesh* mesh, std::string* error) {
  return internal::LoadMeshFileParts(path, mesh, nullptr, error);
}

bool internal::LoadMeshFileParts(const std::string& path, TriangleMesh* mesh,
                                 std::vector<MeshPartRange>* parts, std::string* error) {
  if (!IsRegularFile(path)) {
    if (error) *error = "mesh file '" + path + "' does not exist or is not a regular file";
    return false;
  }
  std::error_code ec;
  if (fs::file_size(path, ec) == 0 || ec) {
    if (error) *error = "mesh file '" + path + "' is empty or unreadable";
    return false;
  }
  std::string why;
  const internal::MeshBackend* backend = internal::GetMeshBackend(&why);
  if (backend == nullptr) {
    if (error) *error = "mesh file '" + path + "' cannot be read: " + why;
    return false;
  }
  if (!backend->load_mesh(path.c_str(), mesh, parts, error)) return false;
  // An STL has no named parts here (the direct reader, which most STL files go through, keeps no
  // names; gz-common names an ascii STL's solids: docs/meshes.md, "Submeshes").
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (parts != nullptr && extension == ".stl") {
    for (internal::MeshPartRange& part : *parts) part.name.clear();
  }
  return true;
}

TriangleMesh ScaleMesh(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  TriangleMesh scaled;
  scaled.vertices.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) scaled.vertices.push_back(v.cwiseProduct(scale));
  scaled.triangles = mesh.triangles;
  if (scale.x() * scale.y() * scale.z() < 0) {
    for (auto& t : scaled.triangles) std::swap(t[1], t[2]);
  }
  return scaled;
}

// ------------------------------------------------------------------------------- MeshCache

std::optional<std::string> MeshCache::Resolve(const std::string& uri,
                                              const MeshResolveOptions& options, std::string* error,
                                              MeshFoundBy* found_by) {
  // model:// URIs do not depend on the description's folder: one lookup per run. package://
  // ones do (its repository, its ancestors, package:///).
  const bool same_everywhere = StartsWith(uri, "model://");
  std::string key = uri + '\n' + (same_everywhere ? std::string() : BaseFolder(options).string()) +
                    '\n' + (options.use_environment ? "env" : "") +
                    (options.search_repository ? "repo" : "") + '\n';
  for (const auto& p : options.package_paths) key += p + '\n';
  key += '\n';
  for (const auto& p : options.model_paths) key += p + '\n';
  std::lock_guard<std::mutex> lock(mutex_);
  auto found = resolved_.find(key);
  if (found == resolved_.end()) {
    Resolved resolved;
    resolved.path = ResolveMeshUri(uri, options, &resolved.error, &resolved.found_by);
    found = resolved_.emplace(key, std::move(resolved)).first;
  }
  if (!found->second.path && error) *error = found->second.error;
  if (found_by) *found_by = found->second.found_by;
  return found->second.path;
}

// ------------------------------------------------------------------------------- geometry

namespace {

// The volume of a primitive (box, cylinder, sphere, capsule, ellipsoid) and, in I_GGcm_G, its
// inertia at density 1 about its center; 0 for a mesh or another type.
double CalcPrimitiveVolume(const Geometry& geometry, RotationalInertia<double>* I_GGcm_G) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  double volume = 0;
  switch (geometry.type) {
    case Geometry::Type::kBox: {
      const Eigen::Vector3d& s = geometry.size;
      const UnitInertia<double> G = UnitInertia<double>::SolidBox(s.x(), s.y(), s.z());
      volume = s.x() * s.y() * s.z();
      *I_GGcm_G = G * volume;
      break;
    }
    case Geometry::Type::kCylinder: {
      const double r = geometry.radius, L = geometry.length;
      const UnitInertia<double> G = UnitInertia<double>::SolidCylinder(r, L, z);
      volume = kPi * r * r * L;
      *I_GGcm_G = G * volume;
      break;
    }
    case Geometry::Type::kSphere: {
      const double r = geometry.radius;
      const UnitInertia<double> G = UnitInertia<double>::SolidSphere(r);
      volume = 4.0 / 3.0 * kPi * r * r * r;
      *I_GGcm_G = G * volume;
      break;
    }
    case Geometry::Type::kCapsule: {
      const double r = geometry.radius, L = geometry.length;
      const UnitInertia<double> G = UnitInertia<double>::SolidCapsule(r, L, z);
      volume = kPi * r * r * L + 4.0 / 3.0 * kPi * r * r * r;
      *I_GGcm_G = G * volume;
      break;
    }
    case Geometry::Type::kEllipsoid: {
      const Eigen::Vector3d& a = geometry.radii;
      const UnitInertia<double> G = UnitInertia<double>::SolidEllipsoid(a.x(), a.y(), a.z());
      volume = 4.0 / 3.0 * kPi * a.x() * a.y() * a.z();
      *I_GGcm_G = G * volume;
      break;
    }
    case Geometry::Type::kMesh:
    case Geometry::Type::kOther:
      break;
  }
  return volume;
}

// Loads the mesh at `path` (through the cache when there is one): its mass properties at
// density 1 once scaled, and its unscaled vertex positions (for the bounding box: each distinct
// one once, which gives the same box). Either may be null on failure, with the reason.
void LoadGeometryMesh(const Geometry& geometry, const std::string& path,
                      const MeshResolveOptions& options, std::optional<MeshMassProperties>* mesh,
                      std::shared_ptr<const std::vector<Eigen::Vector3d>>* vertices,
                      std::string* reason) {
  const MeshSubmesh submesh = SubmeshOf(geometry);
  if (options.cache != nullptr) {
    *mesh = options.cache->MassProperties(path, geometry.scale, options.inertia, reason, submesh);
    if (!*mesh) return;
    if (std::shared_ptr<const MeshPoints> points = options.cache->Points(path, reason, submesh)) {
      *vertices = std::shared_ptr<const std::vector<Eigen::Vector3d>>(points, &points->positions);
    }
  } else {
    auto triangles = std::make_shared<TriangleMesh>();
    if (LoadMeshSubmesh(path, submesh, triangles.get(), reason)) {
      MeshInertiaOptions unit_density = options.inertia;
      unit_density.density = 1;
      *mesh = CalcMeshMassProperties(ScaleMesh(*triangles, geometry.scale), unit_density);
      *vertices =
          std::shared_ptr<const std::vector<Eigen::Vector3d>>(triangles, &triangles->vertices);
    }
  }
}

// Fills in a mesh geometry's volume, box in B, path and diagnostics, and its center and inertia
// at density 1 in G. False, with the error, if the mesh cannot be resolved or loaded.
bool CalcMeshGeometry(const Geometry& geometry, const MeshResolveOptions& options,
                      GeometryMassProperties* result, Eigen::Vector3d* p_GoGcm_G,
                      RotationalInertia<double>* I_GGcm_G, std::string* error) {
  std::string reason;
  MeshFoundBy found_by = MeshFoundBy::kNone;
  const std::optional<std::string> path =
      ResolveGeometryMeshUri(geometry, options, &reason, &found_by);
  if (!path) {
    if (error) *error = Describe(geometry) + ": " + reason;
    return false;
  }
  if (!geometry.scale.allFinite()) {
    if (error) *error = Describe(geometry) + ": the scale is not finite";
    return false;
  }
  std::optional<MeshMassProperties> mesh;
  std::shared_ptr<const std::vector<Eigen::Vector3d>> vertices;  // for the bounding box
  LoadGeometryMesh(geometry, *path, options, &mesh, &vertices, &reason);
  if (!mesh || !vertices) {
    if (error) *error = Describe(geometry) + ": " + reason;
    return false;
  }
  // The box of the scaled vertices as posed in B (exact; one pass over the vertices).
  for (const Eigen::Vector3d& v : *vertices) {
    result->box_B.extend(geometry.X_BG.p_AB + geometry.X_BG.R_AB * v.cwiseProduct(geometry.scale));
  }
  result->volume = mesh->mass;  // Density 1.
  *p_GoGcm_G = mesh->p_GoGcm_G;
  *I_GGcm_G = mesh->I_GGcm_G;
  result->mesh_path = *path;
  result->mesh_found_by = found_by;
  result->mesh_diagnostics = mesh->diagnostics;
  return true;
}

}  // namespace

std::optional<GeometryMassProperties> CalcGeometryMassProperties(const Geometry& geometry,
                                                                 const MeshResolveOptions& options,
                                                                 std::string* error) {
  GeometryMassProperties result;
  Eigen::Vector3d p_GoGcm_G = Eigen::Vector3d::Zero();
  RotationalInertia<double> I_GGcm_G;
  try {
    switch (geometry.type) {
      case Geometry::Type::kBox:
      case Geometry::Type::kCylinder:
      case Geometry::Type::kSphere:
      case Geometry::Type::kCapsule:
      case Geometry::Type::kEllipsoid:
        result.volume = CalcPrimitiveVolume(geometry, &I_GGcm_G);
        break;
      case Geometry::Type::kMesh:
        if (!CalcMeshGeometry(geometry, options, &result, &p_GoGcm_G, &I_GGcm_G, error)) {
          return std::nullopt;
        }
        break;
      case Geometry::Type::kOther:
        if (error) *error = Describe(geometry) + ": this geometry type has no volume model";
        return std::nullopt;
    }
  } catch (const std::exception& e) {
    if (error) *error = Describe(geometry) + ": " + e.what();
    return std::nullopt;
  }
  if (!(result.volume > 0) || !std::isfinite(result.volume)) {
    if (error) {
      std::ostringstream message;
      message << Describe(geometry) << ": the volume is " << result.volume
              << " (a zero dimension or scale?)";
      *error = message.str();
    }
    return std::nullopt;
  }
  if (geometry.type != Geometry::Type::kMesh) {
    const std::optional<Eigen::AlignedBox3d> box = CalcPrimitiveBounds(geometry);
    if (!box) {
      if (error) *error = Describe(geometry) + ": its pose or a dimension is not finite";
      return std::nullopt;
    }
    result.box_B = *box;
  }
  result.p_BoGcm_B = geometry.X_BG.p_AB + geometry.X_BG.R_AB * p_GoGcm_G;
  result.I_GGcm_B = I_GGcm_G.ReExpress(geometry.X_BG.R_AB);
  return result;
}

std::optional<Eigen::AlignedBox3d> CalcGeometryBounds(const Geometry& geometry,
                                                      const MeshResolveOptions& options,
                                                      std::string* error) {
  if (geometry.type != Geometry::Type::kMesh) {
    if (geometry.type == Geometry::Type::kOther) {
      if (error) *error = Describe(geometry) + ": this geometry type has no known extent";
      return std::nullopt;
    }
    std::optional<Eigen::AlignedBox3d> box = CalcPrimitiveBounds(geometry);
    if (!box && error) *error = Describe(geometry) + ": its pose or a dimension is not finite";
    return box;
  }
  try {
    std::string reason;
    const std::optional<std::string> path = ResolveGeometryMeshUri(geometry, options, &reason);
    if (!path) {
      if (error) *error = Describe(geometry) + ": " + reason;
      return std::nullopt;
    }
    const Eigen::Vector3d& s = geometry.scale;
    const Pose& X_BG = geometry.X_BG;
    if (!s.allFinite() || !X_BG.p_AB.allFinite() || !X_BG.R_AB.allFinite()) {
      if (error) *error = Describe(geometry) + ": the scale or the pose is not finite";
      return std::nullopt;
    }
    std::optional<Eigen::AlignedBox3d> file_box;
    const MeshSubmesh submesh = SubmeshOf(geometry);
    if (options.cache != nullptr) {
      file_box = options.cache->Bounds(*path, &reason, submesh);
    } else if (!submesh.name.empty()) {  // the box of the part's vertices
      TriangleMesh part;
      if (LoadMeshSubmesh(*path, submesh, &part, &reason)) {
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d& v : part.vertices) box.extend(v);
        file_box = box;
      }
    } else {
      Eigen::AlignedBox3d box;
      if (LoadMeshBounds(*path, &box, nullptr, &reason)) file_box = box;
    }
    if (!file_box) {
      if (error) *error = Describe(geometry) + ": " + reason;
      return std::nullopt;
    }
    // Scaled componentwise (a negative factor swaps that side's ends), then the 8 corners posed
    // (an upper bound of the posed vertices' box: see the header).
    const Eigen::Vector3d a = file_box->min().cwiseProduct(s), b = file_box->max().cwiseProduct(s);
    const Eigen::AlignedBox3d scaled(a.cwiseMin(b), a.cwiseMax(b));
    Eigen::AlignedBox3d box_B;
    for (int corner = 0; corner < 8; ++corner) {
      box_B.extend(X_BG.p_AB +
                   X_BG.R_AB * scaled.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
    }
    return box_B;
  } catch (const std::exception& e) {
    if (error) *error = Describe(geometry) + ": " + e.what();
    return std::nullopt;
  }
}

std::optional<LinkGeometryInertia> CalcLinkGeometryInertia(const Link& link, double mass,
                                                           const MeshResolveOptions& options,
                                                           std::string* error) {
  if (!(mass >= 0) || !std::isfinite(mass)) {
    if (error) {
      std::ostringstream message;
      message << "link '" << link.name << "': the mass " << mass << " is negative or not finite";
      *error = message.str();
    }
    return std::nullopt;
  }
  // Sums the geometries of one kind (collision or visual) as separate uniform solids.
  auto from_set = [&](bool collision,
                      std::string* set_error) -> std::optional<LinkGeometryInertia> {
    LinkGeometryInertia result;
    result.from_collision = collision;
    for (const Geometry& geometry : link.geometries) {
      if (geometry.is_collision != collision) continue;
      std::string reason;
      std::optional<GeometryMassProperties> part =
          CalcGeometryMassProperties(geometry, options, &reason);
      if (!part) {
        *set_error = reason;
        return std::nullopt;
      }
      result.volume += part->volume;
      result.box_B.extend(part->box_B);
      result.geometries.push_back(std::move(*part));
    }
    Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
    for (const auto& part : result.geometries) first_moment += part.volume * part.p_BoGcm_B;
    result.p_BoBcm_B = first_moment / result.volume;
    // Each part's central inertia shifted away from its center to the composite center
    // (additions of positive semi-definite terms only), then scaled to the mass.
    RotationalInertia<double> I = RotationalInertia<double>::TriaxiallySymmetric(0);
    for (const auto& part : result.geometries) {
      I += part.I_GGcm_B.ShiftFromCenterOfMass(part.volume, result.p_BoBcm_B - part.p_BoGcm_B);
    }
    result.I_BBcm_B = I.MultiplyByScalarSkipValidityCheck(mass / result.volume);
    result.mass = mass;
    return result;
  };
  const bool has_collision = std::any_of(link.geometries.begin(), link.geometries.end(),
                                         [](const Geometry& g) { return g.is_collision; });
  const bool has_visual = std::any_of(link.geometries.begin(), link.geometries.end(),
                                      [](const Geometry& g) { return !g.is_collision; });
  std::string collision_error, visual_error;
  if (has_collision) {
    if (auto result = from_set(true, &collision_error)) return result;
  }
  if (has_visual) {
    if (auto result = from_set(false, &visual_error)) {
      result->note = collision_error;
      return result;
    }
  }
  if (error) {
    if (!has_collision && !has_visual) {
      *error = "link '" + link.name + "' has no collision or visual geometry";
    } else {
      *error = "link '" + link.name + "': " + (has_collision ? collision_error : visual_error);
      if (has_collision && has_visual) *error += "; and " + visual_error;
    }
  }
  return std::nullopt;
}

}  // namespace massprops
