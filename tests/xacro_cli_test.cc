// `massprops check`, `fix` and `trace` on xacro packages (docs/xacro.md), end to end on the
// packages of ../shared/xacro/ (read in place; fixes run on a temporary copy). CI has no ROS
// xacro: the xacro-on-PATH route is run with tests/recorded_xacro.sh, which does NOT expand: it
// prints the package's recorded expansion (made with ROS's xacro, ../shared/xacro/README.md).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "shared_data.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kTool = MASSPROPS_TOOL_PATH;
const fs::path kXacroDir = MASSPROPS_XACRO_DIR;
const std::string kRecorded = std::string(MASSPROPS_TESTS_DIR) + "/recorded_xacro.sh";

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

RunResult RunTool(const std::string& args, const std::string& dir, const std::string& env = "") {
  const std::string err_path =
      ::testing::TempDir() + "massprops_xacro_cli_stderr_" + std::to_string(getpid()) + ".txt";
  const std::string command = "cd " + Quote(dir) + " && " + env + " " + Quote(kTool) + " " + args +
                              " 2> " + Quote(err_path);
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    result.out.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.err = ReadAll(err_path);
  std::remove(err_path.c_str());
  return result;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class XacroCliTest : public ::testing::Test {
 protected:
  void SetUp() override { MASSPROPS_SKIP_WITHOUT_SHARED("xacro/pmb2/expanded.urdf"); }
};

// pmb2's antennas (urdf/objects/antenna.urdf.xacro lines 26-28, one macro for both antennas)
// have ixx = 2.371e-8, iyy = 2.833e-8, izz = 3.849e-8 with products 6.119e-8, 1.179e-8, 7.74e-9:
// the products exceed the moments, so no mass distribution has them (inertia-not-physical); the
// expanded lines are 445 and 474 (expanded.urdf).
TEST_F(XacroCliTest, CheckThroughTheExpanderPointsAtTheSourceLineFirst) {
  const RunResult r = RunTool(
      "check pmb2/src/robots/pmb2.urdf.xacro --source-root pmb2 "
      "--no-geometry --xacro-command " +
          Quote(kRecorded),
      kXacroDir.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(Contains(r.out,
                       "pmb2/src/urdf/objects/antenna.urdf.xacro:26: error: link "
                       "'base_antenna_left_link'"))
      << r.out;
  EXPECT_TRUE(Contains(r.out,
                       "(inertia ixx: literal; generated <expansion of "
                       "pmb2/src/robots/pmb2.urdf.xacro>:445)"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "antenna.urdf.xacro:26: error: link 'base_antenna_right_link'"));
}

TEST_F(XacroCliTest, WithoutAnExpanderCheckSaysHowToGiveTheExpansion) {
  const RunResult r =
      RunTool("check pmb2/src/robots/pmb2.urdf.xacro", kXacroDir.string(), "PATH=/nonexistent");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "no xacro program found on PATH")) << r.err;
  EXPECT_TRUE(Contains(r.err, "--expanded robot.urdf --source-root PKG_DIR")) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST_F(XacroCliTest, JsonSarifAndGithubCarryBothPlaces) {
  const std::string base = "check --expanded pmb2/expanded.urdf --source-root pmb2 --no-geometry ";
  const RunResult j = RunTool(base + "--format json", kXacroDir.string());
  ASSERT_EQ(j.exit_code, 1) << j.err;
  const json finding = json::parse(j.out).at("files")[0].at("findings")[0];
  EXPECT_EQ(finding.at("file"), "pmb2/expanded.urdf");  // the generated place stays
  EXPECT_EQ(finding.at("line"), 445);
  const json& source = finding.at("source");
  EXPECT_EQ(source.at("file"), "pmb2/src/urdf/objects/antenna.urdf.xacro");
  EXPECT_EQ(source.at("line"), 26);
  EXPECT_EQ(source.at("how"), "literal");
  EXPECT_EQ(source.at("text"), "0.00000002371");
  EXPECT_EQ(source.at("generated").at("line"), 445);

  const RunResult s = RunTool(base + "--format sarif", kXacroDir.string());
  const json result = json::parse(s.out).at("runs")[0].at("results")[0];
  const json& physical = result.at("locations")[0].at("physicalLocation");
  EXPECT_EQ(physical.at("artifactLocation").at("uri"), "pmb2/src/urdf/objects/antenna.urdf.xacro");
  EXPECT_EQ(physical.at("region").at("startLine"), 26);
  // SARIF 2.1.0 (OASIS 2020) 3.27.22: relatedLocations is an array of location objects, each
  // with a unique non-negative id (3.28.2) when given.
  const json& related = result.at("relatedLocations")[0];
  EXPECT_EQ(related.at("id"), 1);
  EXPECT_EQ(related.at("physicalLocation").at("artifactLocation").at("uri"), "pmb2/expanded.urdf");
  EXPECT_EQ(related.at("physicalLocation").at("region").at("startLine"), 445);

  const RunResult g = RunTool(base + "--format github", kXacroDir.string());
  EXPECT_EQ(g.out.rfind("::error file=pmb2/src/urdf/objects/antenna.urdf.xacro,line=26,", 0), 0u)
      << g.out;
  EXPECT_TRUE(Contains(g.out, "generated pmb2/expanded.urdf:445")) << g.out;
}

// A products-sign-suspect finding points at the product it is about: franka's fingers write
// yz: -0.00000106 on line 25 of end_effectors/franka_hand/inertials.yaml (xx is on line 20).
TEST_F(XacroCliTest, AProductsSignFindingPointsAtTheProductsLine) {
  const RunResult r = RunTool(
      "check --expanded franka_fr3/expanded.urdf --source-root franka_fr3 -q", kXacroDir.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;  // warnings only
  EXPECT_TRUE(Contains(r.out,
                       "franka_fr3/src/end_effectors/franka_hand/inertials.yaml:25: "
                       "warning: link 'fr3_leftfinger'"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "(inertia iyz: yaml; generated franka_fr3/expanded.urdf:300)"))
      << r.out;
}

class XacroFixTest : public XacroCliTest {
 protected:
  void SetUp() override {
    XacroCliTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    copy_ = fs::temp_directory_path() / ("massprops_xacro_fix_" + std::to_string(getpid()));
    fs::remove_all(copy_);
    fs::copy(kXacroDir / "pmb2", copy_, fs::copy_options::recursive);
    for (const auto& entry : fs::recursive_directory_iterator(copy_)) {
      fs::permissions(entry.path(), fs::perms::owner_write, fs::perm_options::add);
    }
    fs::permissions(copy_, fs::perms::owner_write, fs::perm_options::add);
  }
  void TearDown() override {
    if (!copy_.empty() && !std::getenv("MASSPROPS_KEEP")) fs::remove_all(copy_);
  }
  fs::path copy_;
};

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST_F(XacroFixTest, FixEditsOnlyTheRepairedLiteralsInTheSource) {
  const RunResult r = RunTool(
      "fix src/robots/pmb2.urdf.xacro --source-root . --no-geometry "
      "--in-place --xacro-command " +
          Quote(kRecorded),
      copy_.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  // Only antenna.urdf.xacro changed, and in it only lines 26-28 (the six inertia values).
  for (const auto& entry : fs::recursive_directory_iterator(kXacroDir / "pmb2")) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), kXacroDir / "pmb2");
    if (relative == "src/urdf/objects/antenna.urdf.xacro") continue;
    EXPECT_EQ(ReadAll(entry.path()), ReadAll(copy_ / relative)) << relative;
  }
  const std::vector<std::string> before =
      Lines(ReadAll(kXacroDir / "pmb2/src/urdf/objects/antenna.urdf.xacro"));
  const std::vector<std::string> after =
      Lines(ReadAll(copy_ / "src/urdf/objects/antenna.urdf.xacro"));
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (i + 1 >= 26 && i + 1 <= 28) {
      EXPECT_NE(before[i], after[i]) << "line " << i + 1;
    } else {
      EXPECT_EQ(before[i], after[i]) << "line " << i + 1;
    }
  }
  // The values written are those `fix` writes into the expanded URDF itself (the tested URDF
  // route): a second, independent path to the same repair.
  const RunResult urdf =
      RunTool("fix expanded.urdf -o - --no-geometry", (kXacroDir / "pmb2").string());
  const std::vector<std::string> fixed = Lines(urdf.out);
  ASSERT_GT(fixed.size(), 446u);
  // expanded.urdf line 445: <inertia ixx=".." ixy=".." ixz=".." iyy=".." iyz=".." izz=".."/>
  for (const char* attribute : {"ixx=", "ixy=", "ixz=", "iyy=", "iyz=", "izz="}) {
    const std::string& line = fixed[444];
    const std::size_t at = line.find(attribute);
    ASSERT_NE(at, std::string::npos) << line;
    const std::string value = line.substr(at, line.find('"', at + 5) - at + 1);
    const std::string edited = after[25] + after[26] + after[27];
    EXPECT_TRUE(Contains(edited, value)) << value << " not in " << edited;
  }
  EXPECT_TRUE(Contains(r.out, "6 verified")) << r.out;
  // (A second run cannot be asked to find nothing: the recorded expansion does not change with
  // the sources. Its numbers then no longer trace, and fix says so instead of editing.)
}

// franka_fr3's fingers: products-sign-suspect on both (their collision boxes imply iyz > 0, the
// YAML writes yz: -0.00000106). Both fingers read the same YAML lines (rightfinger: *finger, an
// alias), and both are repaired to the same negated value: the one YAML value is edited (line 25
// of end_effectors/franka_hand/inertials.yaml) and nothing else in the package.
TEST_F(XacroCliTest, FixEditsAYamlValueThatOnlyTheRepairedLinksRead) {
  const fs::path copy =
      fs::temp_directory_path() / ("massprops_xacro_fix_yaml_" + std::to_string(getpid()));
  fs::remove_all(copy);
  fs::copy(kXacroDir / "franka_fr3", copy, fs::copy_options::recursive);
  for (const auto& entry : fs::recursive_directory_iterator(copy)) {
    fs::permissions(entry.path(), fs::perms::owner_write, fs::perm_options::add);
  }
  const RunResult r = RunTool(
      "fix src/robots/fr3/fr3.urdf.xacro --source-root . --apply "
      "products-sign-suspect --in-place --xacro-command " +
          Quote(kRecorded),
      copy.string());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const fs::path yaml = "src/end_effectors/franka_hand/inertials.yaml";
  for (const auto& entry : fs::recursive_directory_iterator(kXacroDir / "franka_fr3")) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), kXacroDir / "franka_fr3");
    if (relative == yaml) continue;
    EXPECT_EQ(ReadAll(entry.path()), ReadAll(copy / relative)) << relative;
  }
  const std::vector<std::string> before = Lines(ReadAll(kXacroDir / "franka_fr3" / yaml));
  const std::vector<std::string> after = Lines(ReadAll(copy / yaml));
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (i + 1 == 25) {
      EXPECT_EQ(before[i], "    yz: -0.00000106");
      EXPECT_EQ(after[i], "    yz: 1.06e-06");  // negated, written as FormatShortest writes it
    } else {
      EXPECT_EQ(before[i], after[i]) << "line " << i + 1;
    }
  }
  fs::remove_all(copy);
}

// A package written here: legs share the literal ixx="0.01" and take izz as a macro argument; the
// body's inertia is its own literal; the arm's ixx and iyy are its own literals but its izz is
// computed (m·5). Its source robot.urdf.xacro, and robot.urdf, the expansion ROS's xacro gives
// (written by hand), in `dir`; returns the source.
std::string WriteSmallPackage(const fs::path& dir) {
  fs::create_directories(dir);
  const std::string source = R"(<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="leg" params="side izz">
    <link name="${side}_leg">
      <inertial>
        <mass value="1"/>
        <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="${izz}"/>
      </inertial>
    </link>
  </xacro:macro>
  <xacro:leg side="left" izz="0.005"/>
  <xacro:leg side="right" izz="0.5"/>
  <link name="body">
    <inertial>
      <mass value="2"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="5"/>
    </inertial>
  </link>
  <xacro:macro name="arm" params="m">
    <link name="arm">
      <inertial>
        <mass value="${m}"/>
        <inertia ixx="0.02" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="${m*5}"/>
      </inertial>
    </link>
  </xacro:macro>
  <xacro:arm m="1"/>
</robot>
)";
  std::ofstream(dir / "robot.urdf.xacro") << source;
  // The expansion ROS's xacro gives (written by hand: ${izz} prints the argument as a float).
  std::ofstream(dir / "robot.urdf") << R"(<?xml version="1.0"?>
<robot name="r">
  <link name="left_leg">
    <inertial>
      <mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.005"/>
    </inertial>
  </link>
  <link name="right_leg">
    <inertial>
      <mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.5"/>
    </inertial>
  </link>
  <link name="body">
    <inertial>
      <mass value="2"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="5"/>
    </inertial>
  </link>
  <link name="arm">
    <inertial>
      <mass value="1"/>
      <inertia ixx="0.02" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="5"/>
    </inertial>
  </link>
</robot>
)";
  return source;
}

// The package of WriteSmallPackage: the legs' shared literal and the arm's computed izz leave
// their repairs to a person; the body's own literal is edited.
TEST(XacroFixRefusalTest, SharedParameterAndComputedValuesAreLeftForAPerson) {
  const fs::path dir =
      fs::temp_directory_path() / ("massprops_xacro_refusal_" + std::to_string(getpid()));
  const std::string source = WriteSmallPackage(dir);
  // right_leg: 0.01 + 0.01 < 0.5 and body: 1 + 1 < 5 break the triangle inequality.
  const RunResult r =
      RunTool("fix --expanded robot.urdf --source-root . --no-geometry --in-place", dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // repairs left to do by hand
  EXPECT_TRUE(Contains(r.out, "robot.urdf.xacro:7: link 'right_leg': change inertia ixx to"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "the value is shared with 'left_leg', which need no such repair"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "robot.urdf.xacro:12: link 'right_leg': change inertia izz to"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "is a macro argument or property (0.5)")) << r.out;
  // arm: izz = m·5 = 5 at the call on line 27 (m = 1), and 0.02 + 0.03 < 5.
  EXPECT_TRUE(Contains(r.out, "robot.urdf.xacro:27: link 'arm': change inertia izz to")) << r.out;
  EXPECT_TRUE(Contains(r.out, "the value is computed (from m=1), not written: change its inputs"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "robot.urdf.xacro:23: link 'arm': change inertia ixx to")) << r.out;
  EXPECT_TRUE(Contains(r.out, "a part of a repair is not written")) << r.out;
  // The body's literals are its own: edited in place (line 16), nothing else in the file.
  const std::vector<std::string> before = Lines(source);
  const std::vector<std::string> after = Lines(ReadAll(dir / "robot.urdf.xacro"));
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (i + 1 == 16) {
      EXPECT_NE(before[i], after[i]);
    } else {
      EXPECT_EQ(before[i], after[i]) << "line " << i + 1;
    }
  }
  EXPECT_TRUE(Contains(r.out, "re-expansion could not be verified")) << r.out;
  fs::remove_all(dir);
}

// `trace` in its three formats on the package of WriteSmallPackage (no ../shared needed). Counted
// by hand from the source: 4 links, each with a mass and 6 inertia numbers and no origin, 28
// numbers; the arm's izz = m·5 is computed at the call on line 27 (m = 1), every other number has
// one place: a literal (lines 6, 7, 15, 16, 23) or an argument (izz on lines 11 and 12, the arm's
// mass m on line 27).
TEST(XacroTraceCliTest, EveryFormatOfTraceOnAPackageWrittenHere) {
  const fs::path dir =
      fs::temp_directory_path() / ("massprops_xacro_trace_" + std::to_string(getpid()));
  WriteSmallPackage(dir);
  const std::string trace = "trace --expanded robot.urdf --source-root . --format ";
  const RunResult summary = RunTool(trace + "summary", dir.string());
  ASSERT_EQ(summary.exit_code, 0) << summary.err;
  EXPECT_EQ(summary.out, "28\t27\t0\t1\t0\n");  // numbers, one place, several, computed, none

  const RunResult text = RunTool(trace + "text", dir.string());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::vector<std::string> lines = Lines(text.out);
  ASSERT_EQ(lines.size(), 28u) << text.out;
  // robot.urdf: the arm's <inertia> is on line 24, the right leg's on line 12.
  EXPECT_TRUE(
      Contains(text.out, "arm inertia izz 5 (generated 24): robot.urdf.xacro:27 computed (m=1)"))
      << text.out;
  EXPECT_TRUE(
      Contains(text.out, "right_leg inertia izz 0.5 (generated 12): robot.urdf.xacro:12 parameter"))
      << text.out;

  const RunResult json_run = RunTool(trace + "json", dir.string());
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const json data = json::parse(json_run.out);
  ASSERT_EQ(data["numbers"].size(), 28u);
  std::map<std::string, int> how;
  for (const json& number : data["numbers"]) {
    ASSERT_EQ(number["places"].size(), 1u) << number.dump();
    ++how[number["places"][0]["how"].get<std::string>()];
  }
  // Literals: 2 legs × 6 (mass, ixx..iyz) + the body's 7 + the arm's 5 = 24; arguments: the
  // legs' izz and the arm's mass = 3; computed: the arm's izz = 1.
  EXPECT_EQ(how, (std::map<std::string, int>{{"computed", 1}, {"literal", 24}, {"parameter", 3}}));
  const json& left_mass = data["numbers"][0];
  EXPECT_EQ(left_mass["link"], "left_leg");
  EXPECT_EQ(left_mass["generated_line"], 5);
  EXPECT_EQ(left_mass["places"][0]["line"], 6);
  fs::remove_all(dir);
}

TEST_F(XacroCliTest, TraceSummaryCountsEveryInertialNumber) {
  // pmb2: 21 links with <inertial> (README.md), each with mass, origin xyz and rpy, six inertia
  // entries except where an attribute is absent: the expanded text has 188 such numbers
  // (grep -c of the attributes in expanded.urdf's inertials, see docs/xacro.md).
  const RunResult r =
      RunTool("trace --expanded pmb2/expanded.urdf --source-root pmb2 --format summary",
              kXacroDir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  int total = 0, one = 0, several = 0, computed = 0, none = 0;
  in >> total >> one >> several >> computed >> none;
  EXPECT_EQ(total, 188);
  EXPECT_EQ(one + several + computed + none, total);
}

}  // namespace
