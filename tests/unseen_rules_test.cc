// The rule changes of issue 25 (warnings that hold on robots the rules were never tuned on), each
// on a fixture of testdata/check/unseen/ whose numbers are worked out by hand in its comment:
// the mesh hull's per-axis bound, a center of mass outside a whole CAD mesh, a placeholder inertia
// on a geometry-less link judged against the kinematic tree, and a mass lost in an edit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "finding_test_support.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/check/unseen/";

// Checks the fixture as `massprops check` does by default: the meshes' boxes and vertices read.
std::vector<Finding> Check(const std::string& name) {
  return test_support::CheckAsTheTool(kDir + name + ".urdf", /*closed_meshes=*/false);
}

using test_support::Dump;
using test_support::Select;
using test_support::ValueOf;

// Box 0.1 x 0.2 x 0.3 m, 1 kg, COM at its center: ixx <= m (0.1² + 0.15²) = 0.0325 kg·m² (the
// farthest vertex from the x axis). ixx = 0.0375 is 15/13 of it; the bounding-sphere test
// (tr/2 = 0.038 <= 1.21 · 0.035 = 0.04235) lets it pass.
TEST(UnseenRulesTest, AnInertiaTheMeshHullCannotHoldIsReported) {
  const std::vector<Finding> findings = Check("hull-bound");
  const std::vector<Finding> exceeds = Select(findings, "inertia-exceeds-geometry");
  ASSERT_EQ(exceeds.size(), 1u) << Dump(findings);
  EXPECT_EQ(exceeds[0].link, "part");
  // Mesh vertices are 32-bit floats: 0.1, 0.2, 0.3 carry a relative rounding of about 6e-8.
  EXPECT_NEAR(ValueOf(exceeds[0], "hull_bound"), 0.0325, 1e-8);
  EXPECT_NEAR(ValueOf(exceeds[0], "moment"), 0.0375, 1e-12);
  EXPECT_NEAR(ValueOf(exceeds[0], "ratio"), 15.0 / 13.0, 1e-6);
  EXPECT_TRUE(Check("hull-bound-ok").empty()) << Dump(Check("hull-bound-ok"));
}

// Half-diagonal sqrt(0.05² + 0.1² + 0.15²) = sqrt(0.035) = 0.187083 m; allowed 0.25 of it =
// 0.0467707 m; the COM at x = 0.16 is 0.06 m past the x = 0.1 face.
TEST(UnseenRulesTest, ACenterOfMassOutsideAWholeMeshIsReported) {
  const std::vector<Finding> findings = Check("mesh-com-outside");
  const std::vector<Finding> outside = Select(findings, "com-outside-geometry");
  ASSERT_EQ(outside.size(), 1u) << Dump(findings);
  EXPECT_NEAR(ValueOf(outside[0], "distance"), 0.06, 1e-7);
  EXPECT_NEAR(ValueOf(outside[0], "allowed"), 0.25 * std::sqrt(0.035), 1e-7);
  EXPECT_TRUE(Check("mesh-com-outside-ok").empty()) << Dump(Check("mesh-com-outside-ok"));
}

// k = sqrt(3 · 0.015 / (2 · 0.15)) = sqrt(0.15) = 0.387298 m against the 0.03 m span from the
// finger's origin to its child joint: 12.9099 times (over 5). The tip (leaf, 0.05 kg, 1e-6) has
// k = sqrt(3e-6 / 0.1) = 0.0055 m against its parent's 0.03 m span: silent.
TEST(UnseenRulesTest, APlaceholderOnAGeometryLessLinkIsJudgedByItsJoints) {
  const std::vector<Finding> findings = Check("kinematic-scale");
  const std::vector<Finding> units = Select(findings, "units-suspect");
  ASSERT_EQ(units.size(), 1u) << Dump(findings);
  EXPECT_EQ(units[0].link, "finger");
  EXPECT_NEAR(ValueOf(units[0], "radius_of_gyration"), std::sqrt(0.15), 1e-12);
  EXPECT_NEAR(ValueOf(units[0], "kinematic_span"), 0.03, 1e-12);
  EXPECT_NEAR(ValueOf(units[0], "ratio"), std::sqrt(0.15) / 0.03, 1e-9);
  // I = 0.0003: k = sqrt(0.003) = 0.0548 m, 1.83 times the span.
  EXPECT_TRUE(Select(Check("kinematic-scale-ok"), "units-suspect").empty());
}

// torso_1: mass 0, trace 0.0004544 + 0.001141 + 0.001236 = 0.0028314, on its own joint with
// nothing else in its welded group; welded to the root instead, it never moves.
TEST(UnseenRulesTest, AMassLostInAnEditIsReportedOnAMovingBody) {
  const std::vector<Finding> findings = Check("inertia-without-mass");
  const std::vector<Finding> lost = Select(findings, "inertia-without-mass");
  ASSERT_EQ(lost.size(), 1u) << Dump(findings);
  EXPECT_EQ(lost[0].link, "torso_1");
  EXPECT_EQ(lost[0].severity, Severity::kWarning);
  EXPECT_NEAR(ValueOf(lost[0], "trace"), 0.0028314, 1e-15);
  EXPECT_TRUE(Select(Check("inertia-without-mass-ok"), "inertia-without-mass").empty());
}

}  // namespace
}  // namespace massprops
