// The rule changes of issue 43 (warnings, third round), each on a fixture of
// testdata/check/round3/ whose numbers are worked out by hand in its comment: a welded part's
// center of mass left at its frame's origin (com-outside-geometry), a tensor written for the part
// before it was turned (inertia-exceeds-geometry, axis by axis over the primitives as placed), an
// inertia no body inside the whole model can have (inertia-exceeds-model), and mirror twins that
// carry the same numbers but whose centers of mass do not mirror (com-not-mirrored); and the
// look-alikes of each, which stay quiet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "finding_test_support.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/check/round3/";

using test_support::Dump;
using test_support::EvidenceOf;
using test_support::Select;
using test_support::ValueOf;

std::vector<Finding> CheckFile(const std::string& file) {
  return test_support::CheckAsTheTool(file);
}

// Checks the fixture as `massprops check` does by default.
std::vector<Finding> Check(const std::string& name) { return CheckFile(kDir + name + ".urdf"); }

bool Flags(const std::vector<Finding>& findings, const std::string& link) {
  return std::any_of(findings.begin(), findings.end(), [&](const Finding& f) {
    return f.link == link && f.severity != Severity::kNote;
  });
}

// Every headline a whole sentence of at most 110 characters, without an ellipsis.
void ExpectReadableHeadlines(const std::vector<Finding>& findings) {
  for (const Finding& f : findings) {
    EXPECT_LE(f.headline.size(), 110u) << f.headline;
    EXPECT_EQ(f.headline.find("…"), std::string::npos) << f.headline;
  }
}

// 'front_cover': its box spans x 0.11..0.13 m, its COM is (0, 0, 0): 0.11 m outside, allowed
// max(0.01, 0.25 × 0.5 × sqrt(0.0504)) = 0.0280624 m. The chassis (3 kg) carries its own mass,
// so the origin inside the chassis box is no lumped mass.
TEST(WarningsRound3Test, AWeldedCoverWhoseCenterOfMassWasLeftAtItsOriginIsReported) {
  const std::vector<Finding> findings = Check("com-left-at-origin");
  const std::vector<Finding> com = Select(findings, "com-outside-geometry");
  ASSERT_EQ(com.size(), 1u) << Dump(findings);
  EXPECT_EQ(com[0].link, "front_cover");
  EXPECT_NEAR(ValueOf(com[0], "distance"), 0.11, 1e-12);
  EXPECT_NEAR(ValueOf(com[0], "allowed"), 0.25 * 0.5 * std::sqrt(0.0504), 1e-12);
  EXPECT_NEAR(EvidenceOf(com[0], "box_center_x_m"), 0.12, 1e-12);
  ExpectReadableHeadlines(com);
}

// The look-alikes: a COM written at the part's middle; a sensor frame's COM outside its 8 mm
// visual marker; a 5 kg ballast (more than the 3.85 kg of the rest of its group) whose COM sits
// at the origin, inside the chassis: the group's mass lumped on one link.
TEST(WarningsRound3Test, ACenterOfMassOutsideAMarkerOrLumpedFromWeldedNeighboursIsNotReported) {
  const std::vector<Finding> findings = Check("com-left-at-origin");
  EXPECT_FALSE(Flags(findings, "rear_cover")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "imu_frame")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "ballast")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "chassis")) << Dump(findings);
}

// 'beam': the box 0.4 × 0.1 × 0.1 m turned by rpy (0, 0, 1.5708) lies along y; from the y axis
// through the COM (0, 0, 0) its corners (x, y, z) = (a cos θ − b sin θ, a sin θ + b cos θ, ±0.05),
// a = ±0.2, b = ±0.05, are at most x² + z² = 0.005 m² away (θ = 1.5708 is not quite π/2: the
// corners are computed from it), so a body inside has iyy <= m · 0.005; the unrotated tensor's
// iyy = 0.0141667 is 2.8333 times that.
TEST(WarningsRound3Test, ATensorWrittenBeforeThePartWasTurnedIsReportedAxisByAxis) {
  const std::vector<Finding> findings = Check("tensor-not-rotated");
  const std::vector<Finding> exceeds = Select(findings, "inertia-exceeds-geometry");
  ASSERT_EQ(exceeds.size(), 2u) << Dump(findings);  // 'beam', and 'hub' (below)
  EXPECT_EQ(exceeds[0].link, "beam");
  const double c = std::cos(1.5708), s = std::sin(1.5708);
  double reach2 = 0;  // the farthest corner from the y axis through (0, 0, 0)
  for (const double a : {-0.2, 0.2}) {
    for (const double b : {-0.05, 0.05}) reach2 = std::max(reach2, std::pow(c * a - s * b, 2));
  }
  reach2 += 0.05 * 0.05;
  EXPECT_NEAR(reach2, 0.005, 1e-4);
  EXPECT_NEAR(ValueOf(exceeds[0], "moment"), 0.0141667, 1e-9);
  EXPECT_NEAR(ValueOf(exceeds[0], "axis_bound"), 1.0 * reach2, 1e-12);
  EXPECT_NEAR(ValueOf(exceeds[0], "ratio"), 0.0141667 / reach2, 1e-9);
  EXPECT_NEAR(ValueOf(exceeds[0], "ratio"), 2.8333, 1e-3);
  ExpectReadableHeadlines(exceeds);
}

// The look-alikes: the same box with the tensor rotated with it (each moment 1/3 of its axis
// bound), and a thin ring whose mass is on its rim (0.5 of the bound about z, 0.499 about x).
TEST(WarningsRound3Test, APartThatFitsItsGeometryAsPlacedIsNotReported) {
  const std::vector<Finding> findings = Check("tensor-not-rotated");
  EXPECT_FALSE(Flags(findings, "beam_ok")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "ring")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "base")) << Dump(findings);
}

// 'hub' (1 kg, I = 0.012 kg·m² on every axis, a disc of r 0.05 m and length 0.05 m along z):
// its moments pass (3.84 times the bound about x, its trace 0.036 above the bounds' sum 0.01125:
// a larger body, allowed 4 times), but along z the mass is spread by tr(I)/2 − Izz = 0.006 kg·m²
// where the disc reaches 0.025 m from its middle: 0.006 / (1 · 0.025²) = 9.6 times, beyond 4.
TEST(WarningsRound3Test, AnIsotropicTensorOnADiscLargerThanItsBoundIsReportedByItsSecondMoment) {
  const std::vector<Finding> findings = Check("tensor-not-rotated");
  const std::vector<Finding> exceeds = Select(findings, "inertia-exceeds-geometry");
  const auto hub = std::find_if(exceeds.begin(), exceeds.end(),
                                [](const Finding& f) { return f.link == "hub"; });
  ASSERT_NE(hub, exceeds.end()) << Dump(findings);
  EXPECT_NEAR(ValueOf(*hub, "second_moment"), 0.018 - 0.012, 1e-12);
  EXPECT_NEAR(ValueOf(*hub, "width_bound"), 0.025 * 0.025, 1e-12);
  EXPECT_NEAR(ValueOf(*hub, "ratio"), 9.6, 1e-9);
}

// 'wheel': 1 kg, a cylinder r 0.1 m, width 0.02 m turned to lie along y, I = 0.001 kg·m² on
// every axis. Along y: tr(I)/2 − Iyy = 0.0015 − 0.001 = 0.0005 kg·m²; a body inside the wheel
// has at most m · (0.02 / 2)² = 0.0001 kg·m²: 5 times. Its moments pass the per-axis bound
// (about x: 0.001 / (0.1² + 0.01²) = 0.099).
TEST(WarningsRound3Test, APlaceholderTypedOnAWheelIsReportedAlongItsWidth) {
  const std::vector<Finding> findings = Check("wheel-placeholder");
  const std::vector<Finding> exceeds = Select(findings, "inertia-exceeds-geometry");
  ASSERT_EQ(exceeds.size(), 1u) << Dump(findings);
  EXPECT_EQ(exceeds[0].link, "wheel");
  EXPECT_NEAR(ValueOf(exceeds[0], "second_moment"), 0.0005, 1e-12);
  EXPECT_NEAR(ValueOf(exceeds[0], "width_bound"), 1.0 * 0.01 * 0.01, 1e-12);
  EXPECT_NEAR(ValueOf(exceeds[0], "ratio"), 5, 1e-9);
  EXPECT_NEAR(EvidenceOf(exceeds[0], "second_moment_kg_m2"), 0.0005, 1e-12);
  EXPECT_NEAR(EvidenceOf(exceeds[0], "max_for_its_width_kg_m2"), 0.0001, 1e-12);
  EXPECT_NEAR(EvidenceOf(exceeds[0], "width_m"), 0.02, 1e-12);
  EXPECT_NEAR(std::abs(EvidenceOf(exceeds[0], "axis_y")), 1, 1e-9);
  EXPECT_NE(exceeds[0].headline.find("2 cm width"), std::string::npos) << exceeds[0].headline;
  ExpectReadableHeadlines(exceeds);
}

// The look-alikes: a solid wheel (along y, m w²/12 = 3.3333e-5 kg·m², 1/3 of m (w/2)²), a caster
// ball of r 0.05 m with the same 0.001 kg·m² (0.0005 <= m r² = 0.0025), and the typed-in wheel
// whose collision mesh does not resolve (its geometry is not known whole: not judged), and a
// plate welded to the world with I = 0.1 kg·m² per axis (20 times along its 0.1 m width, but
// static: its inertia never enters the dynamics).
TEST(WarningsRound3Test, ASolidWheelABallCasterOrAWheelOfUnknownGeometryIsNotReported) {
  const std::vector<Finding> findings = Check("wheel-placeholder");
  EXPECT_FALSE(Flags(findings, "wheel_solid")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "wheel_ball")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "wheel_unknown")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "frame_plate")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "base")) << Dump(findings);
}

// 'base_link': k = sqrt(0.48 / 2) = 0.489898 m; the farthest corner of the model from its COM is
// (0.26, 0.06, 0.045), R = sqrt(0.073225) = 0.270601 m; k / R = 1.81041 > 1.5.
TEST(WarningsRound3Test, AnInertiaNoBodyInsideTheWholeModelCanHaveIsReported) {
  const std::vector<Finding> findings = Check("inertia-exceeds-model");
  const std::vector<Finding> model = Select(findings, "inertia-exceeds-model");
  ASSERT_EQ(model.size(), 1u) << Dump(findings);
  EXPECT_EQ(model[0].link, "base_link");
  EXPECT_NEAR(ValueOf(model[0], "radius_of_gyration"), std::sqrt(0.24), 1e-12);
  EXPECT_NEAR(ValueOf(model[0], "model_reach"), std::sqrt(0.073225), 1e-12);
  EXPECT_NEAR(ValueOf(model[0], "ratio"), std::sqrt(0.24) / std::sqrt(0.073225), 1e-9);
  EXPECT_NEAR(EvidenceOf(model[0], "radius_of_gyration_m"), 0.489898, 1e-6);
  // The rules judging the link by itself allowed it.
  EXPECT_TRUE(Select(findings, "units-suspect").empty()) << Dump(findings);
  ExpectReadableHeadlines(model);
}

// The same vehicle with k = sqrt(0.012) = 0.109545 m on its base, 0.405 of R.
TEST(WarningsRound3Test, AnInertiaThatFitsTheWholeModelIsNotReported) {
  const std::vector<Finding> findings = Check("drone-ok");
  EXPECT_TRUE(Select(findings, "inertia-exceeds-model").empty()) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "base_link")) << Dump(findings);
}

// The same vehicle with a rotor mesh that does not resolve: the model's extent is unknown, so the
// base is not judged by it.
TEST(WarningsRound3Test, AModelWithGeometryOfUnknownSizeDoesNotBoundItsLinks) {
  const std::vector<Finding> findings = Check("drone-unknown-mesh");
  EXPECT_TRUE(Select(findings, "inertia-exceeds-model").empty()) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "base_link")) << Dump(findings);
}

// The drone with its base drawn by a 0.4 x 0.4 x 0.1 m plate of its own (before, only
// geometry-less links were judged): k = sqrt(0.48 / 2) = 0.489898 m; the farthest point of the
// model from its COM is a plate corner (0.2, 0.2, 0.05), R = sqrt(0.0825) = 0.287228 m (the motors
// reach 0.2375 m); k / R = 1.70561 > 1.5. The plate's own allowance passes it (the sphere of
// twice its half-diagonal: 0.24 <= 0.33; izz 3 times its axis bound 0.08, within 4).
TEST(WarningsRound3Test, ADrawnDroneBaseBeyondTheWholeVehicleIsReported) {
  const std::vector<Finding> findings = Check("drone-drawn-base");
  const std::vector<Finding> model = Select(findings, "inertia-exceeds-model");
  ASSERT_EQ(model.size(), 1u) << Dump(findings);
  EXPECT_EQ(model[0].link, "base_link");
  EXPECT_NEAR(ValueOf(model[0], "radius_of_gyration"), std::sqrt(0.24), 1e-12);
  EXPECT_NEAR(ValueOf(model[0], "model_reach"), std::sqrt(0.0825), 1e-9);
  EXPECT_NEAR(ValueOf(model[0], "ratio"), std::sqrt(0.24 / 0.0825), 1e-8);
  EXPECT_NEAR(EvidenceOf(model[0], "model_reach_m"), 0.287228, 1e-6);
  // One finding per defect: the plate's own rule did not report it.
  EXPECT_TRUE(Select(findings, "inertia-exceeds-geometry").empty()) << Dump(findings);
  ExpectReadableHeadlines(model);
}

// The same drone with the fourth motor a mesh that does not resolve: the model's extent is
// unknown, the base is not judged by it.
TEST(WarningsRound3Test, ADrawnDroneBaseInAModelOfUnknownExtentIsNotJudgedByIt) {
  const std::vector<Finding> findings = Check("drone-drawn-base-unknown-mesh");
  EXPECT_TRUE(Select(findings, "inertia-exceeds-model").empty()) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "base_link")) << Dump(findings);
}

// A long arm's base, k = sqrt(3 x 1.176 / 20) = 0.42 m: 1.62 times its own box's reach
// (0.259808 m) but 0.275 of the whole model's, R = sqrt(1 + 0.0025 + 1.3225) = 1.52480 m (the
// forearm's far corner): judged against the whole reach, quiet.
TEST(WarningsRound3Test, ALongArmsBaseIsJudgedAgainstTheWholeReach) {
  const std::vector<Finding> findings = Check("long-arm-base-ok");
  EXPECT_TRUE(Select(findings, "inertia-exceeds-model").empty()) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "base")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "upper_arm")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "forearm")) << Dump(findings);
}

// segment: 0.2 kg over a closed 0.02 x 0.02 x 0.035 m box mesh (1.4e-5 m³) is 14285.7 kg/m³,
// beyond 1.1 x lead (12474), and its written inertial is the box's own at 0.2 kg (centroid
// (0.01, 0.01, 0.0175); 0.2 (0.02² + 0.035²) / 12 = 2.70833e-5 about x and y, 0.2 x 0.0008 / 12
// = 1.33333e-5 about z): a uniform solid denser than lead. The look-alikes are quiet:
// servo_bracket (89286 kg/m³, but its tensor is a 4 x 2 x 4 cm servo's, not the 1 x 1 x 1.4 cm
// bracket's: a lumped motor), counterweight (lead, 11340 kg/m³) and motor (copper, 8960 kg/m³),
// both with their boxes' own inertia.
TEST(WarningsRound3Test, APartDenserThanLeadWhoseInertiaIsItsMeshsIsReported) {
  const std::vector<Finding> findings = Check("denser-than-lead");
  const std::vector<Finding> dense = Select(findings, "density-implausible");
  ASSERT_EQ(dense.size(), 1u) << Dump(findings);
  EXPECT_EQ(dense[0].link, "segment");
  EXPECT_NEAR(ValueOf(dense[0], "volume"), 1.4e-5, 1.4e-5 * 1e-6);  // float STL vertices
  EXPECT_NEAR(ValueOf(dense[0], "density"), 0.2 / 1.4e-5, 0.2 / 1.4e-5 * 1e-6);
  // The written moments are the box's to their printed digits (6 significant: 1e-5 relative).
  EXPECT_LT(ValueOf(dense[0], "moment_difference"), 1e-5);
  EXPECT_LT(ValueOf(dense[0], "com_offset"), 1e-7);
  // At steel's 7850 kg/m³ the segment would weigh 7850 x 1.4e-5 = 0.1099 kg.
  EXPECT_NEAR(EvidenceOf(dense[0], "mass_if_steel_kg"), 0.1099, 1e-6);
  EXPECT_NEAR(EvidenceOf(dense[0], "density_kg_m3"), 14285.714, 0.02);
  EXPECT_FALSE(Flags(findings, "servo_bracket")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "counterweight")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "motor")) << Dump(findings);
  ExpectReadableHeadlines(dense);
}

// The same segment under a 70-character name: the headline is a shorter whole sentence within
// 110 characters, the name whole, nothing cut.
TEST(WarningsRound3Test, ADenserThanLeadHeadlineForALongNameIsAShorterSentence) {
  std::ifstream in(kDir + "denser-than-lead.urdf");
  std::stringstream text;
  text << in.rdbuf();
  std::string urdf = text.str();
  const std::string name(70, 's');
  for (std::size_t at = urdf.find("\"segment\""); at != std::string::npos;
       at = urdf.find("\"segment\"", at + 1)) {
    urdf.replace(at + 1, 7, name);
  }
  const std::string mesh = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh/box_ascii.stl";
  for (std::size_t at = urdf.find("../../mesh/box_ascii.stl"); at != std::string::npos;
       at = urdf.find("../../mesh/box_ascii.stl", at + 1)) {
    urdf.replace(at, 24, mesh);
  }
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "massprops_round3_long_name.urdf";
  std::ofstream(file) << urdf;
  const std::vector<Finding> dense = Select(CheckFile(file.string()), "density-implausible");
  std::filesystem::remove(file);
  ASSERT_EQ(dense.size(), 1u);
  EXPECT_EQ(dense[0].link, name);
  EXPECT_EQ(dense[0].headline, "link '" + name + "': denser than lead (14300 kg/m³)");
  ExpectReadableHeadlines(dense);
}

// The legs carry one part's numbers; the right COM is 0.025 m off the left's mirror image,
// allowed max(0.005, 0.02 × 0.308221) = 0.00616441 m (before: 0.0308221 m, 10% of the
// half-diagonal). The arms differ on purpose (2 and 2.03 kg): 10% of the half-diagonal still.
TEST(WarningsRound3Test, MirrorTwinsCarryingTheSameNumbersMustMirrorToTheRounding) {
  const std::vector<Finding> findings = Check("mirror-copy");
  const std::vector<Finding> mirror = Select(findings, "com-not-mirrored");
  ASSERT_EQ(mirror.size(), 1u) << Dump(findings);
  EXPECT_EQ(mirror[0].link, "right_leg");
  EXPECT_NEAR(ValueOf(mirror[0], "com_miss"), 0.025, 1e-12);
  EXPECT_NEAR(ValueOf(mirror[0], "expected_com_x"), 0.0, 1e-12);
  EXPECT_NEAR(ValueOf(mirror[0], "expected_com_y"), -0.3, 1e-12);
  EXPECT_NEAR(ValueOf(mirror[0], "expected_com_z"), -0.6, 1e-12);
  EXPECT_FALSE(Flags(findings, "right_arm")) << Dump(findings);
  EXPECT_FALSE(Flags(findings, "left_arm")) << Dump(findings);
  ExpectReadableHeadlines(mirror);
}

}  // namespace
}  // namespace massprops
