#pragma once
// The one pipeline of `massprops check` on one file's text: read, reader findings, the rules,
// the geometry glue and the target profile's findings. `check` (main.cc) runs it on the files
// it reads; the language server (lsp_server.cc) runs it on an editor's unsaved buffer, named by
// the file's path so that meshes, package:// URIs and SDF includes resolve from the file's place.
// Defined in src/tool/check_pipeline.cc.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/reporters.h"

namespace massprops::cli {

/// What one file is checked with.
struct CheckSettings {
  Target target = Target::kGeneric;
  CheckOptions options;
  Severity fail_on = Severity::kError;
  std::vector<std::string> model_paths;
  std::vector<std::string> package_paths;            // the configuration's, after --package-path
  std::size_t max_input_bytes = kMaxModelFileBytes;  // --max-input-size
};

/// The settings of a file from its target profile (`target`), then its configuration (`config`,
/// may be null; its own target applies when `target` is nullopt), each overriding the one
/// before. Command-line overrides are the caller's to apply afterwards.
CheckSettings MakeCheckSettings(std::optional<Target> target, const Config* config);

/// The ReadOptions `check` reads a file with under `settings`.
ReadOptions CheckReadOptions(const CheckSettings& settings);

/// Checks what was read from one file: `read` came from ReadModelFile or ReadModelString with
/// CheckReadOptions(settings); `file` is the name it was read under ("-" for standard input);
/// `text` is the file's text when the caller holds it, or null (then the target profiles read
/// it from `file` when they need it). Returns the file's result as `check` reports it (path
/// "<stdin>" for "-"). Reads meshes through the run's mesh cache (geometry_cli.h).
FileResult CheckReadModels(const std::string& file, const ReadResult& read,
                           const CheckSettings& settings, const std::string* text);

}  // namespace massprops::cli
