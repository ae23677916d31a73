#pragma once
// `--target generic|mujoco|drake|gazebo` on check, report and fix (include/massprops/
// target_profile.h). Defined in tools/target_command.cc.
#include <CLI/CLI.hpp>
#include <string>

#include "massprops/target_profile.h"

namespace massprops::cli {

/// Adds `--target NAME` to a subcommand; `*target` stays "" when it is not given.
CLI::Option* AddTargetOption(CLI::App* command, std::string* target);

/// The <mujoco><compiler> settings of the URDF file at `path` (MuJoCo's URDF defaults when the
/// file is "-", cannot be read, or has none). Never throws.
MujocoCompilerOptions ReadMujocoOptions(const std::string& path);

}  // namespace massprops::cli
