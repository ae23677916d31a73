// `massprops check -j N`: files are checked in parallel, and the output does not depend on N.
// The reference is the tool itself with -j 1 (one thread, the order of the command line): every
// byte of standard output and the exit code must be the same with -j 4, over the whole corpus
// (../shared/corpus, every URDF and SDF of its MANIFEST, run from the corpus folder with the
// model paths of tools/corpus_summary.py), in every output format.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "tool_runner.h"

namespace {

using massprops::test_support::CorpusDir;
using massprops::test_support::ManifestRow;
using massprops::test_support::ReadCorpusManifest;
using massprops::test_support::RunTool;
using massprops::test_support::ToolRun;

std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The corpus model files (relative to the corpus folder), in MANIFEST order.
std::vector<std::string> CorpusModelFiles() {
  std::vector<std::string> files;
  for (const ManifestRow& row : ReadCorpusManifest()) {
    if (row.format == "urdf" || row.format == "sdf") files.push_back(row.file);
  }
  return files;
}

// `cd CORPUS && massprops check -j JOBS ARGS FILES...` with the corpus' model paths (those of
// tools/corpus_summary.py); standard output and the exit code.
ToolRun CheckCorpus(int jobs, const std::string& args, const std::vector<std::string>& files) {
  std::string command = "cd " + Quote(CorpusDir()) + " && " + Quote(MASSPROPS_TOOL_PATH) +
                        " check -j " + std::to_string(jobs) + " " + args;
  for (const std::string& folder : massprops::test_support::CorpusModelFolders()) {
    command += " --model-path " + folder;
  }
  for (const std::string& file : files) command += " " + Quote(file);
  command += " 2>/dev/null";
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

class CheckJobsTest : public ::testing::TestWithParam<const char*> {};

TEST_P(CheckJobsTest, FourJobsGiveTheBytesOfOneJobOnTheWholeCorpus) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<std::string> files = CorpusModelFiles();
  // The MANIFEST lists 298 URDF and SDF files (counted with awk on its format column); a short
  // list would make the comparison weak.
  ASSERT_GE(files.size(), 298u);
  const std::string format = std::string("--format ") + GetParam();
  const ToolRun one = CheckCorpus(1, format, files);
  const ToolRun four = CheckCorpus(4, format, files);
  ASSERT_GE(one.exit_code, 0);
  // The corpus has models with invalid inertias (MANIFEST invalid_inertial_links): exit code 1 or
  // 2 (some files do not load), never 0.
  EXPECT_NE(one.exit_code, 0);
  EXPECT_EQ(four.exit_code, one.exit_code);
  if (std::string(GetParam()) == "json") {
    // JSON lists every file, in command-line order (the other formats list findings only).
    std::size_t position = 0;
    for (const std::string& file : {files.front(), files[files.size() / 2], files.back()}) {
      const std::size_t found = one.output.find("\"" + file + "\"", position);
      ASSERT_NE(found, std::string::npos) << file << " missing or out of order";
      position = found;
    }
  } else {
    EXPECT_NE(one.output.find(".urdf"), std::string::npos);  // findings name their files
    EXPECT_NE(one.output.find(".sdf"), std::string::npos);
  }
  EXPECT_TRUE(four.output == one.output) << "-j 4 and -j 1 outputs differ (" << four.output.size()
                                         << " and " << one.output.size() << " bytes)";
}

INSTANTIATE_TEST_SUITE_P(Formats, CheckJobsTest,
                         ::testing::Values("text", "json", "sarif", "github"));

TEST(CheckJobsFolderTest, AFolderCheckedWithFourJobsGivesTheBytesOfOneJob) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/example-robot-data");
  const std::string folder = Quote(CorpusDir() + "/example-robot-data");
  const ToolRun one = RunTool("check -j 1 --format json " + folder);
  const ToolRun four = RunTool("check -j 4 --format json " + folder);
  ASSERT_GE(one.exit_code, 0);
  EXPECT_EQ(four.exit_code, one.exit_code);
  EXPECT_NE(one.output.find("\"files\""), std::string::npos);
  EXPECT_TRUE(four.output == one.output);
}

TEST(CheckJobsFolderTest, NegativeJobCountIsAUsageError) {
  const ToolRun run = RunTool("check -j -1 " + Quote(CorpusDir()), true);
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace
