// End-to-end tests of `massprops report` and `massprops merge-fixed` (the built tool at
// MASSPROPS_TOOL_PATH) on testdata/report/. Expected numbers are hand-derived in
// tests/mass_report_test.cc; exit codes are the contract of docs/report.md.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tool_runner.h"

namespace {

using massprops::test_support::RunTool;
using massprops::test_support::ToolRun;

std::string Fixture(const std::string& name) {
  return "'" + std::string(MASSPROPS_TESTDATA_DIR) + "/report/" + name + "'";
}

TEST(ReportCliTest, JsonReportOfTheTwoLinkArmAtNinetyDegreesHasTheHandComputedCom) {
  const ToolRun run =
      RunTool("report --format json --joint joint1=1.5707963267948966 " + Fixture("arm.urdf"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(run.output);
  const nlohmann::json& total = json["models"][0]["total"];
  // Hand-derived (mass_report_test.cc): C = (0, 2.5/4.5, 0.5/4.5), m = 4.5.
  EXPECT_NEAR(total["mass"].get<double>(), 4.5, 1e-15);
  EXPECT_NEAR(total["com"][0].get<double>(), 0, 1e-15);
  EXPECT_NEAR(total["com"][1].get<double>(), 2.5 / 4.5, 1e-15);
  EXPECT_NEAR(total["com"][2].get<double>(), 0.5 / 4.5, 1e-15);
  EXPECT_EQ(total["frame"], "base");
  EXPECT_TRUE(json["errors"].empty());
}

TEST(ReportCliTest, FrameOptionNamesTheFrameOfEveryEntry) {
  const ToolRun run = RunTool("report --format json --frame link2 " + Fixture("arm.urdf"));
  ASSERT_EQ(run.exit_code, 0);
  const nlohmann::json json = nlohmann::json::parse(run.output);
  for (const auto& link : json["models"][0]["links"]) EXPECT_EQ(link["frame"], "link2");
  for (const auto& group : json["models"][0]["welded_groups"]) EXPECT_EQ(group["frame"], "link2");
  EXPECT_EQ(json["models"][0]["total"]["frame"], "link2");
  // link2's frame is at base (1,0,0) at q = 0, not turned: the base link's com (0,0,0) is at
  // (−1, 0, 0) in it.
  EXPECT_NEAR(json["models"][0]["links"][0]["com"][0].get<double>(), -1, 1e-15);
}

TEST(ReportCliTest, UnknownJointIsAUsageErrorWithExitTwo) {
  const ToolRun run = RunTool("report --joint elbow=1 " + Fixture("arm.urdf"), true);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("no joint named 'elbow'"), std::string::npos) << run.output;
  EXPECT_EQ(RunTool("report --joint joint1=abc " + Fixture("arm.urdf")).exit_code, 2);
  EXPECT_EQ(RunTool("report --joint tip_fixed=1 " + Fixture("arm.urdf")).exit_code, 2);
  EXPECT_EQ(RunTool("report --format xml " + Fixture("arm.urdf")).exit_code, 2);
}

TEST(ReportCliTest, AnUnreadableFileGivesExitTwoAndTheOtherFilesAreStillReported) {
  const ToolRun run =
      RunTool("report --format json " + Fixture("missing.urdf") + " " + Fixture("welded.urdf"));
  EXPECT_EQ(run.exit_code, 2);
  const nlohmann::json json = nlohmann::json::parse(run.output);
  ASSERT_EQ(json["models"].size(), 1u);
  EXPECT_EQ(json["models"][0]["name"], "welded");
  ASSERT_EQ(json["errors"].size(), 1u);
  EXPECT_NE(json["errors"][0]["file"].get<std::string>().find("missing.urdf"), std::string::npos);
}

TEST(ReportCliTest, CsvHasAHeaderAndOneRowPerBody) {
  const ToolRun run = RunTool("report --format csv " + Fixture("welded.urdf"));
  ASSERT_EQ(run.exit_code, 0);
  std::istringstream in(run.output);
  std::string line;
  int rows = -1;  // the header
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 6 + 2 + 1);  // 6 links, 2 welded groups, 1 total
  EXPECT_EQ(run.output.rfind("file,model,kind,name,frame,mass,", 0), 0u);
}

TEST(ReportCliTest, TextReportSaysHowManyDigitsTheFarTinyBodyLost) {
  const ToolRun run = RunTool("report " + Fixture("far_tiny.urdf"));
  ASSERT_EQ(run.exit_code, 0);
  // log10(0.01·1000² / 3e-11) = 14.52 (mass_report_test.cc).
  EXPECT_NE(run.output.find("about 14.5 significant digits lost"), std::string::npos) << run.output;
}

TEST(ReportCliTest, OnlyAndSubtreeRestrictTheReport) {
  ToolRun run = RunTool("report --format json " + Fixture("welded.urdf") + " --only arm_box");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  nlohmann::json json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["models"][0]["links"].size(), 1u);
  EXPECT_EQ(json["models"][0]["welded_groups"].size(), 1u);
  EXPECT_TRUE(json["models"][0]["total"].is_null());
  run = RunTool("report --format json --subtree arm " + Fixture("welded.urdf"));
  ASSERT_EQ(run.exit_code, 0);
  json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["models"][0]["links"].size(), 2u);
  // Group arm: m = 4, com (0.875, 0, 0) in the arm frame (mass_report_test.cc).
  EXPECT_EQ(json["models"][0]["total"]["frame"], "arm");
  EXPECT_NEAR(json["models"][0]["total"]["com"][0].get<double>(), 0.875, 1e-15);
  EXPECT_EQ(RunTool("report --subtree nowhere " + Fixture("welded.urdf")).exit_code, 2);
}

TEST(ReportCliTest, MergeFixedWritesAModelWithOneLinkPerWeldedGroup) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("massprops_merge_" + std::to_string(getpid()) + ".urdf");
  const ToolRun run =
      RunTool("merge-fixed " + Fixture("welded.urdf") + " -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0);
  // The merged file's report: two links, each its own group; the total is unchanged
  // (m = 16, C = (1, 1/4, −3/32), mass_report_test.cc).
  const ToolRun report = RunTool("report --format json '" + out.string() + "'");
  std::filesystem::remove(out);
  ASSERT_EQ(report.exit_code, 0);
  const nlohmann::json json = nlohmann::json::parse(report.output);
  EXPECT_EQ(json["models"][0]["links"].size(), 2u);
  const nlohmann::json& total = json["models"][0]["total"];
  EXPECT_NEAR(total["mass"].get<double>(), 16, 1e-14);
  EXPECT_NEAR(total["com"][0].get<double>(), 1, 1e-14);
  EXPECT_NEAR(total["com"][1].get<double>(), 0.25, 1e-14);
  EXPECT_NEAR(total["com"][2].get<double>(), -3.0 / 32, 1e-14);
}

std::string SdfFixture(const std::string& name) {
  return "'" + std::string(MASSPROPS_TESTDATA_DIR) + "/merge_sdf/" + name + "'";
}

// SDF: the merged file's whole-model composite equals the original's (merging moves no mass), and
// the welded pair is one link (testdata/merge_sdf/two_boxes.sdf, hand-computed in
// merge_fixed_test.cc).
TEST(ReportCliTest, MergeFixedMergesSdfAndKeepsTheWholeModelComposite) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("massprops_merge_" + std::to_string(getpid()) + ".sdf");
  const ToolRun run =
      RunTool("merge-fixed " + SdfFixture("two_boxes.sdf") + " -o '" + out.string() + "'", true);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("merged 1 link(s) into 1 welded group root(s)"), std::string::npos);
  const ToolRun merged = RunTool("report --format json '" + out.string() + "'");
  const ToolRun original = RunTool("report --format json " + SdfFixture("two_boxes.sdf"));
  std::filesystem::remove(out);
  ASSERT_EQ(merged.exit_code, 0);
  const nlohmann::json a = nlohmann::json::parse(original.output)["models"][0];
  const nlohmann::json b = nlohmann::json::parse(merged.output)["models"][0];
  EXPECT_EQ(a["links"].size(), 4u);
  EXPECT_EQ(b["links"].size(), 3u);
  // By hand: 2 + 2 + 1 + 1 kg.
  EXPECT_EQ(a["total"]["mass"].get<double>(), 6);
  EXPECT_EQ(b["total"]["mass"].get<double>(), 6);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(b["total"]["com"][i].get<double>(), a["total"]["com"][i].get<double>(), 1e-14);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(b["total"]["inertia_about_com"][i][k].get<double>(),
                  a["total"]["inertia_about_com"][i][k].get<double>(), 1e-13);
    }
  }
}

TEST(ReportCliTest, MergeFixedRefusesWhatItCannotEditInSdfWithExitTwoAndTheLine) {
  const ToolRun run = RunTool("merge-fixed " + SdfFixture("cross_scope.sdf") + " -o -", true);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("cross_scope.sdf:8: <link> 'inner::x': merge-fixed does not support"),
            std::string::npos)
      << run.output;
}

TEST(ReportCliTest, MergeFixedForGazeboWritesAnSdfUnchangedWithANote) {
  const ToolRun run =
      RunTool("merge-fixed --target gazebo " + SdfFixture("two_boxes.sdf") + " -o -", true);
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.output.find("<joint name=\"weld\" type=\"fixed\">"), std::string::npos);
  EXPECT_NE(run.output.find("note: Gazebo does not lump the fixed joints of an SDF model"),
            std::string::npos)
      << run.output;
}

// testdata/urdf/inertia_unreadable.urdf: urdfdom loads the pad with mass 0.0075 kg at
// (0.02, 0, 0) and an inertia it could not read (tests/urdf_unreadable_inertial_test.cc). Every
// format says the inertia is unknown rather than printing zeros; the composites say they are
// incomplete and which link makes them so.
TEST(ReportCliTest, ALinkWhoseInertiaCannotBeReadHasItsMassAndAnUnknownInertiaInEveryFormat) {
  const std::string file =
      "'" + std::string(MASSPROPS_TESTDATA_DIR) + "/urdf/inertia_unreadable.urdf'";
  const ToolRun json_run = RunTool("report --format json " + file);
  ASSERT_EQ(json_run.exit_code, 0) << json_run.output;
  const nlohmann::json model = nlohmann::json::parse(json_run.output)["models"][0];
  const nlohmann::json& pad = model["links"][1];
  EXPECT_EQ(pad["name"], "pad");
  EXPECT_EQ(pad["mass"].get<double>(), 0.0075);
  EXPECT_EQ(pad["com"][0].get<double>(), 0.02);
  EXPECT_TRUE(pad["inertia_about_com"].is_null());
  EXPECT_TRUE(pad["principal_moments"].is_null());
  EXPECT_TRUE(pad["equivalent_box"].is_null());
  EXPECT_EQ(pad["unknown"], nlohmann::json({"inertia"}));
  EXPECT_FALSE(model["links"][0].contains("unknown"));  // the finger is known
  const nlohmann::json& group = model["welded_groups"][0];
  EXPECT_NEAR(group["mass"].get<double>(), 0.1075, 1e-16);  // 0.1 + 0.0075
  EXPECT_TRUE(group["inertia_about_com"].is_null());
  EXPECT_EQ(group["incomplete_links"], nlohmann::json({"pad"}));
  EXPECT_EQ(model["total"]["incomplete_links"], nlohmann::json({"pad"}));
  EXPECT_EQ(model["total"]["unknown"], nlohmann::json({"inertia"}));

  const ToolRun text = RunTool("report " + file);
  ASSERT_EQ(text.exit_code, 0);
  EXPECT_NE(text.output.find("note: link 'pad': its <inertial> could not be read wholly"),
            std::string::npos)
      << text.output;
  EXPECT_NE(text.output.find("note: group 'finger': incomplete: inertia unknown, since the "
                             "numbers of pad are partly unknown"),
            std::string::npos)
      << text.output;
  EXPECT_NE(text.output.find("0.0075"), std::string::npos);

  // CSV: the pad's row has its mass and center of mass, and empty inertia fields.
  const ToolRun csv = RunTool("report --format csv " + file);
  ASSERT_EQ(csv.exit_code, 0);
  std::istringstream lines(csv.output);
  std::string line, pad_row;
  while (std::getline(lines, line)) {
    if (line.find(",link,pad,") != std::string::npos) pad_row = line;
  }
  EXPECT_NE(pad_row.find(",link,pad,pad,0.0074999999999999997,0.02,0,0,,,,,,,,,,"),
            std::string::npos)
      << pad_row;
}

}  // namespace
