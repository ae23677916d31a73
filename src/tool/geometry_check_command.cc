// The `massprops check` options of the geometry rules (see src/tool/geometry_cli.h).
#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "geometry_cli.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/reporters.h"

namespace massprops::cli {
namespace {

struct GeometryArgs {
  bool enabled = false;      // --geometry
  bool no_geometry = false;  // --no-geometry
  double factor = 2;
  bool no_cache = false;         // --no-cache
  int jobs = 0;                  // --jobs (0: one per core)
  std::size_t file_threads = 1;  // the threads that check files
  std::vector<std::string> package_paths;
  MeshCache cache;  // One per run: each mesh file is read once (and kept between runs).
  std::once_flag persistent_once;
};

GeometryArgs& Args() {
  static GeometryArgs args;
  return args;
}

// The run's mesh cache; unless --no-cache, backed by the persistent one (docs/meshes.md#cache),
// set up on first use: a run that reads no mesh never looks for it. Its entries are written when
// the cache is destroyed at exit.
MeshCache* RunCache() {
  GeometryArgs& args = Args();
  std::call_once(args.persistent_once, [&args] {
    if (args.no_cache) return;
    const std::string folder = DefaultMeshCacheFolder();
    if (!folder.empty()) args.cache.UsePersistentCache(folder);
  });
  return &args.cache;
}

// --package-path, then the configuration's package-paths.
std::vector<std::string> PackagePaths(const std::vector<std::string>& config_package_paths) {
  std::vector<std::string> paths = Args().package_paths;
  paths.insert(paths.end(), config_package_paths.begin(), config_package_paths.end());
  return paths;
}

// How each distinct mesh URI of the model's links resolved; a URI that another model of the
// same file (an SDF world's) resolved to the same file is listed once.
void RecordMeshUris(const Model& model, const MeshResolveOptions& resolve, FileResult* result) {
  std::set<std::pair<std::string, std::string>> holders;  // (uri, file holding the geometry)
  std::set<std::pair<std::string, std::string>> listed;   // (uri, path found)
  for (const MeshUriResolution& known : result->mesh_uris) listed.insert({known.uri, known.path});
  for (const Link& link : model.links) {
    for (const Geometry& geometry : link.geometries) {
      if (geometry.type != Geometry::Type::kMesh) continue;
      if (!holders.insert({geometry.uri, geometry.location.file}).second) continue;
      MeshUriResolution mesh;
      mesh.uri = geometry.uri;
      std::string error;
      mesh.path = ResolveGeometryMeshUri(geometry, resolve, &error, &mesh.found_by).value_or("");
      if (!listed.insert({mesh.uri, mesh.path}).second) continue;
      result->mesh_uris.push_back(std::move(mesh));
    }
  }
}

}  // namespace

CLI::Option* AddPackagePathOption(CLI::App* command, std::vector<std::string>* paths) {
  return command
      ->add_option("--package-path", *paths,
                   "Folder searched for package:// mesh URIs before ROS_PACKAGE_PATH and "
                   "AMENT_PREFIX_PATH (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
}

MeshResolveOptions MakeResolveOptions(const std::vector<std::string>& package_paths,
                                      const std::vector<std::string>& model_paths,
                                      const std::string& model_file, MeshCache* cache) {
  MeshResolveOptions resolve;
  resolve.package_paths = package_paths;
  resolve.model_paths = model_paths;
  resolve.model_file = model_file;
  resolve.cache = cache;
  return resolve;
}

std::vector<std::string> WithConfigPackagePaths(std::vector<std::string> package_paths,
                                                const std::string& model_file) {
  if (const std::optional<std::string> path = FindConfigFor(model_file)) {
    const Config config = LoadConfig(*path);
    package_paths.insert(package_paths.end(), config.package_paths.begin(),
                         config.package_paths.end());
  }
  return package_paths;
}

void SetMeshJobs(int jobs, std::size_t file_threads) {
  Args().jobs = jobs;
  Args().file_threads = std::max<std::size_t>(1, file_threads);
}

void AddGeometryCheckOptions(CLI::App* check, const OptionFilter& wanted) {
  GeometryArgs& args = Args();
  CLI::Option* geometry = nullptr;
  if (wanted.Wants({"--geometry"})) {
    geometry = check->add_flag("--geometry", args.enabled,
                               "Read the meshes' mass properties: rules "
                               "inertia-disagrees-with-geometry and mesh-unreadable, and mesh "
                               "solids for products-sign-suspect");
  }
  if (wanted.Wants({"--no-geometry"})) {
    CLI::Option* no_geometry = check->add_flag(
        "--no-geometry", args.no_geometry,
        "Do not read meshes at all (by default their bounding boxes are read, so that mesh-only "
        "links are judged against their size)");
    if (geometry != nullptr) no_geometry->excludes(geometry);
  }
  if (wanted.Wants({"--geometry-factor"})) {
    check
        ->add_option("--geometry-factor", args.factor,
                     "inertia-disagrees-with-geometry: principal moments differing by more than "
                     "this factor")
        ->check(CLI::Range(1.0 + 1e-12, 1e300))
        ->capture_default_str();
  }
  if (wanted.Wants({"--package-path"})) AddPackagePathOption(check, &args.package_paths);
  if (wanted.Wants({"--no-cache"})) {
    check->add_flag("--no-cache", args.no_cache,
                    "Read every mesh again: neither use nor update the cache of mesh numbers kept "
                    "between runs (docs/meshes.md; `massprops cache clean` empties it)");
  }
}

void UseGeometryShapes(const Model& model, const std::vector<std::string>& model_paths,
                       CheckOptions* options,
                       const std::vector<std::string>& config_package_paths) {
  GeometryArgs& args = Args();
  if (args.no_geometry) return;
  const MeshResolveOptions resolve =
      MakeResolveOptions(PackagePaths(config_package_paths), model_paths, model.file, RunCache());
  const bool has_mesh = std::any_of(model.links.begin(), model.links.end(), [](const Link& link) {
    return std::any_of(link.geometries.begin(), link.geometries.end(),
                       [](const Geometry& g) { return g.type == Geometry::Type::kMesh; });
  });
  if (has_mesh) {  // the cores are asked for only now: start-up without meshes does not pay
    const std::size_t wanted =
        args.jobs > 0 ? static_cast<std::size_t>(args.jobs) : std::thread::hardware_concurrency();
    PrefetchModelMeshes(model, resolve,
                        static_cast<int>(std::max<std::size_t>(1, wanted / args.file_threads)));
  }
  if (args.enabled) options->shape = MakeLinkShapeFunction(resolve);
  options->box = MakeLinkBoxFunction(resolve);
  options->points = MakeLinkPointsFunction(resolve);
  options->closed_mesh = MakeClosedMeshShapeFunction(resolve);  // the density rules
}

void CountMeshLinks(const Model& model, const std::vector<std::string>& model_paths,
                    FileResult* result, const std::vector<std::string>& config_package_paths) {
  GeometryArgs& args = Args();
  if (args.no_geometry) return;
  const MeshResolveOptions resolve =
      MakeResolveOptions(PackagePaths(config_package_paths), model_paths, model.file, RunCache());
  RecordMeshUris(model, resolve, result);
  // An SDF <submesh> its file does not have: a warning at the <submesh>, and the geometry of
  // unknown size (never the whole file); such a link is not counted as one whose mesh did not
  // resolve when no other mesh of it failed.
  std::set<std::string> submesh_only;  // links whose failing meshes are all unknown submeshes
  for (const Link& link : model.links) {
    if (std::none_of(link.geometries.begin(), link.geometries.end(),
                     [](const Geometry& g) { return !g.submesh.empty(); })) {
      continue;
    }
    bool unknown = false, other = false;
    for (const Geometry& g : link.geometries) {
      if (g.type != Geometry::Type::kMesh) continue;
      if (std::optional<std::string> why = UnknownSubmeshMessage(g, resolve)) {
        const SourceLocation& at = g.submesh_location.line > 0 ? g.submesh_location : g.location;
        result->findings.push_back(ReadWarningFinding(
            MakeReadError(at.file, at.line, "<submesh> of link '" + link.name + "'", *why)));
        unknown = true;
      } else if (!CalcGeometryBounds(g, resolve, nullptr)) {
        other = true;
      }
    }
    if (unknown && !other) submesh_only.insert(link.name);
  }
  if (args.enabled) return;
  const LinkBoxFunction box = MakeLinkBoxFunction(resolve);
  for (const Link& link : model.links) {
    const bool has_mesh =
        std::any_of(link.geometries.begin(), link.geometries.end(),
                    [](const Geometry& g) { return g.type == Geometry::Type::kMesh; });
    if (!has_mesh) continue;
    ++result->mesh_links;
    const std::optional<LinkGeometryBox> found = box(link);
    if (!found || found->unresolved_uri.empty() || submesh_only.count(link.name)) continue;
    ++result->mesh_links_unresolved;
    if (result->first_unresolved_mesh.empty())
      result->first_unresolved_mesh = found->unresolved_uri;
  }
}

void AddGeometryFindings(const Model& model, const CheckOptions& options,
                         const std::vector<std::string>& model_paths,
                         std::vector<Finding>* findings,
                         const std::vector<std::string>& config_package_paths) {
  GeometryArgs& args = Args();
  if (!args.enabled) return;
  GeometryCheckOptions geometry;
  geometry.enabled = true;
  geometry.factor = args.factor;
  geometry.resolve =
      MakeResolveOptions(PackagePaths(config_package_paths), model_paths, model.file, RunCache());
  geometry.check = options;
  const std::vector<Finding> found = CheckModelGeometry(model, geometry);
  findings->insert(findings->end(), found.begin(), found.end());
}

}  // namespace massprops::cli
