// The `massprops check` options of the geometry rules (see src/tool/geometry_cli.h).
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "geometry_cli.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops::cli {
namespace {

struct GeometryArgs {
  bool enabled = false;
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

void AddGeometryCheckOptions(CLI::App* check) {
  GeometryArgs& args = Args();
  check->add_flag("--geometry", args.enabled,
                  "Read link geometry (meshes too): rules inertia-disagrees-with-geometry and "
                  "mesh-unreadable");
  check
      ->add_option("--geometry-factor", args.factor,
                   "inertia-disagrees-with-geometry: principal moments differing by more than "
                   "this factor")
      ->check(CLI::Range(1.0 + 1e-12, 1e300))
      ->capture_default_str();
  AddPackagePathOption(check, &args.package_paths);
}

void UseGeometryShapes(const Model& model, const std::vector<std::string>& model_paths,
                       CheckOptions* options) {
  GeometryArgs& args = Args();
  if (!args.enabled) return;
  options->shape = MakeLinkShapeFunction(
      MakeResolveOptions(args.package_paths, model_paths, model.file, &args.cache));
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
