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

}  // namespace massprops::cli
