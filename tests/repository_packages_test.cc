// Tests of repository_packages.h and of the package:// resolution order of mesh_loader.h
// (MeshResolveOptions): layouts made in a temporary folder, each URI resolving to the file the
// layout puts there (worked out from the layout by hand) or reported unresolved.

#include "massprops/mesh/repository_packages.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "massprops/mesh/mesh_loader.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;

void Write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

void WritePackageXml(const fs::path& folder, const std::string& name) {
  Write(folder / "package.xml", "<?xml version=\"1.0\"?>\n<package format=\"3\">\n  <name> " +
                                    name + " </name>\n  <version>0.1.0</version>\n</package>\n");
}

// A fresh folder under the system's temporary folder, removed at the end of the test.
class RepositoryPackagesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    top_ = fs::temp_directory_path() /
           ("massprops_repo_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(top_);
    fs::create_directories(top_);
  }
  void TearDown() override { fs::remove_all(top_); }

  // Options as the tool makes them for a description at `model_file`, without environment.
  static MeshResolveOptions For(const fs::path& model_file) {
    MeshResolveOptions options;
    options.use_environment = false;
    options.model_file = model_file.string();
    return options;
  }

  // The path `uri` resolves to from `options`, and how; "" and kNone when it does not.
  static std::pair<std::string, MeshFoundBy> Resolve(const std::string& uri,
                                                     const MeshResolveOptions& options,
                                                     std::string* error = nullptr) {
    MeshFoundBy how = MeshFoundBy::kFlag;  // must be overwritten
    std::string reason;
    const std::optional<std::string> path = ResolveMeshUri(uri, options, &reason, &how);
    if (error) *error = reason;
    return {path.value_or(""), how};
  }

  fs::path top_;
};

// A repository (.git) with two packages: robot_description (the description's own) and
// robot_meshes, whose folder is named otherwise (shared_parts): both are found by their
// package.xml, and nothing outside the repository is.
TEST_F(RepositoryPackagesTest, ARepositoryWithTwoPackagesResolvesBothByTheirPackageXml) {
  const fs::path repo = top_ / "repo";
  fs::create_directories(repo / ".git");
  WritePackageXml(repo / "robot_description", "robot_description");
  Write(repo / "robot_description/urdf/robot.urdf", "<robot name='r'/>");
  Write(repo / "robot_description/meshes/base.stl", "solid base\nendsolid base\n");
  WritePackageXml(repo / "shared_parts", "robot_meshes");
  Write(repo / "shared_parts/meshes/arm.stl", "solid arm\nendsolid arm\n");
  WritePackageXml(top_ / "outside", "outside_pkg");  // beside the repository, not in it
  Write(top_ / "outside/x.stl", "solid x\nendsolid x\n");

  const MeshResolveOptions options = For(repo / "robot_description/urdf/robot.urdf");
  EXPECT_EQ(Resolve("package://robot_description/meshes/base.stl", options),
            std::make_pair((repo / "robot_description/meshes/base.stl").string(),
                           MeshFoundBy::kRepositoryPackage));
  EXPECT_EQ(Resolve("package://robot_meshes/meshes/arm.stl", options),
            std::make_pair((repo / "shared_parts/meshes/arm.stl").string(),
                           MeshFoundBy::kRepositoryPackage));
  std::string error;
  EXPECT_EQ(Resolve("package://outside_pkg/x.stl", options, &error).second, MeshFoundBy::kNone);
  EXPECT_NE(error.find("package 'outside_pkg' not found in the packages under " + repo.string()),
            std::string::npos)
      << error;
  EXPECT_EQ(Resolve("package://robot_meshes/meshes/missing.stl", options, &error).second,
            MeshFoundBy::kNone);
  EXPECT_NE(error.find("found but the file is not there: " +
                       (repo / "shared_parts/meshes/missing.stl").string()),
            std::string::npos)
      << error;
}

// A CAD export: the package folder has no package.xml; the nearest ancestor named as the
// package is it.
TEST_F(RepositoryPackagesTest, APackageWithoutPackageXmlIsItsAncestorFolderOfThatName) {
  const fs::path repo = top_ / "cad_export";
  fs::create_directories(repo / ".git");
  Write(repo / "my_robot/urdf/my_robot.urdf", "<robot name='r'/>");
  Write(repo / "my_robot/meshes/a.stl", "solid a\nendsolid a\n");
  const MeshResolveOptions options = For(repo / "my_robot/urdf/my_robot.urdf");
  EXPECT_EQ(Resolve("package://my_robot/meshes/a.stl", options),
            std::make_pair((repo / "my_robot/meshes/a.stl").string(), MeshFoundBy::kAncestor));
  EXPECT_EQ(FindAncestorNamed((repo / "my_robot/urdf").string(), "my_robot"),
            (repo / "my_robot").string());
  // Not an ancestor: a sibling folder of that name is no package without a package.xml.
  Write(repo / "other_robot/meshes/b.stl", "solid b\nendsolid b\n");
  EXPECT_EQ(Resolve("package://other_robot/meshes/b.stl", options).second, MeshFoundBy::kNone);
}

// onshape-to-robot writes package:///file beside the URDF (open_duck_mini_v2/robot.urdf +
// body_front.stl; toddlerbot's meshes/torso_visual.stl).
TEST_F(RepositoryPackagesTest, AnEmptyPackageNameIsTheFolderOfTheDescription) {
  const fs::path duck = top_ / "open_duck_mini_v2";
  Write(duck / "robot.urdf", "<robot name='duck'/>");
  Write(duck / "body_front.stl", "solid b\nendsolid b\n");
  Write(duck / "meshes/torso_visual.stl", "solid t\nendsolid t\n");
  const MeshResolveOptions options = For(duck / "robot.urdf");
  EXPECT_EQ(Resolve("package:///body_front.stl", options),
            std::make_pair((duck / "body_front.stl").string(), MeshFoundBy::kBesideFile));
  EXPECT_EQ(Resolve("package:///meshes/torso_visual.stl", options),
            std::make_pair((duck / "meshes/torso_visual.stl").string(), MeshFoundBy::kBesideFile));
  std::string error;
  EXPECT_EQ(Resolve("package:///missing.stl", options, &error).second, MeshFoundBy::kNone);
  EXPECT_NE(error.find("no such file: " + (duck / "missing.stl").string()), std::string::npos)
      << error;
  EXPECT_NE(error.find("package:/// names a file beside the description"), std::string::npos)
      << error;
  EXPECT_EQ(Resolve("package:///../open_duck_mini_v2/body_front.stl", options, &error).second,
            MeshFoundBy::kNone);
  EXPECT_NE(error.find("leaves the package folder"), std::string::npos) << error;
}

// The folder is named `arm` but its package.xml names `arm_description`: the package.xml wins,
// so package://arm does not resolve there and package://arm_description does.
TEST_F(RepositoryPackagesTest, APackageXmlNamingAnotherPackageWinsOverTheFolderName) {
  const fs::path repo = top_ / "r";
  fs::create_directories(repo / ".git");
  WritePackageXml(repo / "arm", "arm_description");
  Write(repo / "arm/urdf/arm.urdf", "<robot name='arm'/>");
  Write(repo / "arm/meshes/link.stl", "solid l\nendsolid l\n");
  const MeshResolveOptions options = For(repo / "arm/urdf/arm.urdf");
  std::string error;
  EXPECT_EQ(Resolve("package://arm/meshes/link.stl", options, &error).second, MeshFoundBy::kNone);
  EXPECT_NE(error.find("package 'arm' not found"), std::string::npos) << error;
  EXPECT_EQ(
      Resolve("package://arm_description/meshes/link.stl", options),
      std::make_pair((repo / "arm/meshes/link.stl").string(), MeshFoundBy::kRepositoryPackage));
  EXPECT_EQ(FindAncestorNamed((repo / "arm/urdf").string(), "arm"), std::nullopt);
}

// --package-path first, then the repository, then the ancestor, then the environment.
TEST_F(RepositoryPackagesTest, TheOrderIsFlagRepositoryAncestorEnvironment) {
  const fs::path repo = top_ / "ws";
  fs::create_directories(repo / ".git");
  // The package `robot` three times: by package.xml in the repository, as the ancestor of the
  // description (no package.xml), and in a folder given as a flag; and in ROS_PACKAGE_PATH.
  Write(repo / "robot/urdf/robot.urdf", "<robot name='r'/>");
  Write(repo / "robot/m.stl", "solid m\nendsolid m\n");
  WritePackageXml(repo / "src/robot_pkg", "robot");
  Write(repo / "src/robot_pkg/m.stl", "solid m\nendsolid m\n");
  Write(top_ / "flag/robot/m.stl", "solid m\nendsolid m\n");
  Write(top_ / "env/robot/m.stl", "solid m\nendsolid m\n");
  Write(top_ / "env/robot/only_env.stl", "solid m\nendsolid m\n");
  MeshResolveOptions options = For(repo / "robot/urdf/robot.urdf");
  options.package_paths = {(top_ / "flag").string()};
  ASSERT_EQ(setenv("ROS_PACKAGE_PATH", (top_ / "env").string().c_str(), 1), 0);
  options.use_environment = true;
  EXPECT_EQ(Resolve("package://robot/m.stl", options),
            std::make_pair((top_ / "flag/robot/m.stl").string(), MeshFoundBy::kFlag));
  options.package_paths.clear();
  EXPECT_EQ(
      Resolve("package://robot/m.stl", options),
      std::make_pair((repo / "src/robot_pkg/m.stl").string(), MeshFoundBy::kRepositoryPackage));
  fs::remove(repo / "src/robot_pkg/package.xml");
  EXPECT_EQ(Resolve("package://robot/m.stl", options),
            std::make_pair((repo / "robot/m.stl").string(), MeshFoundBy::kAncestor));
  // A file only the environment's package holds: the first package that holds it wins.
  EXPECT_EQ(Resolve("package://robot/only_env.stl", options),
            std::make_pair((top_ / "env/robot/only_env.stl").string(), MeshFoundBy::kEnvironment));
  options.search_repository = false;
  EXPECT_EQ(Resolve("package://robot/m.stl", options),
            std::make_pair((top_ / "env/robot/m.stl").string(), MeshFoundBy::kEnvironment));
  unsetenv("ROS_PACKAGE_PATH");
}

// The crawl skips build/, install/, log/, hidden folders, folders marked COLCON_IGNORE (and the
// like), and does not search inside a package; it goes through submodules (.git files).
TEST_F(RepositoryPackagesTest, TheCrawlSkipsWorkspaceOutputsHiddenAndIgnoredFolders) {
  const fs::path repo = top_ / "repo";
  fs::create_directories(repo / ".git");
  Write(repo / "desc/robot.urdf", "<robot name='r'/>");
  WritePackageXml(repo / "build/p_build", "p_build");
  WritePackageXml(repo / "install/share/p_install", "p_install");
  WritePackageXml(repo / "log/p_log", "p_log");
  WritePackageXml(repo / ".cache/p_hidden", "p_hidden");
  WritePackageXml(repo / "ignored/p_ignored", "p_ignored");
  Write(repo / "ignored/COLCON_IGNORE", "");
  WritePackageXml(repo / "outer", "outer");
  WritePackageXml(repo / "outer/inner", "inner");  // inside a package: not a package
  WritePackageXml(repo / "third_party/sub/p_sub", "p_sub");
  Write(repo / "third_party/sub/.git", "gitdir: ../../.git/modules/sub\n");  // a submodule
  RepositoryPackages packages;
  const std::string from = (repo / "desc").string();
  for (const char* name : {"p_build", "p_install", "p_log", "p_hidden", "p_ignored", "inner"}) {
    EXPECT_EQ(packages.Find(from, name), std::nullopt) << name;
  }
  EXPECT_EQ(packages.Find(from, "outer"), (repo / "outer").string());
  EXPECT_EQ(packages.Find(from, "p_sub"), (repo / "third_party/sub/p_sub").string());
  EXPECT_FALSE(packages.truncated());
  // Listed: desc, then from repo: repo, desc skipped (seen), ignored, outer, third_party,
  // third_party/sub, third_party/sub/p_sub = 7 folders, each once although Find ran 8 times.
  EXPECT_EQ(packages.folders_listed(), 7);
}

// The nearest package of a name wins: the crawl goes up from the description's folder.
TEST_F(RepositoryPackagesTest, TheNearestOfTwoPackagesWithOneNameWins) {
  const fs::path repo = top_ / "repo";
  fs::create_directories(repo / ".git");
  WritePackageXml(repo / "a/shared", "shared");
  WritePackageXml(repo / "b/c/vendor/shared", "shared");
  Write(repo / "b/c/robot.urdf", "<robot name='r'/>");
  RepositoryPackages packages;
  EXPECT_EQ(packages.Find((repo / "b/c").string(), "shared"),
            (repo / "b/c/vendor/shared").string());
  // From elsewhere the shallower one is nearer.
  EXPECT_EQ(packages.Find((repo / "d").string(), "shared"), (repo / "a/shared").string());
}

// The crawl lists at most max_folders folders per run; a package beyond is not found and
// truncated() says so.
TEST_F(RepositoryPackagesTest, TheCrawlStopsAtItsBound) {
  const fs::path repo = top_ / "repo";
  fs::create_directories(repo / ".git");
  for (int i = 0; i < 20; ++i) fs::create_directories(repo / ("d" + std::to_string(100 + i)));
  WritePackageXml(repo / "zz_last", "last");
  RepositoryPackages bounded(10);
  EXPECT_EQ(bounded.Find(repo.string(), "last"), std::nullopt);
  EXPECT_TRUE(bounded.truncated());
  EXPECT_EQ(bounded.folders_listed(), 10);
  RepositoryPackages enough(100);  // repo, 20 folders, zz_last = 22 listed
  EXPECT_EQ(enough.Find(repo.string(), "last"), (repo / "zz_last").string());
  EXPECT_FALSE(enough.truncated());
  EXPECT_EQ(enough.folders_listed(), 22);
}

TEST_F(RepositoryPackagesTest, TheRepositoryRootIsTheNearestFolderWithDotGit) {
  const fs::path repo = top_ / "repo";
  Write(repo / ".git", "gitdir: /elsewhere/worktrees/repo\n");  // a worktree's .git file
  fs::create_directories(repo / "a/b");
  EXPECT_EQ(FindRepositoryRoot((repo / "a/b").string()), repo.string());
  EXPECT_EQ(FindRepositoryRoot((repo / "a/b/").string()), repo.string());
  EXPECT_EQ(FindRepositoryRoot(repo.string()), repo.string());
  EXPECT_EQ(FindPackageSearchRoot((repo / "a/b").string()), repo.string());
  // No .git above: the filesystem root (the temporary folder is in no repository here).
  if (FindRepositoryRoot(top_.string()) == "/") {
    EXPECT_EQ(FindRepositoryRoot((top_ / "no_git/x").string()), "/");
  }
}

// Outside a repository the crawl covers the folder that holds the description's package (a
// downloaded archive of a repository: its packages are siblings), else the description's own
// folder; never the whole file system.
TEST_F(RepositoryPackagesTest, OutsideARepositoryTheCrawlCoversTheFolderThatHoldsThePackage) {
  if (FindRepositoryRoot(top_.string()) != "/") GTEST_SKIP() << "the temporary folder has a .git";
  const fs::path archive = top_ / "robot-main";  // unpacked, no .git
  WritePackageXml(archive / "robot_description", "robot_description");
  Write(archive / "robot_description/urdf/robot.urdf", "<robot name='r'/>");
  WritePackageXml(archive / "robot_meshes", "robot_meshes");
  Write(archive / "robot_meshes/m.stl", "solid m\nendsolid m\n");
  WritePackageXml(top_ / "beside_archive", "beside");  // above the archive: not searched
  const fs::path urdf_folder = archive / "robot_description/urdf";
  EXPECT_EQ(FindPackageSearchRoot(urdf_folder.string()), archive.string());
  const MeshResolveOptions options = For(urdf_folder / "robot.urdf");
  EXPECT_EQ(
      Resolve("package://robot_meshes/m.stl", options),
      std::make_pair((archive / "robot_meshes/m.stl").string(), MeshFoundBy::kRepositoryPackage));
  EXPECT_EQ(RepositoryPackages().Find(urdf_folder.string(), "beside"), std::nullopt);
  // No package.xml above: only the description's folder.
  fs::create_directories(top_ / "loose/urdf");
  EXPECT_EQ(FindPackageSearchRoot((top_ / "loose/urdf").string()), (top_ / "loose/urdf").string());
}

TEST_F(RepositoryPackagesTest, PackageXmlNameIsTrimmedAndBadManifestsNameNothing) {
  WritePackageXml(top_ / "ok", "ok_pkg");
  Write(top_ / "broken/package.xml", "<package><name>unclosed");
  Write(top_ / "nameless/package.xml", "<package><version>1</version></package>");
  EXPECT_EQ(PackageXmlName((top_ / "ok").string()), "ok_pkg");
  EXPECT_EQ(PackageXmlName((top_ / "broken").string()), "");
  EXPECT_EQ(PackageXmlName((top_ / "nameless").string()), "");
  EXPECT_EQ(PackageXmlName((top_ / "absent").string()), "");
}

// One MeshCache per run: its crawl is shared by the files of the run and each URI is resolved
// once per description folder.
TEST_F(RepositoryPackagesTest, TheCacheCrawlsOncePerRun) {
  const fs::path repo = top_ / "repo";
  fs::create_directories(repo / ".git");
  WritePackageXml(repo / "pkg", "pkg");
  Write(repo / "pkg/m.stl", "solid m\nendsolid m\n");
  Write(repo / "one/a.urdf", "<robot name='a'/>");
  Write(repo / "two/b.urdf", "<robot name='b'/>");
  MeshCache cache;
  MeshResolveOptions options = For(repo / "one/a.urdf");
  options.cache = &cache;
  MeshFoundBy how = MeshFoundBy::kNone;
  std::string error;
  EXPECT_EQ(cache.Resolve("package://pkg/m.stl", options, &error, &how),
            (repo / "pkg/m.stl").string());
  EXPECT_EQ(how, MeshFoundBy::kRepositoryPackage);
  const int listed = cache.packages().folders_listed();
  options.model_file = (repo / "two/b.urdf").string();
  EXPECT_EQ(cache.Resolve("package://pkg/m.stl", options, &error, &how),
            (repo / "pkg/m.stl").string());
  // From two/: two is listed (nothing new under repo, already crawled from one/).
  EXPECT_EQ(cache.packages().folders_listed(), listed + 1);
}

}  // namespace
}  // namespace massprops
