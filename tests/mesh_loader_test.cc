// Tests of mesh_loader.h: URI resolution, loading STL/OBJ/DAE through assimp, and the inertia a
// link's geometry implies. Fixtures are in testdata/mesh (see the comments in each file).

#include "massprops/mesh/mesh_loader.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "massprops/io/model_reader.h"
#include "shared_data.h"

namespace massprops {
namespace {

constexpr double kPi = 3.14159265358979323846;
namespace fs = std::filesystem;
const std::string kMeshDir = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh";

double RelativeDifference(const RotationalInertia<double>& actual,
                          const RotationalInertia<double>& expected) {
  return (actual.CopyToFullMatrix3() - expected.CopyToFullMatrix3()).cwiseAbs().maxCoeff() /
         expected.CopyToFullMatrix3().cwiseAbs().maxCoeff();
}

RotationalInertia<double> Inertia(double xx, double yy, double zz, double xy = 0, double xz = 0,
                                  double yz = 0) {
  return RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(xx, yy, zz, xy, xz, yz,
                                                                        true);
}

// Assimp keeps coordinates as 32-bit floats (ai_real): a coordinate written 0.1 arrives as the
// float nearest to 0.1. Closed forms are evaluated at these values.
double F(double x) { return static_cast<double>(static_cast<float>(x)); }

// Options that see only what the test gives (no environment variables, no repository crawl:
// tests/repository_packages_test.cc tests those).
MeshResolveOptions IsolatedOptions() {
  MeshResolveOptions options;
  options.use_environment = false;
  options.search_repository = false;
  return options;
}

// Box a × b × c of mass m about its center (textbook: solid cuboid).
RotationalInertia<double> Box(double m, double a, double b, double c) {
  return Inertia(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
}

// ---------------------------------------------------------------------------------- loading

TEST(MeshLoaderTest, AsciiAndBinaryStlLoadAsTheSameClosedBox) {
  // testdata/mesh/box_*.stl: the box [0, 0.1] × [0, 0.2] × [0, 0.3] (written by hand as 12
  // facets): V = 0.006, center (0.05, 0.1, 0.15).
  for (const char* name : {"box_ascii.stl", "box_binary.stl"}) {
    TriangleMesh mesh;
    std::string error;
    ASSERT_TRUE(LoadMeshFile(kMeshDir + "/" + name, &mesh, &error)) << error;
    EXPECT_EQ(mesh.triangles.size(), 12u) << name;
    const MeshMassProperties p = CalcMeshMassProperties(mesh);
    EXPECT_TRUE(p.diagnostics.IsClosedManifold()) << name;
    EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kClosedSolid);
    // Both arrive as float32 coordinates (see F).
    const double a = F(0.1), b = F(0.2), c = F(0.3), V = a * b * c;
    EXPECT_NEAR(p.volume, V, 1e-12 * V) << name;
    EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(a, b, c) / 2).norm(), 1e-15) << name;
    EXPECT_LT(RelativeDifference(p.I_GGcm_G, Box(V, a, b, c)), 1e-12) << name;
  }
}

TEST(MeshLoaderTest, ObjQuadsAreTriangulated) {
  // testdata/mesh/cube_quads.obj: cube of side 2 centered at the origin, 6 quads.
  // V = 8, I = m·L²/6 = 8·4/6 (textbook: solid cube).
  TriangleMesh mesh;
  std::string error;
  ASSERT_TRUE(LoadMeshFile(kMeshDir + "/cube_quads.obj", &mesh, &error)) << error;
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_TRUE(p.diagnostics.IsClosedManifold());
  EXPECT_NEAR(p.volume, 8, 1e-14);
  EXPECT_LT(p.p_GoGcm_G.norm(), 1e-15);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(32.0 / 6, 32.0 / 6, 32.0 / 6)), 1e-14);
}

TEST(MeshLoaderTest, DaeInCentimetersIsLoadedInMetersWithoutTurningItsUpAxis) {
  // testdata/mesh/tet_cm.dae: <unit meter="0.01">, <up_axis>Z_UP</up_axis>, a corner tetrahedron
  // with legs 10, 20, 30 (cm) along x, y, z under a node translated by 5 (cm) along x. Assimp 5.2
  // applies the unit as a scale in the root node's transform (and would turn Z_UP to Y_UP unless
  // told not to). In meters: legs 0.1, 0.2, 0.3 from (0.05, 0, 0), so V = 0.1·0.2·0.3/6 = 0.001
  // and the center is (0.05 + 0.1/4, 0.2/4, 0.3/4) (centroid of the 4 vertices).
  TriangleMesh mesh;
  std::string error;
  ASSERT_TRUE(LoadMeshFile(kMeshDir + "/tet_cm.dae", &mesh, &error)) << error;
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_TRUE(p.diagnostics.IsClosedManifold());
  EXPECT_FALSE(p.diagnostics.winding_inverted);
  // Float32 arithmetic in assimp (cm values times 0.01f): 1e-6 relative.
  EXPECT_NEAR(p.volume, 0.001, 1e-6 * 0.001);
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(0.075, 0.05, 0.075)).norm(), 1e-7);
  // The z leg (0.3 m) is still along z: the largest extent is in z.
  double z_max = 0;
  for (const auto& v : mesh.vertices) z_max = std::max(z_max, v.z());
  EXPECT_NEAR(z_max, 0.3, 1e-7);
}

TEST(MeshLoaderTest, OpenObjIsModelledByItsHull) {
  // testdata/mesh/open_box.obj: the 0.1 × 0.2 × 0.3 box without its top: 4 boundary edges, and
  // its hull is the whole box.
  TriangleMesh mesh;
  std::string error;
  ASSERT_TRUE(LoadMeshFile(kMeshDir + "/open_box.obj", &mesh, &error)) << error;
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_EQ(p.diagnostics.boundary_edges, 4);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kConvexHull);
  const double a = F(0.1), b = F(0.2), c = F(0.3), V = a * b * c;
  EXPECT_NEAR(p.volume, V, 1e-12 * V);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Box(V, a, b, c)), 1e-12);
}

TEST(MeshLoaderTest, UnreadableFilesAreErrorsNotCrashes) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty.stl", "empty"},
      {"not_a_mesh.stl", "cannot be read"},
      {"points_only.obj", "no triangle"},
      {"does_not_exist.stl", "does not exist"},
      {"packages", "not a regular file"},  // A directory.
  };
  for (const auto& [name, reason] : cases) {
    TriangleMesh mesh;
    std::string error;
    EXPECT_FALSE(LoadMeshFile(kMeshDir + "/" + name, &mesh, &error)) << name;
    EXPECT_NE(error.find(name), std::string::npos) << error;
    EXPECT_NE(error.find(reason), std::string::npos) << error;
  }
}

// ---------------------------------------------------------------------------------- URIs

TEST(MeshLoaderTest, PackageUriResolvesThroughGivenPathsByFolderOrPackageXmlName) {
  MeshResolveOptions options = IsolatedOptions();
  options.package_paths = {"/nonexistent/folder", MASSPROPS_TESTDATA_DIR};
  std::string error;
  // The folder testdata/mesh is the package "mesh".
  EXPECT_EQ(ResolveMeshUri("package://mesh/box_ascii.stl", options, &error),
            kMeshDir + "/box_ascii.stl")
      << error;
  // testdata/mesh/packages/renamed_folder/package.xml names the package "mesh_fixture_pkg".
  options.package_paths = {kMeshDir + "/packages"};
  EXPECT_EQ(ResolveMeshUri("package://mesh_fixture_pkg/tet_inward.obj", options, &error),
            kMeshDir + "/packages/renamed_folder/tet_inward.obj")
      << error;
  // The package folder itself on the path.
  options.package_paths = {kMeshDir + "/packages/renamed_folder"};
  EXPECT_EQ(ResolveMeshUri("package://mesh_fixture_pkg/tet_inward.obj", options, &error),
            kMeshDir + "/packages/renamed_folder/tet_inward.obj")
      << error;
}

TEST(MeshLoaderTest, PackageUriFailuresSayWhatWasSearched) {
  MeshResolveOptions options = IsolatedOptions();
  options.package_paths = {MASSPROPS_TESTDATA_DIR};
  std::string error;
  EXPECT_FALSE(ResolveMeshUri("package://no_such_pkg/a.stl", options, &error));
  EXPECT_NE(error.find("package 'no_such_pkg' not found in"), std::string::npos) << error;
  EXPECT_NE(error.find(MASSPROPS_TESTDATA_DIR), std::string::npos) << error;
  EXPECT_FALSE(ResolveMeshUri("package://mesh/missing.stl", options, &error));
  EXPECT_NE(error.find("found but the file is not there"), std::string::npos) << error;
  // package:///a.stl is a file beside the description (repository_packages_test.cc).
  EXPECT_FALSE(ResolveMeshUri("package:///a.stl", options, &error));
  EXPECT_NE(error.find("beside the description"), std::string::npos) << error;
  EXPECT_FALSE(ResolveMeshUri("model:///a.sdf", options, &error));
  EXPECT_NE(error.find("no model name"), std::string::npos) << error;
}

TEST(MeshLoaderTest, PackageUriResolvesThroughRosPackagePath) {
  MeshResolveOptions options;  // Environment on, no given paths.
  const std::string value = std::string("/nonexistent:") + MASSPROPS_TESTDATA_DIR;
  ASSERT_EQ(setenv("ROS_PACKAGE_PATH", value.c_str(), 1), 0);
  std::string error;
  EXPECT_EQ(ResolveMeshUri("package://mesh/box_binary.stl", options, &error),
            kMeshDir + "/box_binary.stl")
      << error;
  unsetenv("ROS_PACKAGE_PATH");
  options.use_environment = false;
  EXPECT_FALSE(ResolveMeshUri("package://mesh/box_binary.stl", options, &error));
}

TEST(MeshLoaderTest, ModelUriResolvesThroughModelPathsAndSdfPath) {
  MeshResolveOptions options = IsolatedOptions();
  options.model_paths = {MASSPROPS_TESTDATA_DIR};
  std::string error;
  EXPECT_EQ(ResolveMeshUri("model://mesh/cube_quads.obj", options, &error),
            kMeshDir + "/cube_quads.obj")
      << error;
  options = MeshResolveOptions();
  ASSERT_EQ(setenv("SDF_PATH", MASSPROPS_TESTDATA_DIR, 1), 0);
  EXPECT_EQ(ResolveMeshUri("model://mesh/cube_quads.obj", options, &error),
            kMeshDir + "/cube_quads.obj")
      << error;
  unsetenv("SDF_PATH");
  ASSERT_EQ(setenv("GZ_SIM_RESOURCE_PATH", MASSPROPS_TESTDATA_DIR, 1), 0);
  EXPECT_EQ(ResolveMeshUri("model://mesh/cube_quads.obj", options, &error),
            kMeshDir + "/cube_quads.obj")
      << error;
  unsetenv("GZ_SIM_RESOURCE_PATH");
  EXPECT_FALSE(ResolveMeshUri("model://nowhere/x.obj", IsolatedOptions(), &error));
  EXPECT_NE(error.find("model 'nowhere' not found"), std::string::npos) << error;
}

TEST(MeshLoaderTest, FileUrisAbsoluteAndRelativePathsResolve) {
  MeshResolveOptions options = IsolatedOptions();
  options.model_file = kMeshDir + "/robot.urdf";
  std::string error;
  EXPECT_EQ(ResolveMeshUri("file://" + kMeshDir + "/box_ascii.stl", options, &error),
            kMeshDir + "/box_ascii.stl")
      << error;
  EXPECT_EQ(ResolveMeshUri(kMeshDir + "/box_ascii.stl", options, &error),
            kMeshDir + "/box_ascii.stl")
      << error;
  // Relative to the model file's folder.
  EXPECT_EQ(ResolveMeshUri("box_ascii.stl", options, &error), kMeshDir + "/box_ascii.stl") << error;
  EXPECT_EQ(ResolveMeshUri("packages/../box_ascii.stl", options, &error),
            kMeshDir + "/box_ascii.stl")
      << error;
  EXPECT_FALSE(ResolveMeshUri("nothing_here.stl", options, &error));
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
  EXPECT_FALSE(ResolveMeshUri("https://example.com/a.stl", options, &error));
  EXPECT_NE(error.find("scheme 'https' is not supported"), std::string::npos) << error;
  EXPECT_FALSE(ResolveMeshUri("", options, &error));
}

// ---------------------------------------------------------------------------------- geometry

TEST(MeshLoaderTest, PrimitivesGiveTheirClosedFormsInTheLinkFrame) {
  const MeshResolveOptions options = IsolatedOptions();
  std::string error;
  Geometry box;
  box.type = Geometry::Type::kBox;
  box.size = {1, 2, 3};
  box.X_BG.p_AB = {0.5, -1, 2};
  box.X_BG.R_AB = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  auto p = CalcGeometryMassProperties(box, options, &error);
  ASSERT_TRUE(p) << error;
  // V = 6; turned 90° about z the sides along B's x, y, z are 2, 1, 3.
  EXPECT_NEAR(p->volume, 6, 1e-15);
  EXPECT_LT((p->p_BoGcm_B - Eigen::Vector3d(0.5, -1, 2)).norm(), 1e-15);
  EXPECT_LT(RelativeDifference(p->I_GGcm_B, Box(6, 2, 1, 3)), 1e-15);
  EXPECT_FALSE(p->mesh_diagnostics);

  Geometry cylinder;
  cylinder.type = Geometry::Type::kCylinder;
  cylinder.radius = 0.1;
  cylinder.length = 0.4;
  p = CalcGeometryMassProperties(cylinder, options, &error);
  ASSERT_TRUE(p) << error;
  // V = π r² L; I = m r²/2 about z, m(3r² + L²)/12 about x and y (textbook).
  const double Vc = kPi * 0.01 * 0.4;
  EXPECT_NEAR(p->volume, Vc, 1e-16);
  EXPECT_LT(RelativeDifference(p->I_GGcm_B, Inertia(Vc * 0.19 / 12, Vc * 0.19 / 12, Vc * 0.005)),
            1e-14);

  Geometry sphere;
  sphere.type = Geometry::Type::kSphere;
  sphere.radius = 0.5;
  p = CalcGeometryMassProperties(sphere, options, &error);
  ASSERT_TRUE(p) << error;
  const double Vs = 4 * kPi * 0.125 / 3;  // 4/3·π·r³; I = 2/5·m·r² (textbook).
  EXPECT_NEAR(p->volume, Vs, 1e-15);
  EXPECT_NEAR(p->I_GGcm_B(1, 1), 0.4 * Vs * 0.25, 1e-15);

  Geometry capsule;
  capsule.type = Geometry::Type::kCapsule;
  capsule.radius = 0.1;
  capsule.length = 0.2;
  p = CalcGeometryMassProperties(capsule, options, &error);
  ASSERT_TRUE(p) << error;
  // V = π r² L + 4/3·π·r³ (cylinder plus two hemispheres).
  EXPECT_NEAR(p->volume, kPi * 0.01 * 0.2 + 4 * kPi * 0.001 / 3, 1e-16);

  Geometry ellipsoid;
  ellipsoid.type = Geometry::Type::kEllipsoid;
  ellipsoid.radii = {0.1, 0.2, 0.3};
  p = CalcGeometryMassProperties(ellipsoid, options, &error);
  ASSERT_TRUE(p) << error;
  // V = 4/3·π·abc; Ixx = m(b² + c²)/5 (textbook: solid ellipsoid).
  const double Ve = 4 * kPi * 0.006 / 3;
  EXPECT_NEAR(p->volume, Ve, 1e-16);
  EXPECT_NEAR(p->I_GGcm_B(0, 0), Ve * 0.13 / 5, 1e-16);

  Geometry other;
  other.type = Geometry::Type::kOther;
  EXPECT_FALSE(CalcGeometryMassProperties(other, options, &error));
  EXPECT_NE(error.find("no volume model"), std::string::npos) << error;
  box.size = {1, 0, 1};
  EXPECT_FALSE(CalcGeometryMassProperties(box, options, &error));
  EXPECT_NE(error.find("volume is 0"), std::string::npos) << error;
  box.size = {1, -1, 1};
  EXPECT_FALSE(CalcGeometryMassProperties(box, options, &error));
}

TEST(MeshLoaderTest, MeshScaleStretchesAndAMirrorScaleKeepsTheWinding) {
  MeshResolveOptions options = IsolatedOptions();
  Geometry mesh;
  mesh.type = Geometry::Type::kMesh;
  mesh.uri = kMeshDir + "/cube_quads.obj";
  mesh.scale = {0.5, 1, 2};
  std::string error;
  auto p = CalcGeometryMassProperties(mesh, options, &error);
  ASSERT_TRUE(p) << error;
  // The side-2 cube scaled to 1 × 2 × 4: V = 8.
  EXPECT_NEAR(p->volume, 8, 1e-14);
  EXPECT_LT(RelativeDifference(p->I_GGcm_B, Box(8, 1, 2, 4)), 1e-14);
  EXPECT_EQ(p->mesh_path, kMeshDir + "/cube_quads.obj");
  ASSERT_TRUE(p->mesh_diagnostics);
  EXPECT_FALSE(p->mesh_diagnostics->winding_inverted);
  // Mirrored along x: the same solid, winding still outward.
  mesh.scale = {-0.5, 1, 2};
  p = CalcGeometryMassProperties(mesh, options, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_NEAR(p->volume, 8, 1e-14);
  EXPECT_FALSE(p->mesh_diagnostics->winding_inverted);
  // A mesh wound inward in its file is reported so.
  mesh.uri = kMeshDir + "/packages/renamed_folder/tet_inward.obj";
  mesh.scale = {1, 1, 1};
  p = CalcGeometryMassProperties(mesh, options, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_TRUE(p->mesh_diagnostics->winding_inverted);
  EXPECT_NEAR(p->volume, 1.0, 1e-15);  // Legs 1, 2, 3: V = 6/6.
  mesh.uri = kMeshDir + "/missing.stl";
  EXPECT_FALSE(CalcGeometryMassProperties(mesh, options, &error));
  EXPECT_NE(error.find("collision (mesh '"), std::string::npos) << error;
}

// ---------------------------------------------------------------------------------- links

class LinkGeometryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ReadResult read = ReadModelFile(kMeshDir + "/robot.urdf");
    ASSERT_TRUE(read.ok() && read.models.size() == 1);
    model_ = read.models[0];
    options_ = IsolatedOptions();
    options_.model_file = kMeshDir + "/robot.urdf";
    options_.package_paths = {MASSPROPS_TESTDATA_DIR};
    options_.cache = &cache_;
  }
  const Link& link(const std::string& name) const { return model_.links[model_.FindLink(name)]; }

  Model model_;
  MeshCache cache_;
  MeshResolveOptions options_;
};

TEST_F(LinkGeometryTest, ScaledRotatedMeshGivesTheBoxInertiaInTheLinkFrame) {
  // box_ascii.stl (0.1 × 0.2 × 0.3 from the origin) scaled by (3, 1, 1): 0.3 × 0.2 × 0.3, center
  // (0.15, 0.1, 0.15) in G; X_BG turns 90° about z and moves by (1, 0, 0): center
  // (1 − 0.1, 0.15, 0.15), sides along B's x, y, z 0.2, 0.3, 0.3. Mass 2.
  std::string error;
  const auto g = CalcLinkGeometryInertia(link("scaled_box"), 2.0, options_, &error);
  ASSERT_TRUE(g) << error;
  EXPECT_TRUE(g->from_collision);
  // The file's coordinates are float32 (see F); the scale is applied in double.
  const double a = 3 * F(0.1), b = F(0.2), c = F(0.3);
  EXPECT_NEAR(g->volume, a * b * c, 1e-12 * a * b * c);
  EXPECT_LT((g->p_BoBcm_B - Eigen::Vector3d(1 - b / 2, a / 2, c / 2)).norm(), 1e-12);
  EXPECT_LT(RelativeDifference(g->I_BBcm_B, Box(2, b, a, c)), 1e-12);
  ASSERT_EQ(g->geometries.size(), 1u);
  EXPECT_EQ(g->geometries[0].mesh_path, kMeshDir + "/box_ascii.stl");
  // The bounding box of the posed vertices: x from 1 − b to 1, y from 0 to a, z from 0 to c.
  EXPECT_LT((g->box_B.min() - Eigen::Vector3d(1 - b, 0, 0)).norm(), 1e-15);
  EXPECT_LT((g->box_B.max() - Eigen::Vector3d(1, a, c)).norm(), 1e-15);
}

TEST(MeshLoaderTest, RelativeMeshOfAnIncludedSdfModelResolvesFromTheModelsOwnFile) {
  // testdata/mesh/sdf/world.sdf includes model://mesh_part, whose mesh URI ../../../box_ascii.stl
  // is relative to models/mesh_part/model.sdf (from the world's folder it names nothing).
  ReadOptions read_options;
  read_options.sdf.model_paths = {kMeshDir + "/sdf/models"};
  const ReadResult read = ReadModelFile(kMeshDir + "/sdf/world.sdf", read_options);
  ASSERT_TRUE(read.errors.empty()) << read.errors.front().ToString();
  ASSERT_EQ(read.models.size(), 1u);
  const Model& model = read.models[0];
  ASSERT_EQ(model.links.size(), 1u);
  MeshResolveOptions options;
  options.use_environment = false;
  options.model_file = model.file;  // the world
  std::string error;
  const auto g = CalcLinkGeometryInertia(model.links[0], 2.0, options, &error);
  ASSERT_TRUE(g) << error;
  // The 0.1 x 0.2 x 0.3 box: volume 0.006 m³ (to the STL's float32 rounding).
  EXPECT_NEAR(g->volume, 0.006, 1e-9);
  const std::string& path = g->geometries.at(0).mesh_path;
  EXPECT_EQ(fs::weakly_canonical(path), fs::weakly_canonical(kMeshDir + "/box_ascii.stl"));
}

TEST_F(LinkGeometryTest, SeveralCollisionsAreSummedAsOneUniformBody) {
  // Box 0.2³ at the origin (V1 = 0.008) and sphere r = 0.1 at z = 0.5 (V2 = 4/3·π·0.001), mass
  // 3 spread uniformly: each part gets m·Vi/V; composite center z = 0.5·V2/V; then the parallel
  // axis theorem (textbook) about the composite center. The 5 m visual box is not used.
  std::string error;
  const auto g = CalcLinkGeometryInertia(link("box_and_sphere"), 3.0, options_, &error);
  ASSERT_TRUE(g) << error;
  const double V1 = 0.008, V2 = 4 * kPi * 0.001 / 3, V = V1 + V2;
  const double m1 = 3 * V1 / V, m2 = 3 * V2 / V;
  const double zc = 0.5 * V2 / V;
  const double d1 = zc, d2 = 0.5 - zc;
  const double Ixx = m1 * 0.08 / 12 + m1 * d1 * d1 + 0.4 * m2 * 0.01 + m2 * d2 * d2;
  const double Izz = m1 * 0.08 / 12 + 0.4 * m2 * 0.01;
  EXPECT_NEAR(g->volume, V, 1e-16);
  EXPECT_LT((g->p_BoBcm_B - Eigen::Vector3d(0, 0, zc)).norm(), 1e-15);
  EXPECT_LT(RelativeDifference(g->I_BBcm_B, Inertia(Ixx, Ixx, Izz)), 1e-14);
  EXPECT_EQ(g->geometries.size(), 2u);
  EXPECT_TRUE(g->from_collision);
}

TEST_F(LinkGeometryTest, VisualGeometryIsUsedWhenThereIsNoCollision) {
  // cube_quads.obj through package://mesh: side 2, mass 1: I = 4/6.
  std::string error;
  const auto g = CalcLinkGeometryInertia(link("visual_only"), 1.0, options_, &error);
  ASSERT_TRUE(g) << error;
  EXPECT_FALSE(g->from_collision);
  EXPECT_TRUE(g->note.empty());
  EXPECT_LT(RelativeDifference(g->I_BBcm_B, Inertia(4.0 / 6, 4.0 / 6, 4.0 / 6)), 1e-14);
}

TEST_F(LinkGeometryTest, VisualGeometryIsUsedWhenACollisionMeshIsMissing) {
  // The visual cylinder r = 0.1, L = 0.4 of mass 1: Izz = 0.005, Ixx = (0.03 + 0.16)/12.
  std::string error;
  const auto g = CalcLinkGeometryInertia(link("broken_collision"), 1.0, options_, &error);
  ASSERT_TRUE(g) << error;
  EXPECT_FALSE(g->from_collision);
  EXPECT_NE(g->note.find("missing.stl"), std::string::npos) << g->note;
  EXPECT_LT(RelativeDifference(g->I_BBcm_B, Inertia(0.19 / 12, 0.19 / 12, 0.005)), 1e-14);
}

TEST_F(LinkGeometryTest, MeshSharedByTwoLinksIsLoadedOnce) {
  std::string error;
  const auto a = CalcLinkGeometryInertia(link("shared_a"), 1.0, options_, &error);
  const auto b = CalcLinkGeometryInertia(link("shared_b"), 1.0, options_, &error);
  ASSERT_TRUE(a && b) << error;
  EXPECT_EQ(cache_.files_loaded(), 1);
  // The 0.1 × 0.2 × 0.3 box of mass 1 (float32 coordinates, see F).
  EXPECT_LT(RelativeDifference(b->I_BBcm_B, Box(1, F(0.1), F(0.2), F(0.3))), 1e-12);
  // A file that fails to load is remembered too: read once, the same error twice.
  std::string first, second;
  EXPECT_FALSE(cache_.Load(kMeshDir + "/not_a_mesh.stl", &first));
  EXPECT_FALSE(cache_.Load(kMeshDir + "/not_a_mesh.stl", &second));
  EXPECT_EQ(cache_.files_loaded(), 2);
  EXPECT_EQ(first, second);
  EXPECT_NE(first.find("cannot be read"), std::string::npos) << first;
}

TEST_F(LinkGeometryTest, LinkWithoutGeometryOrWithBadMassIsAnError) {
  std::string error;
  EXPECT_FALSE(CalcLinkGeometryInertia(link("no_geometry"), 1.0, options_, &error));
  EXPECT_NE(error.find("has no collision or visual geometry"), std::string::npos) << error;
  EXPECT_FALSE(CalcLinkGeometryInertia(link("scaled_box"), -1.0, options_, &error));
  EXPECT_NE(error.find("negative or not finite"), std::string::npos) << error;
}

TEST_F(LinkGeometryTest, ZeroMassGivesZeroInertia) {
  std::string error;
  const auto g = CalcLinkGeometryInertia(link("scaled_box"), 0.0, options_, &error);
  ASSERT_TRUE(g) << error;
  EXPECT_TRUE(g->I_BBcm_B.IsZero());
}

// MeshInertiaOptions::read_stl_directly (the density rules): the STL's own triangles, read without
// assimp, give the same volume, center and inertia as assimp's joined mesh, to the last bit for
// the fixtures' boxes and to round-off for the corpus' SolidWorks STL files; the diagnostics then
// count the unjoined corners (12 triangles: 36 vertices, 28 of them duplicates of 8).
TEST(MeshLoaderTest, StlReadDirectlyGivesTheSameMassProperties) {
  std::vector<std::string> files = {kMeshDir + "/box_ascii.stl", kMeshDir + "/box_binary.stl"};
  const std::string corpus = std::string(MASSPROPS_CORPUS_DIR) +
                             "/example-robot-data/robots/double_pendulum_description/meshes/";
  if (test_support::SharedPartPresent(
          "corpus/example-robot-data/robots/double_pendulum_description/meshes")) {
    for (const char* name : {"base_link.stl", "link1.stl", "link2.stl"})
      files.push_back(corpus + name);
  }
  for (const std::string& file : files) {
    MeshCache cache;
    std::string error;
    MeshInertiaOptions assimp, direct;
    direct.read_stl_directly = true;
    const Eigen::Vector3d scale(1, 2, 3);
    const auto a = cache.MassProperties(file, scale, assimp, &error);
    const auto d = cache.MassProperties(file, scale, direct, &error);
    ASSERT_TRUE(a && d) << file << ": " << error;
    EXPECT_NEAR(d->volume, a->volume, 1e-14 * a->volume) << file;
    EXPECT_LE((d->p_GoGcm_G - a->p_GoGcm_G).norm(), 1e-12 * (1 + a->p_GoGcm_G.norm())) << file;
    const Eigen::Matrix3d Ia = a->I_GGcm_G.CopyToFullMatrix3();
    const Eigen::Matrix3d Id = d->I_GGcm_G.CopyToFullMatrix3();
    EXPECT_LE((Id - Ia).norm(), 1e-12 * Ia.norm()) << file;
    EXPECT_EQ(d->diagnostics.num_triangles, a->diagnostics.num_triangles) << file;
    EXPECT_EQ(d->diagnostics.boundary_edges, a->diagnostics.boundary_edges) << file;
    EXPECT_EQ(d->diagnostics.reference_point_sensitivity == 0,
              a->diagnostics.reference_point_sensitivity == 0)
        << file;
    if (file == files[0]) {
      EXPECT_EQ(d->diagnostics.num_vertices, 36);
      EXPECT_EQ(d->diagnostics.duplicate_vertices_merged, 28);
    }
  }
}

}  // namespace
}  // namespace massprops
