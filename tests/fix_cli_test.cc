// End-to-end tests of `massprops fix` (the built tool, MASSPROPS_TOOL_PATH).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utime.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "massprops/output/xml_patch.h"
#include "tool_runner.h"

namespace {

namespace fs = std::filesystem;

const std::string kFixDir = std::string(MASSPROPS_TESTDATA_DIR) + "/fix";

std::string ReadFile(const fs::path& path) { return massprops::test_support::ReadWholeFile(path); }

void WriteFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

using ToolRun = massprops::test_support::SplitToolRun;

// Runs the tool with `args` (shell words), capturing stdout and stderr.
ToolRun RunTool(const std::string& args, const fs::path& scratch) {
  return massprops::test_support::RunToolSplit(args, scratch);
}

class FixCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-fix-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_ / "ro", fs::perms::owner_all, ec);
    fs::remove_all(dir_, ec);
  }
  fs::path dir_;
};

// Line numbers (1-based) inside <inertial> ... </inertial>, found by a plain text scan.
std::vector<bool> InertialLines(const std::string& text) {
  std::vector<bool> inside;
  bool open = false;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const bool opens = line.find("<inertial") != std::string::npos;
    const bool closes = line.find("</inertial>") != std::string::npos;
    inside.push_back(open || opens || closes);
    if (opens) open = true;
    if (closes) open = false;
  }
  return inside;
}

TEST_F(FixCliTest, CadExportIsPatchedExactlyAsTheGoldenFile) {
  // Golden file reviewed by hand, every heuristic asked for (--apply all): upper_arm mass
  // 2000 → 2 (grams); forearm products negated; wrist 0.251 − 1·0.5² = 0.001 (written with the
  // fewest digits, 6, that pass the checks: not 0.0010000000000000009); cover (no <inertial>)
  // is left alone: its box lies inside base_link's, whose 4 kg carries it (a lumped mass, no
  // inertial-missing finding).
  const ToolRun run = RunTool("fix --apply all '" + kFixDir + "/cad_export.urdf'", dir_);
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, ReadFile(kFixDir + "/golden/cad_export.urdf"));
}

TEST_F(FixCliTest, WithoutApplyOnlyTheLinkWithAnErrorChanges) {
  // The contract: `fix FILE` never changes a link that has no error. cad_export has one error
  // (forearm: principal moments 0.0055, 0.0055, 0.019 break the triangle inequality) and three
  // heuristic findings (units, inertia about the origin, missing inertial), left alone.
  // The projection by hand: the violation 0.019 − 2·0.0055 = 0.008 is removed along (−1,−1,1)/√3,
  // moments (0.0081667, 0.0081667, 0.0163333) on the same axes, i.e. I = a·1 + b·11ᵀ with
  // a = 0.0081667, b = 0.0027222: diagonal a + b = 0.0108889, products 0.00272222.
  const std::string before = ReadFile(kFixDir + "/cad_export.urdf");
  const ToolRun run = RunTool("fix '" + kFixDir + "/cad_export.urdf'", dir_);
  EXPECT_EQ(run.code, 0) << run.err;
  const massprops::LineChanges changes = massprops::DiffLines(before, run.out);
  ASSERT_EQ(changes.removed.size(), 1u);
  EXPECT_EQ(changes.removed[0], 33);  // forearm's <inertia>
  EXPECT_NE(run.out.find("iyy=\"0.0108889\" izz=\"0.0108889\" ixx=\"0.0108889\"   "
                         "ixy=\"0.00272222\" ixz=\"0.00272222\" iyz=\"0.00272222\""),
            std::string::npos)
      << run.out;
  // What was not applied is said, with the option that applies it.
  EXPECT_NE(run.err.find("units-suspect"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--apply"), std::string::npos) << run.err;
  // --dry-run lists what each heuristic would do.
  const ToolRun dry = RunTool("fix --dry-run '" + kFixDir + "/cad_export.urdf'", dir_);
  EXPECT_NE(dry.out.find("not applied (a guess): link 'wrist' [inertia-about-origin-suspect"),
            std::string::npos)
      << dry.out;
  EXPECT_NE(dry.out.find("  = help: --apply inertia-about-origin-suspect applies it\n"),
            std::string::npos)
      << dry.out;
  EXPECT_EQ(RunTool("fix --apply no-such-rule '" + kFixDir + "/cad_export.urdf'", dir_).code, 2);
}

TEST_F(FixCliTest, ARepairThatFailsItsOwnCheckIsRefusedWithTheReason) {
  // 2.2 kg with moments 1e-20 and a broken triangle inequality (1e-20 + 1e-20 < 3e-20): a radius
  // of gyration of about 1e-10 m, which is no body: a units or placeholder mistake, not repaired.
  const fs::path file = dir_ / "tiny.urdf";
  WriteFile(file,
            "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"2.2\"/><inertia "
            "ixx=\"1e-20\" ixy=\"0\" ixz=\"0\" iyy=\"1e-20\" iyz=\"0\" izz=\"3e-20\"/>"
            "</inertial></link></robot>\n");
  const ToolRun run = RunTool("fix '" + file.string() + "'", dir_);
  EXPECT_EQ(run.code, 1);
  EXPECT_EQ(run.out, ReadFile(file));
  EXPECT_NE(run.err.find("tiny.urdf:1: error: link 'a': not repaired: its inertia is far too small "
                         "for its mass to be a rounding error [inertia-not-physical]\n"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("  = evidence: a units or placeholder mistake, not a rounding error: a "
                         "projection would hide it\n"),
            std::string::npos)
      << run.err;
}

TEST_F(FixCliTest, CadExportDiffTouchesOnlyInertialLines) {
  const std::string before = ReadFile(kFixDir + "/cad_export.urdf");
  const std::string after = ReadFile(kFixDir + "/golden/cad_export.urdf");
  const massprops::LineChanges changes = massprops::DiffLines(before, after);
  const std::vector<bool> old_inertial = InertialLines(before);
  const std::vector<bool> new_inertial = InertialLines(after);
  EXPECT_EQ(changes.removed.size(), 3u);  // a <mass> and two <inertia> lines
  for (int line : changes.removed) EXPECT_TRUE(old_inertial.at(line - 1)) << "line " << line;
  for (int line : changes.added) EXPECT_TRUE(new_inertial.at(line - 1)) << "line " << line;
}

TEST_F(FixCliTest, FixingTheFixedFileChangesNothing) {
  const std::string golden = kFixDir + "/golden/cad_export.urdf";
  const ToolRun run = RunTool("fix --diff '" + golden + "'", dir_);
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.out, "");
  const ToolRun again = RunTool("fix '" + golden + "'", dir_);
  EXPECT_EQ(again.out, ReadFile(golden));
}

TEST_F(FixCliTest, TheFixedFilePassesCheck) {
  const ToolRun run = RunTool("check '" + kFixDir + "/golden/cad_export.urdf'", dir_);
  EXPECT_EQ(run.code, 0) << run.out;
  EXPECT_NE(run.out.find("0 errors, 0 warnings"), std::string::npos) << run.out;
}

TEST_F(FixCliTest, DiffHasUnifiedHeadersAndHunks) {
  const ToolRun run =
      RunTool("fix --apply units-suspect --diff '" + kFixDir + "/cad_export.urdf'", dir_);
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.out.rfind("--- a/" + kFixDir + "/cad_export.urdf\n+++ b/", 0), 0u) << run.out;
  EXPECT_NE(run.out.find("-      <mass value=\"2000\"/>\n+      <mass value=\"2\"/>\n"),
            std::string::npos);
}

TEST_F(FixCliTest, DryRunExplainsEachRepairAndWritesNothing) {
  const fs::path copy = dir_ / "robot.urdf";
  fs::copy_file(kFixDir + "/cad_export.urdf", copy);
  const ToolRun run = RunTool("fix --dry-run '" + copy.string() + "'", dir_);
  EXPECT_EQ(run.code, 0);
  EXPECT_NE(run.out.find("link 'upper_arm' [units-suspect → rescale-units]"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("mass value (line 21): 2000 → 2"), std::string::npos);
  EXPECT_NE(run.out.find("why: "), std::string::npos);
  EXPECT_EQ(ReadFile(copy), ReadFile(kFixDir + "/cad_export.urdf"));
}

TEST_F(FixCliTest, InPlaceReplacesTheFileAndKeepsABackup) {
  const fs::path copy = dir_ / "robot.urdf";
  fs::copy_file(kFixDir + "/cad_export.urdf", copy);
  const ToolRun run =
      RunTool("fix --apply all --in-place --backup .orig '" + copy.string() + "'", dir_);
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(ReadFile(copy), ReadFile(kFixDir + "/golden/cad_export.urdf"));
  EXPECT_EQ(ReadFile(dir_ / "robot.urdf.orig"), ReadFile(kFixDir + "/cad_export.urdf"));
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++files;
  EXPECT_EQ(files, 4);  // robot.urdf, robot.urdf.orig, stdout.txt, stderr.txt
}

TEST_F(FixCliTest, AFileThatNeedsNoChangeIsNeverRewritten) {
  const fs::path copy = dir_ / "clean.urdf";
  fs::copy_file(kFixDir + "/golden/cad_export.urdf", copy);
  struct utimbuf old_times {};
  old_times.actime = old_times.modtime = 1000000000;  // 2001-09-09
  ASSERT_EQ(utime(copy.c_str(), &old_times), 0);
  const ToolRun run = RunTool("fix --in-place --backup .orig '" + copy.string() + "'", dir_);
  EXPECT_EQ(run.code, 0);
  struct stat st {};
  ASSERT_EQ(stat(copy.c_str(), &st), 0);
  EXPECT_EQ(st.st_mtime, 1000000000);
  EXPECT_FALSE(fs::exists(dir_ / "clean.urdf.orig"));
}

TEST_F(FixCliTest, OutputIntoAMissingFolderFailsAndLeavesTheInputAlone) {
  const fs::path copy = dir_ / "robot.urdf";
  fs::copy_file(kFixDir + "/cad_export.urdf", copy);
  const ToolRun run = RunTool(
      "fix -o '" + (dir_ / "no/such/dir/out.urdf").string() + "' '" + copy.string() + "'", dir_);
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(ReadFile(copy), ReadFile(kFixDir + "/cad_export.urdf"));
  EXPECT_FALSE(fs::exists(dir_ / "no"));
}

TEST_F(FixCliTest, InPlaceInAReadOnlyFolderFailsAndLeavesTheOriginalUntouched) {
  if (geteuid() == 0) GTEST_SKIP() << "root can write into a read-only folder";
  const fs::path ro = dir_ / "ro";
  fs::create_directory(ro);
  fs::copy_file(kFixDir + "/cad_export.urdf", ro / "robot.urdf");
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  const ToolRun run = RunTool("fix --in-place '" + (ro / "robot.urdf").string() + "'", dir_);
  EXPECT_EQ(run.code, 2);
  EXPECT_EQ(ReadFile(ro / "robot.urdf"), ReadFile(kFixDir + "/cad_export.urdf"));
}

TEST_F(FixCliTest, OutputFileGetsTheCorrectedText) {
  const fs::path out = dir_ / "fixed.urdf";
  const ToolRun run =
      RunTool("fix --apply all -o '" + out.string() + "' '" + kFixDir + "/cad_export.urdf'", dir_);
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(ReadFile(out), ReadFile(kFixDir + "/golden/cad_export.urdf"));
}

TEST_F(FixCliTest, SdfElementTextsAreRepaired) {
  const ToolRun run = RunTool("fix '" + kFixDir + "/invalid_inertia.sdf'", dir_);
  EXPECT_EQ(run.code, 0) << run.err;
  // Balance-free projection, hand-derived in repair_test: 0.1 + 0.2/3 (plus the 1e-9 floor),
  // written with 6 significant digits, the fewest that pass: 0.166667 + 0.266667 >= 0.433333.
  EXPECT_NE(run.out.find("<ixx>0.166667</ixx>"), std::string::npos) << run.out;
  WriteFile(dir_ / "fixed.sdf", run.out);
  EXPECT_EQ(RunTool("check '" + (dir_ / "fixed.sdf").string() + "'", dir_).code, 0);
}

TEST_F(FixCliTest, BalanceRepairWritesTheMeanMoment) {
  const ToolRun run = RunTool("fix --repair balance '" + kFixDir + "/invalid_inertia.sdf'", dir_);
  EXPECT_EQ(run.code, 0);
  // (0.1 + 0.2 + 0.5) / 3 = 0.2666..., written with 6 significant digits (equal moments are
  // valid at any rounding).
  EXPECT_NE(run.out.find("<izz>0.266667</izz>"), std::string::npos) << run.out;
}

TEST_F(FixCliTest, FromGeometryAtAnImpossibleMassIsRefusedWithTheWaysForward) {
  // upper_arm: 2000 kg (grams written as kg) in a cylinder r 0.05, l 0.4. Its geometry's
  // inertia at that mass, Ixx = 2000 (3 r² + l²) / 12 = 27.9 kg·m², is what --from-geometry would
  // write; but 2000 kg in the cylinder's box grown twice (0.1 x 0.1 x 0.4 m, 8 times 0.004 m³)
  // is 62 500 kg/m³, denser than osmium (22 590): density-implausible, so the repair is refused
  // (docs/fix.md: a repair must pass the checks it is judged by) and the numbers stay.
  const ToolRun run =
      RunTool("fix '" + kFixDir + "/cad_export.urdf' --from-geometry upper_arm", dir_);
  EXPECT_EQ(run.code, 0) << run.err;
  const std::size_t link = run.out.find("<link name=\"upper_arm\">");
  ASSERT_NE(link, std::string::npos);
  const std::size_t ixx = run.out.find("ixx=\"", link);
  ASSERT_NE(ixx, std::string::npos);
  EXPECT_EQ(run.out.substr(ixx, 15), "ixx=\"0.0279167\"");  // as written
  EXPECT_NE(run.err.find("link 'upper_arm': not repaired"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("density-implausible"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("density 62500"), std::string::npos) << run.err;
  // The ways forward: the unit repair (2 kg) and the weighed mass.
  EXPECT_NE(run.err.find("massprops fix --apply units-suspect"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("massprops fix --mass upper_arm=KG"), std::string::npos) << run.err;
  // A refused repair is said once, with its reason, not as "left as it is".
  EXPECT_EQ(run.err.find("is left as it is"), std::string::npos) << run.err;
}

TEST_F(FixCliTest, ErrorsWithoutARepairGiveExitCodeOne) {
  // A negative mass on a link without geometry: nothing to compute a mass from.
  const fs::path file = dir_ / "neg.urdf";
  WriteFile(file,
            "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"-2\"/><inertia "
            "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>"
            "</robot>\n");
  const ToolRun run = RunTool("fix '" + file.string() + "'", dir_);
  EXPECT_EQ(run.code, 1);
  // In `check`'s words: `file:line: error: HEADLINE [rule]`, the headline mass-not-positive's.
  EXPECT_NE(run.err.find("neg.urdf:1: error: link 'a': mass -2 kg is negative; no body has it "
                         "[mass-not-positive] (no repair)\n"),
            std::string::npos)
      << run.err;
  const ToolRun check = RunTool("check '" + file.string() + "'", dir_);
  EXPECT_NE(check.out.find("neg.urdf:1: error: link 'a': mass -2 kg is negative; no body has it "
                           "[mass-not-positive]\n"),
            std::string::npos)
      << check.out;
}

TEST_F(FixCliTest, UnreadableInputAndBadOptionsGiveExitCodeTwo) {
  const fs::path file = dir_ / "broken.urdf";
  WriteFile(file, "<robot name=\"r\"><link name=\"a\">");
  EXPECT_EQ(RunTool("fix '" + file.string() + "'", dir_).code, 2);
  EXPECT_EQ(RunTool("fix '" + (dir_ / "missing.urdf").string() + "'", dir_).code, 2);
  EXPECT_EQ(RunTool("fix --backup .b '" + kFixDir + "/cad_export.urdf'", dir_).code, 2);
  EXPECT_EQ(RunTool("fix --repair nearest '" + kFixDir + "/cad_export.urdf'", dir_).code, 2);
}

}  // namespace
