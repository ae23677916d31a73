// The geometry rules: inertia-disagrees-with-geometry and mesh-unreadable.
#include "massprops/analysis/geometry_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "massprops/io/model_reader.h"
#include "tool_runner.h"

namespace massprops {
namespace {

using massprops::test_support::RunTool;
using massprops::test_support::ToolRun;

const std::string kBoxes = std::string(MASSPROPS_TESTDATA_DIR) + "/geometry/boxes.urdf";

std::vector<Finding> Check(const GeometryCheckOptions& options, MeshCache* cache) {
  const ReadResult read = ReadModelFile(kBoxes);
  EXPECT_TRUE(read.errors.empty());
  GeometryCheckOptions o = options;
  o.resolve.use_environment = false;
  o.resolve.cache = cache;
  return CheckModelGeometry(read.models.at(0), o);
}

GeometryCheckOptions On() {
  GeometryCheckOptions options;
  options.enabled = true;
  return options;
}

bool Has(const std::vector<Finding>& findings, const std::string& rule, const std::string& link) {
  return std::any_of(findings.begin(), findings.end(),
                     [&](const Finding& f) { return f.rule == rule && f.link == link; });
}

TEST(GeometryChecksTest, DeclaredTenTimesTheBoxFormulaDisagreesWithGeometry) {
  MeshCache cache;
  const std::vector<Finding> findings = Check(On(), &cache);
  // Box formula m(b²+c²)/12 (fixture comment) vs 10x declared: factor 10 > 2.
  ASSERT_TRUE(Has(findings, kInertiaDisagreesWithGeometryRule, "box_ten_times"));
  for (const Finding& f : findings) {
    if (f.link != "box_ten_times") continue;
    EXPECT_EQ(f.severity, Severity::kWarning);
    for (const auto& [name, value] : f.values) {
      if (name == "factor") {
        EXPECT_NEAR(value, 10, 1e-12);
      }
    }
  }
}

TEST(GeometryChecksTest, DeclaredOneAndAHalfTimesTheBoxFormulaIsWithinTheDefaultFactor) {
  MeshCache cache;
  const std::vector<Finding> findings = Check(On(), &cache);
  EXPECT_FALSE(Has(findings, kInertiaDisagreesWithGeometryRule, "box_one_and_a_half"));
  EXPECT_FALSE(Has(findings, kInertiaDisagreesWithGeometryRule, "box_exact"));
  EXPECT_FALSE(Has(findings, kInertiaDisagreesWithGeometryRule, "box_turned"));
  EXPECT_FALSE(Has(findings, kInertiaDisagreesWithGeometryRule, "mesh_box"));
}

TEST(GeometryChecksTest, AFactorBelowOneAndAHalfFlagsTheOneAndAHalfLink) {
  MeshCache cache;
  GeometryCheckOptions options = On();
  options.factor = 1.4;  // 1.5 > 1.4
  EXPECT_TRUE(Has(Check(options, &cache), kInertiaDisagreesWithGeometryRule, "box_one_and_a_half"));
}

TEST(GeometryChecksTest, MissingMeshIsMeshUnreadableNamingTheUri) {
  MeshCache cache;
  const std::vector<Finding> findings = Check(On(), &cache);
  ASSERT_TRUE(Has(findings, kMeshUnreadableRule, "missing_mesh"));
  for (const Finding& f : findings) {
    if (f.rule == kMeshUnreadableRule) {
      EXPECT_NE(f.message.find("no_such_mesh.stl"), std::string::npos) << f.message;
    }
  }
  EXPECT_FALSE(Has(findings, kMeshUnreadableRule, "mesh_box"));
}

TEST(GeometryChecksTest, IgnoreCommentOnTheLinkSilencesTheRule) {
  MeshCache cache;
  EXPECT_FALSE(
      Has(Check(On(), &cache), kInertiaDisagreesWithGeometryRule, "box_ten_times_ignored"));
}

TEST(GeometryChecksTest, OverridesDisableAndChangeSeverity) {
  MeshCache cache;
  GeometryCheckOptions options = On();
  options.check.overrides[kMeshUnreadableRule] = std::nullopt;
  options.check.overrides[kInertiaDisagreesWithGeometryRule] = Severity::kError;
  const std::vector<Finding> findings = Check(options, &cache);
  EXPECT_FALSE(Has(findings, kMeshUnreadableRule, "missing_mesh"));
  ASSERT_TRUE(Has(findings, kInertiaDisagreesWithGeometryRule, "box_ten_times"));
  for (const Finding& f : findings) EXPECT_EQ(f.severity, Severity::kError);
}

TEST(GeometryChecksTest, WithoutGeometryEnabledThereAreNoFindings) {
  MeshCache cache;
  EXPECT_TRUE(Check(GeometryCheckOptions(), &cache).empty());
}

TEST(GeometryChecksTest, CheckCommandRunsTheRulesOnlyWithTheGeometryFlag) {
  const ToolRun with = RunTool("check --geometry '" + kBoxes + "'", true);
  EXPECT_NE(with.output.find("inertia-disagrees-with-geometry"), std::string::npos) << with.output;
  EXPECT_NE(with.output.find("mesh-unreadable"), std::string::npos) << with.output;
  const ToolRun without = RunTool("check '" + kBoxes + "'", true);
  EXPECT_EQ(without.output.find("inertia-disagrees-with-geometry"), std::string::npos)
      << without.output;
  EXPECT_EQ(without.output.find("mesh-unreadable"), std::string::npos) << without.output;
}

TEST(GeometryChecksTest, CheckCommandAcceptsTheFactorAndDisablingTheRules) {
  const ToolRun run = RunTool(
      "check --geometry --geometry-factor 20 --disable mesh-unreadable '" + kBoxes + "'", true);
  EXPECT_EQ(run.output.find("inertia-disagrees-with-geometry"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("mesh-unreadable"), std::string::npos) << run.output;
  const ToolRun list = RunTool("check --list-rules", true);
  EXPECT_NE(list.output.find("inertia-disagrees-with-geometry"), std::string::npos);
}

}  // namespace
}  // namespace massprops
