// `--target` (see src/tool/target_cli.h and docs/targets.md).
#include <fstream>
#include <sstream>
#include <string>

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

}  // namespace massprops::cli
