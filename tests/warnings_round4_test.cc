// The bounds of issue 49 (warnings, fourth round): what a mass can do inside its own geometry.
// Each fixture of testdata/check/round4/ works its numbers out by hand in its comment; here they
// are computed again from the formulas (Bhatia–Davis per direction, the bounding ellipsoid of
// Wensing, Kim and Slotine 2018, the least trace of a ball of the densest material, mass over
// the hull's volume), and the look-alikes stay quiet under every rule.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "finding_test_support.h"
#include "massprops/analysis/check_stats.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/check/round4/";

using test_support::Dump;
using test_support::EvidenceOf;
using test_support::Select;
using test_support::ValueOf;

// `massprops check` on the fixture, with inertia-beyond-hull (off by default) as a warning.
std::vector<Finding> CheckAll(const std::string& name) {
  CheckOptions options;
  options.overrides["inertia-beyond-hull"] = Severity::kWarning;
  return test_support::CheckAsTheTool(kDir + name + ".urdf", true, options);
}

bool Flags(const std::vector<Finding>& findings, const std::string& link) {
  for (const Finding& f : findings) {
    if (f.link == link) return true;
  }
  return false;
}

// Osmium's and lead's densities (CRC Handbook of Chemistry and Physics), kg/m³.
constexpr double kOsmium = 22590, kLead = 11340;

// (6/5) m r², r = (3m / (4πρ))^(1/3): the trace of a uniform ball of density ρ and mass m.
double BallTrace(double m, double rho) {
  const double r = std::cbrt(3 * m / (4 * M_PI * rho));
  return 1.2 * m * r * r;
}

// box_on_face: the 0.1 x 0.2 x 0.3 m box mesh (0 <= z <= 0.3), 2 kg, its own central tensor, the
// center of mass on the top face. Along z: Σzz = 2 · 0.3² / 12; the mesh grown 1.1 times about
// its centre z = 0.15 reaches 0.15 ± 0.165, so Bhatia–Davis allows 2 · (0.315 − 0.3) · (0.3 +
// 0.015).
TEST(WarningsRound4Test, ACenterOfMassOnAFaceWithACentredTensorIsBeyondTheHull) {
  const std::vector<Finding> findings = CheckAll("com-on-face");
  const std::vector<Finding> beyond = Select(findings, "inertia-beyond-hull");
  ASSERT_EQ(beyond.size(), 1u) << Dump(findings);
  EXPECT_EQ(beyond[0].link, "box_on_face");
  const double spread = 2 * 0.3 * 0.3 / 12;
  const double bound = 2 * (0.315 - 0.3) * (0.3 + 0.015);
  // The worst of the directions judged is z itself (a face normal of the hull and a frame axis).
  EXPECT_NEAR(ValueOf(beyond[0], "second_moment"), spread, 1e-9);
  EXPECT_NEAR(ValueOf(beyond[0], "direction_bound"), bound, 1e-7);  // float STL vertices
  EXPECT_NEAR(ValueOf(beyond[0], "ratio"), spread / bound, 1e-5);
  EXPECT_NE(beyond[0].headline.find("along z"), std::string::npos) << beyond[0].headline;
  EXPECT_NE(beyond[0].help.find("on the part's face"), std::string::npos) << beyond[0].help;
  // No other rule sees it, and the same numbers with the center of mass at the centre pass.
  EXPECT_EQ(findings.size(), 1u) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "box_centred")) << Dump(findings);
}

// ball: an icosphere of radius R = 0.1 with I = m R² on every axis (a hollow shell has at most
// 2/3 of that). Σ = (3/2 − 1) m R² · 1; the least ellipsoid around the mesh is the ball of radius
// R, grown 1.1 times: tr(Q⁻¹ Σ) / m = 3 · 0.5 · R² / (1.1 R)².
TEST(WarningsRound4Test, ATensorBeyondTheBoundingEllipsoidThatPassesEveryAxisIsReported) {
  const std::vector<Finding> findings = CheckAll("ball-beyond-ellipsoid");
  const std::vector<Finding> beyond = Select(findings, "inertia-beyond-hull");
  ASSERT_EQ(beyond.size(), 1u) << Dump(findings);
  EXPECT_EQ(beyond[0].link, "ball");
  // Khachiyan's ellipsoid is within a few per mille of the least one (link_measure.cc).
  EXPECT_NEAR(ValueOf(beyond[0], "ellipsoid_ratio"), 1.5 / 1.21, 0.01);
  EXPECT_EQ(findings.size(), 1u) << Dump(findings);  // every axis and direction bound holds
  EXPECT_FALSE(Flags(findings, "shell")) << Dump(findings);
}

// raised: a 0.1 m cube written with the 0.5 kg part's tensor, 0.5 · 0.02 / 12 about each axis,
// and a mass of 10 kg: below a 10 kg ball of osmium's trace.
TEST(WarningsRound4Test, AMassRaisedWithItsTensorKeptIsMoreCompactThanOsmium) {
  const std::vector<Finding> findings = CheckAll("mass-raised");
  const std::vector<Finding> compact = Select(findings, "inertia-too-compact");
  ASSERT_EQ(compact.size(), 1u) << Dump(findings);
  EXPECT_EQ(compact[0].link, "raised");
  EXPECT_EQ(compact[0].severity, Severity::kNote);
  const double trace = 3 * 0.5 * 0.02 / 12;
  EXPECT_NEAR(ValueOf(compact[0], "trace"), trace, 1e-15);
  EXPECT_NEAR(ValueOf(compact[0], "least_trace"), BallTrace(10, kOsmium), 1e-12);
  EXPECT_NEAR(EvidenceOf(compact[0], "ball_radius_m"), std::cbrt(30 / (4 * M_PI * kOsmium)), 1e-12);
  EXPECT_NE(compact[0].message.find("no body of this mass is so compact"), std::string::npos);
  // Nothing else: 10 kg over the box grown twice (8e-3 m³) is lighter than osmium.
  EXPECT_EQ(findings.size(), 1u) << Dump(findings);
  // A 1 kg steel ball with its own inertia is less compact than lead's.
  EXPECT_GT(3 * 3.89722e-4, BallTrace(1, kLead));
  EXPECT_FALSE(Flags(findings, "steel_ball")) << Dump(findings);
}

// cube: 0.5 kg in a 2 cm cube mesh (8e-6 m³), 62 500 kg/m³; finger: 0.25 kg in 2 x 2 x 4.5 cm
// (1.8e-5 m³), 13 889 kg/m³, above 1.1 times lead; counterweight: lead itself, quiet.
TEST(WarningsRound4Test, APartHeavierThanOsmiumCouldFillIsImpossible) {
  const std::vector<Finding> findings = CheckAll("heavier-than-osmium");
  const std::vector<Finding> dense = Select(findings, "density-implausible");
  ASSERT_EQ(dense.size(), 2u) << Dump(findings);
  EXPECT_EQ(dense[0].link, "cube");
  EXPECT_NEAR(ValueOf(dense[0], "hull_volume"), 8e-6, 8e-6 * 1e-6);  // float STL vertices
  EXPECT_NEAR(ValueOf(dense[0], "density"), 0.5 / 8e-6, 0.5 / 8e-6 * 1e-6);
  EXPECT_NEAR(EvidenceOf(dense[0], "mass_if_steel_kg"), 7850 * 8e-6, 1e-8);
  EXPECT_NE(dense[0].message.find("osmium"), std::string::npos) << dense[0].message;
  EXPECT_NE(dense[0].headline.find("denser than osmium"), std::string::npos) << dense[0].headline;
  EXPECT_EQ(dense[1].link, "finger");
  EXPECT_NEAR(ValueOf(dense[1], "density"), 0.25 / 1.8e-5, 0.25 / 1.8e-5 * 1e-6);
  EXPECT_GT(0.25 / 1.8e-5, 1.1 * kLead);
  EXPECT_NE(dense[1].headline.find("denser than lead"), std::string::npos) << dense[1].headline;
  EXPECT_FALSE(Flags(findings, "counterweight")) << Dump(findings);
  // One finding per defect: the cube is also more compact than osmium's ball, and its tensor is
  // its closed mesh's own solid (the closed-mesh form of the rule), neither said twice.
  EXPECT_LT(3 * 0.5 * 0.0008 / 12, BallTrace(0.5, kOsmium));
  EXPECT_EQ(findings.size(), 2u) << Dump(findings);
}

// A hollow part, a motor at one end of its bracket, a part drawn by a simplified shell: real
// parts, quiet under every rule (inertia-beyond-hull and the notes included).
TEST(WarningsRound4Test, RealPartsThatLookLikeTheDefectsAreQuiet) {
  const std::vector<Finding> findings = CheckAll("look-alikes");
  EXPECT_TRUE(findings.empty()) << Dump(findings);
}

// What each link's hull costs: built only for a rule that is on and may speak. Off by default,
// inertia-beyond-hull says nothing; density-implausible builds the hull only where the mass over
// a volume inside it (InnerVolume: each primitive's own, the hull of the meshes' extreme points)
// is already beyond its threshold (issue 50: a rule that cannot fire costs one pass).
std::size_t Measured(const std::string& name, const std::vector<std::string>& on) {
  const std::string file = kDir + name + ".urdf";
  const ReadResult read = ReadModelFile(file);
  EXPECT_FALSE(read.models.empty());
  if (read.models.empty()) return 0;
  MeshResolveOptions resolve;
  resolve.model_file = file;
  resolve.use_environment = false;
  CheckOptions options;
  options.box = MakeLinkBoxFunction(resolve);
  options.points = MakeLinkPointsFunction(resolve);
  for (const std::string& rule : on) options.overrides[rule] = Severity::kWarning;
  CheckStats stats;
  CheckModel(read.models[0], options, &stats);
  return stats.link_measures;
}

TEST(WarningsRound4Test, TheHullIsMeasuredOnlyWhereARuleThatIsOnMaySpeak) {
  EXPECT_TRUE(Select(test_support::CheckAsTheTool(kDir + "com-on-face.urdf"), "inertia-beyond-hull")
                  .empty());
  // com-on-face: 2 kg over its box mesh, 0.006 m³ (its 26 extreme points are its corners),
  // 333 kg/m³, far below 1.1 times lead: no hull built by default; both boxes with
  // inertia-beyond-hull on.
  EXPECT_EQ(Measured("com-on-face", {}), 0u);
  EXPECT_EQ(Measured("com-on-face", {"inertia-beyond-hull"}), 2u);
  // heavier-than-osmium: cube (62 500 kg/m³) and finger (13 889) over their boxes; not the lead
  // counterweight, 11 340 kg/m³ over its own box, which is inside its hull.
  EXPECT_EQ(Measured("heavier-than-osmium", {}), 2u);
}

}  // namespace
}  // namespace massprops
