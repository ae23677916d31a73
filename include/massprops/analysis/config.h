#pragma once
/// @file
/// The `.massprops.toml` configuration file of `massprops check`:
/// ```
/// fail-on = "warning"          # error (default) | warning | note
/// tolerance = 1e-6             # relative validity tolerance, 0 <= t < 1
/// target = "mujoco"            # generic (default) | mujoco | drake | gazebo (target_profile.h)
/// model-paths = ["models"]     # folders searched for SDF model:// URIs (relative to the file)
/// package-paths = ["../src"]  # folders searched first for package:// mesh URIs (likewise)
/// [rules]
/// units-suspect = "off"        # off | note | warning | error
/// com-outside-geometry = "note"
/// ```
/// Every key is optional; an unknown key, an unknown rule id or a value of the wrong type is an
/// error that names the line.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/target_profile.h"

namespace massprops {

/// The name `FindConfigUpward` looks for.
inline constexpr const char* kConfigFileName = ".massprops.toml";

/// What a configuration file says. Unset members leave the tool's defaults (or command-line
/// options) alone.
struct Config {
  std::string path;                 ///< The file it was read from (empty for ParseConfig text).
  std::optional<Severity> fail_on;  ///< `fail-on`.
  std::optional<double> tolerance;  ///< `tolerance`.
  std::optional<Target> target;     ///< `target`: the simulator profile (see target_profile.h).
  /// `model-paths`, each made absolute against the folder of the config file (when read from a
  /// file), else as written.
  std::vector<std::string> model_paths;
  /// `package-paths`, made absolute the same way: searched for package:// mesh URIs after
  /// --package-path and before the description's repository (mesh_loader.h).
  std::vector<std::string> package_paths;
  /// `[rules]`: a severity, or nullopt for "off". Same meaning as CheckOptions::overrides.
  std::map<std::string, std::optional<Severity>> overrides;
};

/// A configuration file that cannot be read or is not valid. what() is
/// "file:line:col: error: message" (line and column left out when unknown).
class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string file, int line, int column, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }      ///< 1-based; 0 when unknown.
  int column() const { return column_; }  ///< 1-based; 0 when unknown.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string message_;
};

/// Parses configuration text; `source_name` is used in error messages. Rule ids are checked
/// against AllRules(). Throws ConfigError on a TOML syntax error, an unknown key or rule id, a
/// value of the wrong type or out of range.
Config ParseConfig(std::string_view text, const std::string& source_name);

/// Reads and parses the file at `path` (relative model-paths and package-paths are resolved
/// against its folder).
/// Throws ConfigError when it cannot be read or is not valid (see ParseConfig).
Config LoadConfig(const std::string& path);

/// The first `.massprops.toml` (a regular file) in `dir` or one of its ancestors, nearest first;
/// nullopt when there is none. `dir` is made absolute against the working directory first.
/// Never throws for a missing or unreadable folder (that simply finds nothing).
/// Cost: one stat per folder up to the root.
std::optional<std::string> FindConfigUpward(const std::string& dir);

/// The configuration file that applies to `model_file` (a path, or "-" for standard input), as
/// every command finds it: the nearest `.massprops.toml` upward from the file's folder (the
/// working directory for "-"), else the nearest upward from the working directory; nullopt when
/// there is none. Never throws. Cost: two FindConfigUpward at most.
std::optional<std::string> FindConfigFor(const std::string& model_file);

/// Applies `config` to `options`: its tolerance, then its overrides (replacing those of the same
/// rule).
void ApplyConfig(const Config& config, CheckOptions& options);

}  // namespace massprops
