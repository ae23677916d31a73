#include "massprops/analysis/config.h"

// toml++ compiled into this file (header-only) with hidden visibility: no libtomlplusplus.so
// for the dynamic loader to map and relocate at every start of the tool.
#define TOML_HEADER_ONLY 1
#pragma GCC visibility push(hidden)
#include <toml++/toml.h>
#pragma GCC visibility pop

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

namespace massprops {
namespace {

namespace fs = std::filesystem;

std::string FormatConfigError(const std::string& file, int line, int column,
                              const std::string& message) {
  std::string out = file;
  if (line > 0) {
    out += ":" + std::to_string(line);
    if (column > 0) out += ":" + std::to_string(column);
  }
  return out + ": error: " + message;
}

[[noreturn]] void Fail(const std::string& file, const toml::source_region& where,
                       const std::string& message) {
  throw ConfigError(file, static_cast<int>(where.begin.line), static_cast<int>(where.begin.column),
                    message);
}

bool IsKnownRule(const std::string& id) {
  for (const RuleInfo& rule : AllRules()) {
    if (rule.id == id) return true;
  }
  return false;
}

std::string KnownRuleList() {
  std::string out;
  for (const RuleInfo& rule : AllRules()) {
    if (!out.empty()) out += ", ";
    out += rule.id;
  }
  return out;
}

// Parses a rule level: "off" → nullopt severity; else a Severity. Returns false when invalid.
bool ParseLevel(std::string_view text, std::optional<Severity>& level) {
  if (text == "off") {
    level = std::nullopt;
    return true;
  }
  const std::optional<Severity> severity = ParseSeverity(text);
  if (!severity) return false;
  level = severity;
  return true;
}

}  // namespace

ConfigError::ConfigError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(FormatConfigError(file, line, column, message)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(message) {}

Config ParseConfig(std::string_view text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& error) {
    Fail(source_name, error.source(), std::string(error.description()));
  }

  Config config;
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    if (name == "fail-on") {
      const auto* value = node.as_string();
      const std::optional<Severity> severity =
          value ? ParseSeverity(value->get()) : std::optional<Severity>();
      if (!severity) {
        Fail(source_name, node.source(), "'fail-on' must be \"error\", \"warning\" or \"note\"");
      }
      config.fail_on = severity;
    } else if (name == "tolerance") {
      const std::optional<double> value = node.value<double>();  // integers convert too
      if (!value || !(node.is_floating_point() || node.is_integer())) {
        Fail(source_name, node.source(), "'tolerance' must be a number");
      }
      if (!std::isfinite(*value) || *value < 0 || *value >= 1) {
        Fail(source_name, node.source(),
             "'tolerance' must be at least 0 and less than 1 (it is relative to the trace of the "
             "inertia); got " +
                 std::to_string(*value));
      }
      config.tolerance = *value;
    } else if (name == "target") {
      const auto* value = node.as_string();
      const std::optional<Target> target =
          value ? ParseTarget(value->get()) : std::optional<Target>();
      if (!target) {
        Fail(source_name, node.source(),
             "'target' must be \"generic\", \"mujoco\", \"drake\" or \"gazebo\"");
      }
      config.target = target;
    } else if (name == "model-paths" || name == "package-paths") {
      std::vector<std::string>& paths =
          name == "model-paths" ? config.model_paths : config.package_paths;
      const std::string must = "'" + name + "' must be an array of strings";
      const auto* array = node.as_array();
      if (!array) Fail(source_name, node.source(), must);
      for (const toml::node& element : *array) {
        const auto* path = element.as_string();
        if (!path) Fail(source_name, element.source(), must);
        paths.push_back(path->get());
      }
    } else if (name == "rules") {
      const auto* rules = node.as_table();
      if (!rules) Fail(source_name, node.source(), "'rules' must be a table ([rules])");
      for (const auto& [rule_key, level_node] : *rules) {
        const std::string rule(rule_key.str());
        if (!IsKnownRule(rule)) {
          Fail(source_name, rule_key.source(),
               "unknown rule '" + rule + "' (known rules: " + KnownRuleList() + ")");
        }
        const auto* level_text = level_node.as_string();
        std::optional<Severity> level;
        if (!level_text || !ParseLevel(level_text->get(), level)) {
          Fail(source_name, level_node.source(),
               "rule '" + rule + "' must be \"off\", \"note\", \"warning\" or \"error\"");
        }
        config.overrides[rule] = level;
      }
    } else {
      Fail(source_name, key.source(),
           "unknown key '" + name +
               "' (known keys: fail-on, tolerance, target, model-paths, package-paths, [rules])");
    }
  }
  return config;
}

Config LoadConfig(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, 0, 0, "cannot open the configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path, 0, 0, "cannot read the configuration file");
  Config config = ParseConfig(text.str(), path);
  config.path = path;
  std::error_code ec;
  const fs::path base = fs::absolute(fs::path(path), ec).parent_path();
  for (std::vector<std::string>* paths : {&config.model_paths, &config.package_paths}) {
    for (std::string& path : *paths) {
      const fs::path p(path);
      if (p.is_relative() && !ec) path = (base / p).lexically_normal().string();
    }
  }
  return config;
}

namespace {

// `dir` made absolute and normalized, then each parent up to the root; empty when the working
// directory cannot be known.
std::vector<fs::path> FoldersUpward(const std::string& dir) {
  std::vector<fs::path> folders;
  std::error_code ec;
  fs::path current = fs::absolute(fs::path(dir.empty() ? "." : dir), ec);
  if (ec) return folders;
  current = current.lexically_normal();
  // "/a/b/" (from ".") names the folder "/a/b": without this, "/a/b" would be looked in twice.
  if (!current.has_filename() && current.has_relative_path()) current = current.parent_path();
  while (true) {
    folders.push_back(current);
    const fs::path parent = current.parent_path();
    if (parent == current || parent.empty()) return folders;
    current = parent;
  }
}

// The first of `folders` that holds a configuration file, as "folder/.massprops.toml".
std::optional<std::string> FirstConfigIn(const std::vector<fs::path>& folders) {
  for (const fs::path& folder : folders) {
    std::error_code ec;
    const fs::path candidate = folder / kConfigFileName;
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> FindConfigUpward(const std::string& dir) {
  return FirstConfigIn(FoldersUpward(dir));
}

std::optional<std::string> FindConfigFor(const std::string& model_file) {
  const fs::path dir = model_file == "-" ? fs::path(".") : fs::path(model_file).parent_path();
  const std::vector<fs::path> from_file = FoldersUpward(dir.empty() ? "." : dir.string());
  std::optional<std::string> path = FirstConfigIn(from_file);
  if (path) return path;
  // Upward from the working directory, up to the first folder the search above already looked
  // in: every folder above that one was looked in too (a model below the working directory, the
  // usual case, then costs no second look at any folder).
  std::vector<fs::path> from_cwd = FoldersUpward(".");
  from_cwd.erase(
      std::find_first_of(from_cwd.begin(), from_cwd.end(), from_file.begin(), from_file.end()),
      from_cwd.end());
  return FirstConfigIn(from_cwd);
}

void ApplyConfig(const Config& config, CheckOptions& options) {
  if (config.tolerance) options.tolerance = *config.tolerance;
  for (const auto& [rule, level] : config.overrides) options.overrides[rule] = level;
}

}  // namespace massprops
