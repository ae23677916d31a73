// How PatchModelText finds the element a repair is for (xml_patch.h): by structure (element path),
// scoped name and line; never inside a comment; an included model's link never in the top file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "massprops/analysis/repair.h"
#include "massprops/output/xml_patch.h"

namespace massprops {
namespace {

Repair SetMass(const std::string& link, int link_line, int mass_line, double value) {
  Repair r;
  r.link = link;
  r.link_line = link_line;
  r.changes.push_back({"mass", "value", mass_line, 0, {0}, {value}});
  return r;
}

Repair SetSdfMass(const std::string& link, int link_line, int mass_line, double value) {
  Repair r = SetMass(link, link_line, mass_line, value);
  r.changes.back().attribute = "";
  return r;
}

TEST(PatchLocationTest, ACommentedOutLinkOnTheSameLineIsNotEdited) {
  // The defect: the first "<link" on the line was inside a comment and got the edit.
  const std::string before =
      "<robot name=\"r\">\n"
      "<!-- <link name=\"a\"><inertial><mass value=\"1\"/></inertial></link> --> "
      "<link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>\n"
      "</robot>\n";
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {SetMass("a", 2, 2, 5)});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  EXPECT_EQ(result.text,
            "<robot name=\"r\">\n"
            "<!-- <link name=\"a\"><inertial><mass value=\"1\"/></inertial></link> --> "
            "<link name=\"a\"><inertial><mass value=\"5\"/></inertial></link>\n"
            "</robot>\n");
}

TEST(PatchLocationTest, ALinkThatExistsOnlyInACommentIsAnErrorNotAnEdit) {
  const std::string before =
      "<robot name=\"r\">\n"
      "<!-- <link name=\"a\"><inertial><mass value=\"1\"/></inertial></link> -->\n"
      "</robot>\n";
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {SetMass("a", 2, 2, 5)});
  EXPECT_EQ(result.text, before);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.applied, 0);
  EXPECT_NE(result.errors[0].message.find("no <link name=\"a\">"), std::string::npos)
      << result.errors[0].message;
}

TEST(PatchLocationTest, AnIncludedModelsLinkIsNotPatchedInTheTopLevelFile) {
  // The defect: the finding was about "cargo::body" (a link of an included model, in another
  // file); the top-level file has its own link "body" on the same line, which was rewritten.
  const std::string top =
      "<sdf version=\"1.9\"><model name=\"cart\">\n"
      "<link name=\"body\"><inertial><mass>1</mass></inertial></link>"
      "<include><uri>model://box</uri><name>cargo</name></include>\n"
      "</model></sdf>\n";
  const PatchResult result =
      PatchModelText(top, Model::Format::kSdf, {SetSdfMass("cargo::body", 2, 2, 5)});
  EXPECT_EQ(result.text, top);
  EXPECT_EQ(result.applied, 0);
  ASSERT_EQ(result.errors.size(), 1u);
}

TEST(PatchLocationTest, TheIncludedFileIsPatchedWhenAskedFor) {
  // The included model's own file: its link is scoped "body" there, "cargo::body" in the model.
  const std::string included =
      "<sdf version=\"1.9\">\n"
      "  <model name=\"box\">\n"
      "    <link name=\"body\"><inertial><mass>1</mass></inertial></link>\n"
      "  </model>\n"
      "</sdf>\n";
  PatchOptions options;
  options.included = true;
  const PatchResult result =
      PatchModelText(included, Model::Format::kSdf, {SetSdfMass("cargo::body", 3, 3, 5)}, options);
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  EXPECT_EQ(result.text,
            "<sdf version=\"1.9\">\n"
            "  <model name=\"box\">\n"
            "    <link name=\"body\"><inertial><mass>5</mass></inertial></link>\n"
            "  </model>\n"
            "</sdf>\n");
  // Without `included`, the scoped name must match exactly: nothing is patched.
  const PatchResult strict =
      PatchModelText(included, Model::Format::kSdf, {SetSdfMass("cargo::body", 3, 3, 5)});
  EXPECT_EQ(strict.text, included);
  EXPECT_EQ(strict.errors.size(), 1u);
}

TEST(PatchLocationTest, NestedModelLinksAreFoundByTheirScopedName) {
  // Two links named "wheel" on one line: the nested model's ("inner::wheel") and the top one's.
  const std::string before =
      "<sdf version=\"1.9\"><model name=\"m\">\n"
      "<model name=\"inner\"><link name=\"wheel\"><inertial><mass>1</mass></inertial></link>"
      "</model><link name=\"wheel\"><inertial><mass>1</mass></inertial></link>\n"
      "</model></sdf>\n";
  const PatchResult inner =
      PatchModelText(before, Model::Format::kSdf, {SetSdfMass("inner::wheel", 2, 2, 7)});
  ASSERT_TRUE(inner.errors.empty()) << inner.errors[0].message;
  EXPECT_EQ(inner.text,
            "<sdf version=\"1.9\"><model name=\"m\">\n"
            "<model name=\"inner\"><link name=\"wheel\"><inertial><mass>7</mass></inertial></link>"
            "</model><link name=\"wheel\"><inertial><mass>1</mass></inertial></link>\n"
            "</model></sdf>\n");
  const PatchResult outer =
      PatchModelText(before, Model::Format::kSdf, {SetSdfMass("wheel", 2, 2, 7)});
  ASSERT_TRUE(outer.errors.empty()) << outer.errors[0].message;
  EXPECT_EQ(outer.text,
            "<sdf version=\"1.9\"><model name=\"m\">\n"
            "<model name=\"inner\"><link name=\"wheel\"><inertial><mass>1</mass></inertial></link>"
            "</model><link name=\"wheel\"><inertial><mass>7</mass></inertial></link>\n"
            "</model></sdf>\n");
}

TEST(PatchLocationTest, ALinkOutsideTheElementPathIsNotEdited) {
  // A <link> inside <gazebo> is not a link of the robot (the reader ignores it too).
  const std::string before =
      "<robot name=\"r\">\n"
      "<gazebo><link name=\"a\"><inertial><mass value=\"1\"/></inertial></link></gazebo>"
      "<link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>\n"
      "</robot>\n";
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {SetMass("a", 2, 2, 3)});
  ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
  EXPECT_EQ(result.text,
            "<robot name=\"r\">\n"
            "<gazebo><link name=\"a\"><inertial><mass value=\"1\"/></inertial></link></gazebo>"
            "<link name=\"a\"><inertial><mass value=\"3\"/></inertial></link>\n"
            "</robot>\n");
}

TEST(PatchLocationTest, TheLinkMustBeAtTheLineTheModelSays) {
  const std::string before =
      "<robot name=\"r\">\n"
      "<link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>\n"
      "</robot>\n";
  const PatchResult result = PatchModelText(before, Model::Format::kUrdf, {SetMass("a", 3, 2, 3)});
  EXPECT_EQ(result.text, before);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_NE(result.errors[0].message.find("line 2, the model says 3"), std::string::npos)
      << result.errors[0].message;
}

}  // namespace
}  // namespace massprops
