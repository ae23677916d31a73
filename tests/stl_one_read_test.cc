// A binary STL read once, without assimp (src/mesh/stl_direct.cc): MeshCache's mesh of it must be
// LoadMeshFile's (assimp 5.2's importer and vertex joining), vertex for vertex, so that every
// number derived from it is the same. The reference in every test is assimp itself (LoadMeshFile
// reads through it), the second library the direct reader is held to.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "massprops/mesh/mesh_inertia.h"
#include "massprops/mesh/mesh_loader.h"
#include "mesh_test_support.h"
#include "shared_data.h"

namespace massprops {
namespace {
namespace fs = std::filesystem;

const std::string kMeshDir = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh";

using testing_support::ExpectSameMesh;

std::string Facet(const std::array<float, 3>& n, const std::array<std::array<float, 3>, 3>& corners,
                  std::uint16_t attribute) {
  std::string bytes(reinterpret_cast<const char*>(n.data()), 12);
  for (const auto& c : corners) bytes.append(reinterpret_cast<const char*>(c.data()), 12);
  bytes.append(reinterpret_cast<const char*>(&attribute), 2);
  return bytes;
}

// A closed tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), wound outward, with a -0 written for
// some zero coordinates, a facet normal within 1e-5 of another's at two shared corners (joined by
// assimp), `header` as its 80-byte header and `attribute` on the last facet.
std::string Tetrahedron(const std::string& header, std::uint16_t attribute) {
  std::string bytes = header;
  bytes.resize(80, ' ');
  const std::uint32_t count = 4;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  const float r = 1 / std::sqrt(3.0f);
  bytes += Facet({0, 0, -1}, {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}}, 0);
  bytes += Facet({0, -1, 0}, {{{-0.0f, 0, 0}, {1, 0, -0.0f}, {0, 0, 1}}}, 0);
  // The normal written is not the facet's (files often hold wrong ones): within 1e-5 of the
  // first facet's, so assimp joins the two corners this facet shares with it.
  bytes += Facet({0, 1e-6f, -1}, {{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}}, 0);
  bytes += Facet({r, r, r + 1e-6f}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, attribute);
  return bytes;
}

class StlOneReadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-stl-test-XXXXXX").string();
    folder_ = mkdtemp(pattern.data());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(folder_, ec);
  }
  std::string Write(const std::string& name, const std::string& bytes) {
    const std::string path = folder_ + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  std::string folder_;
};

void ExpectLoaderMesh(const std::string& path) {
  MeshCache cache;
  std::string error;
  const std::shared_ptr<const TriangleMesh> direct = cache.Load(path, &error);
  ASSERT_TRUE(direct) << path << ": " << error;
  TriangleMesh assimp;
  ASSERT_TRUE(LoadMeshFile(path, &assimp, &error)) << path << ": " << error;
  ExpectSameMesh(*direct, assimp, path);
  // The hull-bound points: each position of assimp's mesh once, in order of first appearance
  // (counted here with a plain search), and its vertex count.
  std::vector<Eigen::Vector3d> positions;
  for (const Eigen::Vector3d& v : assimp.vertices) {
    bool seen = false;
    for (const Eigen::Vector3d& p : positions) seen = seen || p == v;
    if (!seen) positions.push_back(v);
  }
  const std::shared_ptr<const MeshPoints> points = cache.Points(path, &error);
  ASSERT_TRUE(points) << error;
  EXPECT_EQ(points->loader_vertices, static_cast<std::int64_t>(assimp.vertices.size())) << path;
  ASSERT_EQ(points->positions.size(), positions.size()) << path;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    EXPECT_TRUE(points->positions[i] == positions[i]) << path << " point " << i;
  }
  // The mass properties, from the same read, as assimp's mesh gives them, with each model of an
  // open mesh (closed solid: integrated as it is; convex hull of the loader's vertices; thin
  // shell), and what users are told about the mesh.
  for (const MeshSolidModel model :
       {MeshSolidModel::kClosedSolid, MeshSolidModel::kConvexHull, MeshSolidModel::kThinShell}) {
    MeshInertiaOptions options;
    options.open_mesh_model = model;
    const auto from_cache = cache.MassProperties(path, Eigen::Vector3d(1, 1, 1), options, &error);
    ASSERT_TRUE(from_cache) << error;
    const MeshMassProperties expected = CalcMeshMassProperties(assimp, options);
    const std::string what = path + " as " + ToString(model);
    EXPECT_EQ(from_cache->volume, expected.volume) << what;
    EXPECT_EQ(from_cache->area, expected.area) << what;
    EXPECT_TRUE(from_cache->p_GoGcm_G == expected.p_GoGcm_G) << what;
    EXPECT_TRUE(from_cache->I_GGcm_G.CopyToFullMatrix3() == expected.I_GGcm_G.CopyToFullMatrix3())
        << what;
    EXPECT_EQ(from_cache->diagnostics.model, expected.diagnostics.model) << what;
    EXPECT_EQ(from_cache->diagnostics.boundary_edges, expected.diagnostics.boundary_edges) << what;
    EXPECT_EQ(from_cache->diagnostics.fallback_reason, expected.diagnostics.fallback_reason)
        << what;
    EXPECT_EQ(DescribeMeshDiagnostics(from_cache->diagnostics),
              DescribeMeshDiagnostics(expected.diagnostics))
        << what;
  }
}

TEST_F(StlOneReadTest, BinaryStlIsTheLoadersMeshWithSignedZerosAndNearNormals) {
  ExpectLoaderMesh(Write("tetra.stl", Tetrahedron("plain", 0)));
  // The volume of the unit corner tetrahedron, 1/6, as assimp's mesh gives it.
  MeshCache cache;
  std::string error;
  const auto p = cache.MassProperties(Write("again.stl", Tetrahedron("plain", 0)),
                                      Eigen::Vector3d(1, 1, 1), MeshInertiaOptions{}, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_NEAR(p->volume, 1.0 / 6, 1e-12);
}

// SolidWorks writes "COLOR=" and "MATERIAL=" in the header of every export; assimp gives colors to
// the vertices only when a facet sets bit 15 of its attribute, and then compares them when it
// joins vertices: such a file is left to assimp, the others read directly. Both must give
// assimp's mesh.
TEST_F(StlOneReadTest, ColorHeaderWithAndWithoutColoredFacets) {
  const std::string header = std::string("COLOR=") + "\x7f\x7f\x7f\xff" + " MATERIAL=";
  ExpectLoaderMesh(Write("header_only.stl", Tetrahedron(header, 0)));
  ExpectLoaderMesh(Write("colored_facet.stl", Tetrahedron(header, 0x8000 | 0x1f)));
}

// An open mesh (one facet of the tetrahedron left out): the convex hull of the loader's vertices.
TEST_F(StlOneReadTest, OpenMeshGetsTheHullOfTheLoadersVertices) {
  std::string bytes = Tetrahedron("open", 0);
  const std::uint32_t count = 3;
  bytes.replace(80, 4, reinterpret_cast<const char*>(&count), 4);
  bytes.resize(84 + 50 * 3);
  ExpectLoaderMesh(Write("open.stl", bytes));
}

// Assimp 5.2.4 joins a vertex with any element of its hash bucket that is within 1e-5 in position
// and normal, not only with one at the same position: two nearby positions that share a bucket
// are joined. The direct reader leaves such a file to assimp. The file: the tetrahedron with the
// origin corner of its third facet (whose normal is within 1e-5 of the first's) moved by d < 1e-5
// along x, d chosen so that both positions land in one bucket of assimp's table (its hash: boost's
// hash_combine of std::hash<float>; its bucket count: a std::unordered_map reserved for the 12
// corners, as assimp reserves its own). Assimp's mesh then has one vertex fewer than exact
// positions would give: the test fails if the direct reader does not leave the file to assimp.
TEST_F(StlOneReadTest, NearbyPositionsInOneBucketOfAssimpsTable) {
  std::unordered_map<unsigned, unsigned> probe;
  probe.reserve(12);
  const std::size_t buckets = probe.bucket_count();
  auto bucket = [&](float x) {
    std::size_t seed = 0;
    for (const float c : {x, 0.0f, 0.0f}) {
      seed ^= std::hash<float>()(c) + 0x9e3779b9 + (seed << 6) + (seed >> 2);
    }
    return seed % buckets;
  };
  float d = 0;
  for (int k = 1; k < 90 && d == 0; ++k) {
    if (bucket(k * 1e-7f) == bucket(0.0f)) d = k * 1e-7f;
  }
  ASSERT_GT(d, 0) << "no offset below 1e-5 shares the origin's bucket";
  std::string bytes = Tetrahedron("near", 0);
  // Facet 3 starts at 84 + 2·50; its first corner after the 12-byte normal.
  bytes.replace(84 + 2 * 50 + 12, 4, reinterpret_cast<const char*>(&d), 4);
  const std::string path = Write("near.stl", bytes);
  TriangleMesh assimp;
  std::string error;
  ASSERT_TRUE(LoadMeshFile(path, &assimp, &error)) << error;
  // 12 corners: facet 3's corner (0, 1, 0) joined by its near normal, and its corner (d, 0, 0)
  // joined to the origin (counted by hand: 3 + 3 + 1 + 3 kept).
  EXPECT_EQ(assimp.vertices.size(), 10u);
  ExpectLoaderMesh(path);
}

// The unit cube's surface, each face an n × n grid of squares, two triangles each, wound outward
// with the face's normal: 12·n² facets on 6·n² + 2 distinct positions (Euler: V − E + F = 2 with
// F = 12n², E = 18n²).
std::string GridCube(int n) {
  std::string bytes(80, ' ');
  const std::uint32_t count = 12u * static_cast<std::uint32_t>(n * n);
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {0.0f, 1.0f}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::array<float, 3> normal{0, 0, 0};
      normal[static_cast<std::size_t>(axis)] = side == 0 ? -1.0f : 1.0f;
      auto at = [&](int i, int j) {
        std::array<float, 3> p{};
        p[static_cast<std::size_t>(axis)] = side;
        p[static_cast<std::size_t>(u)] = static_cast<float>(i) / static_cast<float>(n);
        p[static_cast<std::size_t>(v)] = static_cast<float>(j) / static_cast<float>(n);
        return p;
      };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
          if (side == 1.0f) {
            bytes += Facet(normal, {{at(i, j), at(i + 1, j), at(i + 1, j + 1)}}, 0);
            bytes += Facet(normal, {{at(i, j), at(i + 1, j + 1), at(i, j + 1)}}, 0);
          } else {
            bytes += Facet(normal, {{at(i, j), at(i + 1, j + 1), at(i + 1, j)}}, 0);
            bytes += Facet(normal, {{at(i, j), at(i, j + 1), at(i + 1, j + 1)}}, 0);
          }
        }
      }
    }
  }
  return bytes;
}

// A binary STL bigger than the reader's piece (1 310 facets, 65 500 bytes) is read a piece at a
// time: 12·21² = 5 292 facets are four pieces, the last one partial. Its mesh is still assimp's,
// and its numbers are the hand-derived ones of the unit cube.
TEST_F(StlOneReadTest, AFileOfSeveralPiecesIsTheLoadersMesh) {
  const int n = 21;
  const std::string path = Write("grid.stl", GridCube(n));
  ExpectLoaderMesh(path);
  MeshCache cache;
  std::string error;
  const auto points = cache.Points(path, &error);
  ASSERT_TRUE(points) << error;
  EXPECT_EQ(points->positions.size(), static_cast<std::size_t>(6 * n * n + 2));
  const auto p = cache.MassProperties(path, Eigen::Vector3d(1, 1, 1), MeshInertiaOptions{}, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_NEAR(p->volume, 1.0, 1e-12);
  EXPECT_NEAR(p->p_GoGcm_G.x(), 0.5, 1e-12);
  // A solid unit cube about its center: 1/6 (= (1² + 1²)/12) per axis, kg·m² per kg/m³.
  EXPECT_NEAR(p->I_GGcm_G.get_moments()(0), 1.0 / 6, 1e-12);
}

// A binary STL one facet shorter than its header says is no binary STL (assimp's size test): the
// direct reader leaves it to assimp, whose error the user sees.
TEST_F(StlOneReadTest, AFileShorterThanItsHeaderSaysIsLeftToAssimp) {
  std::string bytes = GridCube(21);
  bytes.resize(bytes.size() - 50);
  const std::string path = Write("short.stl", bytes);
  MeshCache cache;
  std::string error;
  TriangleMesh assimp;
  std::string assimp_error;
  const bool assimp_reads = LoadMeshFile(path, &assimp, &assimp_error);
  const auto mesh = cache.Load(path, &error);
  EXPECT_EQ(static_cast<bool>(mesh), assimp_reads);
  if (assimp_reads) {
    testing_support::ExpectSameMesh(*mesh, assimp, path);
  } else {
    EXPECT_EQ(error, assimp_error);
  }
}

// Every binary STL shipped in testdata and in ../shared/corpus (testdata's alone: the tests above).
TEST(StlOneReadCorpusTest, EveryBinaryStlIsTheLoadersMesh) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus");
  const std::vector<std::string> files =
      testing_support::MeshFilesUnder({kMeshDir, std::string(MASSPROPS_CORPUS_DIR)}, {".stl"});
  ASSERT_GE(files.size(), 3u);
  int checked = 0;
  for (const std::string& file : files) {
    TriangleMesh assimp;
    std::string error;
    if (!LoadMeshFile(file, &assimp, &error)) continue;  // unreadable fixtures
    ExpectLoaderMesh(file);
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

}  // namespace
}  // namespace massprops
