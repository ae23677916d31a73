#pragma once
// `massprops check --geometry`: the options and the glue that runs the geometry rules
// (include/massprops/analysis/geometry_checks.h) inside the check command. Defined in
// src/tool/geometry_check_command.cc; main.cc calls these.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"
#include "massprops/output/reporters.h"
#include "option_filter.h"

namespace massprops::cli {

/// Adds `--package-path DIR` (repeatable) to a subcommand (check, fix, report).
CLI::Option* AddPackagePathOption(CLI::App* command, std::vector<std::string>* paths);

/// Where a run's meshes are found: the given folders, the model file (relative paths, its
/// repository and ancestors for package://) and the run's cache; the environment variables too.
MeshResolveOptions MakeResolveOptions(const std::vector<std::string>& package_paths,
                                      const std::vector<std::string>& model_paths,
                                      const std::string& model_file, MeshCache* cache);

/// `package_paths` (--package-path) followed by the package-paths of the configuration file
/// that applies to `model_file` (FindConfigFor), as `report` and `fix` search them. Throws
/// ConfigError when that file is not valid.
std::vector<std::string> WithConfigPackagePaths(std::vector<std::string> package_paths,
                                                const std::string& model_file);

/// How many threads read the meshes of one file (PrefetchModelMeshes): `jobs` (--jobs; 0: one
/// per core) shared among the `file_threads` threads that check files, at least 1.
void SetMeshJobs(int jobs, std::size_t file_threads);

/// Adds those of --geometry, --no-geometry, --geometry-factor X and --package-path DIR that
/// `wanted` asks for to the check subcommand.
void AddGeometryCheckOptions(CLI::App* check, const OptionFilter& wanted);

/// By default sets options->box to the meshes' bounding boxes (MakeLinkBoxFunction, the run's
/// mesh cache), so that CheckModel judges mesh-only links against their size; with --geometry
/// also options->shape to a mesh-reading LinkShapeFunction (the meshes' mass properties); and
/// options->closed_mesh (MakeClosedMeshShapeFunction) for the density rules. With
/// --no-geometry leaves `options` unchanged.
/// `config_package_paths` (the file's .massprops.toml package-paths) are searched after
/// --package-path, here and in the two functions below.
void UseGeometryShapes(const Model& model, const std::vector<std::string>& model_paths,
                       CheckOptions* options, const std::vector<std::string>& config_package_paths);

/// In the default mode (neither --geometry, whose mesh-unreadable findings name each mesh, nor
/// --no-geometry): counts into *result the links of `model` whose geometry includes a mesh, and
/// those with a mesh that does not resolve or cannot be read (with the first such URI), for the
/// one summary line that replaces a finding per link. Each mesh file is read once per run.
/// Unless --no-geometry (so with --geometry too), also records how each mesh URI resolved
/// (result->mesh_uris).
void CountMeshLinks(const Model& model, const std::vector<std::string>& model_paths,
                    FileResult* result, const std::vector<std::string>& config_package_paths);

/// Appends the geometry findings of `model` when --geometry was given (one mesh cache per run),
/// honouring `options.overrides` for the geometry rules. `model_paths` are searched for
/// model:// mesh URIs.
void AddGeometryFindings(const Model& model, const CheckOptions& options,
                         const std::vector<std::string>& model_paths,
                         std::vector<Finding>* findings,
                         const std::vector<std::string>& config_package_paths);

}  // namespace massprops::cli
