// End-to-end tests of how `massprops check`, `report` and the configuration file find meshes
// with no flag (issue 29): packages of the description's repository, package:/// beside the
// file, the configuration's package-paths; and what JSON says of how each mesh was found.
// Layouts are made in a temporary folder; the expected counts are read off each layout.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tool_runner.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;
using test_support::RunTool;
using test_support::ToolRun;

const std::string kBox = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh/box_ascii.stl";

void Write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

void CopyBox(const fs::path& to) {
  fs::create_directories(to.parent_path());
  fs::copy_file(kBox, to, fs::copy_options::overwrite_existing);
}

// A link whose only geometry is the mesh `uri`: 1 kg, the central inertia of the box of
// box_ascii.stl (0.1 × 0.2 × 0.3 m, center (0.05, 0.1, 0.15)): ixx = (0.2² + 0.3²)/12,
// iyy = (0.1² + 0.3²)/12, izz = (0.1² + 0.2²)/12 (solid cuboid).
std::string MeshLink(const std::string& name, const std::string& uri) {
  return "  <link name='" + name +
         "'>\n    <inertial><origin xyz='0.05 0.1 0.15'/><mass value='1'/>"
         "<inertia ixx='0.0108333' iyy='0.0083333' izz='0.0041667' ixy='0' ixz='0' iyz='0'/>"
         "</inertial>\n    <visual><geometry><mesh filename='" +
         uri + "'/></geometry></visual>\n  </link>\n";
}

std::string Fixed(const std::string& parent, const std::string& child) {
  return "  <joint name='" + child + "_joint' type='fixed'><parent link='" + parent +
         "'/><child link='" + child + "'/></joint>\n";
}

std::string Quote(const fs::path& path) { return "'" + path.string() + "'"; }

class MeshResolutionCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    top_ = fs::temp_directory_path() /
           ("massprops_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(top_);
    fs::create_directories(top_);
  }
  void TearDown() override { fs::remove_all(top_); }

  // A repository with the packages robot_description (the description's) and robot_meshes (in
  // a folder named shared_parts); robot.urdf uses one mesh of each and one of no package.
  fs::path MakeRepository() {
    const fs::path repo = top_ / "repo";
    fs::create_directories(repo / ".git");
    Write(repo / "robot_description/package.xml",
          "<package format='3'><name>robot_description</name></package>");
    CopyBox(repo / "robot_description/meshes/base.stl");
    Write(repo / "shared_parts/package.xml",
          "<package format='3'><name>robot_meshes</name></package>");
    CopyBox(repo / "shared_parts/meshes/arm.stl");
    const fs::path urdf = repo / "robot_description/urdf/robot.urdf";
    Write(urdf, "<robot name='r'>\n" +
                    MeshLink("base", "package://robot_description/meshes/base.stl") +
                    MeshLink("arm", "package://robot_meshes/meshes/arm.stl") +
                    MeshLink("lost", "package://nowhere_pkg/x.stl") + Fixed("base", "arm") +
                    Fixed("base", "lost") + "</robot>\n");
    return urdf;
  }

  fs::path top_;
};

TEST_F(MeshResolutionCliTest, CheckFindsTheRepositorysPackagesAndSaysHowInJson) {
  const fs::path urdf = MakeRepository();
  const fs::path repo = top_ / "repo";
  ToolRun run = RunTool("check --format json " + Quote(urdf));
  const nlohmann::json report = nlohmann::json::parse(run.output);
  const nlohmann::json& file = report.at("files").at(0);
  EXPECT_EQ(file.at("mesh_links"), 3);
  EXPECT_EQ(file.at("mesh_links_unresolved"), 1);  // lost
  const nlohmann::json expected_counts = {
      {"flag", 0},        {"repository-package", 2}, {"ancestor", 0}, {"environment", 0},
      {"beside-file", 0}, {"relative", 0},           {"absolute", 0}, {"unresolved", 1}};
  EXPECT_EQ(file.at("mesh_resolution"), expected_counts);
  EXPECT_EQ(report.at("summary").at("mesh_resolution"), expected_counts);
  const nlohmann::json expected_uris = {
      {{"uri", "package://robot_description/meshes/base.stl"},
       {"found_by", "repository-package"},
       {"path", (repo / "robot_description/meshes/base.stl").string()}},
      {{"uri", "package://robot_meshes/meshes/arm.stl"},
       {"found_by", "repository-package"},
       {"path", (repo / "shared_parts/meshes/arm.stl").string()}},
      {{"uri", "package://nowhere_pkg/x.stl"}, {"found_by", "none"}, {"path", nullptr}}};
  EXPECT_EQ(file.at("mesh_uris"), expected_uris);
  EXPECT_EQ(report.at("summary").at("first_unresolved_mesh"), "package://nowhere_pkg/x.stl");

  // The text summary still names what did not resolve.
  run = RunTool("check " + Quote(urdf));
  EXPECT_NE(run.output.find("massprops: 1 link's mesh did not resolve or could not be read: "
                            "their size is unknown to the geometry rules (use --package-path DIR; "
                            "first: 'package://nowhere_pkg/x.stl')"),
            std::string::npos)
      << run.output;

  // SARIF carries the totals; --no-geometry reads no mesh, so lists none.
  run = RunTool("check --format sarif " + Quote(urdf));
  EXPECT_EQ(
      nlohmann::json::parse(run.output).at("runs").at(0).at("properties").at("mesh_resolution"),
      expected_counts);
  run = RunTool("check --no-geometry --format json " + Quote(urdf));
  EXPECT_EQ(nlohmann::json::parse(run.output).at("files").at(0).at("mesh_uris").size(), 0u);

  // --geometry resolves the same way (mesh-unreadable names only the lost mesh; the whole
  // error, with the folder searched, is the reasoning that --explain prints).
  run = RunTool("check --geometry --explain " + Quote(urdf));
  EXPECT_NE(run.output.find("[mesh-unreadable]"), std::string::npos) << run.output;
  // The why is wrapped under "  = why: " (9 columns): read it as one line.
  EXPECT_NE(std::regex_replace(run.output, std::regex("\n {9}"), " ")
                .find("package 'nowhere_pkg' not found in the packages under " + repo.string()),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("robot_meshes"), std::string::npos) << run.output;
}

TEST_F(MeshResolutionCliTest, ReportSaysHowEachMeshOfTheGeometryWasFound) {
  const fs::path urdf = MakeRepository();
  const ToolRun run = RunTool("report --geometry --format json " + Quote(urdf));
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::size_t found = 0;
  for (std::size_t at = run.output.find("\"found_by\": \"repository-package\"");
       at != std::string::npos;
       at = run.output.find("\"found_by\": \"repository-package\"", at + 1)) {
    ++found;
  }
  EXPECT_EQ(found, 2u) << run.output;  // base and arm; lost has a geometry error instead
}

// onshape-to-robot: package:///body_front.stl and package:///meshes/torso_visual.stl beside
// robot.urdf, in no repository with .git (a downloaded export).
TEST_F(MeshResolutionCliTest, AnOnshapeExportsMeshesResolveBesideTheFile) {
  const fs::path duck = top_ / "open_duck_mini_v2";
  CopyBox(duck / "body_front.stl");
  CopyBox(duck / "meshes/torso_visual.stl");
  Write(duck / "robot.urdf", "<robot name='duck'>\n" +
                                 MeshLink("body", "package:///body_front.stl") +
                                 MeshLink("torso", "package:///meshes/torso_visual.stl") +
                                 Fixed("body", "torso") + "</robot>\n");
  ToolRun run = RunTool("check --format json " + Quote(duck / "robot.urdf"));
  const nlohmann::json file = nlohmann::json::parse(run.output).at("files").at(0);
  EXPECT_EQ(file.at("mesh_links"), 2);
  EXPECT_EQ(file.at("mesh_links_unresolved"), 0);
  EXPECT_EQ(file.at("mesh_resolution").at("beside-file"), 2);
  EXPECT_EQ(file.at("mesh_uris").at(1).at("path"), (duck / "meshes/torso_visual.stl").string());
  run = RunTool("check " + Quote(duck / "robot.urdf"));
  EXPECT_EQ(run.output.find("did not resolve"), std::string::npos) << run.output;
}

// .massprops.toml's package-paths (relative to its folder) are searched like --package-path,
// after it, by check and report.
TEST_F(MeshResolutionCliTest, TheConfigurationsPackagePathsAreSearched) {
  const fs::path repo = top_ / "repo";
  fs::create_directories(repo / ".git");
  CopyBox(top_ / "elsewhere/far_pkg/m.stl");  // outside the repository
  const fs::path urdf = repo / "desc/robot.urdf";
  Write(urdf, "<robot name='r'>\n" + MeshLink("base", "package://far_pkg/m.stl") + "</robot>\n");
  ToolRun run = RunTool("check --format json " + Quote(urdf));
  EXPECT_EQ(nlohmann::json::parse(run.output).at("files").at(0).at("mesh_links_unresolved"), 1);
  Write(repo / "desc/.massprops.toml", "package-paths = [\"../../elsewhere\"]\n");
  run = RunTool("check --format json " + Quote(urdf));
  const nlohmann::json file = nlohmann::json::parse(run.output).at("files").at(0);
  EXPECT_EQ(file.at("mesh_links_unresolved"), 0) << run.output;
  EXPECT_EQ(file.at("mesh_uris").at(0).at("found_by"), "flag");
  EXPECT_EQ(file.at("mesh_uris").at(0).at("path"), (top_ / "elsewhere/far_pkg/m.stl").string());
  run = RunTool("report --geometry --format json " + Quote(urdf));
  EXPECT_NE(run.output.find("\"found_by\": \"flag\""), std::string::npos) << run.output;
  // A bad value names the key.
  Write(repo / "desc/.massprops.toml", "package-paths = \"../../elsewhere\"\n");
  run = RunTool("check " + Quote(urdf), true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("'package-paths' must be an array of strings"), std::string::npos)
      << run.output;
}

}  // namespace
}  // namespace massprops
