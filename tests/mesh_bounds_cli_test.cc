// End-to-end tests of the meshes' bounding boxes that `massprops check` and `fix` read by default
// (issue 12): mesh-only links are judged against their size, `--no-geometry` turns it off, and
// meshes that do not resolve are one summary line. Fixtures: testdata/check/mesh-only-absurd-
// inertia.urdf and mesh-unresolved.urdf (their comments work out the numbers by hand).

#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tool_runner.h"

namespace massprops {
namespace {

using test_support::RunTool;
using test_support::ToolRun;

const std::string kCheckDir = std::string(MASSPROPS_TESTDATA_DIR) + "/check";
const std::string kAbsurd = kCheckDir + "/mesh-only-absurd-inertia.urdf";
const std::string kUnresolved = kCheckDir + "/mesh-unresolved.urdf";
const std::string kDefects = std::string(MASSPROPS_TESTDATA_DIR) + "/geometry/mesh_defects.urdf";

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

TEST(MeshBoundsCliTest, MeshOnlyLinksWithAbsurdInertiasAreFlaggedByDefault) {
  // --explain: each finding's full reasoning (its message) under its headline (issue 32).
  const ToolRun run = RunTool("check --explain --fail-on warning '" + kAbsurd + "'");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  // finger: 0.1 kg, k = 0.67 m in a 0.1 × 0.2 × 0.3 m mesh: spread tr(I)/2 = 0.0448905 against
  // m·(1.1e)² = 0.1 · 1.21 · 0.035 = 0.004235 (a whole CAD mesh is the part's envelope: 1.1
  // half-diagonals, docs/rules.md), ratio 0.0448905 / 0.004235 = 10.5999.
  EXPECT_NE(run.output.find("link 'finger': no mass distribution inside the bounding box of the "
                            "collision mesh geometry"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("ratio 10.5999)\n"), std::string::npos);
  EXPECT_NE(run.output.find("link 'finger': inertia 10.6x too large for its size (mass changed?) "
                            "[inertia-exceeds-geometry]"),
            std::string::npos)
      << run.output;
  // base: 0.7 kg, k = 13 mm in the mesh scaled by 3 (e = 0.561249 m): k/e = 0.0231627.
  // The why is wrapped under "  = why: " (9 columns): read it as one line.
  const std::string why = std::regex_replace(run.output, std::regex("\n {9}"), " ");
  EXPECT_NE(why.find("link 'base': radius of gyration sqrt(tr(I)/(2m)) = 0.013 m is "
                     "0.0231627 times the half-diagonal 0.561249 m of its visual mesh"),
            std::string::npos)
      << run.output;
  // finger's 0.1 kg over its closed 0.006 m³ mesh is also 16.7 kg/m³, lighter than any solid
  // (density-implausible); base's units-suspect already says its unit slip.
  EXPECT_NE(run.output.find("link 'finger': mass 0.1 kg over the volume 0.006 m³"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(Count(run.output, "warning:"), 3) << run.output;
  EXPECT_EQ(run.output.find("did not resolve"), std::string::npos);
}

TEST(MeshBoundsCliTest, NoGeometryRestoresTheJudgementWithoutMeshes) {
  // Without the meshes these links have no geometry of known size, and neither radius of
  // gyration exceeds the 10 m that is flagged without geometry: nothing to say (as before
  // issue 12).
  // Their numbers alone still say one thing (issue 49): base's 0.7 kg with tr(I) = 2.37e-4 kg·m²
  // is more compact than a ball of osmium of 0.7 kg ((6/5) · 0.7 · r², r = (3 · 0.7 / (4π ·
  // 22590))^(1/3): 3.19e-4), the inertia-too-compact note; no warning.
  ToolRun run = RunTool("check --no-geometry --fail-on warning '" + kAbsurd + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("link 'base': inertia 0.742x that of a ball of osmium"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("massprops: checked 1 file: 0 errors, 0 warnings, 1 note\n"),
            std::string::npos)
      << run.output;
  run = RunTool("check --no-geometry '" + kUnresolved + "'");
  EXPECT_EQ(run.output, "massprops: checked 1 file: 0 errors, 0 warnings, 0 notes\n");
  run = RunTool("check --no-geometry --format json '" + kUnresolved + "'");
  const nlohmann::json report = nlohmann::json::parse(run.output);
  EXPECT_EQ(report.at("summary").at("mesh_links"), 0);
  EXPECT_EQ(report.at("summary").at("mesh_links_unresolved"), 0);
  EXPECT_TRUE(report.at("summary").at("first_unresolved_mesh").is_null());
  // The mesh-only defects of mesh_defects.urdf (a mass in grams, an inertia about the origin, a
  // mesh in millimetres) are seen by default, and not with --no-geometry.
  run = RunTool("check --no-geometry '" + kDefects + "'");
  EXPECT_NE(run.output.find("0 warnings"), std::string::npos) << run.output;
  run = RunTool("check '" + kDefects + "'");
  EXPECT_NE(run.output.find("3 warnings"), std::string::npos) << run.output;
  // Both at once is a usage error.
  EXPECT_EQ(RunTool("check --geometry --no-geometry '" + kAbsurd + "'").exit_code, 2);
}

TEST(MeshBoundsCliTest, MeshesThatDoNotResolveAreOneLineOfTheSummary) {
  ToolRun run = RunTool("check '" + kUnresolved + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(Count(run.output, "did not resolve"), 1) << run.output;
  EXPECT_NE(run.output.find("massprops: 3 links' meshes did not resolve or could not be read: "
                            "their size is unknown to the geometry rules (use --package-path DIR; "
                            "first: 'package://nowhere/meshes/a.stl')\n"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(Count(run.output, "warning:"), 0) << run.output;  // no finding per link
  EXPECT_EQ(RunTool("check --quiet '" + kUnresolved + "'").output, "");

  run = RunTool("check --format json '" + kUnresolved + "'");
  const nlohmann::json report = nlohmann::json::parse(run.output);
  const nlohmann::json& summary = report.at("summary");
  EXPECT_EQ(summary.at("mesh_links"), 4);  // a, b, c and d (whose mesh resolves)
  EXPECT_EQ(summary.at("mesh_links_unresolved"), 3);
  EXPECT_EQ(summary.at("first_unresolved_mesh"), "package://nowhere/meshes/a.stl");
  EXPECT_EQ(summary.at("warnings"), 0);

  // An MJCF mesh written inline (vertex and face, no file) that cannot be used has no filename.
  run = RunTool("check --format json '" + std::string(MASSPROPS_TESTDATA_DIR) +
                "/fuzz/regressions/mjcf/face-index-not-an-int32'");
  const nlohmann::json inline_mesh = nlohmann::json::parse(run.output).at("summary");
  EXPECT_EQ(inline_mesh.at("mesh_links_unresolved"), 1);
  EXPECT_EQ(inline_mesh.at("first_unresolved_mesh"), "(no filename)");

  run = RunTool("check --format sarif '" + kUnresolved + "'");
  const nlohmann::json sarif = nlohmann::json::parse(run.output);
  const nlohmann::json& properties = sarif.at("runs").at(0).at("properties");
  EXPECT_EQ(properties.at("mesh_links_unresolved"), 3);

  // --geometry names each mesh that cannot be used (mesh-unreadable: a has two) instead.
  run = RunTool("check --geometry '" + kUnresolved + "'");
  EXPECT_EQ(Count(run.output, "[mesh-unreadable]"), 4) << run.output;
  EXPECT_EQ(run.output.find("did not resolve or could not be read"), std::string::npos);
}

TEST(MeshBoundsCliTest, StlAndObjBoxesAreReadWithoutLoadingTheMeshLibraries) {
  // glibc's loader names every library it opens under LD_DEBUG=files: the default reads the STL
  // boxes directly; --geometry loads assimp (libmassprops_meshlibs.so) for the ascii STL's
  // points (a closed binary STL is integrated and its points read without it: issue 33).
  // --no-cache: what a run reads when no earlier run left the numbers in the cache.
  const std::string command =
      std::string("LD_DEBUG=files '") + MASSPROPS_TOOL_PATH + "' check --no-cache ";
  auto opened = [&](const std::string& args) {  // the loader's messages (standard error)
    std::string text;
    FILE* pipe = popen((command + args + " 2>&1 >/dev/null").c_str(), "r");
    if (pipe == nullptr) return text;
    char buffer[4096];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) text.append(buffer, n);
    pclose(pipe);
    return text;
  };
  const std::string quiet = opened("'" + kAbsurd + "'");
  const std::string full = opened("--geometry '" + kAbsurd + "'");
  if (full.find("libstdc++.so") == std::string::npos) GTEST_SKIP() << "no LD_DEBUG output";
  EXPECT_EQ(quiet.find("massprops_meshlibs"), std::string::npos);
  EXPECT_NE(full.find("massprops_meshlibs"), std::string::npos);
  // The tool has the library's objects linked in (CMakeLists.txt, docs/benchmarks.md section 3):
  // it never loads libmassprops.so, not even with the mesh module, which links no copy of it.
  EXPECT_EQ(quiet.find("libmassprops.so"), std::string::npos) << quiet;
  EXPECT_EQ(full.find("libmassprops.so"), std::string::npos) << full;
  // yaml-cpp is in the same module (src/io/yaml_scalars.h, issue 33): only a .yaml file of a
  // xacro package maps it, never a start-up.
  EXPECT_EQ(quiet.find("libyaml-cpp"), std::string::npos) << quiet;
}

TEST(MeshBoundsCliTest, FixJudgesAndRechecksWithTheSameMeshBoxes) {
  // base (0.7 kg, k = 13 mm in a mesh of half-diagonal 0.561 m): read as grams, 0.7 g gives
  // k = 0.013·√1000 = 0.411 m, 0.73 of the half-diagonal: the repair `check`'s finding implies.
  ToolRun run = RunTool("fix --diff --apply units-suspect '" + kAbsurd + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("+      <mass value=\"7e-04\"/>"), std::string::npos) << run.output;
  run = RunTool("fix --diff --no-geometry --apply units-suspect '" + kAbsurd + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output, "") << run.output;
}

}  // namespace
}  // namespace massprops
