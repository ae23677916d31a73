#pragma once
// `--target generic|mujoco|drake|gazebo` on check, report and fix (include/massprops/
// target_profile.h). Defined in src/tool/target_command.cc.
#include <CLI/CLI.hpp>
#include <string>

#include "massprops/analysis/target_profile.h"

namespace massprops::cli {

/// Adds `--target NAME` to a subcommand; `*target` stays "" when it is not given.
CLI::Option* AddTargetOption(CLI::App* command, std::string* target);

/// The text of the model file at `path`, for what the target profiles read from it (MuJoCo's
/// <mujoco><compiler>, Gazebo's lumping tags); "" for "-" or a file that cannot be read.
/// Never throws.
std::string ReadTextForTarget(const std::string& path);

/// The target of `file` as `check` decides it: `cli_target` (--target) when not empty, else the
/// `target = "..."` of the .massprops.toml `check` uses for that file (the nearest one upward from
/// the file's folder, else upward from the working directory; "-" is in the working directory),
/// else generic. The configuration file is read only when --target is not given. Throws
/// massprops::ConfigError when that file is not valid.
Target ResolveTarget(const std::string& cli_target, const std::string& file);

}  // namespace massprops::cli
