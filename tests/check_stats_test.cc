#include "massprops/analysis/check_stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/io/urdf_reader.h"

// A rule that is off is not computed: its measurement counter (CheckStats) stays 0, where with
// the rule on it is positive (issue 50). And the whole-model measurement of inertia-exceeds-model
// costs about log n per link, not the 8 n of a scan of every corner of the model's geometry.

namespace massprops {
namespace {

const std::string kCheckDir = std::string(MASSPROPS_TESTDATA_DIR) + "/check/";

Model ReadFixture(const std::string& name) {
  const ReadResult result = ReadUrdfFile(kCheckDir + name);
  EXPECT_TRUE(result.ok()) << name;
  return result.models.empty() ? Model() : result.models[0];
}

std::vector<const Finding*> Select(const std::vector<Finding>& findings, const std::string& rule) {
  std::vector<const Finding*> out;
  for (const Finding& f : findings) {
    if (f.rule == rule) out.push_back(&f);
  }
  return out;
}

double ValueOf(const Finding& f, const std::string& name) {
  for (const auto& [key, value] : f.values) {
    if (key == name) return value;
  }
  ADD_FAILURE() << "no value " << name;
  return NAN;
}

CheckOptions Off(const std::string& rule) {
  CheckOptions options;
  options.overrides[rule] = std::nullopt;  // --disable RULE, --severity RULE=off, the toml file
  return options;
}

TEST(CheckStatsTest, InertiaExceedsModelMeasuresTheModelOnlyWhenOn) {
  // The drone of the fixture's comment: its base's radius of gyration 0.489898 m, the farthest
  // point of the model a plate corner (0.2, 0.2, 0.05) from the base's COM at the origin:
  // R = sqrt(0.04 + 0.04 + 0.0025) = sqrt(0.0825) (hand-derived, in the fixture).
  const Model model = ReadFixture("round3/drone-drawn-base.urdf");
  CheckStats on;
  const std::vector<Finding> found = CheckModel(model, CheckOptions(), &on);
  const std::vector<const Finding*> exceeds = Select(found, "inertia-exceeds-model");
  ASSERT_EQ(exceeds.size(), 1u);
  EXPECT_NEAR(ValueOf(*exceeds[0], "model_reach"), std::sqrt(0.0825), 1e-12);
  EXPECT_EQ(on.model_extents, 1u);  // one tree
  EXPECT_GT(on.model_reach_measurements, 0u);
  EXPECT_GT(on.model_reach_distances, 0u);

  CheckStats off;
  const std::vector<Finding> without = CheckModel(model, Off("inertia-exceeds-model"), &off);
  EXPECT_TRUE(Select(without, "inertia-exceeds-model").empty());
  EXPECT_EQ(off.model_extents, 0u);
  EXPECT_EQ(off.model_reach_measurements, 0u);
  EXPECT_EQ(off.model_reach_distances, 0u);
  // Every other rule's findings are the same.
  EXPECT_EQ(without.size() + 1, found.size());
}

TEST(CheckStatsTest, ComNotMirroredJudgesPairsOnlyWhenOn) {
  // Two mirrored pairs (arms and legs, the fixture's comment): both judged, both reported.
  const Model model = ReadFixture("round2/com-not-mirrored.urdf");
  CheckStats on;
  const std::vector<Finding> found = CheckModel(model, CheckOptions(), &on);
  EXPECT_EQ(Select(found, "com-not-mirrored").size(), 2u);
  EXPECT_EQ(on.mirrored_pairs, 2u);
  CheckStats off;
  const std::vector<Finding> without = CheckModel(model, Off("com-not-mirrored"), &off);
  EXPECT_TRUE(Select(without, "com-not-mirrored").empty());
  EXPECT_EQ(off.mirrored_pairs, 0u);
}

TEST(CheckStatsTest, CopiedPlaceholdersMeasureAssembliesOnlyWhenUnitsSuspectIsOn) {
  const Model model = ReadFixture("round2/copied-placeholders.urdf");
  CheckStats on;
  const std::vector<Finding> found = CheckModel(model, CheckOptions(), &on);
  EXPECT_FALSE(Select(found, "units-suspect").empty());
  EXPECT_GT(on.copied_groups, 0u);
  CheckStats off;
  CheckModel(model, Off("units-suspect"), &off);
  EXPECT_EQ(off.copied_groups, 0u);
}

// The chain of tools/gen_chain.py (a 1.5 kg box 0.04 x 0.04 x 0.1 m per link, revolute joints
// 0.1 m apart along z), n links.
// tools/gen_chain.py's chain: joints of `joint_type`; with `massless`, every link but the last
// has mass 0 and a zero inertia.
std::string ChainUrdf(int n, const std::string& joint_type = "revolute", bool massless = false,
                      bool collision = true) {
  std::string text = "<robot name=\"chain\">\n";
  for (int k = 0; k < n; ++k) {
    const std::string name = "link" + std::to_string(k);
    const bool light = massless && k < n - 1;
    text += "<link name=\"" + name + "\"><inertial><origin xyz=\"0 0 0.05\"/>" +
            (light ? "<mass value=\"0\"/><inertia ixx=\"0\" ixy=\"0\" ixz=\"0\" iyy=\"0\" "
                     "iyz=\"0\" izz=\"0\"/>"
                   : "<mass value=\"1.5\"/><inertia ixx=\"0.00145\" ixy=\"0\" ixz=\"0\" "
                     "iyy=\"0.00145\" iyz=\"0\" izz=\"0.0004\"/>") +
            "</inertial>" +
            (collision ? "<collision><origin xyz=\"0 0 0.05\"/><geometry><box size=\"0.04 "
                         "0.04 0.1\"/></geometry></collision>"
                       : "") +
            "</link>\n";
    if (k > 0) {
      text += "<joint name=\"joint" + std::to_string(k) + "\" type=\"" + joint_type +
              "\"><origin xyz=\"0 0 0.1\"/><parent link=\"link" + std::to_string(k - 1) +
              "\"/><child link=\"" + name +
              "\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
              "velocity=\"1\"/></joint>\n";
    }
  }
  return text + "</robot>\n";
}

TEST(CheckStatsTest, EachLinkIsMeasuredAgainstTheModelInFarFewerThanAllItsCorners) {
  constexpr int kLinks = 2000;
  const ReadResult read = ReadUrdfString(ChainUrdf(kLinks), "chain.urdf");
  ASSERT_TRUE(read.ok());
  CheckStats stats;
  const std::vector<Finding> found = CheckModel(read.models[0], CheckOptions(), &stats);
  // Each link's k = sqrt((0.00145 + 0.00145 + 0.0004) / (2 * 1.5)) = 0.0332 m lies within its
  // own box: nothing to report, and every link is measured (mass 1.5 kg > the dummy's 1 g).
  EXPECT_TRUE(Select(found, "inertia-exceeds-model").empty());
  EXPECT_EQ(stats.model_extents, 1u);
  EXPECT_EQ(stats.model_reach_measurements, static_cast<std::size_t>(kLinks));
  // A scan would evaluate all 8 * 2000 corners per link; the index a few leaves of 8 (the
  // farthest corner lies at one end of the chain).
  EXPECT_LT(stats.model_reach_distances, 100u * kLinks);
}

// A welded chain: every link of the one group asks for the group's composite (whether it
// weighs in its group), and the composite is composed once, not once per member (issue 50: a
// group of n links cost n^2).
TEST(CheckStatsTest, AWeldedGroupIsComposedOnceWhateverItsMembersAsk) {
  constexpr int kLinks = 300;
  const ReadResult read = ReadUrdfString(ChainUrdf(kLinks, "fixed"), "welded.urdf");
  ASSERT_TRUE(read.ok());
  CheckStats stats;
  CheckModel(read.models[0], CheckOptions(), &stats);
  EXPECT_GE(stats.group_composite_questions, static_cast<std::size_t>(kLinks));
  EXPECT_EQ(stats.group_composites, 1u);
}

// A welded chain with no geometry: no link's own geometry gives its size, so units-suspect asks
// how far its welded group's geometry reaches from each link; the group's corners are indexed
// once (none here: every link is a bare inertial), not gathered again per member.
TEST(CheckStatsTest, AWeldedGroupsReachIsIndexedOnceWhateverItsMembersAsk) {
  constexpr int kLinks = 300;
  const ReadResult read = ReadUrdfString(ChainUrdf(kLinks, "fixed", false, false), "bare.urdf");
  ASSERT_TRUE(read.ok());
  CheckStats stats;
  CheckModel(read.models[0], CheckOptions(), &stats);
  EXPECT_GE(stats.group_reach_questions, static_cast<std::size_t>(kLinks - 1));
  EXPECT_EQ(stats.group_corner_indexes, 1u);
}

// Massless links carrying the last: each massless link is a moving body that asks what is
// outboard of it; each link's subtree is composed once, from its child's (n, not n^2 / 2).
TEST(CheckStatsTest, WhatIsOutboardIsComposedOncePerLink) {
  constexpr int kLinks = 300;
  const ReadResult read =
      ReadUrdfString(ChainUrdf(kLinks, "revolute", /*massless=*/true), "massless.urdf");
  ASSERT_TRUE(read.ok());
  CheckStats stats;
  const std::vector<Finding> found = CheckModel(read.models[0], CheckOptions(), &stats);
  EXPECT_GE(stats.outboard_questions, static_cast<std::size_t>(kLinks - 1));
  EXPECT_EQ(stats.subtree_composites, static_cast<std::size_t>(kLinks));
  // link1 moves on joint1 (about y, at its origin) and carries only the last link, of 1.5 kg
  // with its COM 0.1 * (299 - 1) + 0.05 = 29.85 m up: the moment about the joint axis is
  // Iyy + m d^2 = 0.00145 + 1.5 * 29.85^2 (parallel axis theorem, by hand).
  bool seen = false;
  for (const Finding& f : found) {
    if (f.link != "link1") continue;
    for (const auto& [key, value] : f.values) {
      if (key != "moment_outboard") continue;
      EXPECT_NEAR(value, 0.00145 + 1.5 * 29.85 * 29.85, 1e-9) << f.rule;
      seen = true;
    }
  }
  EXPECT_TRUE(seen);
}

}  // namespace
}  // namespace massprops
