// The `massprops check` options of the geometry rules (see src/tool/geometry_cli.h).
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "geometry_cli.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/reporters.h"

namespace massprops::cli {
namespace {

struct GeometryArgs {
  bool enabled = false;      // --geometry
  bool no_geometry = false;  // --no-geometry
  double factor = 2;
  std::vector<std::string> package_paths;
  MeshCache cache;  // One per run: each mesh file is read once.
};

GeometryArgs& Args() {
  static GeometryArgs args;
  return args;
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
}

void UseGeometryShapes(const Model& model, const std::vector<std::string>& model_paths,
                       CheckOptions* options) {
  GeometryArgs& args = Args();
  if (args.no_geometry) return;
  const MeshResolveOptions resolve =
      MakeResolveOptions(args.package_paths, model_paths, model.file, &args.cache);
  if (args.enabled) options->shape = MakeLinkShapeFunction(resolve);
  options->box = MakeLinkBoxFunction(resolve);
  options->closed_mesh = MakeClosedMeshShapeFunction(resolve);  // the density rules
}

void CountMeshLinks(const Model& model, const std::vector<std::string>& model_paths,
                    FileResult* result) {
  GeometryArgs& args = Args();
  if (args.no_geometry || args.enabled) return;
  const LinkBoxFunction box = MakeLinkBoxFunction(
      MakeResolveOptions(args.package_paths, model_paths, model.file, &args.cache));
  for (const Link& link : model.links) {
    const bool has_mesh =
        std::any_of(link.geometries.begin(), link.geometries.end(),
                    [](const Geometry& g) { return g.type == Geometry::Type::kMesh; });
    if (!has_mesh) continue;
    ++result->mesh_links;
    const std::optional<LinkGeometryBox> found = box(link);
    if (!found || found->unresolved_uri.empty()) continue;
    ++result->mesh_links_unresolved;
    if (result->first_unresolved_mesh.empty())
      result->first_unresolved_mesh = found->unresolved_uri;
  }
}

void AddGeometryFindings(const Model& model, const CheckOptions& options,
                         const std::vector<std::string>& model_paths,
                         std::vector<Finding>* findings) {
  GeometryArgs& args = Args();
  if (!args.enabled) return;
  GeometryCheckOptions geometry;
  geometry.enabled = true;
  geometry.factor = args.factor;
  geometry.resolve = MakeResolveOptions(args.package_paths, model_paths, model.file, &args.cache);
  geometry.check = options;
  const std::vector<Finding> found = CheckModelGeometry(model, geometry);
  findings->insert(findings->end(), found.begin(), found.end());
}

}  // namespace massprops::cli
