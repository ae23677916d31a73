// SDF <submesh> (issue 49): a geometry that names one part of a multi-part mesh file is that part
// alone, as placed in the file or recentred on its bounding box (<center>), never the whole file;
// a part the file does not have is a warning and a geometry of unknown size. Fixtures:
// testdata/sdf/submesh.sdf over testdata/mesh/two_boxes.obj (two `o` objects) and
// testdata/mesh/two_parts.dae (named nodes, one mesh under a node without a name); their comments
// give the parts' sizes and places. Expected values are hand-derived from those: a uniform box
// a x b x c has volume abc and, for mass m, central moments m (b^2 + c^2) / 12, m (a^2 + c^2) / 12,
// m (a^2 + b^2) / 12 about its axes; two boxes together follow the parallel-axis theorem
// (I = sum of I_i + m_i (|d_i|^2 1 - d_i d_i^T), d_i from the common center of mass).
// Every coordinate of the fixtures is exact in binary floating point, so tolerances are round-off.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "massprops/io/sdf_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"
#include "tool_runner.h"

namespace massprops {
namespace {

const std::string kTestdata = MASSPROPS_TESTDATA_DIR;
const std::string kSdf = kTestdata + "/sdf/submesh.sdf";
const std::string kObj = kTestdata + "/mesh/two_boxes.obj";
const std::string kDae = kTestdata + "/mesh/two_parts.dae";

// A box's volume, center and central inertia at mass 1 (the formulas of the file comment).
struct Expected {
  double volume;
  Eigen::Vector3d center;
  Eigen::Matrix3d inertia;  // about the center, mass 1
  Eigen::Vector3d lo, hi;   // bounding box in the link frame
};

Eigen::Matrix3d BoxInertia(double a, double b, double c) {
  return Eigen::Vector3d((b * b + c * c) / 12, (a * a + c * c) / 12, (a * a + b * b) / 12)
      .asDiagonal();
}

Expected Box(const Eigen::Vector3d& size, const Eigen::Vector3d& center) {
  return {size.prod(), center, BoxInertia(size.x(), size.y(), size.z()), center - size / 2,
          center + size / 2};
}

// small 0.25 x 0.5 x 0.125 at (1, 0, 0) and large 1 x 0.5 x 2 at (0, 2, 0.5), one density, their
// total mass 1: the parallel-axis theorem about the common center.
Expected WholeObj() {
  const Expected small = Box({0.25, 0.5, 0.125}, {1, 0, 0});
  const Expected large = Box({1, 0.5, 2}, {0, 2, 0.5});
  Expected whole;
  whole.volume = small.volume + large.volume;  // 1.015625
  whole.center = (small.volume * small.center + large.volume * large.center) / whole.volume;
  whole.inertia.setZero();
  for (const Expected* part : {&small, &large}) {
    const double m = part->volume / whole.volume;
    const Eigen::Vector3d d = part->center - whole.center;
    whole.inertia +=
        m * part->inertia + m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  whole.lo = Eigen::Vector3d(-0.5, -0.25, -0.5);
  whole.hi = Eigen::Vector3d(1.125, 2.25, 1.5);
  return whole;
}

std::map<std::string, Expected> ExpectedLinks() {
  return {
      {"small_placed", Box({0.25, 0.5, 0.125}, {1, 0, 0})},
      {"small_centered", Box({0.25, 0.5, 0.125}, {0, 0, 0})},
      // 'large' recentred, then scaled by (2, 1, 0.5): 2 x 0.5 x 1; the collision raised 1 m.
      {"large_scaled", Box({2, 0.5, 1}, {0, 0, 1})},
      // 'Body': the unit cube scaled (2, 1, 1) and moved to (0, 0, 1) by its node.
      {"body_placed", Box({2, 1, 1}, {0, 0, 1})},
      // 'Prop': the unit cube scaled (0.5, 0.25, 0.125), recentred.
      {"prop_centered", Box({0.5, 0.25, 0.125}, {0, 0, 0})},
      {"whole_file", WholeObj()},
  };
}

Model ReadFixture() {
  const ReadResult read = ReadSdfFile(kSdf);
  EXPECT_TRUE(read.ok()) << (read.ok() ? "" : read.errors.front().ToString());
  EXPECT_TRUE(read.warnings.empty());
  EXPECT_EQ(read.models.size(), 1u);
  return read.models.empty() ? Model() : read.models.front();
}

const Link* Find(const Model& model, const std::string& name) {
  const int i = model.FindLink(name);
  return i < 0 ? nullptr : &model.links[static_cast<std::size_t>(i)];
}

MeshResolveOptions Options(MeshCache* cache) {
  MeshResolveOptions options;
  options.model_file = kSdf;
  options.use_environment = false;
  options.search_repository = false;
  options.cache = cache;
  return options;
}

void ExpectGeometryOfLinks(const MeshResolveOptions& options) {
  const Model model = ReadFixture();
  for (const auto& [name, want] : ExpectedLinks()) {
    SCOPED_TRACE(name);
    const Link* link = Find(model, name);
    ASSERT_NE(link, nullptr);
    std::string error;
    const std::optional<LinkGeometryInertia> got =
        CalcLinkGeometryInertia(*link, 1, options, &error);
    ASSERT_TRUE(got) << error;
    EXPECT_NEAR(got->volume, want.volume, 1e-14);
    EXPECT_LT((got->p_BoBcm_B - want.center).norm(), 1e-14) << got->p_BoBcm_B.transpose();
    EXPECT_LT((got->I_BBcm_B.CopyToFullMatrix3() - want.inertia).norm(), 1e-14)
        << got->I_BBcm_B.CopyToFullMatrix3();
    EXPECT_EQ(got->box_B.min(), want.lo);
    EXPECT_EQ(got->box_B.max(), want.hi);
    // The box the default check reads (the file's box scaled and posed: exact here, no rotation).
    ASSERT_EQ(link->geometries.size(), 1u);
    const std::optional<Eigen::AlignedBox3d> box =
        CalcGeometryBounds(link->geometries.front(), options, &error);
    ASSERT_TRUE(box) << error;
    EXPECT_EQ(box->min(), want.lo);
    EXPECT_EQ(box->max(), want.hi);
  }
}

TEST(SubmeshTest, TheReaderKeepsEachMeshsSubmeshNameAndCenterFlag) {
  const Model model = ReadFixture();
  const std::map<std::string, std::pair<std::string, bool>> want = {
      {"small_placed", {"small", false}}, {"small_centered", {"small", true}},
      {"large_scaled", {"large", true}},  {"body_placed", {"Body", false}},
      {"prop_centered", {"Prop", true}},  {"whole_file", {"", false}},
      {"unknown_part", {"n-prop", true}}};
  for (const auto& [name, submesh] : want) {
    const Link* link = Find(model, name);
    ASSERT_NE(link, nullptr) << name;
    ASSERT_EQ(link->geometries.size(), 1u) << name;
    EXPECT_EQ(link->geometries[0].submesh, submesh.first) << name;
    EXPECT_EQ(link->geometries[0].center_submesh, submesh.second) << name;
    EXPECT_EQ(link->geometries[0].submesh_location.line > 0, !submesh.first.empty()) << name;
  }
}

TEST(SubmeshTest, EachLinkIsItsOwnPartWithACache) {
  MeshCache cache;
  ExpectGeometryOfLinks(Options(&cache));
  // Each file imported once for the whole file and all its parts.
  EXPECT_EQ(cache.files_loaded(), 2);
}

TEST(SubmeshTest, EachLinkIsItsOwnPartWithoutACache) { ExpectGeometryOfLinks(Options(nullptr)); }

TEST(SubmeshTest, PartsAreNamedAsGzCommonNamesSubmeshes) {
  MeshCache cache;
  std::string error;
  // OBJ: the `o` objects; DAE: the nodes' names (not their ids), a node without a name under its
  // nearest named ancestor.
  std::optional<std::vector<std::string>> obj = cache.SubmeshNames(kObj, &error);
  ASSERT_TRUE(obj) << error;
  std::sort(obj->begin(), obj->end());
  EXPECT_EQ(*obj, (std::vector<std::string>{"large", "small"}));
  std::optional<std::vector<std::string>> dae = cache.SubmeshNames(kDae, &error);
  ASSERT_TRUE(dae) << error;
  std::sort(dae->begin(), dae->end());
  EXPECT_EQ(*dae, (std::vector<std::string>{"Body", "Prop"}));
  TriangleMesh mesh;
  ASSERT_TRUE(LoadMeshSubmesh(kDae, {"Prop", false}, &mesh, &error)) << error;
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  EXPECT_EQ(box.min(), Eigen::Vector3d(2.75, 0.375, -0.0625));
  EXPECT_EQ(box.max(), Eigen::Vector3d(3.25, 0.625, 0.0625));
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_FALSE(LoadMeshSubmesh(kDae, {"n-prop", true}, &mesh, &error));
  EXPECT_NE(error.find("has no submesh 'n-prop'"), std::string::npos) << error;
  // An STL has no named parts.
  EXPECT_EQ(cache.SubmeshNames(kTestdata + "/mesh/box_binary.stl", &error),
            std::vector<std::string>{});
}

TEST(SubmeshTest, AnUnknownSubmeshIsAGeometryOfUnknownSizeWithAMessage) {
  const Model model = ReadFixture();
  const Link* link = Find(model, "unknown_part");
  ASSERT_NE(link, nullptr);
  MeshCache cache;
  const MeshResolveOptions options = Options(&cache);
  std::string error;
  EXPECT_FALSE(CalcLinkGeometryInertia(*link, 1, options, &error));
  EXPECT_FALSE(CalcGeometryBounds(link->geometries[0], options, &error));
  EXPECT_NE(error.find("no submesh 'n-prop'"), std::string::npos) << error;
  const std::optional<std::string> message = UnknownSubmeshMessage(link->geometries[0], options);
  ASSERT_TRUE(message);
  EXPECT_EQ(*message,
            "mesh '../mesh/two_parts.dae' has no submesh 'n-prop'; its parts are 'Body', 'Prop'; "
            "the geometry's size is unknown to the rules");
  EXPECT_FALSE(UnknownSubmeshMessage(Find(model, "prop_centered")->geometries[0], options));
  EXPECT_FALSE(UnknownSubmeshMessage(Find(model, "whole_file")->geometries[0], options));
}

TEST(SubmeshTest, ThePersistentCacheKeepsPartsAndCenteringApart) {
  const std::string folder = ::testing::TempDir() + "/submesh_cache";
  std::filesystem::remove_all(folder);
  const std::vector<MeshSubmesh> selections = {
      {}, {"small", false}, {"small", true}, {"large", true}};
  std::vector<Eigen::AlignedBox3d> first;
  {
    MeshCache cache;
    cache.UsePersistentCache(folder);
    for (const MeshSubmesh& s : selections) {
      std::string error;
      const std::optional<Eigen::AlignedBox3d> box = cache.Bounds(kObj, &error, s);
      ASSERT_TRUE(box) << error;
      first.push_back(*box);
      ASSERT_TRUE(cache.MassProperties(kObj, Eigen::Vector3d::Ones(), {}, &error, s)) << error;
    }
  }  // written at destruction
  MeshCache again;
  again.UsePersistentCache(folder);
  for (std::size_t i = 0; i < selections.size(); ++i) {
    std::string error;
    const std::optional<Eigen::AlignedBox3d> box = again.Bounds(kObj, &error, selections[i]);
    ASSERT_TRUE(box) << error;
    EXPECT_EQ(box->min(), first[i].min()) << i;
    EXPECT_EQ(box->max(), first[i].max()) << i;
    const std::optional<MeshMassProperties> mass =
        again.MassProperties(kObj, Eigen::Vector3d::Ones(), {}, &error, selections[i]);
    ASSERT_TRUE(mass) << error;
    // Volumes: both boxes 1.015625, 'small' 0.015625 (placed or not), 'large' 1.
    const double volume[] = {1.015625, 0.015625, 0.015625, 1.0};
    EXPECT_NEAR(mass->volume, volume[i], 1e-14) << i;
  }
  EXPECT_EQ(again.files_loaded(), 0);  // all four from the entries the first cache wrote
  EXPECT_EQ(first[1].min(), Eigen::Vector3d(0.875, -0.25, -0.0625));
  EXPECT_EQ(first[2].min(), Eigen::Vector3d(-0.125, -0.25, -0.0625));
  EXPECT_EQ(first[3].max(), Eigen::Vector3d(0.5, 0.25, 1.0));
}

TEST(SubmeshTest, AMissingNameOrABadCenterIsAWarningAndTheWholeFile) {
  const ReadResult read = ReadSdfString(R"(<sdf version="1.9"><model name="m"><link name="l">
  <visual name="v"><geometry><mesh><uri>x.obj</uri>
    <submesh><name> </name><center>yes</center></submesh>
  </mesh></geometry></visual></link></model></sdf>)",
                                        "inline.sdf");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.warnings.size(), 2u);
  EXPECT_EQ(read.warnings[0].location.line, 3);
  EXPECT_NE(read.warnings[0].message.find("no submesh <name>"), std::string::npos);
  EXPECT_NE(read.warnings[1].message.find("'yes' is not a boolean"), std::string::npos);
  const Geometry& g = read.models.at(0).links.at(0).geometries.at(0);
  EXPECT_EQ(g.submesh, "");
  EXPECT_FALSE(g.center_submesh);
}

TEST(SubmeshTest, CheckWarnsAtTheSubmeshAndCountsNoUnresolvedMesh) {
  const test_support::ToolRun run =
      test_support::RunTool("check --explain --no-cache '" + kSdf + "'");
  // unknown_part's <submesh> is line 190 of the fixture.
  EXPECT_NE(run.output.find("submesh.sdf:190: warning: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("no submesh 'n-prop'"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("did not resolve"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace massprops
