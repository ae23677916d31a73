// End-to-end tests of the `massprops` tool: runs the built executable (MASSPROPS_TOOL_PATH) on the
// fixtures of testdata/cli/ and the bundled example, and checks exit codes and outputs.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../src/tool/option_filter.h"
#include "massprops/analysis/checks.h"

namespace {

using nlohmann::json;

const std::string kTool = MASSPROPS_TOOL_PATH;
const std::string kCliData = std::string(MASSPROPS_TESTDATA_DIR) + "/cli";

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `sh -c "cd DIR && [ENV] massprops ARGS [< STDIN]"` and collects its exit code and output.
RunResult RunTool(const std::string& args, const std::string& stdin_file = "",
                  const std::string& env = "", const std::string& dir = kCliData) {
  const std::string err_path =
      ::testing::TempDir() + "massprops_cli_test_stderr_" + std::to_string(getpid()) + ".txt";
  std::string command = "cd " + Quote(dir) + " && " + env + " " + Quote(kTool) + " " + args;
  if (!stdin_file.empty()) command += " < " + Quote(stdin_file);
  command += " 2> " + Quote(err_path);
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.err = ReadAll(err_path);
  std::remove(err_path.c_str());
  return result;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// 1-based numbers of the lines of `file` that contain `needle`, in order.
std::vector<int> LinesContaining(const std::string& file, const std::string& needle) {
  std::istringstream in(ReadAll(file));
  std::vector<int> lines;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (Contains(line, needle)) lines.push_back(number);
  }
  return lines;
}

// (rule, link) pairs of every finding in a JSON report.
std::vector<std::pair<std::string, std::string>> RulesAndLinks(const json& report) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const json& file : report.at("files")) {
    for (const json& finding : file.at("findings")) {
      out.emplace_back(finding.at("rule"), finding.at("link"));
    }
  }
  return out;
}

bool HasFinding(const json& report, const std::string& rule, const std::string& link) {
  for (const auto& [r, l] : RulesAndLinks(report)) {
    if (r == rule && l == link) return true;
  }
  return false;
}

TEST(CliTest, VersionPrintsTheProjectVersionAndExitsZero) {
  const RunResult run = RunTool("--version");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, std::string("massprops ") + MASSPROPS_VERSION + "\n");
}

TEST(CliTest, HelpDescribesTheCheckCommandAndExitsZero) {
  RunResult run = RunTool("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_TRUE(Contains(run.out, "check")) << run.out;
  EXPECT_TRUE(Contains(run.out, "Exit codes")) << run.out;
  run = RunTool("check --help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option : {"--format", "--fail-on", "--disable", "--severity", "--tolerance",
                             "--config", "--model-path", "--quiet", "--list-rules", "--color"}) {
    EXPECT_TRUE(Contains(run.out, option)) << option << " missing from:\n" << run.out;
  }
}

TEST(CliTest, UsageErrorsExitWithTwo) {
  EXPECT_EQ(RunTool("").exit_code, 2);  // a subcommand is required
  EXPECT_EQ(RunTool("frobnicate").exit_code, 2);
  EXPECT_EQ(RunTool("check --format xml clean.urdf").exit_code, 2);
  EXPECT_EQ(RunTool("check --fail-on fatal clean.urdf").exit_code, 2);
  EXPECT_EQ(RunTool("check --tolerance 2 clean.urdf").exit_code, 2);
  EXPECT_EQ(RunTool("check --no-such-option clean.urdf").exit_code, 2);
  const RunResult unknown_rule = RunTool("check --disable no-such-rule clean.urdf");
  EXPECT_EQ(unknown_rule.exit_code, 2);
  EXPECT_TRUE(Contains(unknown_rule.err, "no-such-rule")) << unknown_rule.err;
  EXPECT_EQ(RunTool("check --severity inertial-missing clean.urdf").exit_code, 2);
  EXPECT_EQ(RunTool("check --severity inertial-missing=loud clean.urdf").exit_code, 2);
  EXPECT_TRUE(unknown_rule.out.empty());
}

TEST(CliTest, ACleanModelExitsZeroAndReportsNothing) {
  RunResult run = RunTool("check clean.urdf");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(run.out, "massprops: checked 1 file: 0 errors, 0 warnings, 0 notes\n");
  run = RunTool("check --quiet clean.urdf");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "");
  run = RunTool("check clean.sdf");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(run.out, "massprops: checked 1 file: 0 errors, 0 warnings, 0 notes\n");
}

TEST(CliTest, AnImpossibleInertiaExitsOneWithAFileLineDiagnostic) {
  const RunResult run = RunTool("check not_physical.urdf");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  // The arm's inertia is the second <inertial> of the fixture; the finding points at the
  // <inertial> or at its <inertia>.
  const int inertial_line = LinesContaining(kCliData + "/not_physical.urdf", "<inertial>")[1];
  const int inertia_line = LinesContaining(kCliData + "/not_physical.urdf", "<inertia ")[1];
  const bool at_inertial =
      Contains(run.out, "not_physical.urdf:" + std::to_string(inertial_line) + ":");
  const bool at_inertia =
      Contains(run.out, "not_physical.urdf:" + std::to_string(inertia_line) + ":");
  EXPECT_TRUE(at_inertial || at_inertia) << run.out;
  EXPECT_TRUE(Contains(run.out, ": error: ")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[inertia-not-physical]\n")) << run.out;
}

TEST(CliTest, JsonOutputParsesAndNamesRuleLinkAndLine) {
  const RunResult run = RunTool("check --format json not_physical.urdf");
  EXPECT_EQ(run.exit_code, 1);
  const json report = json::parse(run.out);
  EXPECT_EQ(report.at("version"), MASSPROPS_VERSION);
  ASSERT_EQ(report.at("files").size(), 1u);
  const json& file = report["files"][0];
  EXPECT_EQ(file.at("path"), "not_physical.urdf");
  EXPECT_EQ(file.at("format"), "urdf");
  EXPECT_EQ(file.at("models"), json::array({"not_physical"}));
  EXPECT_TRUE(HasFinding(report, "inertia-not-physical", "arm")) << run.out;
  for (const json& finding : file.at("findings")) {
    if (finding.at("rule") != "inertia-not-physical") continue;
    EXPECT_EQ(finding.at("severity"), "error");
    EXPECT_GT(finding.at("line").get<int>(), 0);
  }
  EXPECT_GE(report.at("summary").at("errors").get<int>(), 1);
  EXPECT_EQ(report.at("summary").at("read_errors"), 0);
}

TEST(CliTest, FailOnDecidesWhetherWarningsFailTheRun) {
  // missing_inertial.urdf has one warning (inertial-missing) and one note (the massless pan link).
  RunResult run = RunTool("check missing_inertial.urdf");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(Contains(run.out, ": warning: ")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[inertial-missing]")) << run.out;
  EXPECT_EQ(RunTool("check --fail-on warning missing_inertial.urdf").exit_code, 1);
  EXPECT_EQ(RunTool("check --fail-on note missing_inertial.urdf").exit_code, 1);
  EXPECT_EQ(RunTool("check --fail-on error missing_inertial.urdf").exit_code, 0);
}

TEST(CliTest, RulesCanBeDisabledOrHaveTheirSeverityChanged) {
  RunResult run =
      RunTool("check --fail-on warning --disable inertial-missing missing_inertial.urdf");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_FALSE(Contains(run.out, "[inertial-missing]")) << run.out;
  EXPECT_EQ(RunTool("check --severity inertial-missing=error missing_inertial.urdf").exit_code, 1);
  run = RunTool("check --fail-on warning --severity inertial-missing=note missing_inertial.urdf");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_TRUE(Contains(run.out, ": note: ")) << run.out;
  EXPECT_EQ(RunTool("check --fail-on warning --severity inertial-missing=off missing_inertial.urdf")
                .exit_code,
            0);
}

TEST(CliTest, ADashReadsTheModelFromStandardInput) {
  const RunResult run = RunTool("check -", kCliData + "/not_physical.urdf");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_TRUE(Contains(run.out, "<stdin>:")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[inertia-not-physical]")) << run.out;
  EXPECT_EQ(RunTool("check -", kCliData + "/clean.urdf").exit_code, 0);
}

TEST(CliTest, AFolderIsSearchedRecursivelyForModelsOnly) {
  // tree/ holds a.urdf (clean), sub/UPPER.URDF (clean; extensions match in any case),
  // sub/b.sdf (clean), sub/robot.xml (a <robot>: not physical), launch.xml (root <launch>) and
  // notes.txt; the last two are skipped and counted as skipped.
  const RunResult run = RunTool("check --format json tree");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  const json report = json::parse(run.out);
  std::vector<std::string> paths;
  for (const json& file : report.at("files")) paths.push_back(file.at("path"));
  EXPECT_EQ(paths, (std::vector<std::string>{"tree/a.urdf", "tree/sub/UPPER.URDF", "tree/sub/b.sdf",
                                             "tree/sub/robot.xml"}));
  EXPECT_EQ(report["files"][2].at("format"), "sdf");
  EXPECT_TRUE(HasFinding(report, "inertia-not-physical", "arm"));
  EXPECT_EQ(report.at("summary").at("files"), 4);
  EXPECT_EQ(report.at("summary").at("skipped_files"), 2);
  const RunResult text = RunTool("check tree");
  EXPECT_TRUE(Contains(text.err + text.out, "2 other files in the folders skipped"))
      << text.out << text.err;
}

TEST(CliTest, AMissingFileExitsTwoAndTheOtherFilesAreStillReported) {
  RunResult run = RunTool("check --format json no_such_file.urdf clean.urdf");
  EXPECT_EQ(run.exit_code, 2);
  const json report = json::parse(run.out);
  ASSERT_EQ(report.at("files").size(), 2u);
  EXPECT_EQ(report["files"][0].at("path"), "no_such_file.urdf");
  EXPECT_EQ(report["files"][0].at("errors").size(), 1u);
  EXPECT_EQ(report["files"][1].at("path"), "clean.urdf");
  EXPECT_EQ(report["files"][1].at("models"), json::array({"clean"}));
  EXPECT_TRUE(report["files"][1].at("errors").empty());
  EXPECT_EQ(report.at("summary").at("read_errors"), 1);

  // A read error outranks findings: exit 2 even with an error finding in the other file.
  run = RunTool("check no_such_file.urdf not_physical.urdf");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(Contains(run.out, "no_such_file.urdf")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[read-error]")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[inertia-not-physical]")) << run.out;
}

// --max-input-size on check and report: clean.urdf is 1 449 bytes and clean.sdf is larger than
// 100 (`wc -c`), so a limit of 100 bytes refuses both with exit 2 and a message naming the option;
// 1K (1 024 bytes, a power of 1024) still refuses clean.urdf and 2K reads it.
TEST(CliTest, MaxInputSizeSetsTheLargestFileRead) {
  for (const std::string command : {"check", "report"}) {
    for (const std::string file : {"clean.urdf", "clean.sdf"}) {
      const RunResult refused = RunTool(command + " --max-input-size 100 " + file);
      EXPECT_EQ(refused.exit_code, 2) << command << " " << file;
      EXPECT_TRUE(Contains(refused.out + refused.err, "limit of 100 bytes"))
          << refused.out << refused.err;
      EXPECT_TRUE(Contains(refused.out + refused.err, "--max-input-size"))
          << refused.out << refused.err;
      EXPECT_EQ(RunTool(command + " --max-input-size 1M " + file).exit_code, 0)
          << command << " " << file;
    }
  }
  EXPECT_EQ(RunTool("check --max-input-size 1K clean.urdf").exit_code, 2);
  EXPECT_EQ(RunTool("check --max-input-size 2K clean.urdf").exit_code, 0);
  EXPECT_EQ(RunTool("check --max-input-size 0 clean.urdf").exit_code, 2);     // usage error
  EXPECT_EQ(RunTool("check --max-input-size lots clean.urdf").exit_code, 2);  // usage error
}

TEST(CliTest, AMalformedFileIsAReadErrorWithALine) {
  const RunResult run = RunTool("check malformed.urdf");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(Contains(run.out, "malformed.urdf:")) << run.out;
  EXPECT_TRUE(Contains(run.out, ": error: ")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[read-error]")) << run.out;
}

TEST(CliTest, SarifOutputHasTheRequiredFieldsAndRelativeUris) {
  const RunResult run = RunTool("check --format sarif not_physical.urdf");
  EXPECT_EQ(run.exit_code, 1);
  const json log = json::parse(run.out);
  EXPECT_EQ(log.at("version"), "2.1.0");
  const json& run0 = log.at("runs").at(0);
  EXPECT_EQ(run0.at("tool").at("driver").at("name"), "massprops");
  EXPECT_EQ(run0.at("tool").at("driver").at("version"), MASSPROPS_VERSION);
  bool found = false;
  for (const json& result : run0.at("results")) {
    const json& physical = result.at("locations").at(0).at("physicalLocation");
    EXPECT_EQ(physical.at("artifactLocation").at("uri"), "not_physical.urdf");
    EXPECT_GE(physical.at("region").at("startLine").get<int>(), 1);
    const json& rule = run0["tool"]["driver"]["rules"].at(result.at("ruleIndex").get<int>());
    EXPECT_EQ(rule.at("id"), result.at("ruleId"));
    if (result.at("ruleId") == "inertia-not-physical") {
      found = true;
      EXPECT_EQ(result.at("level"), "error");
    }
  }
  EXPECT_TRUE(found) << run.out;
}

TEST(CliTest, GithubOutputIsWorkflowCommands) {
  const RunResult run = RunTool("check --format github not_physical.urdf");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out.rfind("::error file=not_physical.urdf,line=", 0), 0u) << run.out;
  EXPECT_TRUE(Contains(run.out, ",title=inertia-not-physical::")) << run.out;
}

TEST(CliTest, ColourOnlyWhenAskedOrOnATerminal) {
  // The tool's stdout is a pipe here, so auto means no colour.
  EXPECT_FALSE(Contains(RunTool("check not_physical.urdf").out, "\x1b["));
  EXPECT_TRUE(Contains(RunTool("check --color always not_physical.urdf").out, "\x1b["));
  EXPECT_TRUE(
      Contains(RunTool("check --color always not_physical.urdf", "", "NO_COLOR=1").out, "\x1b["));
  EXPECT_FALSE(Contains(RunTool("check --color never not_physical.urdf").out, "\x1b["));
}

TEST(CliTest, AConfigFileFoundUpwardAppliesAndTheCommandLineWins) {
  // configured/.massprops.toml says fail-on = "warning"; the model there has one warning.
  EXPECT_EQ(RunTool("check configured/missing_inertial.urdf").exit_code, 1);
  EXPECT_EQ(RunTool("check --fail-on error configured/missing_inertial.urdf").exit_code, 0);
  // The same model outside that folder: the default fail level.
  EXPECT_EQ(RunTool("check missing_inertial.urdf").exit_code, 0);
}

TEST(CliTest, AnExplicitConfigReplacesTheOneFoundUpward) {
  const RunResult run =
      RunTool("check --config disable_missing_inertial.toml configured/missing_inertial.urdf");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_FALSE(Contains(run.out, "[inertial-missing]")) << run.out;
  EXPECT_EQ(RunTool("check --config no_such_config.toml clean.urdf").exit_code, 2);
}

TEST(CliTest, ABadConfigFileExitsTwoNamingItsLine) {
  // bad_config/.massprops.toml names an unknown rule on line 3.
  const RunResult run = RunTool("check bad_config/missing_inertial.urdf");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(Contains(run.err, ".massprops.toml:3:")) << run.err;
  EXPECT_TRUE(Contains(run.err, "no-such-rule")) << run.err;
  EXPECT_EQ(run.out, "");
}

TEST(CliTest, ListRulesNamesEveryRule) {
  RunResult run = RunTool("check --list-rules");
  EXPECT_EQ(run.exit_code, 0);
  for (const massprops::RuleInfo& rule : massprops::AllRules()) {
    EXPECT_TRUE(Contains(run.out, std::string(rule.id))) << rule.id;
  }
  run = RunTool("check --list-rules --format json");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(json::parse(run.out).size(), massprops::AllRules().size());
}

TEST(CliTest, WithoutAFileTheBundledExampleIsCheckedAndNamed) {
  RunResult run = RunTool("check");
  // The example has an impossible inertia (an error), so the run fails.
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_TRUE(Contains(run.err, "two_link_arm.urdf")) << run.err;
  EXPECT_TRUE(Contains(run.out, "two_link_arm.urdf:")) << run.out;

  run = RunTool("check --format json");
  EXPECT_EQ(run.exit_code, 1);
  const json report = json::parse(run.out);
  ASSERT_EQ(report.at("files").size(), 1u);
  const std::string path = report["files"][0].at("path");
  EXPECT_EQ(path.substr(path.size() - std::string("/examples/two_link_arm.urdf").size()),
            "/examples/two_link_arm.urdf");
  EXPECT_EQ(report["files"][0].at("models"), json::array({"two_link_arm"}));
  // The three defects documented in the example (hand-derived there): ixx = 0.0046 >
  // iyy + izz = 0.00448667 on the forearm; kg*mm^2 on the upper arm (radius of gyration
  // sqrt(tr(I) / 2m) = sqrt(23750 / 3) = 89.0 m for a 0.30 m link); no <inertial> on the camera.
  EXPECT_TRUE(HasFinding(report, "inertia-not-physical", "forearm")) << run.out;
  EXPECT_TRUE(HasFinding(report, "units-suspect", "upper_arm")) << run.out;
  EXPECT_TRUE(HasFinding(report, "inertial-missing", "camera_link")) << run.out;
  // The valid base and the massless tool frame draw nothing.
  for (const auto& [rule, link] : RulesAndLinks(report)) {
    EXPECT_NE(link, "base_link") << rule;
    EXPECT_NE(link, "tool0") << rule;
  }
}

// A URDF written for Drake (a joint to `world`, a <limit> without velocity): urdfdom refuses it,
// massprops says so (urdf-not-loadable, an error by default) and still checks its inertias from a
// lenient reading; a team that targets Drake only can lower the rule and keep the physics.
TEST(CliTest, AFileUrdfdomRefusesIsAFindingAndItsInertiasAreStillChecked) {
  RunResult run = RunTool("check drake_world.urdf");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  // The headline: urdfdom's own first clause, whole (its message is longer than a headline).
  EXPECT_TRUE(Contains(run.out,
                       "drake_world.urdf:11: error: ROS's URDF parser refuses this file: Could not "
                       "parse limit element for joint [shoulder] [urdf-not-loadable]\n"))
      << run.out;
  EXPECT_TRUE(Contains(run.out, "[urdf-not-loadable]")) << run.out;
  EXPECT_TRUE(Contains(run.out, "[inertia-not-physical]")) << run.out;
  EXPECT_EQ(run.err, "") << "urdfdom's messages are not printed";
  run = RunTool("check --severity urdf-not-loadable=warning --fail-on error drake_world.urdf");
  EXPECT_EQ(run.exit_code, 1) << "the inertia is still an error: " << run.out;
  EXPECT_TRUE(Contains(run.out, "warning: ROS's URDF parser refuses this file")) << run.out;
  run = RunTool(
      "check --severity urdf-not-loadable=off --severity inertia-not-physical=off "
      "drake_world.urdf");
  EXPECT_EQ(run.exit_code, 0) << run.out;
}

// `target = "mujoco"` in .massprops.toml applies to `fix` and `report` as it does to `check`
// (docs/targets.md), and --target on the command line wins. The fixture is a thin disk written
// with rounded digits: moments 0.0833333, 0.0833333, 0.1666667, so A + B = 0.1666666 < C.
// Hand-derived from MuJoCo 2.2.2's exact triangle test (mjCBody::Compile, user_objects.cc):
// MuJoCo refuses it; physics accepts it (the deficit 1e-7 is below the generic 1e-6 of the trace).
TEST(CliTest, FixAndReportTakeTheTargetFromTheConfigurationFile) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("massprops_cli_target_" + std::to_string(getpid()));
  fs::create_directories(dir);
  {
    std::ofstream(dir / "disk.urdf")
        << "<robot name=\"r\"><link name=\"base\"><inertial><mass value=\"1\"/><inertia "
           "ixx=\"0.0833333\" iyy=\"0.0833333\" izz=\"0.1666667\" ixy=\"0\" ixz=\"0\" "
           "iyz=\"0\"/></inertial></link></robot>\n";
    std::ofstream(dir / ".massprops.toml") << "target = \"mujoco\"\n";
  }
  const std::string file = Quote((dir / "disk.urdf").string());  // run from testdata/cli

  RunResult run = RunTool("fix --dry-run " + file);
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(Contains(run.out, "disk.urdf:1: ")) << "the MuJoCo repair is planned: " << run.out;
  EXPECT_FALSE(Contains(run.out, "no change needed")) << run.out;
  run = RunTool("fix --dry-run --target generic " + file);
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(Contains(run.out, "disk.urdf: no change needed")) << run.out;

  run = RunTool("report " + file);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(Contains(run.out, "Bodies as MuJoCo 2.2.2 compiles r")) << run.out;
  EXPECT_TRUE(Contains(run.out, "MuJoCo refuses: inertia must satisfy A + B >= C")) << run.out;
  run = RunTool("report --target generic " + file);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(Contains(run.out, "MuJoCo")) << run.out;

  // A configuration file that is not valid is exit 2 for fix and report too, as for check.
  std::ofstream(dir / ".massprops.toml") << "target = \"bullet\"\n";
  EXPECT_EQ(RunTool("fix --dry-run " + file).exit_code, 2);
  EXPECT_EQ(RunTool("report " + file).exit_code, 2);
  fs::remove_all(dir);
}

// merge-fixed --target: gazebo merges as libsdformat lumps (tests/merge_fixed_test.cc has the
// numbers); mujoco and drake are refused as usage errors, before the file is read.
TEST(CliTest, MergeFixedTakesGazeboAndRefusesMujocoAndDrake) {
  RunResult run = RunTool("merge-fixed --target gazebo clean.urdf -o -");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(Contains(run.out, "<robot")) << run.out;
  for (const std::string target : {"mujoco", "drake"}) {
    run = RunTool("merge-fixed --target " + target + " no_such_file.urdf -o -");
    EXPECT_EQ(run.exit_code, 2) << target;
    EXPECT_TRUE(Contains(run.err, "merge-fixed --target " + target + " is not supported"))
        << run.err;
    EXPECT_EQ(run.out, "");
  }
}

// `report --format json --target gazebo`: each model gets "target_bodies", the bodies Gazebo
// simulates (docs/report.md), without the world. The chain world -> base -> a -> b is welded by
// fixed joints; base -> a carries <preserveFixedJoint>. Masses 1, 2, 3 kg at the link origins,
// each with inertia diag(0.1, 0.1, 0.1) kg·m², a 1 m along x from base, b 1 m along x from a.
// Hand-derived (libsdformat's lumping rules, gazebosim/sdformat parser_urdf.cc): the bodies are
// base (1 kg) and a + b: m = 5 kg, c = (3·1)/5 = 0.6 m along x, about c Ixx = 0.2 and
// Iyy = Izz = 0.2 + 2·0.6² + 3·0.4² = 1.4 kg·m².
// Writes that chain as `path`.
void WriteGazeboChain(const std::filesystem::path& path) {
  auto link = [](const std::string& name, const std::string& mass) {
    return "<link name=\"" + name + "\"><inertial><mass value=\"" + mass +
           "\"/><inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" "
           "iyz=\"0\"/></inertial></link>";
  };
  auto joint = [](const std::string& name, const std::string& parent, const std::string& child) {
    return "<joint name=\"" + name + "\" type=\"fixed\"><parent link=\"" + parent +
           "\"/><child link=\"" + child + "\"/><origin xyz=\"1 0 0\"/></joint>";
  };
  std::ofstream(path) << "<robot name=\"chain\"><link name=\"world\"/>" << link("base", "1")
                      << link("a", "2") << link("b", "3") << joint("to_world", "world", "base")
                      << joint("keep", "base", "a") << joint("weld", "a", "b")
                      << "<gazebo reference=\"keep\"><preserveFixedJoint>true</preserveFixedJoint>"
                         "</gazebo></robot>\n";
}

TEST(CliTest, JsonReportListsTheTargetBodiesWithoutTheWorld) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("massprops_cli_bodies_" + std::to_string(getpid()));
  fs::create_directories(dir);
  WriteGazeboChain(dir / "chain.urdf");
  const RunResult run =
      RunTool("report --format json --target gazebo " + Quote((dir / "chain.urdf").string()));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const json report = json::parse(run.out);
  const json& model = report.at("models").at(0);
  EXPECT_EQ(model.at("target"), "gazebo");
  const json& bodies = model.at("target_bodies");
  ASSERT_EQ(bodies.size(), 2u) << bodies.dump();
  EXPECT_EQ(bodies[0].at("name"), "base");
  EXPECT_EQ(bodies[0].at("links"), json({"base"}));
  EXPECT_DOUBLE_EQ(bodies[0].at("mass").get<double>(), 1);
  EXPECT_EQ(bodies[1].at("links"), json({"a", "b"}));
  EXPECT_EQ(bodies[1].at("frame"), "a");
  EXPECT_DOUBLE_EQ(bodies[1].at("mass").get<double>(), 5);
  EXPECT_NEAR(bodies[1].at("com")[0].get<double>(), 0.6, 1e-15);
  EXPECT_NEAR(bodies[1].at("inertia_about_com")[0][0].get<double>(), 0.2, 1e-15);
  EXPECT_NEAR(bodies[1].at("inertia_about_com")[1][1].get<double>(), 1.4, 1e-14);
  EXPECT_NEAR(bodies[1].at("inertia_about_com")[2][2].get<double>(), 1.4, 1e-14);
  // Without a target the JSON has no target part.
  const RunResult plain = RunTool("report --format json " + Quote((dir / "chain.urdf").string()));
  EXPECT_FALSE(json::parse(plain.out).at("models").at(0).contains("target_bodies"));
  fs::remove_all(dir);
}

// The CSV report's columns, per row.
std::vector<std::vector<std::string>> CsvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += c;
      }
    }
    cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// `report --format csv --target gazebo`: the same bodies as the JSON test above, as rows of kind
// target_body (hand-derived there: a + b is 5 kg at x = 0.6 with Ixx = 0.2, Iyy = Izz = 1.4; its
// principal moments, ascending, are then 0.2, 1.4, 1.4), the target in the column "target".
TEST(CliTest, CsvReportListsTheTargetBodiesAsRowsWithTheTargetColumns) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("massprops_cli_csv_" + std::to_string(getpid()));
  fs::create_directories(dir);
  WriteGazeboChain(dir / "chain.urdf");
  const RunResult run =
      RunTool("report --format csv --target gazebo " + Quote((dir / "chain.urdf").string()));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::vector<std::string>> rows = CsvRows(run.out);
  ASSERT_FALSE(rows.empty());
  const std::vector<std::string>& header = rows[0];
  ASSERT_EQ(header.size(), 35u);  // 32 columns of the report, then target, target_moving, _message
  EXPECT_EQ(header[32], "target");
  EXPECT_EQ(header[33], "target_moving");
  EXPECT_EQ(header[34], "target_message");
  std::vector<std::vector<std::string>> bodies;
  for (const auto& row : rows) {
    EXPECT_EQ(row.size(), header.size());
    if (row.size() == header.size() && row[2] == "target_body") bodies.push_back(row);
    if (row.size() == header.size() && row[2] != "target_body" && &row != &rows[0]) {
      EXPECT_EQ(row[32], "");  // The report's own rows have no target.
    }
  }
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_EQ(bodies[0][3], "base");
  EXPECT_EQ(bodies[1][3], "a");
  EXPECT_EQ(bodies[1][4], "a");     // frame
  EXPECT_EQ(bodies[1][31], "a;b");  // links
  EXPECT_EQ(bodies[1][32], "gazebo");
  EXPECT_EQ(std::stod(bodies[1][5]), 5);              // mass
  EXPECT_NEAR(std::stod(bodies[1][6]), 0.6, 1e-15);   // com_x
  EXPECT_NEAR(std::stod(bodies[1][9]), 0.2, 1e-15);   // ixx
  EXPECT_NEAR(std::stod(bodies[1][10]), 1.4, 1e-14);  // iyy
  EXPECT_NEAR(std::stod(bodies[1][15]), 0.2, 1e-15);  // principal_moment_1
  EXPECT_NEAR(std::stod(bodies[1][17]), 1.4, 1e-14);  // principal_moment_3
  // Without a target the header is the report's own.
  const RunResult plain = RunTool("report --format csv " + Quote((dir / "chain.urdf").string()));
  EXPECT_EQ(CsvRows(plain.out)[0].size(), 32u);
  fs::remove_all(dir);
}

// `report --format csv --target mujoco` on the example arm: MuJoCo's bodies (static or moving,
// principal moments as its eigen-solver gives them) and its refusal as a row of kind
// target_refusal naming the body and quoting MuJoCo (README.md: the forearm's principal moments
// 0.000213333, 0.00427333, 0.0046 fail A + B >= C).
TEST(CliTest, CsvReportGivesMujocosRefusalAsARow) {
  const RunResult run = RunTool("report --format csv --target mujoco " +
                                Quote(std::string(MASSPROPS_EXAMPLES_DIR) + "/two_link_arm.urdf"));
  const std::vector<std::vector<std::string>> rows = CsvRows(run.out);
  ASSERT_FALSE(rows.empty());
  int bodies = 0, refusals = 0;
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 35u);
    if (row[2] == "target_body") {
      ++bodies;
      EXPECT_EQ(row[32], "mujoco");
      EXPECT_TRUE(row[33] == "true" || row[33] == "false") << row[33];
      EXPECT_EQ(row[6], "");  // MuJoCo's bodies have no center of mass in the report
    }
    if (row[2] == "target_refusal") {
      ++refusals;
      EXPECT_EQ(row[3], "forearm");
      EXPECT_NE(row[34].find("inertia must satisfy A + B >= C"), std::string::npos) << row[34];
    }
  }
  EXPECT_GT(bodies, 0);
  EXPECT_EQ(refusals, 1);
}

// `massprops check` builds only the options its command line names (src/tool/option_filter.h).
TEST(CheckOptionFilterTest, OnlyTheOptionsTheCommandLineNamesAreBuilt) {
  using massprops::cli::OptionFilter;
  const auto filter = [](std::vector<const char*> argv) {
    return OptionFilter::ForCheck(static_cast<int>(argv.size()), argv.data());
  };
  OptionFilter named = filter({"massprops", "check", "-q", "--format", "json", "a.urdf", "-"});
  EXPECT_FALSE(named.all());
  EXPECT_TRUE(named.Wants({"-q", "--quiet"}));
  EXPECT_TRUE(named.Wants({"--format"}));
  EXPECT_FALSE(named.Wants({"--fail-on"}));
  EXPECT_FALSE(named.Wants({"-j", "--jobs"}));
  named = filter({"massprops", "check", "--fail-on=warning", "--jobs", "2"});
  EXPECT_TRUE(named.Wants({"--fail-on"}));
  EXPECT_TRUE(named.Wants({"-j", "--jobs"}));
  EXPECT_FALSE(named.Wants({"--format"}));
  EXPECT_FALSE(filter({"massprops", "check"}).all());  // the bundled example: FILE only
}

TEST(CheckOptionFilterTest, EveryOptionIsBuiltWhenAWordIsNotCertainlyUnderstood) {
  using massprops::cli::OptionFilter;
  const auto all = [](std::vector<const char*> argv) {
    return OptionFilter::ForCheck(static_cast<int>(argv.size()), argv.data()).all();
  };
  EXPECT_TRUE(all({"massprops"}));
  EXPECT_TRUE(all({"massprops", "report", "a.urdf"}));  // not check
  EXPECT_TRUE(all({"massprops", "--version"}));
  EXPECT_TRUE(all({"massprops", "check", "--help"}));
  EXPECT_TRUE(all({"massprops", "check", "-h"}));
  EXPECT_TRUE(all({"massprops", "check", "-q", "--formt", "json"}));  // a typo: CLI11's message
  EXPECT_TRUE(all({"massprops", "check", "-qj2", "a.urdf"}));         // a run of short options
  EXPECT_TRUE(all({"massprops", "check", "-j4", "a.urdf"}));
  EXPECT_TRUE(all({"massprops", "check", "--tolerance", "-1"}));
  EXPECT_TRUE(all({"massprops", "check", "-q", "--", "-odd-name.urdf"}));
  EXPECT_TRUE(OptionFilter().all());
}

// The filter's list of names is complete (so that every option takes the short way) and names
// only real options: `check --help` lists exactly these, besides -h and --help.
TEST(CheckOptionFilterTest, CheckOptionNamesAreThoseOfTheHelp) {
  const RunResult run = RunTool("check --help");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::set<std::string> in_help;
  const std::regex option_line(R"(^\s+(-[^ ]*(?:, ?-[^ ]*)*))");
  std::istringstream lines(run.out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (!std::regex_search(line, match, option_line)) continue;
    std::istringstream names(std::regex_replace(match[1].str(), std::regex(","), " "));
    for (std::string name; names >> name;) in_help.insert(name.substr(0, name.find('=')));
  }
  std::set<std::string> known = {"-h", "--help"};
  for (std::string_view name : massprops::cli::CheckOptionNames()) known.emplace(name);
  EXPECT_EQ(in_help, known) << run.out;
}

// The same bytes, exit code and messages whether only the options named are built or all of them
// (`--` before the files makes the tool build them all; after it every word is a FILE anyway).
TEST(CheckOptionFilterTest, EachOptionGivesTheSameResultWhetherOnlyItOrEveryOptionIsBuilt) {
  const std::string files = "not_physical.urdf missing_inertial.urdf clean.sdf";
  for (const char* options :
       {"", "-q", "--quiet", "--format json", "--format=sarif", "--format github", "--color always",
        "--fail-on warning", "--fail-on=note", "--disable inertial-missing",
        "--severity inertial-missing=error", "--tolerance 0.01", "--tolerance=0",
        "--config disable_missing_inertial.toml", "--model-path tree", "--target mujoco",
        "--target drake", "-j 2", "--jobs=1", "--list-rules", "--geometry", "--no-geometry",
        "--geometry-factor 3", "--package-path tree",
        "-q --format json --fail-on note --disable inertial-missing -j 1 --no-geometry",
        // Usage errors: the same message either way.
        "--geometry --no-geometry", "--format xml", "--tolerance 2", "--config no-such.toml",
        "--target bullet", "--geometry-factor 1"}) {
    const RunResult named = RunTool(std::string("check ") + options + " " + files);
    const RunResult every = RunTool(std::string("check ") + options + " -- " + files);
    EXPECT_EQ(named.exit_code, every.exit_code) << options;
    EXPECT_EQ(named.out, every.out) << options;
    EXPECT_EQ(named.err, every.err) << options;
    EXPECT_NE(named.exit_code, -1) << options;
  }
}

}  // namespace
