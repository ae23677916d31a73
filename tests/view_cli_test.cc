// `massprops view` and `report --format html` end to end, without a browser: the page's JSON
// block (docs/view.md) read back and checked against numbers worked out by hand. The page in a
// real browser is tested by tests/browser/view_browser_test.py.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "shared_data.h"
#include "tool_runner.h"

namespace {

using massprops::test_support::RunTool;
using massprops::test_support::ToolRun;
using nlohmann::json;

const std::string kFixture = std::string("'") + MASSPROPS_TESTDATA_DIR + "/view/five_links.urdf'";
const std::string kCorpus = MASSPROPS_CORPUS_DIR;

// The JSON block of a page.
json PageData(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"massprops-data\">";
  const std::size_t begin = page.find(open);
  if (begin == std::string::npos) return nullptr;
  const std::size_t end = page.find("</script>", begin);
  if (end == std::string::npos) return nullptr;
  return json::parse(page.substr(begin + open.size(), end - begin - open.size()));
}

const json& Link(const json& model, const std::string& name) {
  for (const json& link : model["links"]) {
    if (link["name"] == name) return link;
  }
  static const json kNone;
  return kNone;
}

TEST(ViewCliTest, PageHoldsOneScriptAndTheEquivalentBoxOfEachLink) {
  const ToolRun run = RunTool("view " + kFixture);
  ASSERT_EQ(run.exit_code, 0);
  // One data block and one script, nothing fetched from elsewhere.
  std::size_t scripts = 0;
  for (std::size_t at = run.output.find("<script"); at != std::string::npos;
       at = run.output.find("<script", at + 1)) {
    ++scripts;
  }
  EXPECT_EQ(scripts, 2u);
  EXPECT_EQ(run.output.find("<script src"), std::string::npos);
  EXPECT_EQ(run.output.find("<link rel=\"stylesheet\""), std::string::npos);

  const json data = PageData(run.output);
  ASSERT_TRUE(data.is_object());
  ASSERT_EQ(data["models"].size(), 1u);
  const json& model = data["models"][0];
  EXPECT_EQ(model["name"], "five_links");
  EXPECT_EQ(model["links"].size(), 5u);

  // base's inertia is that of a uniform 2 kg box 0.3 x 0.2 x 0.1 m (m/12 (b² + c²) etc., the
  // numbers of the fixture): its equivalent box is that box, sides in the order of ascending
  // principal moments, along the inertial frame's axes (rpy 0 0 0.3) at its origin.
  const json& base = Link(model, "base");
  ASSERT_TRUE(base.is_object());
  EXPECT_TRUE(base["box_exists"].get<bool>());
  const double sides[3] = {0.3, 0.2, 0.1};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(base["box"][k].get<double>(), sides[k], 1e-12);
  // First principal axis (smallest moment, longest side) = the inertial frame's x axis rotated by
  // 0.3 rad about z, up to sign; the COM is the inertial origin (base is the root).
  EXPECT_NEAR(std::abs(base["axes"][0].get<double>()), std::cos(0.3), 1e-9);
  EXPECT_NEAR(std::abs(base["axes"][3].get<double>()), std::sin(0.3), 1e-9);
  EXPECT_NEAR(base["com"][0].get<double>(), 0.01, 1e-15);
  EXPECT_NEAR(base["com"][2].get<double>(), 0.05, 1e-15);
  // Uniform solid ellipsoid with the same moments: a_k² = 5 (I_i + I_j − I_k)/(2m) = (5/12) s_k²
  // (hand-derived from the box and ellipsoid moments m (b² + c²)/12 and m (b² + c²)/5).
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(base["ellipsoid"][k].get<double>(), std::sqrt(5.0 / 12.0) * sides[k], 1e-12);
  }

  // bad: izz = 0.01 > ixx + iyy = 0.002, so no box: sides sqrt(6 (λi + λj − λk)/m) clamped at 0:
  // moments 0.001, 0.001, 0.01, m = 0.5: sqrt(12 · 0.01) twice and 0.
  const json& bad = Link(model, "bad");
  EXPECT_FALSE(bad["box_exists"].get<bool>());
  EXPECT_NEAR(bad["box"][0].get<double>(), std::sqrt(0.12), 1e-12);
  EXPECT_NEAR(bad["box"][1].get<double>(), std::sqrt(0.12), 1e-12);
  EXPECT_EQ(bad["box"][2].get<double>(), 0.0);
  bool not_physical = false;
  for (const json& finding : bad["findings"]) {
    if (finding["rule"] == "inertia-not-physical") {
      not_physical = true;
      EXPECT_EQ(finding["severity"], "error");
      EXPECT_GT(finding["line"].get<int>(), 0);
      EXPECT_TRUE(finding["fixed_by_repair"].get<bool>());
    }
  }
  EXPECT_TRUE(not_physical);
  EXPECT_TRUE(bad["repair"].is_string());

  // camera_frame has no <inertial>: URDF mass 0, no box. Its pose: 0.1 0 0.1 from base.
  const json& camera = Link(model, "camera_frame");
  EXPECT_TRUE(camera["box"].is_null());
  EXPECT_NEAR(camera["pose"]["p"][0].get<double>(), 0.1, 1e-15);
  EXPECT_NEAR(camera["pose"]["p"][2].get<double>(), 0.1, 1e-15);

  // Two welded groups of two links: base + camera_frame (2 kg) and arm + tool (1.5 kg); the
  // total is the sum of the masses.
  ASSERT_EQ(model["groups"].size(), 2u);
  EXPECT_EQ(model["groups"][0]["root"], "base");
  EXPECT_NEAR(model["groups"][0]["mass"].get<double>(), 2, 1e-12);
  EXPECT_EQ(model["groups"][1]["root"], "arm");
  EXPECT_NEAR(model["groups"][1]["mass"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(model["total"]["mass"].get<double>(), 2 + 1.2 + 0.5 + 0.3, 1e-12);
}

TEST(ViewCliTest, MeshesAreDrawnFromTheirFilesAndDecimated) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus");
  const std::string model =
      "'" + kCorpus +
      "/example-robot-data/robots/double_pendulum_description/urdf/double_pendulum.urdf'";
  const ToolRun run = RunTool("view " + model + " --package-path '" + kCorpus + "'");
  ASSERT_EQ(run.exit_code, 0);
  const json data = PageData(run.output);
  ASSERT_TRUE(data.is_object());
  ASSERT_FALSE(data["meshes"].empty());
  for (const json& mesh : data["meshes"]) {
    const std::size_t triangles = mesh["t"].size() / 3;
    EXPECT_GT(triangles, 0u);
    EXPECT_LE(triangles, 4000u);  // kMaxMeshTriangles
    EXPECT_LE(triangles, mesh["triangles_in_file"].get<std::size_t>());
    for (const json& q : mesh["q"]) {
      ASSERT_GE(q.get<int>(), 0);
      ASSERT_LE(q.get<int>(), 4095);
    }
    for (const json& index : mesh["t"]) ASSERT_LT(index.get<std::size_t>(), mesh["q"].size() / 3);
  }
  // Without the package path they are found too: example-robot-data is an ancestor folder of
  // the model (docs/meshes.md, "Packages found with no flags").
  const ToolRun found = RunTool("view " + model);
  ASSERT_EQ(found.exit_code, 0);
  EXPECT_EQ(PageData(found.output)["meshes"].size(), data["meshes"].size());
  // A mesh found nowhere (package://nowhere/...): the page says why, per geometry.
  const ToolRun lost =
      RunTool(std::string("view '") + MASSPROPS_TESTDATA_DIR + "/check/mesh-unresolved.urdf'");
  ASSERT_EQ(lost.exit_code, 0);
  const json lost_data = PageData(lost.output);
  const json& error = lost_data["models"][0]["links"][0]["geometry"][0]["error"];
  ASSERT_TRUE(error.is_string());
  EXPECT_NE(error.get<std::string>().find("package 'nowhere' not found"), std::string::npos)
      << error;
}

TEST(ViewCliTest, MjcfBodiesAreDrawnWithTheirGeomsAndEquivalentBoxes) {
  // Gymnasium's ant (testdata/mjcf/MANIFEST.tsv): the world, the torso and 12 leg bodies; the
  // torso a sphere of radius 0.25 at density 5 (the file's <default> geom), the legs 12 capsules
  // written with fromto, the floor a plane of the world.
  const ToolRun run =
      RunTool(std::string("view '") + MASSPROPS_TESTDATA_DIR + "/mjcf/gymnasium/ant.xml'");
  ASSERT_EQ(run.exit_code, 0);
  const json data = PageData(run.output);
  ASSERT_TRUE(data.is_object());
  const json& model = data["models"][0];
  EXPECT_EQ(model["links"].size(), 14u);
  int capsules = 0;
  for (const json& link : model["links"]) {
    for (const json& g : link["geometry"]) capsules += g["type"] == "capsule" ? 1 : 0;
  }
  EXPECT_EQ(capsules, 12);
  const json& torso = Link(model, "torso");
  ASSERT_EQ(torso["geometry"].size(), 1u);
  EXPECT_EQ(torso["geometry"][0]["type"], "sphere");
  EXPECT_DOUBLE_EQ(torso["geometry"][0]["radius"].get<double>(), 0.25);
  // m = ρ·4/3·π·r³; a solid sphere's equivalent box: m/6·a² = 2/5·m·r², so a = r·√2.4.
  const double r = 0.25, mass = 5 * 4.0 / 3 * M_PI * r * r * r;
  EXPECT_NEAR(torso["mass"].get<double>(), mass, 1e-12 * mass);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(torso["box"][i].get<double>(), r * std::sqrt(2.4), 1e-12);
}

TEST(ViewCliTest, ReportFormatHtmlWritesTheSamePage) {
  const ToolRun view = RunTool("view " + kFixture + " -o -");
  const ToolRun report = RunTool("report --format html " + kFixture);
  ASSERT_EQ(report.exit_code, 0);
  EXPECT_EQ(view.output, report.output);
  // The page is of the zero configuration: joint values and frames are refused.
  EXPECT_EQ(RunTool("report --format html --joint shoulder=1 " + kFixture).exit_code, 2);
}

TEST(ViewCliTest, UnreadableFileGivesExitCodeTwoAndAPageThatSaysWhy) {
  const std::string missing = std::string("'") + MASSPROPS_TESTDATA_DIR + "/view/missing.urdf'";
  const ToolRun run = RunTool("view " + missing);
  EXPECT_EQ(run.exit_code, 2);
  const json data = PageData(run.output);
  ASSERT_TRUE(data.is_object());
  EXPECT_TRUE(data["models"].empty());
  ASSERT_EQ(data["errors"].size(), 1u);
}

TEST(ViewCliTest, TextThatLooksLikeMarkupCannotEndTheDataBlock) {
  // A link named "</script><script>alert(1)</script>" (escaped in the XML) stays inside the JSON.
  const std::string urdf =
      "<robot name='r'><link name='&lt;/script&gt;&lt;b&gt;'><inertial><mass value='1'/>"
      "<inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial></link></robot>";
  const ToolRun run = RunTool("view - <<'EOF'\n" + urdf + "\nEOF\n");
  ASSERT_EQ(run.exit_code, 0);
  const json data = PageData(run.output);
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["models"][0]["links"][0]["name"], "</script><b>");
}

}  // namespace
