// The units, products-sign and about-origin checks and their repairs judged against mesh
// geometry (CheckOptions::shape, RepairOptions::shape, MakeLinkShapeFunction), and
// `check --geometry` / `fix --geometry` / `fix --from-geometry` on meshes.
//
// Fixtures: testdata/geometry/mesh_defects.urdf (each link's numbers are derived in its comments
// from the box formula m(b²+c²)/12, the parallel-axis theorem and R·diag·Rᵀ) and
// testdata/mesh/robot.urdf. Meshes are read by assimp as 32-bit floats: values derived from them
// carry a relative rounding of about 1e-7, hence the tolerances below.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "tool_runner.h"

namespace massprops {
namespace {

using massprops::test_support::RunTool;
using massprops::test_support::ToolRun;

const std::string kDefects = std::string(MASSPROPS_TESTDATA_DIR) + "/geometry/mesh_defects.urdf";
const std::string kMeshRobot = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh/robot.urdf";

// The rotated box of products_flipped: entry (x, y) = cos30·sin30·(0.075 − 1/60) (fixture).
const double kProductXY = std::cos(M_PI / 6) * std::sin(M_PI / 6) * (0.075 - 1.0 / 60);

Model Read(const std::string& file) {
  const ReadResult read = ReadModelFile(file);
  EXPECT_TRUE(read.errors.empty());
  return read.models.at(0);
}

LinkShapeFunction MeshShapes(const Model& model, MeshCache* cache) {
  MeshResolveOptions resolve;
  resolve.use_environment = false;
  resolve.model_file = model.file;
  resolve.cache = cache;
  return MakeLinkShapeFunction(resolve);
}

std::vector<std::string> RulesOf(const std::vector<Finding>& findings, const std::string& link) {
  std::vector<std::string> rules;
  for (const Finding& f : findings) {
    if (f.link == link) rules.push_back(f.rule);
  }
  std::sort(rules.begin(), rules.end());
  return rules;
}

double ValueOf(const Finding& finding, const std::string& name) {
  for (const auto& [key, value] : finding.values) {
    if (key == name) return value;
  }
  ADD_FAILURE() << "no value " << name << " in " << finding.rule;
  return NAN;
}

const Finding* Find(const std::vector<Finding>& findings, const std::string& rule,
                    const std::string& link) {
  for (const Finding& f : findings) {
    if (f.rule == rule && f.link == link) return &f;
  }
  return nullptr;
}

TEST(MeshAwareChecksTest, WithoutAShapeFunctionMeshOnlyLinksRaiseNothing) {
  // Every link's geometry is a mesh, and nothing in its numbers alone is wrong enough for a
  // warning. They say one thing as a note (issue 49): 'grams', 2000 kg with tr(I) = 0.0467
  // kg·m², is more compact than an osmium ball of 2000 kg, (6/5) · 2000 · r² with r = (3 · 2000 /
  // (4π · 22590))^(1/3) = 0.276 m: 183 kg·m².
  const std::vector<Finding> findings = CheckModel(Read(kDefects));
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].rule, "inertia-too-compact");
  EXPECT_EQ(findings[0].link, "grams");
  EXPECT_EQ(findings[0].severity, Severity::kNote);
  const double r = std::cbrt(3 * 2000 / (4 * M_PI * 22590));
  EXPECT_NEAR(ValueOf(findings[0], "least_trace"), 1.2 * 2000 * r * r, 1e-9);
}

TEST(MeshAwareChecksTest, MeshShapesRevealGramsInertiaAboutOriginAndFlippedProducts) {
  const Model model = Read(kDefects);
  MeshCache cache;
  CheckOptions options;
  options.shape = MeshShapes(model, &cache);
  const std::vector<Finding> findings = CheckModel(model, options);
  EXPECT_EQ(RulesOf(findings, "grams"), std::vector<std::string>{"units-suspect"});
  EXPECT_EQ(RulesOf(findings, "about_origin"),
            std::vector<std::string>{"inertia-about-origin-suspect"});
  EXPECT_EQ(RulesOf(findings, "products_flipped"),
            std::vector<std::string>{"products-sign-suspect"});
  EXPECT_TRUE(RulesOf(findings, "products_right").empty());
  EXPECT_EQ(RulesOf(findings, "mesh_in_mm"), std::vector<std::string>{"units-suspect"});
  // One ascii STL for five links, read twice: directly for the integrals, and by assimp for its
  // hull points (the vertex count of assimp's join needs the facets' normals; a binary STL gives
  // both from one read: mesh_cache_test).
  EXPECT_EQ(cache.files_loaded(), 2);

  // mesh_in_mm: k = sqrt((0.28/6)/4) against the half-diagonal 1000·sqrt(0.14)/2 of the box
  // scaled by 1000; the message names the missing mesh scale.
  const Finding* mm = Find(findings, "units-suspect", "mesh_in_mm");
  ASSERT_NE(mm, nullptr);
  EXPECT_NEAR(ValueOf(*mm, "ratio"), std::sqrt(0.28 / 6 / 4) / (500 * std::sqrt(0.14)), 1e-9);
  EXPECT_NE(mm->message.find("lacks scale=\"0.001 0.001 0.001\""), std::string::npos)
      << mm->message;

  // grams: k = sqrt(tr(I)/(2m)) = sqrt((0.28/6)/4000); half-diagonal of the 0.1 x 0.2 x 0.3 box
  // = sqrt(0.14)/2.
  const Finding* units = Find(findings, "units-suspect", "grams");
  ASSERT_NE(units, nullptr);
  EXPECT_NEAR(ValueOf(*units, "radius_of_gyration"), std::sqrt(0.28 / 6 / 4000), 1e-12);
  EXPECT_NEAR(ValueOf(*units, "geometry_half_diagonal"), std::sqrt(0.14) / 2, 1e-7);
  EXPECT_NE(units->message.find("grams"), std::string::npos) << units->message;
  EXPECT_NE(units->message.find("collision mesh"), std::string::npos) << units->message;

  // about_origin: shifted to the center of mass the moments are the box's 0.05/6, 0.1/6, 0.13/6.
  const Finding* origin = Find(findings, "inertia-about-origin-suspect", "about_origin");
  ASSERT_NE(origin, nullptr);
  EXPECT_NEAR(ValueOf(*origin, "shifted_principal_min"), 0.05 / 6, 1e-12);
  EXPECT_NEAR(ValueOf(*origin, "shifted_principal_max"), 0.13 / 6, 1e-12);

  const Finding* sign = Find(findings, "products-sign-suspect", "products_flipped");
  ASSERT_NE(sign, nullptr);
  EXPECT_NEAR(ValueOf(*sign, "geometry_ixy"), kProductXY, 1e-7 * kProductXY);
  EXPECT_NEAR(ValueOf(*sign, "geometry_ixz"), 0, 1e-9);
  EXPECT_NEAR(ValueOf(*sign, "mismatch_negated"), 0, 1e-6);
  EXPECT_NEAR(ValueOf(*sign, "mismatch_as_written"), 2, 1e-6);
  EXPECT_NEAR(ValueOf(*sign, "cosine"), -1, 1e-9);
}

TEST(MeshAwareChecksTest, ShapeFunctionGivesTheScaledPosedMeshBox) {
  // scaled_box: the 0.1 x 0.2 x 0.3 box (corner at its origin) scaled by 3 along x, turned 90°
  // about z ((x, y) -> (-y, x)) and moved by (1, 0, 0): x in [0.8, 1], y in [0, 0.3], z in
  // [0, 0.3]. Along B it is 0.2 x 0.3 x 0.3, so per unit mass G = ((0.09+0.09)/12,
  // (0.04+0.09)/12, (0.04+0.09)/12), volume 0.018 m³.
  const Model model = Read(kMeshRobot);
  MeshCache cache;
  const LinkShapeFunction shapes = MeshShapes(model, &cache);
  const std::optional<LinkShape> shape = shapes(model.links.at(model.FindLink("scaled_box")));
  ASSERT_TRUE(shape.has_value());
  EXPECT_EQ(shape->kind, "mesh");
  EXPECT_TRUE(shape->from_collision);
  EXPECT_NEAR(shape->volume, 0.018, 1e-8);
  EXPECT_TRUE(shape->box_B.min().isApprox(Eigen::Vector3d(0.8, 0, 0), 1e-6))
      << shape->box_B.min().transpose();
  EXPECT_TRUE(shape->box_B.max().isApprox(Eigen::Vector3d(1, 0.3, 0.3), 1e-6))
      << shape->box_B.max().transpose();
  EXPECT_TRUE(shape->p_BoBcm_B.isApprox(Eigen::Vector3d(0.9, 0.15, 0.15), 1e-6));
  const Eigen::Vector3d expected(0.18 / 12, 0.13 / 12, 0.13 / 12);
  EXPECT_TRUE(shape->G_BBcm_B.diagonal().isApprox(expected, 1e-6));
  EXPECT_LT(shape->G_BBcm_B(0, 1), 1e-9);
  // A link without geometry has no shape; a link with primitives only is a "primitive" shape.
  EXPECT_FALSE(shapes(model.links.at(model.FindLink("no_geometry"))).has_value());
  const std::optional<LinkShape> primitive =
      shapes(model.links.at(model.FindLink("box_and_sphere")));
  ASSERT_TRUE(primitive.has_value());
  EXPECT_EQ(primitive->kind, "primitive");
  // Box [-0.1, 0.1]³ and sphere of radius 0.1 at z = 0.5 (fixture).
  EXPECT_TRUE(primitive->box_B.max().isApprox(Eigen::Vector3d(0.1, 0.1, 0.6), 1e-15));
  EXPECT_TRUE(primitive->box_B.min().isApprox(Eigen::Vector3d(-0.1, -0.1, -0.1), 1e-15));
}

TEST(MeshAwareChecksTest, ProductsSignEvidenceNeedsSizableProductsAndMatchingMoments) {
  // A synthetic shape: the rotated box of the fixture, per unit mass.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double dx = 0.075 / 2, dy = 1.0 / 120, dz = 0.37 / 12;  // per kg
  LinkShape shape;
  shape.volume = 0.018;
  shape.box_B =
      Eigen::AlignedBox3d(Eigen::Vector3d(-0.3, -0.3, -0.15), Eigen::Vector3d(0.3, 0.3, 0.15));
  shape.G_BBcm_B << c * c * dx + s * s * dy, c * s * (dx - dy), 0, c * s * (dx - dy),
      s * s * dx + c * c * dy, 0, 0, 0, dz;
  Inertial in;
  in.mass = 2;
  in.ixx = 2 * shape.G_BBcm_B(0, 0);
  in.iyy = 2 * shape.G_BBcm_B(1, 1);
  in.izz = 2 * shape.G_BBcm_B(2, 2);
  in.ixy = -2 * shape.G_BBcm_B(0, 1);
  const std::optional<ProductsSignEvidence> flipped = FindProductsSignEvidence(in, shape);
  ASSERT_TRUE(flipped.has_value());
  EXPECT_NEAR(flipped->mismatch_as_written, 2, 1e-12);
  EXPECT_NEAR(flipped->mismatch_negated, 0, 1e-12);
  // Right sign: no evidence.
  Inertial right = in;
  right.ixy = -in.ixy;
  EXPECT_FALSE(FindProductsSignEvidence(right, shape).has_value());
  // Written products under 10% of the mean moment say nothing.
  Inertial small = in;
  small.ixy = -0.09 * (in.ixx + in.iyy + in.izz) / 3;
  EXPECT_FALSE(FindProductsSignEvidence(small, shape).has_value());
  // A moment 2.5 times the geometry's: the geometry does not describe this body.
  Inertial other = in;
  other.izz *= 2.5;
  EXPECT_FALSE(FindProductsSignEvidence(other, shape).has_value());
  // Opposite direction, but 0.45 or 2.1 times the geometry's size: the sizes do not match.
  Inertial small_opposite = in;
  small_opposite.ixy = 0.45 * in.ixy;
  EXPECT_FALSE(FindProductsSignEvidence(small_opposite, shape).has_value());
  Inertial large_opposite = in;
  large_opposite.ixy = 2.1 * in.ixy;
  EXPECT_FALSE(FindProductsSignEvidence(large_opposite, shape).has_value());
  // 1.5 times the size, opposite direction (as finger_edu's middle link in the corpus): evidence.
  Inertial larger = in;
  larger.ixy = 1.5 * in.ixy;
  const std::optional<ProductsSignEvidence> larger_evidence =
      FindProductsSignEvidence(larger, shape);
  ASSERT_TRUE(larger_evidence.has_value());
  EXPECT_NEAR(larger_evidence->cosine, -1, 1e-12);
  EXPECT_NEAR(larger_evidence->mismatch_negated, 0.5, 1e-12);  // |1.5 p − p| / |p|
  // A second product as large as the first, of the geometry's sign: the direction is 45° off
  // the opposite (cosine −1/√2 > −0.9).
  Inertial skew = in;
  skew.iyz = -in.ixy;
  EXPECT_FALSE(FindProductsSignEvidence(skew, shape).has_value());
  // The inertial frame turned 90° about z: the geometry is compared in that frame, where its
  // product (x, y) changes sign; the written numbers (in Bi) that were flipped are now right.
  Inertial turned = in;
  turned.X_BBi.R_AB = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  turned.ixx = in.iyy;
  turned.iyy = in.ixx;
  EXPECT_FALSE(FindProductsSignEvidence(turned, shape).has_value());
  turned.ixy = -turned.ixy;
  EXPECT_TRUE(FindProductsSignEvidence(turned, shape).has_value());
}

TEST(MeshAwareChecksTest, RepairsUseTheMeshes) {
  const Model model = Read(kDefects);
  MeshCache cache;
  CheckOptions check;
  check.shape = MeshShapes(model, &cache);
  RepairOptions options;
  options.shape = check.shape;
  options.apply = {"all"};  // the three repairs are heuristics: asked for by name
  const std::vector<Repair> repairs = PlanRepairs(model, CheckModel(model, check), options);
  // mesh_in_mm gets none: against a mesh, "inertia 1e6 too small" is not chosen on its own.
  ASSERT_EQ(repairs.size(), 3u);
  for (const Repair& r : repairs) {
    EXPECT_EQ(r.resolves, std::vector<std::string>{r.rule}) << r.link;
    if (r.link == "grams") {
      EXPECT_EQ(r.method, "rescale-units");
      EXPECT_EQ(r.after.mass, 2);  // 2000 g
    } else if (r.link == "about_origin") {
      EXPECT_EQ(r.method, "shift-to-com");
      // Box formula (fixture), written with the fewest digits (>= 6) that pass the checks.
      EXPECT_NEAR(r.after.iyy, 0.1 / 6, 5e-6 * 0.1 / 6);
      EXPECT_NEAR(r.after.izz, 0.05 / 6, 5e-6 * 0.05 / 6);
    } else {
      EXPECT_EQ(r.link, "products_flipped");
      EXPECT_EQ(r.method, "negate-products");
      EXPECT_EQ(r.after.ixy, 0.025259074277046125);  // exactly the written number, negated
    }
  }
  // Without the shape function nothing is planned: the checks found nothing.
  EXPECT_TRUE(PlanRepairs(model, CheckModel(model), RepairOptions{}).empty());
}

TEST(MeshAwareChecksTest, FromGeometryUsesAMeshWithTheLinksMass) {
  // scaled_box (mass 2): the box inertia m·G of ShapeFunctionGivesTheScaledPosedMeshBox, at its
  // centroid (0.9, 0.15, 0.15).
  const Model model = Read(kMeshRobot);
  MeshCache cache;
  RepairOptions options;
  options.from_geometry_links = {"scaled_box"};
  const std::vector<Repair> without = PlanRepairs(model, {}, options);
  EXPECT_TRUE(without.empty());  // a mesh, and no shape function: nothing to compute from
  options.shape = MeshShapes(model, &cache);
  const std::vector<Repair> repairs = PlanRepairs(model, {}, options);
  ASSERT_EQ(repairs.size(), 1u);
  const Repair& r = repairs[0];
  EXPECT_EQ(r.method, "from-geometry");
  EXPECT_EQ(r.after.mass, 2);
  EXPECT_NEAR(r.after.ixx, 2 * 0.18 / 12, 1e-7);
  EXPECT_NEAR(r.after.iyy, 2 * 0.13 / 12, 1e-7);
  EXPECT_NEAR(r.after.izz, 2 * 0.13 / 12, 1e-7);
  // The true products are 0; the float vertices' ~1e-19 is written as an unchanged 0.
  EXPECT_EQ(r.after.ixy, 0);
  EXPECT_EQ(r.after.ixz, 0);
  EXPECT_EQ(r.after.iyz, 0);
  EXPECT_TRUE(r.after.X_BBi.p_AB.isApprox(Eigen::Vector3d(0.9, 0.15, 0.15), 1e-6));
  EXPECT_NE(r.why.find("collision mesh"), std::string::npos) << r.why;
}

TEST(MeshAwareChecksTest, CheckCommandJudgesMeshProductsOnlyWithGeometry) {
  // Without --geometry only the meshes' bounding boxes are read: the sign of the products needs
  // the solid's inertia, so products_flipped is not flagged (the size rules are: see
  // mesh_bounds_cli_test.cc); --no-geometry reads no mesh at all.
  const ToolRun boxes = RunTool("check '" + kDefects + "'", true);
  EXPECT_EQ(boxes.exit_code, 0);
  EXPECT_EQ(boxes.output.find("[products-sign-suspect]"), std::string::npos) << boxes.output;
  const ToolRun without = RunTool("check --no-geometry '" + kDefects + "'", true);
  EXPECT_EQ(without.exit_code, 0);
  EXPECT_NE(without.output.find("0 warnings"), std::string::npos) << without.output;
  const ToolRun with = RunTool("check --geometry --fail-on warning '" + kDefects + "'", true);
  EXPECT_EQ(with.exit_code, 1) << with.output;
  // Each finding points at the link's <inertia> line (mesh_defects.urdf lines 13, 28, 44).
  EXPECT_NE(with.output.find("mesh_defects.urdf:13: warning: link 'grams'"), std::string::npos)
      << with.output;
  EXPECT_NE(with.output.find("[units-suspect]"), std::string::npos);
  EXPECT_NE(with.output.find("mesh_defects.urdf:28: warning: link 'about_origin'"),
            std::string::npos);
  EXPECT_NE(with.output.find("[inertia-about-origin-suspect]"), std::string::npos);
  EXPECT_NE(with.output.find("mesh_defects.urdf:44: warning: link 'products_flipped'"),
            std::string::npos);
  EXPECT_NE(with.output.find("[products-sign-suspect]"), std::string::npos);
  EXPECT_EQ(with.output.find("link 'products_right'"), std::string::npos);
}

TEST(MeshAwareChecksTest, FixWithGeometryRepairsTheMeshFindingsAndTheResultChecksClean) {
  // The fixed file goes to a scratch folder laid out like testdata (geometry/ beside mesh/) so
  // that its relative mesh path still resolves.
  namespace fs = std::filesystem;
  std::string pattern = (fs::temp_directory_path() / "massprops-meshfix-XXXXXX").string();
  ASSERT_NE(mkdtemp(pattern.data()), nullptr);
  const fs::path scratch = pattern;
  fs::create_directories(scratch / "geometry");
  fs::create_directories(scratch / "mesh");
  fs::copy_file(fs::path(MASSPROPS_TESTDATA_DIR) / "mesh" / "box_ascii.stl",
                scratch / "mesh" / "box_ascii.stl");
  const std::string fixed = (scratch / "geometry" / "fixed.urdf").string();
  const ToolRun fix =
      RunTool("fix --apply all --geometry '" + kDefects + "' -o '" + fixed + "'", true);
  EXPECT_EQ(fix.exit_code, 0) << fix.output;
  EXPECT_NE(fix.output.find("3 link(s) repaired"), std::string::npos) << fix.output;
  const ToolRun check =
      RunTool("check --geometry --disable inertia-disagrees-with-geometry --fail-on warning '" +
                  fixed + "'",
              true);
  // Only mesh_in_mm's warning is left: its inertia was right and is untouched (its density,
  // 3.3e-7 kg/m³ over the mesh read in metres, is the same defect: units-suspect says it once).
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find("1 warning"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("link 'mesh_in_mm'"), std::string::npos) << check.output;
  // Without --geometry, fix finds nothing to repair in the same file.
  const ToolRun plain = RunTool("fix --dry-run '" + kDefects + "'", true);
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_NE(plain.output.find("no change needed"), std::string::npos) << plain.output;
  std::error_code ec;
  fs::remove_all(scratch, ec);
}

TEST(MeshAwareChecksTest, FixFromGeometryWithoutALinkNameReplacesEveryLinkWithGeometry) {
  // `--from-geometry` with no value, before another option or after FILE: all links. In
  // robot.urdf, scaled_box and box_and_sphere have an inertial and usable geometry. scaled_box is
  // a finding of check too (issue 43: its center of mass is left at its origin, 0.8 m from its
  // mesh, while its welded neighbours carry their own mass), so its repair names that finding.
  for (const std::string& args : {"fix --from-geometry --dry-run '" + kMeshRobot + "'",
                                  "fix --dry-run '" + kMeshRobot + "' --from-geometry"}) {
    const ToolRun run = RunTool(args, true);
    EXPECT_EQ(run.exit_code, 0) << args << "\n" << run.output;
    EXPECT_NE(run.output.find("link 'scaled_box' [com-outside-geometry → from-geometry]"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("link 'box_and_sphere' [--from-geometry"), std::string::npos)
        << run.output;
  }
}

TEST(MeshAwareChecksTest, FixFromGeometrySaysWhyANamedLinkIsLeftAlone) {
  // visual_only's mesh is package://mesh/cube_quads.obj: without --package-path it is found all
  // the same, in the ancestor folder named `mesh` (testdata/mesh; docs/meshes.md, issue 29). A
  // link whose mesh is found nowhere is left as it is, and the reason said: broken_collision's
  // package://mesh/missing.stl (its visual cylinder stands in for it).
  const ToolRun run =
      RunTool("fix --dry-run '" + kMeshRobot + "' --from-geometry=visual_only", true);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("link 'visual_only' [--from-geometry"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("mass 8000"), std::string::npos) << run.output;
  // With the package path it is replaced: a cube of side 2 of water, 8 m³ → 8000 kg.
  const ToolRun found =
      RunTool("fix --dry-run '" + kMeshRobot + "' --package-path '" +
                  std::string(MASSPROPS_TESTDATA_DIR) + "' --from-geometry=visual_only",
              true);
  EXPECT_EQ(found.exit_code, 0) << found.output;
  EXPECT_NE(found.output.find("link 'visual_only' [--from-geometry → from-geometry-density]: new "
                              "<inertial>\n  mass 8000"),
            std::string::npos)
      << found.output;
}

TEST(MeshAwareChecksTest, FixFromGeometryReadsTheMesh) {
  const ToolRun run = RunTool("fix '" + kMeshRobot + "' --from-geometry=scaled_box", true);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const std::size_t link = run.output.find("<link name=\"scaled_box\">");
  ASSERT_NE(link, std::string::npos) << run.output;
  auto number = [&](const std::string& attribute) {
    const std::size_t at = run.output.find(attribute + "=\"", link);
    EXPECT_NE(at, std::string::npos) << attribute;
    return at == std::string::npos
               ? NAN
               : std::strtod(run.output.c_str() + at + attribute.size() + 2, nullptr);
  };
  // m·G for m = 2 (ShapeFunctionGivesTheScaledPosedMeshBox).
  EXPECT_NEAR(number("ixx"), 2 * 0.18 / 12, 1e-7);
  EXPECT_NEAR(number("iyy"), 2 * 0.13 / 12, 1e-7);
  EXPECT_NEAR(number("izz"), 2 * 0.13 / 12, 1e-7);
}

}  // namespace
}  // namespace massprops
