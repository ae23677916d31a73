// Tests of include/massprops/io/model_reader.h: format detection by content, reading paths and
// standard input, and the errors for files that cannot be read. Expected values come from the
// fixtures as written (testdata/urdf/features.urdf has 4 links, its root <robot> is on line 3).

#include "massprops/io/model_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace massprops {
namespace {

const std::string kFeatures = std::string(MASSPROPS_TESTDATA_DIR) + "/urdf/features.urdf";

std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(DetectModelFormatTest, TellsUrdfFromSdfByTheFirstElement) {
  EXPECT_EQ(DetectModelFormat("<robot name=\"r\"/>"), Model::Format::kUrdf);
  EXPECT_EQ(DetectModelFormat("<sdf version=\"1.9\"></sdf>"), Model::Format::kSdf);
  EXPECT_EQ(DetectModelFormat("\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!-- <sdf> in a comment -->\n"
                              "<!DOCTYPE robot [ <!ENTITY x \"<sdf>\"> ]>\n<robot>"),
            Model::Format::kUrdf)
      << "BOM, declaration, comment and DOCTYPE with an internal subset are skipped";
  EXPECT_EQ(DetectModelFormat("  \r\n\t<sdf>"), Model::Format::kSdf);
}

TEST(DetectModelFormatTest, AnythingElseIsUnknown) {
  EXPECT_FALSE(DetectModelFormat(""));
  EXPECT_FALSE(DetectModelFormat("<robots/>")) << "a name that only starts with 'robot'";
  EXPECT_FALSE(DetectModelFormat("<world/>"));
  EXPECT_FALSE(DetectModelFormat("robot"));
  EXPECT_FALSE(DetectModelFormat("<!-- unterminated"));
}

TEST(ModelReaderTest, ReadsAUrdfFileThroughTheUrdfReader) {
  const ReadResult result = ReadModelFile(kFeatures);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.models.size(), 1u);
  EXPECT_EQ(result.models[0].format, Model::Format::kUrdf);
  EXPECT_EQ(result.models[0].links.size(), 4u);
  EXPECT_EQ(result.models[0].location.line, 3);
}

TEST(ModelReaderTest, DetectsTheFormatByContentNotByExtension) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "massprops_model_reader_urdf.sdf";
  std::ofstream(path, std::ios::binary) << Slurp(kFeatures);
  const ReadResult result = ReadModelFile(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.models.at(0).format, Model::Format::kUrdf);
  EXPECT_EQ(result.models.at(0).file, path.string());
}

TEST(ModelReaderTest, HandsSdfTextToTheSdfReader) {
  // Two links and one joint, written for this test.
  const std::string sdf =
      "<?xml version=\"1.0\"?>\n"
      "<sdf version=\"1.9\">\n"
      "  <model name=\"m\">\n"
      "    <link name=\"a\"/>\n"
      "    <link name=\"b\"/>\n"
      "    <joint name=\"j\" type=\"fixed\"><parent>a</parent><child>b</child></joint>\n"
      "  </model>\n"
      "</sdf>\n";
  const ReadResult result = ReadModelString(sdf, "m.sdf");
  ASSERT_TRUE(result.ok()) << (result.errors.empty() ? "" : result.errors[0].ToString());
  ASSERT_EQ(result.models.size(), 1u);
  EXPECT_EQ(result.models[0].format, Model::Format::kSdf);
  EXPECT_EQ(result.models[0].links.size(), 2u);
  EXPECT_EQ(result.models[0].joints.size(), 1u);
}

TEST(ModelReaderTest, TextThatIsNeitherUrdfNorSdfIsAnError) {
  const ReadResult other = ReadModelString("<world/>", "w.xml");
  ASSERT_EQ(other.errors.size(), 1u);
  EXPECT_EQ(other.errors[0].location.file, "w.xml");
  EXPECT_NE(other.errors[0].message.find("neither URDF, SDF nor MJCF"), std::string::npos);
  const ReadResult empty = ReadModelString("", "e.urdf");
  ASSERT_EQ(empty.errors.size(), 1u);
  EXPECT_NE(empty.errors[0].message.find("empty"), std::string::npos);
}

TEST(ModelReaderTest, MissingFilesAndDirectoriesAreErrorsNamingThePath) {
  const ReadResult missing = ReadModelFile(kFeatures + ".missing");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_EQ(missing.errors[0].location.file, kFeatures + ".missing");
  EXPECT_NE(missing.errors[0].message.find("cannot open"), std::string::npos);
  const ReadResult dir = ReadModelFile(MASSPROPS_TESTDATA_DIR);
  ASSERT_EQ(dir.errors.size(), 1u);
  EXPECT_NE(dir.errors[0].message.find("is a directory"), std::string::npos);
}

TEST(ModelReaderTest, FilesLargerThanTheLimitAreRefused) {
  ReadOptions options;
  options.max_file_bytes = 100;  // features.urdf is a few kilobytes
  const ReadResult result = ReadModelFile(kFeatures, options);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_NE(result.errors[0].message.find("larger than the limit"), std::string::npos);
  std::string contents = "left alone?";
  EXPECT_TRUE(ReadInputFile(kFeatures, 100, &contents).has_value());
  EXPECT_FALSE(ReadInputFile(kFeatures, 1 << 20, &contents).has_value());
  EXPECT_EQ(contents, Slurp(kFeatures));
}

// ReadOptions::max_file_bytes reaches the readers of text already in memory and every file an
// SDF includes, not only the first file read: a limit one byte below a text's length refuses it,
// a limit equal to it reads it (the lengths are those of the texts written here).
TEST(ModelReaderTest, TheLimitReachesTheReadersAndTheSdfIncludes) {
  const std::string urdf = Slurp(kFeatures);
  ReadOptions options;
  options.max_file_bytes = urdf.size() - 1;
  const ReadResult refused = ReadModelString(urdf, "features.urdf", options);
  ASSERT_EQ(refused.errors.size(), 1u);
  EXPECT_NE(
      refused.errors[0].message.find("more than the limit of " + std::to_string(urdf.size() - 1)),
      std::string::npos)
      << refused.errors[0].message;
  options.max_file_bytes = urdf.size();
  EXPECT_TRUE(ReadModelString(urdf, "features.urdf", options).ok());

  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "model_reader_limit_test";
  std::filesystem::create_directories(dir);
  const std::string part =
      "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n  <model name=\"part\">\n"
      "    <link name=\"a\"><inertial><mass>1</mass></inertial></link>\n  </model>\n</sdf>\n";
  std::ofstream(dir / "part.sdf") << part;
  const std::string world =
      "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n  <world name=\"w\">\n"
      "    <include><uri>part.sdf</uri></include>\n  </world>\n</sdf>\n";
  ASSERT_LT(world.size(), part.size());  // so that a limit between them judges the include
  options.max_file_bytes = part.size() - 1;
  const ReadResult include_refused = ReadModelString(world, (dir / "world.sdf").string(), options);
  ASSERT_FALSE(include_refused.errors.empty());
  EXPECT_NE(include_refused.errors[0].message.find("more than the limit of " +
                                                   std::to_string(part.size() - 1)),
            std::string::npos)
      << include_refused.errors[0].message;
  options.max_file_bytes = part.size();
  const ReadResult included = ReadModelString(world, (dir / "world.sdf").string(), options);
  ASSERT_TRUE(included.ok()) << included.errors[0].ToString();
  ASSERT_EQ(included.models.size(), 1u);
  EXPECT_EQ(included.models[0].links.size(), 1u);
}

TEST(ModelReaderTest, ReadsStandardInputWhenThePathIsADash) {
  // Standard input of this test process is replaced by the fixture, as `massprops check - <f`.
  ASSERT_NE(std::freopen(kFeatures.c_str(), "rb", stdin), nullptr);
  const ReadResult result = ReadModelFile("-");
  ASSERT_TRUE(result.ok()) << (result.errors.empty() ? "" : result.errors[0].ToString());
  ASSERT_EQ(result.models.size(), 1u);
  EXPECT_EQ(result.models[0].links.size(), 4u);
  EXPECT_EQ(result.models[0].links[0].location.file, "<stdin>");
  EXPECT_EQ(result.models[0].links[0].location.line, 5);
}

}  // namespace
}  // namespace massprops
