// Tests of the cheap mesh bounding boxes of mesh_loader.h (LoadMeshBounds, MeshCache::Bounds,
// CalcGeometryBounds) and of MakeLinkBoxFunction (geometry_checks.h). Fixtures in testdata/mesh
// (each file says what it holds); corpus meshes from ../shared/corpus.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "corpus_manifest.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {

const std::string kMeshDir = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh";

// Assimp and the direct readers keep coordinates as 32-bit floats: a coordinate written 0.1
// arrives as the float nearest to 0.1.
double F(double x) { return static_cast<double>(static_cast<float>(x)); }

void ExpectBox(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& min,
               const Eigen::Vector3d& max, double tolerance, const std::string& what) {
  EXPECT_LE((box.min() - min).cwiseAbs().maxCoeff(), tolerance)
      << what << ": min " << box.min().transpose() << ", expected " << min.transpose();
  EXPECT_LE((box.max() - max).cwiseAbs().maxCoeff(), tolerance)
      << what << ": max " << box.max().transpose() << ", expected " << max.transpose();
}

// The box of the full loader's vertices (LoadMeshFile through assimp).
Eigen::AlignedBox3d FullLoaderBox(const std::string& path) {
  TriangleMesh mesh;
  std::string error;
  EXPECT_TRUE(LoadMeshFile(path, &mesh, &error)) << error;
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  return box;
}

TEST(MeshBoundsTest, StlAsciiAndBinaryAreReadDirectlyWithTheirHandWrittenExtent) {
  // testdata/mesh/box_*.stl: the box [0, 0.1] × [0, 0.2] × [0, 0.3], written by hand as 12 facets.
  for (const char* name : {"box_ascii.stl", "box_binary.stl"}) {
    Eigen::AlignedBox3d box;
    bool direct = false;
    std::string error;
    ASSERT_TRUE(LoadMeshBounds(kMeshDir + "/" + name, &box, &direct, &error)) << error;
    EXPECT_TRUE(direct) << name << ": read without assimp";
    ExpectBox(box, Eigen::Vector3d::Zero(), Eigen::Vector3d(F(0.1), F(0.2), F(0.3)), 0, name);
  }
}

TEST(MeshBoundsTest, ObjCountsOnlyTheVerticesThatAnElementUses) {
  // testdata/mesh/cube_quads.obj: the cube [-1, 1]³ as 6 quads.
  Eigen::AlignedBox3d box;
  bool direct = false;
  std::string error;
  ASSERT_TRUE(LoadMeshBounds(kMeshDir + "/cube_quads.obj", &box, &direct, &error)) << error;
  EXPECT_TRUE(direct);
  ExpectBox(box, Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1), 0, "cube_quads");
  // testdata/mesh/bounds_obj_features.obj (see its comments): a tetrahedron with corners
  // (0, 0, 0), (2, 0, 0) written as "v 4 0 0 2" (w = 2), (0, 3, 0) and (0, 0, 4) used through
  // negative indices, and a vertex at (100, 100, 100) that no element uses: box [0, 2] × [0, 3] ×
  // [0, 4], by hand; the full loader agrees.
  const std::string features = kMeshDir + "/bounds_obj_features.obj";
  ASSERT_TRUE(LoadMeshBounds(features, &box, &direct, &error)) << error;
  EXPECT_TRUE(direct);
  ExpectBox(box, Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 3, 4), 0, "bounds_obj_features");
  const Eigen::AlignedBox3d full = FullLoaderBox(features);
  ExpectBox(box, full.min(), full.max(), 0, "bounds_obj_features vs assimp");
}

TEST(MeshBoundsTest, DaeGoesThroughTheFullLoaderWithItsUnitAndNodeTransform) {
  // testdata/mesh/tet_cm.dae: a corner tetrahedron with legs 10, 20, 30 written in centimetres
  // (<unit meter="0.01">), its node translated by 5 cm along x: in metres the corners are
  // (0.05, 0, 0), (0.15, 0, 0), (0.05, 0.2, 0), (0.05, 0, 0.3).
  Eigen::AlignedBox3d box;
  bool direct = true;
  std::string error;
  ASSERT_TRUE(LoadMeshBounds(kMeshDir + "/tet_cm.dae", &box, &direct, &error)) << error;
  EXPECT_FALSE(direct);
  ExpectBox(box, Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0.15, 0.2, 0.3), 1e-7, "tet_cm");
}

TEST(MeshBoundsTest, FilesTheFullLoaderRefusesAreRefusedWithItsMessage) {
  for (const char* name : {"empty.stl", "not_a_mesh.stl", "points_only.obj", "no_such.stl"}) {
    Eigen::AlignedBox3d box;
    std::string error;
    EXPECT_FALSE(LoadMeshBounds(kMeshDir + "/" + name, &box, nullptr, &error)) << name;
    EXPECT_NE(error.find(name), std::string::npos) << name << ": " << error;
  }
}

TEST(MeshBoundsTest, EveryCorpusMeshHasTheBoxOfTheFullLoadersMesh) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<test_support::ManifestRow> rows = test_support::ReadCorpusManifest("mesh");
  int stl = 0, obj = 0;
  for (const auto& row : rows) {
    const std::string path = test_support::CorpusDir() + "/" + row.file;
    Eigen::AlignedBox3d box;
    bool direct = false;
    std::string error;
    ASSERT_TRUE(LoadMeshBounds(path, &box, &direct, &error)) << error;
    EXPECT_TRUE(direct) << row.file;
    const Eigen::AlignedBox3d full = FullLoaderBox(path);
    // Both are floats of the same written numbers; assimp's ascii parser (fast_atof) may round
    // the last bit differently from strtod: one float ulp of the mesh's size at most.
    const double ulp = std::ldexp(full.diagonal().norm() + full.max().cwiseAbs().maxCoeff(), -23);
    ExpectBox(box, full.min(), full.max(), ulp, row.file);
    (path.substr(path.size() - 3) == "obj" ? obj : stl) += 1;
  }
  EXPECT_EQ(stl, 10);  // MANIFEST.tsv: 10 STL (binary and ascii) and 6 OBJ meshes
  EXPECT_EQ(obj, 6);
}

TEST(MeshBoundsTest, AFileOnlyAssimpReadsIsImportedOnceForItsBoxAndItsNumbers) {
  // tet_cm.dae (above): legs 0.1, 0.2, 0.3 m from (0.05, 0, 0), so the box is (0.05, 0, 0) to
  // (0.15, 0.2, 0.3) and the volume 0.1 * 0.2 * 0.3 / 6 = 0.001 m³ (by hand). Its box comes from
  // the mesh the import gives, which is kept: asking its mass properties next imports nothing.
  // (Before, the box was a separate import whose mesh was dropped: two imports per DAE file.)
  MeshCache cache;
  std::string error;
  const std::optional<Eigen::AlignedBox3d> box = cache.Bounds(kMeshDir + "/tet_cm.dae", &error);
  ASSERT_TRUE(box) << error;
  ExpectBox(*box, Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0.15, 0.2, 0.3), 1e-7, "tet_cm");
  EXPECT_EQ(cache.files_loaded(), 1);
  EXPECT_EQ(cache.files_bounded(), 0);
  const std::optional<MeshMassProperties> mass = cache.MassProperties(
      kMeshDir + "/tet_cm.dae", Eigen::Vector3d::Ones(), MeshInertiaOptions{}, &error);
  ASSERT_TRUE(mass) << error;
  EXPECT_NEAR(mass->volume, 0.1 * 0.2 * 0.3 / 6, 1e-9);
  EXPECT_EQ(cache.files_loaded(), 1);
  EXPECT_EQ(cache.files_bounded(), 0);
  // A file assimp cannot read: the same error as LoadMeshBounds gives, and one try.
  EXPECT_FALSE(cache.Bounds(kMeshDir + "/no_such.dae", &error));
  std::string direct_error;
  Eigen::AlignedBox3d unused;
  EXPECT_FALSE(LoadMeshBounds(kMeshDir + "/no_such.dae", &unused, nullptr, &direct_error));
  EXPECT_EQ(error, direct_error);
  EXPECT_FALSE(cache.Bounds(kMeshDir + "/no_such.dae", &error));
  EXPECT_EQ(cache.files_loaded(), 2);
}

TEST(MeshBoundsTest, CacheReadsEachFileOnceAndReusesALoadedMesh) {
  MeshCache cache;
  std::string error;
  ASSERT_TRUE(cache.Bounds(kMeshDir + "/box_binary.stl", &error)) << error;
  ASSERT_TRUE(cache.Bounds(kMeshDir + "/box_binary.stl", &error));
  EXPECT_EQ(cache.files_bounded(), 1);
  EXPECT_FALSE(cache.Bounds(kMeshDir + "/no_such.stl", &error));
  EXPECT_FALSE(cache.Bounds(kMeshDir + "/no_such.stl", &error));
  EXPECT_EQ(cache.files_bounded(), 2);  // failures are remembered too
  ASSERT_TRUE(cache.Load(kMeshDir + "/cube_quads.obj", &error));
  const std::optional<Eigen::AlignedBox3d> cube =
      cache.Bounds(kMeshDir + "/cube_quads.obj", &error);
  ASSERT_TRUE(cube);
  EXPECT_EQ(cache.files_bounded(), 2);  // from the loaded mesh
  ExpectBox(*cube, Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1), 0, "cube");
}

Geometry MeshGeometry(const std::string& file, const Eigen::Vector3d& scale, const Pose& X_BG) {
  Geometry g;
  g.type = Geometry::Type::kMesh;
  g.uri = kMeshDir + "/" + file;
  g.scale = scale;
  g.X_BG = X_BG;
  return g;
}

TEST(MeshBoundsTest, GeometryBoundsApplyTheScaleAndThePose) {
  MeshResolveOptions options;
  options.use_environment = false;
  std::string error;
  // box_binary.stl [0, 0.1] × [0, 0.2] × [0, 0.3], scale (2, -1, 1): [0, 0.2] × [-0.2, 0] ×
  // [0, 0.3]; turned 90° about z ((x, y, z) → (−y, x, z)): [0, 0.2] × [0, 0.2] × [0, 0.3]; moved
  // by (1, 2, 3): [1, 1.2] × [2, 2.2] × [3, 3.3] (by hand).
  Pose X_BG;
  X_BG.R_AB = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  X_BG.p_AB = Eigen::Vector3d(1, 2, 3);
  std::optional<Eigen::AlignedBox3d> box = CalcGeometryBounds(
      MeshGeometry("box_binary.stl", Eigen::Vector3d(2, -1, 1), X_BG), options, &error);
  ASSERT_TRUE(box) << error;
  ExpectBox(*box, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1 + 2 * F(0.1), 2 + F(0.2), 3 + F(0.3)),
            1e-12, "scaled and turned box");
  // cube_quads.obj [-1, 1]³ turned 45° about z: its corners reach ±√2 in x and y (by hand); the
  // cube's vertices are its corners, so here the corners' box is exact.
  X_BG.R_AB = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  X_BG.p_AB.setZero();
  box = CalcGeometryBounds(MeshGeometry("cube_quads.obj", Eigen::Vector3d::Ones(), X_BG), options,
                           &error);
  ASSERT_TRUE(box) << error;
  const double r = std::sqrt(2.0);
  ExpectBox(*box, Eigen::Vector3d(-r, -r, -1), Eigen::Vector3d(r, r, 1), 1e-12, "cube at 45°");
  // The tetrahedron of bounds_obj_features.obj ([0, 2] × [0, 3] × [0, 4]) turned 90° about x
  // ((x, y, z) → (x, −z, y)): [0, 2] × [−4, 0] × [0, 3].
  X_BG.R_AB = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  box = CalcGeometryBounds(MeshGeometry("bounds_obj_features.obj", Eigen::Vector3d::Ones(), X_BG),
                           options, &error);
  ASSERT_TRUE(box) << error;
  ExpectBox(*box, Eigen::Vector3d(0, -4, 0), Eigen::Vector3d(2, 0, 3), 1e-12, "tetrahedron");
}

TEST(MeshBoundsTest, GeometryBoundsRefuseWhatCannotBeMeasured) {
  MeshResolveOptions options;
  options.use_environment = false;
  std::string error;
  Geometry missing = MeshGeometry("no_such.stl", Eigen::Vector3d::Ones(), Pose{});
  EXPECT_FALSE(CalcGeometryBounds(missing, options, &error));
  EXPECT_NE(error.find("no_such.stl"), std::string::npos) << error;
  Geometry package = missing;
  package.uri = "package://nowhere/x.stl";
  EXPECT_FALSE(CalcGeometryBounds(package, options, &error));
  Geometry nan_scale = MeshGeometry("box_binary.stl", Eigen::Vector3d(1, NAN, 1), Pose{});
  EXPECT_FALSE(CalcGeometryBounds(nan_scale, options, &error));
  Geometry other;
  other.type = Geometry::Type::kOther;
  EXPECT_FALSE(CalcGeometryBounds(other, options, &error));
}

TEST(MeshBoundsTest, LinkBoxIsTheUnionOfEveryGeometryAndCountsTheUnknownOnes) {
  MeshCache cache;
  MeshResolveOptions options;
  options.use_environment = false;
  options.cache = &cache;
  const LinkBoxFunction box_of = MakeLinkBoxFunction(options);
  Link link;
  link.name = "l";
  Geometry collision;  // a box 0.2 × 0.2 × 0.2 centred at (−1, 0, 0): [−1.1, −0.9] × [−0.1, 0.1]²
  collision.type = Geometry::Type::kBox;
  collision.size = Eigen::Vector3d::Constant(0.2);
  collision.X_BG.p_AB = Eigen::Vector3d(-1, 0, 0);
  link.geometries.push_back(collision);
  Geometry visual = MeshGeometry("box_binary.stl", Eigen::Vector3d::Ones(), Pose{});
  visual.is_collision = false;
  link.geometries.push_back(visual);
  Geometry lost = MeshGeometry("no_such.stl", Eigen::Vector3d::Ones(), Pose{});
  lost.is_collision = false;
  link.geometries.push_back(lost);
  const std::optional<LinkGeometryBox> box = box_of(link);
  ASSERT_TRUE(box);
  EXPECT_EQ(box->known, 2);
  EXPECT_EQ(box->meshes, 1);
  EXPECT_EQ(box->unknown, 1);
  EXPECT_TRUE(box->from_collision);
  EXPECT_EQ(box->unresolved_uri, lost.uri);
  // Union of [−1.1, −0.9] × [−0.1, 0.1]² and [0, 0.1] × [0, 0.2] × [0, 0.3] (by hand).
  ExpectBox(box->box_B, Eigen::Vector3d(-1.1, -0.1, -0.1), Eigen::Vector3d(F(0.1), F(0.2), F(0.3)),
            1e-12, "link");
  EXPECT_FALSE(box_of(Link{}));  // no geometry
}

}  // namespace
}  // namespace massprops
