// `--target` (see src/tool/target_cli.h and docs/targets.md).
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "massprops/analysis/config.h"
#include "target_cli.h"

namespace massprops::cli {

CLI::Option* AddTargetOption(CLI::App* command, std::string* target) {
  return command
      ->add_option("--target", *target,
                   "Judge as this simulator does (docs/targets.md): generic (default), mujoco "
                   "(MuJoCo 2.2.2's compiler), drake, gazebo")
      ->check(CLI::IsMember({"generic", "mujoco", "drake", "gazebo"}));
}

std::string ReadTextForTarget(const std::string& path) {
  if (path.empty() || path == "-") return {};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Target ResolveTarget(const std::string& cli_target, const std::string& file) {
  if (!cli_target.empty()) return *ParseTarget(cli_target);
  const std::optional<std::string> path = FindConfigFor(file);
  if (!path) return Target::kGeneric;
  return LoadConfig(*path).target.value_or(Target::kGeneric);
}

}  // namespace massprops::cli
