#pragma once
// Runs the built `massprops` tool (MASSPROPS_TOOL_PATH) for the end-to-end tests.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace massprops::test_support {

struct ToolRun {
  int exit_code = -1;  ///< -1 when the tool could not be started or did not exit normally.
  std::string output;  ///< Standard output (and standard error when asked for).
};

/// Runs `massprops ARGS` through the shell (ARGS are shell words, quote paths yourself) and
/// captures its standard output, and its standard error too when `with_stderr`.
inline ToolRun RunTool(const std::string& args, bool with_stderr = false) {
  const std::string command = std::string("'") + MASSPROPS_TOOL_PATH + "' " + args +
                              (with_stderr ? " 2>&1" : " 2>/dev/null");
  ToolRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace massprops::test_support
