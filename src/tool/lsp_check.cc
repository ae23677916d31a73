// CheckDocument: an editor's buffer through `check`'s pipeline (lsp_server.h).
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "lsp_server.h"
#include "safe_write.h"
#include "massprops/analysis/config.h"

namespace massprops::cli::lsp {
namespace {

namespace fs = std::filesystem;

// The settings `check` would use for the file at `path` (its .massprops.toml, or the one given),
// with the server's target and search folders. Throws ConfigError.
CheckSettings SettingsForPath(const std::string& path, const ServerOptions& options) {
  std::optional<Config> config;
  if (!options.config.empty()) {
    config = LoadConfig(options.config);
  } else if (!path.empty()) {
    if (const std::optional<std::string> found = FindConfigFor(path)) config = LoadConfig(*found);
  }
  std::optional<Target> target;
  if (!options.target.empty()) target = ParseTarget(options.target);
  CheckSettings settings = MakeCheckSettings(target, config ? &*config : nullptr);
  settings.model_paths.insert(settings.model_paths.begin(), options.model_paths.begin(),
                              options.model_paths.end());
  settings.package_paths.insert(settings.package_paths.begin(), options.package_paths.begin(),
                                options.package_paths.end());
  return settings;
}

// Whether `text` ends with `tail` (lower case), in any case: ".URDF" too.
bool EndsWithNoCase(const std::string& text, const std::string& tail) {
  if (text.size() < tail.size()) return false;
  for (std::size_t i = 0; i < tail.size(); ++i) {
    const char c = text[text.size() - tail.size() + i];
    if (std::tolower(static_cast<unsigned char>(c)) != tail[i]) return false;
  }
  return true;
}

// The bytes of the file at `path`, or nullopt when it cannot be read.
std::optional<std::string> FileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A file beside `path` (same folder, so that the expander resolves relative includes and the
// package as it does for the file) holding `text`: "" when it cannot be written (*error says
// why). Its name starts with a dot and ends with ".xacro" (the trace reads it as a source).
std::string WriteBeside(const std::string& path, const std::string& text, std::string* error) {
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::string name = (folder / ".massprops-lsp-XXXXXX.xacro").string();
  const int fd = mkstemps(name.data(), 6);
  if (fd < 0) {
    *error = "cannot write the unsaved buffer beside " + path + ": " + std::strerror(errno);
    return {};
  }
  const bool complete = WriteAll(fd, text);
  close(fd);
  if (!complete) {
    std::remove(name.c_str());
    *error = "cannot write the unsaved buffer beside " + path;
    return {};
  }
  return name;
}

// Whether two paths name the same file (both may be relative to the working directory).
bool SamePath(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

// A .xacro document through its expander (docs/xacro.md): the buffer, when it differs from the
// file, is expanded from a file beside it; the findings' source places in that file are renamed
// to the document's path.
void CheckXacro(const Document& document, const ServerOptions& options, Analysis* analysis) {
  analysis->xacro = true;
  std::string top = document.path;
  std::string buffer_file;
  if (FileText(document.path) != document.text) {
    buffer_file = WriteBeside(document.path, document.text, &analysis->setup_error);
    if (buffer_file.empty()) return;
    top = buffer_file;
  }
  XacroOptions xacro = options.xacro;
  xacro.expanded.clear();
  std::optional<XacroRun> run = StartXacroRun(xacro, top, &analysis->setup_error);
  if (run) {
    // The file on disk holds older text than the buffer: it is not where the numbers were written.
    if (!buffer_file.empty()) run->expansion.trace.exclude_files.push_back(document.path);
    const ReadResult read = ReadModelString(run->expansion.text, run->checked_file,
                                            CheckReadOptions(analysis->settings));
    analysis->result =
        CheckReadModels(run->checked_file, read, analysis->settings, &run->expansion.text);
    FinishXacroRun(&*run, &analysis->result);
    analysis->setup_error.clear();
  }
  if (buffer_file.empty()) return;
  std::remove(buffer_file.c_str());
  for (Finding& finding : analysis->result.findings) {
    if (!finding.source) continue;
    for (SourcePlace& place : finding.source->places) {
      if (SamePath(place.file, buffer_file)) {
        place.file = document.path;
      }
    }
  }
}

}  // namespace

Analysis CheckDocument(const Document& document, const ServerOptions& options) {
  Analysis analysis;
  analysis.version = document.version;
  analysis.text = document.text;
  const std::string name = document.path.empty() ? document.uri : document.path;
  const bool xacro = EndsWithNoCase(name, ".xacro");
  // Editors attach the server to every XML file: one that is not named .urdf, .sdf or .xacro is
  // judged only when its root element is a model's, as `check FOLDER` picks files.
  if (!xacro && !EndsWithNoCase(name, ".urdf") && !EndsWithNoCase(name, ".sdf") &&
      !DetectModelFormat(document.text).has_value()) {
    analysis.not_a_model = true;
    return analysis;
  }
  try {
    analysis.settings = SettingsForPath(document.path, options);
  } catch (const ConfigError& error) {
    analysis.setup_error = error.what();
    return analysis;
  }
  if (xacro) {
    if (!options.xacro_enabled || document.path.empty()) {
      analysis.xacro = true;
      analysis.setup_error =
          "xacro documents are not checked (initializationOptions xacro.enabled)";
      return analysis;
    }
    CheckXacro(document, options, &analysis);
    return analysis;
  }
  analysis.read = ReadModelString(document.text, name, CheckReadOptions(analysis.settings));
  analysis.result = CheckReadModels(name, analysis.read, analysis.settings, &analysis.text);
  return analysis;
}

}  // namespace massprops::cli::lsp
