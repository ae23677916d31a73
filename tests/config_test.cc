#include "massprops/analysis/config.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace massprops {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system temporary folder, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const std::string name = std::string("massprops_config_test_") + std::to_string(getpid()) +
                             "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    path_ = fs::temp_directory_path() / name;
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void WriteFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Runs ParseConfig and returns the ConfigError it throws (fails the test when it does not).
ConfigError ParseError(const std::string& text) {
  try {
    ParseConfig(text, "cfg.toml");
  } catch (const ConfigError& error) {
    return error;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return ConfigError("", 0, 0, "");
}

TEST(ConfigTest, ReadsTheDocumentedExample) {
  // The example of docs/cli.md, every key set.
  const Config config = ParseConfig(
      "fail-on = \"warning\"\n"
      "tolerance = 1e-6\n"
      "model-paths = [\"models\", \"/opt/models\"]\n"
      "[rules]\n"
      "units-suspect = \"off\"\n"
      "com-outside-geometry = \"note\"\n",
      "cfg.toml");
  EXPECT_EQ(config.fail_on, Severity::kWarning);
  ASSERT_TRUE(config.tolerance.has_value());
  EXPECT_EQ(*config.tolerance, 1e-6);
  EXPECT_EQ(config.model_paths, (std::vector<std::string>{"models", "/opt/models"}));
  ASSERT_EQ(config.overrides.size(), 2u);
  EXPECT_FALSE(config.overrides.at("units-suspect").has_value());  // off
  EXPECT_EQ(config.overrides.at("com-outside-geometry"), Severity::kNote);
}

TEST(ConfigTest, AnEmptyFileSetsNothing) {
  const Config config = ParseConfig("# nothing but a comment\n", "cfg.toml");
  EXPECT_FALSE(config.fail_on.has_value());
  EXPECT_FALSE(config.tolerance.has_value());
  EXPECT_TRUE(config.model_paths.empty());
  EXPECT_TRUE(config.overrides.empty());
}

TEST(ConfigTest, AnIntegerToleranceIsANumber) {
  const Config config = ParseConfig("tolerance = 0\n", "cfg.toml");
  ASSERT_TRUE(config.tolerance.has_value());
  EXPECT_EQ(*config.tolerance, 0.0);
}

TEST(ConfigTest, ATomlSyntaxErrorNamesItsLine) {
  // Line 2 holds "= =", which TOML 1.0 does not allow.
  const ConfigError error = ParseError("fail-on = \"note\"\ntolerance = = 3\n");
  EXPECT_EQ(error.file(), "cfg.toml");
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(std::string(error.what()).rfind("cfg.toml:2:", 0), 0u) << error.what();
}

TEST(ConfigTest, AnUnknownKeyIsAnErrorOnItsLine) {
  const ConfigError error = ParseError("fail-on = \"note\"\n\nfail_on = \"error\"\n");
  EXPECT_EQ(error.line(), 3);
  EXPECT_NE(error.message().find("fail_on"), std::string::npos);
}

TEST(ConfigTest, AnUnknownRuleIsAnErrorThatListsTheKnownOnes) {
  const ConfigError error =
      ParseError("[rules]\nunits-suspect = \"off\"\nno-such-rule = \"off\"\n");
  EXPECT_EQ(error.line(), 3);
  EXPECT_NE(error.message().find("no-such-rule"), std::string::npos);
  EXPECT_NE(error.message().find("inertia-not-physical"), std::string::npos);
}

TEST(ConfigTest, ABadRuleLevelIsAnError) {
  EXPECT_EQ(ParseError("[rules]\nunits-suspect = \"loud\"\n").line(), 2);
  EXPECT_EQ(ParseError("[rules]\nunits-suspect = 3\n").line(), 2);
}

TEST(ConfigTest, ABadFailOnIsAnError) {
  EXPECT_EQ(ParseError("fail-on = \"off\"\n").line(), 1);
  EXPECT_EQ(ParseError("fail-on = 1\n").line(), 1);
}

TEST(ConfigTest, AToleranceOutsideZeroToOneOrNotANumberIsAnError) {
  EXPECT_EQ(ParseError("tolerance = 1.0\n").line(), 1);
  EXPECT_EQ(ParseError("tolerance = -1e-9\n").line(), 1);
  EXPECT_EQ(ParseError("tolerance = nan\n").line(), 1);
  EXPECT_EQ(ParseError("tolerance = \"1e-6\"\n").line(), 1);
}

TEST(ConfigTest, WrongTypesForTablesAndArraysAreErrors) {
  EXPECT_EQ(ParseError("rules = \"off\"\n").line(), 1);
  EXPECT_EQ(ParseError("model-paths = \"models\"\n").line(), 1);
  EXPECT_EQ(ParseError("model-paths = [\"a\", 2]\n").line(), 1);
}

TEST(ConfigTest, LoadConfigResolvesModelPathsAgainstTheConfigFolder) {
  TempDir dir;
  const fs::path file = dir.path() / ".massprops.toml";
  WriteFile(file, "fail-on = \"note\"\nmodel-paths = [\"models\", \"/abs\"]\n");
  const Config config = LoadConfig(file.string());
  EXPECT_EQ(config.path, file.string());
  EXPECT_EQ(config.fail_on, Severity::kNote);
  ASSERT_EQ(config.model_paths.size(), 2u);
  EXPECT_EQ(fs::path(config.model_paths[0]), (dir.path() / "models").lexically_normal());
  EXPECT_EQ(config.model_paths[1], "/abs");
}

// package-paths (issue 29) is read like model-paths: an array of strings, relative paths
// made absolute against the configuration file's folder.
TEST(ConfigTest, PackagePathsAreReadAndResolvedLikeModelPaths) {
  TempDir dir;
  const fs::path file = dir.path() / ".massprops.toml";
  WriteFile(file, "package-paths = [\"../src\", \"/opt/ws/src\"]\nmodel-paths = [\"m\"]\n");
  const Config config = LoadConfig(file.string());
  ASSERT_EQ(config.package_paths.size(), 2u);
  EXPECT_EQ(fs::path(config.package_paths[0]), (dir.path() / "../src").lexically_normal());
  EXPECT_EQ(config.package_paths[1], "/opt/ws/src");
  EXPECT_EQ(config.model_paths.size(), 1u);
  EXPECT_EQ(ParseError("package-paths = \"src\"\n").line(), 1);
  EXPECT_EQ(ParseError("package-paths = [\"a\", 2]\n").line(), 1);
  EXPECT_TRUE(ParseConfig("", "cfg.toml").package_paths.empty());
}

TEST(ConfigTest, LoadConfigOfAMissingFileThrowsNamingTheFile) {
  TempDir dir;
  const std::string missing = (dir.path() / "missing.toml").string();
  try {
    LoadConfig(missing);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.file(), missing);
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(std::string(error.what()).rfind(missing + ": error: ", 0), 0u) << error.what();
  }
}

TEST(ConfigTest, LoadConfigErrorsNameTheFileAndLine) {
  TempDir dir;
  const fs::path file = dir.path() / "bad.toml";
  WriteFile(file, "[rules]\nunits-suspect = \"off\"\nmass-not-positive = \"fatal\"\n");
  try {
    LoadConfig(file.string());
    FAIL() << "no ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.line(), 3);
  }
}

TEST(ConfigTest, FindConfigUpwardFindsTheNearestFileAbove) {
  TempDir dir;
  const fs::path deep = dir.path() / "a" / "b" / "c";
  fs::create_directories(deep);
  EXPECT_FALSE(FindConfigUpward(deep.string()).has_value());

  WriteFile(dir.path() / "a" / kConfigFileName, "");
  auto found = FindConfigUpward(deep.string());
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(fs::path(*found), dir.path() / "a" / kConfigFileName);

  WriteFile(dir.path() / "a" / "b" / kConfigFileName, "");
  found = FindConfigUpward(deep.string());
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(fs::path(*found), dir.path() / "a" / "b" / kConfigFileName);
}

TEST(ConfigTest, FindConfigUpwardIgnoresAFolderNamedLikeTheConfig) {
  TempDir dir;
  fs::create_directories(dir.path() / kConfigFileName);
  EXPECT_FALSE(FindConfigUpward(dir.path().string()).has_value());
}

TEST(ConfigTest, FindConfigUpwardOfAMissingFolderStillLooksAboveIt) {
  TempDir dir;
  WriteFile(dir.path() / kConfigFileName, "");
  const auto found = FindConfigUpward((dir.path() / "not" / "there").string());
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(fs::path(*found), dir.path() / kConfigFileName);
}

// The rule every command follows (docs/cli.md): the nearest file upward from the model's folder;
// a model file's own name plays no part (a file named like a folder is not searched "inside").
TEST(ConfigTest, FindConfigForAModelFileSearchesUpwardFromItsFolder) {
  TempDir dir;
  fs::create_directories(dir.path() / "robot" / "urdf");
  WriteFile(dir.path() / "robot" / kConfigFileName, "");
  const auto found = FindConfigFor((dir.path() / "robot" / "urdf" / "arm.urdf").string());
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(fs::path(*found), dir.path() / "robot" / kConfigFileName);
}

TEST(ConfigTest, ApplyConfigSetsToleranceAndReplacesOverridesOfTheSameRule) {
  CheckOptions options;
  options.overrides["units-suspect"] = Severity::kError;
  options.overrides["inertia-not-physical"] = Severity::kWarning;
  Config config;
  config.tolerance = 1e-3;
  config.overrides["units-suspect"] = std::nullopt;
  ApplyConfig(config, options);
  EXPECT_EQ(options.tolerance, 1e-3);
  EXPECT_FALSE(options.overrides.at("units-suspect").has_value());
  EXPECT_EQ(options.overrides.at("inertia-not-physical"), Severity::kWarning);

  Config empty;
  ApplyConfig(empty, options);
  EXPECT_EQ(options.tolerance, 1e-3);  // an unset tolerance leaves the option alone
}

}  // namespace
}  // namespace massprops
