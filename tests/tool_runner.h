#pragma once
// Runs the built `massprops` tool (MASSPROPS_TOOL_PATH) for the end-to-end tests.

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
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

/// A file's whole content ("" when it cannot be read).
inline std::string ReadWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A run whose standard output and standard error are kept apart.
struct SplitToolRun {
  int code = -1;  ///< -1 when the tool did not exit normally.
  std::string out;
  std::string err;
};

/// Runs `massprops ARGS` through the shell with its standard output and error written to
/// stdout.txt and stderr.txt in `dir` (a test's own folder), and returns both.
inline SplitToolRun RunToolSplit(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = std::string("'") + MASSPROPS_TOOL_PATH + "' " + args + " >'" +
                              out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  SplitToolRun run;
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = ReadWholeFile(out);
  run.err = ReadWholeFile(err);
  return run;
}

}  // namespace massprops::test_support
