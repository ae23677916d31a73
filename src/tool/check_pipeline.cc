#include "check_pipeline.h"

#include <utility>

#include "geometry_cli.h"
#include "target_cli.h"

namespace massprops::cli {

CheckSettings MakeCheckSettings(std::optional<Target> target, const Config* config) {
  CheckSettings settings;
  if (target) {
    settings.target = *target;
  } else if (config && config->target) {
    settings.target = *config->target;
  }
  ApplyTargetProfile(settings.target, &settings.options);
  if (config) {
    ApplyConfig(*config, settings.options);
    if (config->fail_on) settings.fail_on = *config->fail_on;
    settings.model_paths = config->model_paths;
    settings.package_paths = config->package_paths;
  }
  return settings;
}

ReadOptions CheckReadOptions(const CheckSettings& settings) {
  ReadOptions read_options;
  read_options.sdf.model_paths = settings.model_paths;
  read_options.mjcf.mujoco_mesh_inertia = settings.target == Target::kMujoco;
  read_options.max_file_bytes = settings.max_input_bytes;
  return read_options;
}

FileResult CheckReadModels(const std::string& file, const ReadResult& read,
                           const CheckSettings& settings, const std::string* text) {
  FileResult result;
  result.path = file == "-" ? "<stdin>" : file;
  result.errors = read.errors;
  for (const ReadError& warning : read.warnings) {
    result.findings.push_back(ReadWarningFinding(warning));
  }
  for (Finding& finding : ReaderFindings(read, settings.options)) {
    result.findings.push_back(std::move(finding));
  }
  for (const Model& model : read.models) {
    result.format = ToString(model.format);
    result.models.push_back(model.name);
    CheckOptions check_options = settings.options;
    UseGeometryShapes(model, settings.model_paths, &check_options, settings.package_paths);
    std::vector<Finding> findings = CheckModel(model, check_options);
    AddGeometryFindings(model, settings.options, settings.model_paths, &findings,
                        settings.package_paths);
    CountMeshLinks(model, settings.model_paths, &result, settings.package_paths);
    if (settings.target != Target::kGeneric) {
      const std::string file_text = text ? *text : ReadTextForTarget(file);
      AddTargetFindings(model, settings.target, check_options, ReadMujocoCompilerOptions(file_text),
                        &findings, file_text);
    }
    result.findings.insert(result.findings.end(), findings.begin(), findings.end());
  }
  return result;
}

}  // namespace massprops::cli
