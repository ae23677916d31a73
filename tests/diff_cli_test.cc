// `massprops diff A B` (docs/cli.md) in its three formats, on two URDFs written here that differ
// in one number: the arm's mass, 1 kg in A and 1.1 kg in B. The expected differences are worked
// out by hand from docs/cli.md's definitions (below, at each test).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tool_runner.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;
using test_support::RunTool;
using test_support::ToolRun;

// base: 2 kg, diag(0.1, 0.2, 0.3) at its origin; arm: `arm_mass`, diag(0.01, 0.01, 0.02) at
// z = 0.1 in its frame, which is 0.5 m above the base's (a revolute joint).
std::string Robot(const std::string& arm_mass) {
  return R"(<robot name="r">
  <link name="base">
    <inertial><mass value="2"/>
      <inertia ixx="0.1" iyy="0.2" izz="0.3" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="arm">
    <inertial><origin xyz="0 0 0.1"/><mass value=")" +
         arm_mass + R"("/>
      <inertia ixx="0.01" iyy="0.01" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit effort="1" velocity="1" lower="-1" upper="1"/>
  </joint>
</robot>
)";
}

class DiffCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("massprops_diff_" + std::to_string(getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "a.urdf") << Robot("1");
    std::ofstream(dir_ / "b.urdf") << Robot("1.1");
  }
  void TearDown() override { fs::remove_all(dir_); }
  ToolRun Diff(const std::string& options) {
    return RunTool("diff " + options + " '" + (dir_ / "a.urdf").string() + "' '" +
                   (dir_ / "b.urdf").string() + "'");
  }
  fs::path dir_;
};

// The arm: mass |1 - 1.1| / 1.1 = 1/11 = 0.0909091, its center and inertia the same. The base is
// the same. The whole robot differs too (its mass 3 vs 3.1).
TEST_F(DiffCliTest, TextNamesTheArmsMassAndCountsTheDifferingLinks) {
  const ToolRun run = Diff("");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("differs: link 'arm': mass 1 vs 1.1 kg (relative 0.0909091)\n"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("link 'base'"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("1 of 2 links and welded groups differ beyond 1e-06; the whole robot "
                            "differs\n"),
            std::string::npos)
      << run.output;
}

// The whole robot in the frame of 'arm' (the first link both have that is not a root), at the
// zero configuration. A: center z = (2·0 + 1·0.6)/3 = 0.2 above the base, -0.3 in the arm's frame;
// B: z = 1.1·0.6/3.1 = 0.66/3.1, a shift of 0.4/31. Inertia about the center (parallel axes):
// A ixx = 0.1 + 2·0.2² + 0.01 + 1·0.4² = 0.35, iyy = 0.45; B ixx = 0.35 + 0.48/31, iyy = 0.45 +
// 0.48/31 = 14.43/31 (the largest moment), izz 0.32 in both. Relative: mass 0.1/3.1 = 1/31;
// inertia (0.48/31)/(14.43/31) = 0.48/14.43; center 0.4/31 over the largest of |0.3|,
// |0.66/3.1 - 0.5| and the radius of gyration sqrt((14.43/31)/3.1) = 0.3875.
TEST_F(DiffCliTest, JsonGivesEachEntrysRelativeDifferences) {
  const ToolRun run = Diff("--format json");
  ASSERT_EQ(run.exit_code, 1) << run.output;
  const nlohmann::json out = nlohmann::json::parse(run.output);
  EXPECT_EQ(out["differs"], true);
  const nlohmann::json& entries = out["entries"];
  ASSERT_EQ(entries.size(), 3u) << out.dump(1);  // base, arm, the whole robot
  EXPECT_EQ(entries[0]["name"], "base");
  EXPECT_EQ(entries[0]["differs"], false);
  EXPECT_EQ(entries[0]["mass_difference"], 0.0);
  EXPECT_EQ(entries[1]["name"], "arm");
  EXPECT_NEAR(entries[1]["mass_difference"].get<double>(), 1.0 / 11, 1e-12);
  EXPECT_EQ(entries[1]["com_difference"], 0.0);
  EXPECT_EQ(entries[1]["inertia_difference"], 0.0);
  const nlohmann::json& total = entries[2];
  EXPECT_EQ(total["kind"], "total");
  EXPECT_EQ(total["name"], "arm");
  EXPECT_NEAR(total["a"]["com"][2].get<double>(), -0.3, 1e-12);
  EXPECT_NEAR(total["b"]["com"][2].get<double>(), 0.66 / 3.1 - 0.5, 1e-12);
  EXPECT_NEAR(total["a"]["inertia"][0][0].get<double>(), 0.35, 1e-12);
  EXPECT_NEAR(total["b"]["inertia"][1][1].get<double>(), 14.43 / 31, 1e-12);
  EXPECT_NEAR(total["mass_difference"].get<double>(), 1.0 / 31, 1e-12);
  EXPECT_NEAR(total["inertia_difference"].get<double>(), 0.48 / 14.43, 1e-12);
  EXPECT_NEAR(total["com_difference"].get<double>(), (0.4 / 31) / std::sqrt(14.43 / 31 / 3.1),
              1e-12);
}

// GitHub: one ::error per difference (the arm and the whole robot), at file B.
TEST_F(DiffCliTest, GithubAnnotatesEachDifferenceAtFileB) {
  const ToolRun run = Diff("--format github");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  const std::string b = (dir_ / "b.urdf").string();
  EXPECT_EQ(run.output.find("::error file=" + b + ",line="), 0u) << run.output;
  EXPECT_NE(run.output.find(",title=massprops diff%3A link 'arm'::mass 1 vs 1.1 kg (relative "
                            "0.0909091)\n"),
            std::string::npos)
      << run.output;
  std::size_t annotations = 0;
  for (std::size_t at = run.output.find("::error"); at != std::string::npos;
       at = run.output.find("::error", at + 1)) {
    ++annotations;
  }
  EXPECT_EQ(annotations, 2u) << run.output;
}

// The largest difference is the arm's mass, 1/11 = 0.0909 < 0.1: nothing differs beyond 0.1.
TEST_F(DiffCliTest, ToleranceAboveTheLargestDifferenceExitsZero) {
  EXPECT_EQ(Diff("--tolerance 0.1").exit_code, 0);
  EXPECT_EQ(Diff("--tolerance 0.09").exit_code, 1);
}

TEST_F(DiffCliTest, AMissingFileExitsTwo) {
  const ToolRun run =
      RunTool("diff '" + (dir_ / "a.urdf").string() + "' '" + (dir_ / "none.urdf").string() + "'");
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace
}  // namespace massprops
