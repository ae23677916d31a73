// The corpus robots that ship their meshes (../shared/corpus/README.md: finger_edu.urdf with 7
// STL, solo.urdf with 6 OBJ, double_pendulum*.urdf with 3 STL, all from Gepetto/
// example-robot-data): every mesh loads, its topology is what is asserted below, and the inertia
// each link's geometry implies for its declared mass is compared with the declared inertia.
// The table this prints (DeclaredVersusMeshInertiaTable) is the one in docs/meshes.md.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "shared_data.h"

namespace massprops {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::string kRobots = std::string(MASSPROPS_CORPUS_DIR) + "/example-robot-data/robots/";

// Every test reads the corpus: skipped without ../shared (tests/shared_data.h).
class CorpusMeshTest : public ::testing::Test {
 protected:
  void SetUp() override { MASSPROPS_SKIP_WITHOUT_SHARED("corpus"); }
};

// What each corpus mesh is, as found by this library (and checked independently where
// possible: a binary STL holds (file size − 84)/50 triangles, by the format's definition).
struct MeshFact {
  const char* path;  // Under kRobots.
  bool binary_stl;
  std::int64_t boundary_edges;  // 0: a closed manifold.
};
const std::vector<MeshFact> kMeshFacts = {
    {"finger_edu_description/meshes/base_back.stl", true, 0},
    {"finger_edu_description/meshes/base_front.stl", true, 46},
    {"finger_edu_description/meshes/base_side_left.stl", true, 12},
    {"finger_edu_description/meshes/base_top.stl", true, 0},
    {"finger_edu_description/meshes/lower_link.stl", true, 0},
    {"finger_edu_description/meshes/middle_link.stl", true, 24},
    {"finger_edu_description/meshes/upper_link.stl", true, 0},
    {"solo_description/meshes/obj/with_foot/solo_body.obj", false, 0},
    {"solo_description/meshes/obj/with_foot/solo_foot.obj", false, 0},
    {"solo_description/meshes/obj/with_foot/solo_lower_leg_left_side.obj", false, 0},
    {"solo_description/meshes/obj/with_foot/solo_lower_leg_right_side.obj", false, 0},
    {"solo_description/meshes/obj/with_foot/solo_upper_leg_left_side.obj", false, 0},
    {"solo_description/meshes/obj/with_foot/solo_upper_leg_right_side.obj", false, 0},
    {"double_pendulum_description/meshes/base_link.stl", true, 172},
    {"double_pendulum_description/meshes/link1.stl", true, 108},
    {"double_pendulum_description/meshes/link2.stl", true, 16},
};

TEST_F(CorpusMeshTest, EveryShippedMeshLoadsAndEnclosesItsVolume) {
  for (const MeshFact& fact : kMeshFacts) {
    const std::string path = kRobots + fact.path;
    TriangleMesh mesh;
    std::string error;
    ASSERT_TRUE(LoadMeshFile(path, &mesh, &error)) << error;
    const MeshMassProperties p = CalcMeshMassProperties(mesh);
    const MeshDiagnostics& d = p.diagnostics;
    if (fact.binary_stl) {
      const auto size = static_cast<std::int64_t>(std::filesystem::file_size(path));
      EXPECT_EQ(d.num_triangles, (size - 84) / 50) << fact.path;
      // STL repeats each vertex in every triangle: every triangle brings 3 vertices.
      EXPECT_GT(d.duplicate_vertices_merged, 0) << fact.path;
    } else {
      EXPECT_EQ(d.duplicate_vertices_merged, 0) << fact.path;  // OBJ shares its vertices.
    }
    EXPECT_EQ(d.boundary_edges, fact.boundary_edges) << fact.path;
    EXPECT_EQ(d.non_manifold_edges, 0) << fact.path;
    EXPECT_EQ(d.inconsistent_edges, 0) << fact.path;
    EXPECT_EQ(d.degenerate_triangles, 0) << fact.path;
    EXPECT_FALSE(d.winding_inverted) << fact.path;
    // Fact found: the SolidWorks/CAD exports with boundary edges are not open: their boundary
    // edges are T-junctions (a vertex of one triangle lying on another's edge), and the
    // divergence-theorem integral does not depend on the reference point to round-off, so they
    // are integrated as the closed solids they are (their convex hulls would overstate the
    // double pendulum's link volumes 2.9x and 1.5x).
    EXPECT_EQ(d.model, MeshSolidModel::kClosedSolid) << fact.path;
    EXPECT_LT(d.reference_point_sensitivity, 1e-12) << fact.path;
    EXPECT_GT(p.volume, 0) << fact.path;
  }
}

// A link's declared inertia (in the link frame) beside the one its geometry implies.
struct Comparison {
  std::string link;
  double mass = 0;
  double volume = 0;
  Eigen::Vector3d declared_moments, mesh_moments;  // Ascending.
  double max_relative_moment_difference = 0;       // max |declared − mesh| / mesh.
  double max_axis_angle_degrees = 0;               // Over the three principal axes.
  double com_distance = 0;                         // |declared com − mesh com|.
  bool from_collision = true;
};

std::vector<Comparison> Compare(const std::string& urdf, MeshCache* cache) {
  const ReadResult read = ReadModelFile(kRobots + urdf);
  EXPECT_TRUE(read.ok() && read.models.size() == 1) << urdf;
  if (read.models.empty()) return {};
  MeshResolveOptions options;
  options.use_environment = false;
  options.package_paths = {
      MASSPROPS_CORPUS_DIR};  // package://example-robot-data/... (corpus README)
  options.model_file = kRobots + urdf;
  options.cache = cache;
  std::vector<Comparison> rows;
  for (const Link& link : read.models[0].links) {
    if (!link.inertial || link.geometries.empty()) continue;
    const Inertial& in = *link.inertial;
    std::string error;
    const auto g = CalcLinkGeometryInertia(link, in.mass, options, &error);
    EXPECT_TRUE(g) << urdf << ": " << error;
    if (!g) continue;
    Comparison row;
    row.link = link.name;
    row.mass = in.mass;
    row.volume = g->volume;
    row.from_collision = g->from_collision;
    const RotationalInertia<double> declared =
        RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(in.ixx, in.iyy, in.izz,
                                                                       in.ixy, in.ixz, in.iyz, true)
            .ReExpress(in.X_BBi.R_AB);
    const auto [lambda_d, axes_d] = declared.CalcPrincipalMomentsAndAxesOfInertia();
    const auto [lambda_m, axes_m] = g->I_BBcm_B.CalcPrincipalMomentsAndAxesOfInertia();
    row.declared_moments = lambda_d;
    row.mesh_moments = lambda_m;
    for (int i = 0; i < 3; ++i) {
      row.max_relative_moment_difference = std::max(
          row.max_relative_moment_difference, std::abs(lambda_d(i) - lambda_m(i)) / lambda_m(i));
      const double cosine = std::min(1.0, std::abs(axes_d.col(i).dot(axes_m.col(i))));
      row.max_axis_angle_degrees =
          std::max(row.max_axis_angle_degrees, std::acos(cosine) * 180 / kPi);
    }
    row.com_distance = (in.X_BBi.p_AB - g->p_BoBcm_B).norm();
    rows.push_back(row);
  }
  return rows;
}

const Comparison& Row(const std::vector<Comparison>& rows, const std::string& link) {
  for (const auto& row : rows) {
    if (row.link == link) return row;
  }
  static const Comparison none;
  ADD_FAILURE() << "no row for " << link;
  return none;
}

TEST_F(CorpusMeshTest, DoublePendulumLinksMatchTheirMeshesAsSteel) {
  // double_pendulum.urdf is a SolidWorks export: its link1 and link2 inertias were computed by
  // CAD from the solids. Their meshes give the same principal moments within 1.5%, the same
  // center within 0.1 mm, and an implied density mass/volume of about 7990 kg/m³: steel
  // (7850-8050 kg/m³, handbook values).
  for (const char* urdf : {"double_pendulum_description/urdf/double_pendulum.urdf",
                           "double_pendulum_description/urdf/double_pendulum_continuous.urdf"}) {
    MeshCache cache;
    const std::vector<Comparison> rows = Compare(urdf, &cache);
    EXPECT_EQ(cache.files_loaded(), 3);
    for (const char* link : {"link1", "link2"}) {
      const Comparison& row = Row(rows, link);
      EXPECT_LT(row.max_relative_moment_difference, 0.015) << link;
      EXPECT_LT(row.com_distance, 1e-4) << link;
      const double density = row.mass / row.volume;
      EXPECT_GT(density, 7850) << link;
      EXPECT_LT(density, 8050) << link;
    }
    // The base is not: its implied density is about 2000 kg/m³ and the mesh's moments are 1.4 to
    // 2.6x the declared ones (its declared mass and inertia do not describe the shipped mesh).
    const Comparison& base = Row(rows, "base_link");
    EXPECT_GT(base.max_relative_moment_difference, 0.5);
    EXPECT_LT(base.mass / base.volume, 2500);
  }
}

TEST_F(CorpusMeshTest, FingerBaseDeclaresAPlaceholderBox) {
  // finger_edu.urdf's finger_base_link declares m = 1 and moments 0.0108333, 0.0566667,
  // 0.0608333 with its center 0.4 m up. Hand-derived: a box a × b × c of mass 1 has
  // (b² + c²)/12, (a² + c²)/12, (a² + b²)/12, so a² + b² = 0.13, a² + c² = 0.68,
  // b² + c² = 0.73 → a = 0.2, b = 0.3, c = 0.8 m: a placeholder box 0.8 m tall (the frame's
  // bounding box) centered at 0.4 m — while its 4 meshes are about 0.2 m parts. The declared
  // moments are 8-12x the geometry's and the centers are 0.35 m apart.
  MeshCache cache;
  const std::vector<Comparison> rows =
      Compare("finger_edu_description/robots/finger_edu.urdf", &cache);
  EXPECT_EQ(cache.files_loaded(), 7);  // base_* and the three links, each loaded once.
  const Comparison& base = Row(rows, "finger_base_link");
  EXPECT_NEAR(base.declared_moments(0), (0.3 * 0.3 + 0.2 * 0.2) / 12, 1e-9);
  for (int i = 0; i < 3; ++i) EXPECT_GT(base.declared_moments(i) / base.mesh_moments(i), 7) << i;
  EXPECT_GT(base.com_distance, 0.3);
  // finger_lower_link declares izz = 0 with ixx = iyy = 0.00012: a thin rod (hand-derived:
  // m·L²/12 = 0.00012 with m = 0.0307 gives L = 0.217 m). Its mesh has a smallest moment of
  // about 1.4e-6, the two others 14% below the declared ones, and its center 19 mm away.
  const Comparison& lower = Row(rows, "finger_lower_link");
  EXPECT_EQ(lower.declared_moments(0), 0.0);
  EXPECT_GT(lower.mesh_moments(0), 1e-6);
  EXPECT_NEAR(lower.com_distance, 0.019, 0.002);
  // The upper and middle links: the same part in two orientations; their declared moments
  // (rounded to 1e-5 kg·m²) are within 7% of the meshes'.
  EXPECT_LT(Row(rows, "finger_upper_link").max_relative_moment_difference, 0.07);
  EXPECT_LT(Row(rows, "finger_middle_link").max_relative_moment_difference, 0.07);
}

TEST_F(CorpusMeshTest, SoloLegsShareMeshesLoadedOnce) {
  // solo.urdf: 13 links with geometry reference 6 OBJ files; the 4 legs are the same parts.
  // Its upper legs and feet agree with their meshes within 3% and 10% (the feet are nearly
  // axially symmetric: the mesh's two smaller moments are equal to 1e-5 relative); its lower
  // legs' declared moments are 48% above the mesh's and the center 17 mm further out, like
  // finger_lower_link's (the same design): the declared values are not those of the shipped
  // lower-leg mesh.
  MeshCache cache;
  const std::vector<Comparison> rows = Compare("solo_description/robots/solo.urdf", &cache);
  EXPECT_EQ(cache.files_loaded(), 6);
  EXPECT_EQ(rows.size(), 13u);
  for (const char* leg : {"FL", "FR", "HL", "HR"}) {
    const std::string name(leg);
    EXPECT_LT(Row(rows, name + "_UPPER_LEG").max_relative_moment_difference, 0.05) << leg;
    EXPECT_LT(Row(rows, name + "_FOOT").max_relative_moment_difference, 0.2) << leg;
    const Comparison& lower = Row(rows, name + "_LOWER_LEG");
    EXPECT_GT(lower.max_relative_moment_difference, 0.4) << leg;
    EXPECT_NEAR(lower.com_distance, 0.017, 0.002) << leg;
  }
}

// `check --geometry` on the three robots (CheckModel with the mesh shape function): the checks
// that judge mesh-only links against their meshes. The expected findings were read off the
// files and the meshes (docs/meshes.md, "What it reveals"): finger_middle_link declares iyz = +5e-5
// where its mesh gives −3.3e-5, while solo's upper legs (the same part, same mesh moments) declare
// +4.671e-5 against their meshes' +3.3e-5; finger_base_link's placeholder inertial is centered
// 0.4 m above meshes no taller than 0.1 m.
std::vector<Finding> CheckWithMeshes(const std::string& relative, MeshCache* cache) {
  const std::string file = kRobots + relative;
  const ReadResult read = ReadModelFile(file);
  EXPECT_TRUE(read.errors.empty()) << file;
  MeshResolveOptions resolve;
  resolve.use_environment = false;
  resolve.package_paths = {MASSPROPS_CORPUS_DIR};
  resolve.model_file = file;
  resolve.cache = cache;
  CheckOptions options;
  options.shape = MakeLinkShapeFunction(resolve);
  return CheckModel(read.models.at(0), options);
}

TEST_F(CorpusMeshTest, MeshAwareChecksFindTheFingersFlippedProductAndPlaceholderBase) {
  MeshCache cache;
  std::vector<std::pair<std::string, std::string>> found;  // (link, rule)
  for (const Finding& f :
       CheckWithMeshes("finger_edu_description/robots/finger_edu.urdf", &cache)) {
    found.emplace_back(f.link, f.rule);
  }
  std::sort(found.begin(), found.end());
  // base_link, the placeholder base: 0.7 kg with tr(I) = 2.37e-4 kg·m², below an osmium ball of
  // 0.7 kg (r = (3 · 0.7 / (4π · 22590))^(1/3) = 0.0195 m, (6/5) · 0.7 · r² = 3.19e-4): the
  // inertia-too-compact note.
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"base_link", "inertia-too-compact"},
      {"finger_base_link", "com-outside-geometry"},
      {"finger_base_link", "inertia-exceeds-geometry"},
      {"finger_middle_link", "products-sign-suspect"}};
  EXPECT_EQ(found, expected);
  // solo: its upper legs carry the right sign; nothing is found on any of its links.
  EXPECT_TRUE(CheckWithMeshes("solo_description/robots/solo.urdf", &cache).empty());
  // double_pendulum: exact CAD exports, nothing found.
  EXPECT_TRUE(
      CheckWithMeshes("double_pendulum_description/urdf/double_pendulum.urdf", &cache).empty());
}

TEST_F(CorpusMeshTest, DeclaredVersusMeshInertiaTable) {
  // Prints the markdown table of docs/meshes.md; asserts only that every link with geometry and
  // an inertial was computed (the findings are asserted in the tests above).
  std::printf(
      "| model | link | mass (kg) | implied density (kg/m³) | declared principal moments "
      "(kg·m²) | mesh principal moments (kg·m²) | max rel. diff. of moments | max axis angle "
      "(°) | com distance (mm) |\n|---|---|---|---|---|---|---|---|---|\n");
  std::size_t total = 0;
  for (const char* urdf :
       {"finger_edu_description/robots/finger_edu.urdf", "solo_description/robots/solo.urdf",
        "double_pendulum_description/urdf/double_pendulum.urdf"}) {
    MeshCache cache;
    const std::vector<Comparison> rows = Compare(urdf, &cache);
    total += rows.size();
    const std::string model = std::filesystem::path(urdf).filename().string();
    for (const Comparison& r : rows) {
      std::printf(
          "| %s | %s | %.5g | %.0f | %.3g, %.3g, %.3g | %.3g, %.3g, %.3g | %.2f | %.1f | %.1f "
          "|\n",
          model.c_str(), r.link.c_str(), r.mass, r.mass / r.volume, r.declared_moments(0),
          r.declared_moments(1), r.declared_moments(2), r.mesh_moments(0), r.mesh_moments(1),
          r.mesh_moments(2), r.max_relative_moment_difference, r.max_axis_angle_degrees,
          r.com_distance * 1e3);
    }
  }
  // finger_edu: 4 links with geometry and inertial; solo: 13; double pendulum: 3.
  EXPECT_EQ(total, 4u + 13u + 3u);
}

}  // namespace
}  // namespace massprops
