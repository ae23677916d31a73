// Reporters on hostile text (reporters.h): invalid UTF-8 and huge names.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "massprops/output/reporters.h"

namespace massprops {
namespace {

// One file with one finding whose link name, message and file name hold the invalid UTF-8 byte
// 0xFF (never valid in UTF-8: RFC 3629, section 3), beside a good file.
std::vector<FileResult> ResultsWithInvalidUtf8() {
  FileResult bad;
  bad.path = "bad\xFF.urdf";
  bad.format = "urdf";
  bad.models = {"r\xFF"};
  Finding finding;
  finding.rule = "mass-not-positive";
  finding.severity = Severity::kError;
  finding.model = "r\xFF";
  finding.link = "l\xFFnk";
  finding.location = {"bad\xFF.urdf", 3, 0};
  finding.message = "link 'l\xFFnk' has mass -1";
  bad.findings.push_back(finding);
  FileResult good;
  good.path = "good.urdf";
  good.format = "urdf";
  good.models = {"g"};
  return {bad, good};
}

TEST(ReportersHostileTest, JsonReplacesInvalidUtf8WithTheReplacementCharacter) {
  const std::string text = RenderJson(ResultsWithInvalidUtf8());
  const nlohmann::json document = nlohmann::json::parse(text);  // valid UTF-8 JSON
  ASSERT_EQ(document["files"].size(), 2u);
  // U+FFFD REPLACEMENT CHARACTER is EF BF BD in UTF-8 (Unicode 15, table 3-7).
  EXPECT_EQ(document["files"][0]["path"], "bad\xEF\xBF\xBD.urdf");
  EXPECT_EQ(document["files"][0]["findings"][0]["link"], "l\xEF\xBF\xBDnk");
  EXPECT_EQ(document["files"][1]["path"], "good.urdf");
}

TEST(ReportersHostileTest, SarifReplacesInvalidUtf8WithTheReplacementCharacter) {
  const nlohmann::json log = nlohmann::json::parse(RenderSarif(ResultsWithInvalidUtf8()));
  const auto& results = log["runs"][0]["results"];
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0]["message"]["text"], "link 'l\xEF\xBF\xBDnk' has mass -1");
}

TEST(ReportersHostileTest, JunitAndGitlabReplaceInvalidUtf8WithTheReplacementCharacter) {
  const std::string xml = RenderJunit(ResultsWithInvalidUtf8());
  tinyxml2::XMLDocument doc;  // an XML parser rejects text that is not UTF-8
  ASSERT_EQ(doc.Parse(xml.c_str(), xml.size()), tinyxml2::XML_SUCCESS) << xml;
  const tinyxml2::XMLElement* suite = doc.FirstChildElement("testsuites")->FirstChildElement();
  EXPECT_STREQ(suite->Attribute("name"), "bad\xEF\xBF\xBD.urdf");
  EXPECT_STREQ(suite->FirstChildElement("testcase")->Attribute("name"),
               "mass-not-positive: l\xEF\xBF\xBDnk");
  const nlohmann::json items = nlohmann::json::parse(RenderGitlab(ResultsWithInvalidUtf8()));
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0]["description"], "link 'l\xEF\xBF\xBDnk' has mass -1");
  EXPECT_EQ(items[0]["location"]["path"], "bad\xEF\xBF\xBD.urdf");
}

TEST(ReportersHostileTest, JunitShortensAMegabyteLinkName) {
  std::vector<FileResult> results = ResultsWithInvalidUtf8();
  Finding& finding = results[0].findings[0];
  finding.link = std::string(1 << 20, 'n');
  finding.message = "link '" + finding.link + "' has mass -1";
  const std::string xml = RenderJunit(results);
  EXPECT_LT(xml.size(), 4000u);
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(xml.c_str(), xml.size()), tinyxml2::XML_SUCCESS);
  const std::string name = doc.FirstChildElement("testsuites")
                               ->FirstChildElement("testsuite")
                               ->FirstChildElement("testcase")
                               ->Attribute("name");
  EXPECT_NE(name.find("[1048576 bytes]"), std::string::npos) << name;
}

TEST(ReportersHostileTest, LongWordsAreShortenedAndShortTextIsKept) {
  EXPECT_EQ(ShortenLongWords("link 'arm' has mass -1"), "link 'arm' has mass -1");
  const std::string name(1000, 'n');
  const std::string shortened = ShortenLongWords("link '" + name + "' has mass -1", 200);
  // The word "'nnn…nnn'" is 1002 bytes: its first 100 and last 50 bytes are kept.
  EXPECT_EQ(shortened, "link '" + std::string(99, 'n') + "\u2026[1002 bytes]\u2026" +
                           std::string(49, 'n') + "' has mass -1");
}

TEST(ReportersHostileTest, ShorteningNeverSplitsAUtf8Character) {
  // 300 two-byte characters "é" (C3 A9): a cut inside one would leave a stray byte.
  std::string word;
  for (int i = 0; i < 300; ++i) word += "\xC3\xA9";
  const std::string shortened = ShortenLongWords(word, 101);
  // Head: 50 bytes → 25 characters; tail: 25 bytes → moved forward to a boundary → 12 characters.
  std::string head, tail;
  for (int i = 0; i < 25; ++i) head += "\xC3\xA9";
  for (int i = 0; i < 12; ++i) tail += "\xC3\xA9";
  EXPECT_EQ(shortened, head + "\u2026[600 bytes]\u2026" + tail);
}

}  // namespace
}  // namespace massprops
