#include "massprops/output/xml_patch.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "massprops/analysis/repair.h"

namespace massprops {
namespace {

// A repair of link `link` (start tag at `link_line`) that sets one number.
Repair OneChange(const std::string& link, int link_line, const std::string& element,
                 const std::string& attribute, int line, double value) {
  Repair r;
  r.link = link;
  r.link_line = link_line;
  r.changes.push_back({element, attribute, line, 0, {0}, {value}});
  return r;
}

TEST(PatchModelTextTest, OnlyTheChangedAttributeValueIsRewritten) {
  // Comments, single quotes, odd spacing and attribute order are kept byte for byte.
  const std::string before =
      "<robot name='r'>  <!-- keep <mass value=\"9\"/> -->\n"
      "  <link   name = 'arm' >\n"
      "    <inertial>\n"
      "      <mass   value = '1.000' />\n"
      "      <inertia izz='0.5'  ixx=\"0.1\" iyy='0.2' ixy='0' ixz='0' iyz='0'/>\n"
      "    </inertial>\n"
      "  </link>\n"
      "</robot>\n";
  Repair r = OneChange("arm", 2, "inertia", "izz", 5, 0.25);
  r.changes.push_back({"mass", "value", 4, 0, {1}, {2}});
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {r});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  EXPECT_EQ(result.applied, 1);
  const std::string expected =
      "<robot name='r'>  <!-- keep <mass value=\"9\"/> -->\n"
      "  <link   name = 'arm' >\n"
      "    <inertial>\n"
      "      <mass   value = '2' />\n"
      "      <inertia izz='0.25'  ixx=\"0.1\" iyy='0.2' ixy='0' ixz='0' iyz='0'/>\n"
      "    </inertial>\n"
      "  </link>\n"
      "</robot>\n";
  EXPECT_EQ(result.text, expected);
}

TEST(PatchModelTextTest, FindsTheRightLinkWhenSeveralShareALine) {
  const std::string before =
      "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>"
      "<link name=\"b\"><inertial><mass value=\"1\"/></inertial></link></robot>";
  const PatchResult result =
      PatchModelText(before, Model::Format::kUrdf, {OneChange("b", 1, "mass", "value", 1, 3)});
  EXPECT_EQ(result.text,
            "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>"
            "<link name=\"b\"><inertial><mass value=\"3\"/></inertial></link></robot>");
}

TEST(PatchModelTextTest, ReplacesOnlyTheXyzOfAnOriginAndKeepsRpy) {
  const std::string before =
      "<robot name=\"r\">\n<link name=\"a\">\n<inertial>\n"
      "<origin rpy=\"0 0 1\" xyz=\"0  0   0\"/>\n<mass value=\"1\"/>\n</inertial>\n</link>\n"
      "</robot>\n";
  Repair r;
  r.link = "a";
  r.link_line = 2;
  r.changes.push_back({"origin", "xyz", 4, 0, {0, 0, 0}, {0.5, 0, -0.25}});
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {r});
  // Each number is replaced in place; the separators ("  ", "   ") are kept.
  EXPECT_EQ(result.text,
            "<robot name=\"r\">\n<link name=\"a\">\n<inertial>\n"
            "<origin rpy=\"0 0 1\" xyz=\"0.5  0   -0.25\"/>\n<mass value=\"1\"/>\n</inertial>\n"
            "</link>\n</robot>\n");
}

TEST(PatchModelTextTest, RewritesSdfElementTextKeepingItsSpacing) {
  const std::string before =
      "<sdf version=\"1.7\"><model name=\"m\">\n"
      "  <link name=\"arm\">\n"
      "    <inertial>\n"
      "      <pose>0 0 0.1 0 0 0</pose>\n"
      "      <mass> 2.0 </mass>\n"
      "      <inertia>\n"
      "        <ixx>0.1</ixx>\n"
      "        <iyy>0.2</iyy>\n"
      "        <izz>0.5</izz>\n"
      "      </inertia>\n"
      "    </inertial>\n"
      "  </link>\n"
      "</model></sdf>\n";
  // Links of the top-level model are named without its name ("arm", as the SDF reader names
  // them); "m::arm" would be a link of a nested model "m" (xml_patch_location_test.cc).
  Repair r = OneChange("arm", 2, "inertia", "izz", 6, 0.25);
  r.changes.push_back({"mass", "", 5, 0, {2}, {1.5}});
  r.changes.push_back({"pose", "", 4, 0, {0, 0, 0.1}, {0, 0, 0.2}});
  r.changes.push_back({"inertia", "ixy", 6, 0, {0}, {-0.01}});  // absent: inserted after <izz>
  const PatchResult result = PatchModelText(before, Model::Format::kSdf, {r});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  EXPECT_EQ(result.text,
            "<sdf version=\"1.7\"><model name=\"m\">\n"
            "  <link name=\"arm\">\n"
            "    <inertial>\n"
            "      <pose>0 0 0.2 0 0 0</pose>\n"
            "      <mass> 1.5 </mass>\n"
            "      <inertia>\n"
            "        <ixx>0.1</ixx>\n"
            "        <iyy>0.2</iyy>\n"
            "        <izz>0.25</izz>\n"
            "        <ixy>-0.01</ixy>\n"
            "      </inertia>\n"
            "    </inertial>\n"
            "  </link>\n"
            "</model></sdf>\n");
}

TEST(PatchModelTextTest, InsertsAnInertialIndentedLikeItsSiblings) {
  const std::string before =
      "<robot name=\"r\">\r\n"
      "\t<link name=\"cover\">\r\n"
      "\t\t<collision><geometry><box size=\"0.1 0.1 0.02\"/></geometry></collision>\r\n"
      "\t</link>\r\n"
      "</robot>\r\n";
  Repair r;
  r.link = "cover";
  r.link_line = 2;
  r.inserts_inertial = true;
  r.after.mass = 0.2;
  r.after.X_BBi.p_AB = Eigen::Vector3d(0, 0, 0.1);
  r.after.ixx = r.after.iyy = 0.001;
  r.after.izz = 0.002;
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {r});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  EXPECT_EQ(result.text,
            "<robot name=\"r\">\r\n"
            "\t<link name=\"cover\">\r\n"
            "\t\t<inertial>\r\n"
            "\t\t\t<origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/>\r\n"
            "\t\t\t<mass value=\"0.2\"/>\r\n"
            "\t\t\t<inertia ixx=\"0.001\" ixy=\"0\" ixz=\"0\" iyy=\"0.001\" iyz=\"0\" "
            "izz=\"0.002\"/>\r\n"
            "\t\t</inertial>\r\n"
            "\t\t<collision><geometry><box size=\"0.1 0.1 0.02\"/></geometry></collision>\r\n"
            "\t</link>\r\n"
            "</robot>\r\n");
}

TEST(PatchModelTextTest, AMissingElementSkipsTheWholeRepair) {
  const std::string before =
      "<robot name=\"r\">\n<link name=\"a\">\n<inertial>\n<mass value=\"1\"/>\n</inertial>\n"
      "</link>\n</robot>\n";
  Repair r = OneChange("a", 2, "mass", "value", 4, 2);
  r.changes.push_back({"inertia", "ixx", 5, 0, {0}, {1}});  // there is no <inertia>
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {r});
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.applied, 0);
  EXPECT_EQ(result.text, before);
}

TEST(PatchModelTextTest, AWrongLineIsRefused) {
  const std::string before = "<robot name=\"r\">\n<link name=\"a\"/>\n</robot>\n";
  const PatchResult result =
      PatchModelText(before, Model::Format::kUrdf, {OneChange("a", 1, "mass", "value", 4, 2)});
  EXPECT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.text, before);
}

TEST(UnifiedDiffTest, EqualTextsHaveNoDiff) { EXPECT_EQ(UnifiedDiff("a\nb\n", "a\nb\n", "f"), ""); }

TEST(UnifiedDiffTest, OneChangedLineWithThreeLinesOfContext) {
  // Unified format (GNU diffutils manual, "Detailed Description of Unified Format"): hunk header
  // "@@ -start,count +start,count @@", three lines of context before and after.
  const std::string before = "1\n2\n3\n4\n5\n6\n7\n8\n9\n";
  const std::string after = "1\n2\n3\n4\nfive\n6\n7\n8\n9\n";
  EXPECT_EQ(UnifiedDiff(before, after, "robot.urdf"),
            "--- a/robot.urdf\n+++ b/robot.urdf\n"
            "@@ -2,7 +2,7 @@\n 2\n 3\n 4\n-5\n+five\n 6\n 7\n 8\n");
}

TEST(UnifiedDiffTest, DistantChangesGetSeparateHunksAndInsertionsCountRight) {
  std::string before, after;
  for (int i = 1; i <= 20; ++i) {
    before += std::to_string(i) + "\n";
    after += (i == 2 ? std::string("two") : std::to_string(i)) + "\n";
    if (i == 17) after += "17.5\n";
  }
  EXPECT_EQ(UnifiedDiff(before, after, "f"),
            "--- a/f\n+++ b/f\n"
            "@@ -1,5 +1,5 @@\n 1\n-2\n+two\n 3\n 4\n 5\n"
            "@@ -15,6 +15,7 @@\n 15\n 16\n 17\n+17.5\n 18\n 19\n 20\n");
}

TEST(UnifiedDiffTest, MarksALastLineWithoutNewline) {
  EXPECT_EQ(UnifiedDiff("a\nb", "a\nc", "f"),
            "--- a/f\n+++ b/f\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+c\n"
            "\\ No newline at end of file\n");
}

TEST(DiffLinesTest, ReportsRemovedAndAddedLineNumbers) {
  const LineChanges changes = DiffLines("a\nb\nc\nd\n", "a\nB\nc\nx\nd\n");
  EXPECT_EQ(changes.removed, std::vector<int>({2}));
  EXPECT_EQ(changes.added, std::vector<int>({2, 4}));
}

// MJCF (issue 36): the repair's Inertial is written into the <body>'s <inertial> attributes.
Repair MjcfRepair(const std::string& body, int line, double mass, const Eigen::Vector3d& pos,
                  const Eigen::Matrix3d& R, double ixx, double iyy, double izz, double ixy = 0) {
  Repair r;
  r.link = body;
  r.link_line = line;
  r.after.mass = mass;
  r.after.X_BBi.p_AB = pos;
  r.after.X_BBi.R_AB = R;
  r.after.ixx = ixx;
  r.after.iyy = iyy;
  r.after.izz = izz;
  r.after.ixy = ixy;
  return r;
}

TEST(PatchMjcfTest, OnlyTheNumbersThatChangeAreRewritten) {
  const std::string before =
      "<mujoco model='m'>  <!-- <body name=\"arm\"> -->\n"
      "  <worldbody>\n"
      "    <body name='arm' pos='0 0 1'>\n"
      "      <inertial  mass='1.000' pos='0 0 0.5' diaginertia='0.1 0.1 0.5'/>\n"
      "    </body>\n"
      "  </worldbody>\n"
      "</mujoco>\n";
  // mass 1 -> 2, izz 0.5 -> 0.2: "1.000" and "0.5" of diaginertia change; "0 0 0.5" is kept.
  const Repair r = MjcfRepair("arm", 3, 2, {0, 0, 0.5}, Eigen::Matrix3d::Identity(), 0.1, 0.1, 0.2);
  const PatchResult result = PatchModelText(before, Model::Format::kMjcf, {r});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  std::string expected = before;
  expected.replace(expected.find("1.000"), 5, "2");
  expected.replace(expected.find("0.1 0.5'/>") + 4, 3, "0.2");
  EXPECT_EQ(result.text, expected);
}

TEST(PatchMjcfTest, ATensorNotDiagonalWithoutOrientationBecomesFullinertia) {
  const std::string before =
      "<mujoco>\n<worldbody>\n<body name=\"b\">\n"
      "<inertial mass=\"1\" pos=\"0 0 0\" diaginertia=\"1 1 1\"/>\n</body>\n</worldbody>\n"
      "</mujoco>\n";
  const Repair r = MjcfRepair("b", 3, 1, {0, 0, 0}, Eigen::Matrix3d::Identity(), 1, 2, 2, 0.25);
  const PatchResult result = PatchModelText(before, Model::Format::kMjcf, {r});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  // MuJoCo's order: M11 M22 M33 M12 M13 M23 (the MJCF reference, <inertial fullinertia>).
  EXPECT_NE(result.text.find("<inertial mass=\"1\" pos=\"0 0 0\" fullinertia=\"1 2 2 0.25 0 0\"/>"),
            std::string::npos)
      << result.text;
}

TEST(PatchMjcfTest, ATensorNotDiagonalInAWrittenOrientationGetsItsPrincipalAxesAsQuat) {
  const std::string before =
      "<mujoco>\n<worldbody>\n<body name=\"b\">\n"
      "<inertial mass=\"1\" pos=\"0 0 0\" euler=\"0 0 90\" diaginertia=\"1 1 1\"/>\n</body>\n"
      "</worldbody>\n</mujoco>\n";
  // The frame written is 90° about z; the repaired tensor in it has a product of inertia.
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).matrix();
  const Repair r = MjcfRepair("b", 3, 1, {0, 0, 0}, Rz, 1, 2, 2, 0.25);
  const PatchResult result = PatchModelText(before, Model::Format::kMjcf, {r});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  ASSERT_EQ(result.text.find("euler"), std::string::npos) << result.text;
  const std::size_t quat = result.text.find("quat=\"");
  const std::size_t diag = result.text.find("diaginertia=\"");
  ASSERT_NE(quat, std::string::npos);
  ASSERT_NE(diag, std::string::npos);
  double q[4], d[3];
  ASSERT_EQ(
      std::sscanf(result.text.c_str() + quat, "quat=\"%lf %lf %lf %lf", &q[0], &q[1], &q[2], &q[3]),
      4);
  ASSERT_EQ(
      std::sscanf(result.text.c_str() + diag, "diaginertia=\"%lf %lf %lf", &d[0], &d[1], &d[2]), 3);
  // What the file now says, R diag(d) R^T, is the repair's tensor in the body frame, Rz I Rz^T.
  Eigen::Matrix3d I;
  I << 1, 0.25, 0, 0.25, 2, 0, 0, 0, 2;
  const Eigen::Matrix3d R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  const Eigen::Matrix3d written =
      R * Eigen::Vector3d(d[0], d[1], d[2]).asDiagonal() * R.transpose();
  EXPECT_LT((written - Rz * I * Rz.transpose()).norm(), 1e-12);
}

TEST(PatchMjcfTest, AGeomDerivedInertiaIsRefusedNamingTheDefaultClass) {
  const std::string before =
      "<mujoco>\n<default>\n  <default class=\"heavy\">\n    <geom density=\"8000\"/>\n"
      "  </default>\n</default>\n<worldbody>\n<body name=\"b\">\n"
      "<geom class=\"heavy\" size=\"0.1\"/>\n</body>\n</worldbody>\n</mujoco>\n";
  Repair r = MjcfRepair("b", 8, 1, {0, 0, 0}, Eigen::Matrix3d::Identity(), 1, 1, 1);
  r.inserts_inertial = true;
  const PatchResult result = PatchModelText(before, Model::Format::kMjcf, {r});
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.text, before);
  EXPECT_NE(result.errors[0].message.find("<default class='heavy'> at line 4"), std::string::npos)
      << result.errors[0].message;
}

TEST(PatchMjcfTest, ACompilerSettingThatChangesTheWrittenNumbersIsRefused) {
  const std::string before =
      "<mujoco>\n<compiler settotalmass=\"5\"/>\n<worldbody>\n<body name=\"b\">\n"
      "<inertial mass=\"1\" pos=\"0 0 0\" diaginertia=\"1 1 1\"/>\n</body>\n</worldbody>\n"
      "</mujoco>\n";
  const Repair r = MjcfRepair("b", 4, 2, {0, 0, 0}, Eigen::Matrix3d::Identity(), 1, 1, 1);
  const PatchResult result = PatchModelText(before, Model::Format::kMjcf, {r});
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_NE(result.errors[0].message.find("<compiler> at line 2 sets settotalmass"),
            std::string::npos)
      << result.errors[0].message;
}

}  // namespace
}  // namespace massprops
