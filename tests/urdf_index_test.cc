// Tests of the URDF reader's index of the text (src/io/urdf/reader.h): the light scan
// (src/io/urdf/scan.cc) against the tinyxml2 index (src/io/urdf/index.cc), through
// internal::DescribeUrdfIndex of include/massprops/io/urdf_reader.h. The scan must either give up
// (the reader then uses the tinyxml2 index) or give exactly the tinyxml2 index: every line, name,
// ignored rule, underflowing number and warning. Checked on a fixture with lines counted by hand,
// on every URDF of the shared corpus, on texts outside the XML the scan reads, and on 30 000
// random mutations of the fixtures (the scan must never accept a text that tinyxml2 refuses, or
// index it differently).

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/io/urdf_reader.h"

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/urdf/";

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::optional<std::string> Scan(const std::string& xml) {
  return internal::DescribeUrdfIndex(xml, /*from_tinyxml2=*/false);
}

std::optional<std::string> Dom(const std::string& xml) {
  return internal::DescribeUrdfIndex(xml, /*from_tinyxml2=*/true);
}

// The lines of testdata/urdf/features.urdf, counted by hand in the file (`cat -n`): <robot> on 3;
// link base on 5 (its ignore comment on 6, <inertial> 7 with <origin> 8, <mass> 9, <inertia> 10;
// <collision> 12, <visual> 16); link arm on 21 (<inertial> 22, <mass> 23, <inertia> 24, no
// <origin>; <visual> 26, <collision> 30 holding the comment of 32, <collision> 34); link tool on
// 38; joint shoulder on 39 (<axis xyz> on 43), wrist on 46, spin on 50; link wheel on 54. No
// number underflows (1e-3 and 1E-6 are normal doubles), and both comments are well formed.
TEST(UrdfIndexTest, ScanGivesTheHandCountedLinesOfTheFixture) {
  const std::string expected =
      "robot 3\n"
      "link 'base' named 5 inertials 7 mass 9 inertia 10 origin 8 holders 12c 16v ignored "
      "inertia-not-physical mass-zero\n"
      "link 'arm' named 21 inertials 22 mass 23 inertia 24 origin 0 holders 26v 30c 34c ignored "
      "all\n"
      "link 'tool' named 38 inertials mass 0 inertia 0 origin 0 holders ignored\n"
      "link 'wheel' named 54 inertials mass 0 inertia 0 origin 0 holders ignored\n"
      "joint 'shoulder' named 39 type 'revolute' axis 43 xyz\n"
      "joint 'wrist' named 46 type 'fixed' axis 0\n"
      "joint 'spin' named 50 type 'continuous' axis 0\n"
      "first link 'arm' 1\nfirst link 'base' 0\nfirst link 'tool' 2\nfirst link 'wheel' 3\n"
      "first joint 'shoulder' 0\nfirst joint 'spin' 2\nfirst joint 'wrist' 1\n";
  const std::string xml = ReadText(kDir + "features.urdf");
  EXPECT_EQ(Scan(xml), expected);
  EXPECT_EQ(Dom(xml), expected);
}

// Underflows (urdfdom reads 1e-400 as 0: the index records the first in urdfdom's order, origin
// xyz before mass), a second <inertial> (its line kept), a malformed massprops comment (a
// warning at its line), a <link> nested in <gazebo> (not a link), a joint without type, an
// unnamed link, a duplicate link name (the first one wins), CRLF line ends and a BOM. Lines by
// hand: the text's lines are numbered in the comments below.
TEST(UrdfIndexTest, ScanAgreesWithTinyxml2OnTheIndexedCases) {
  const std::string xml =
      "\xEF\xBB\xBF<?xml version='1.0'?>\r\n"                                // 1
      "<!-- top --><robot name='r'>\r\n"                                     // 2
      "<link name='a'><inertial>\n"                                          // 3
      "  <mass value='1e-400'/><origin rpy='0 0 0' xyz='0 1e-320 0'/>\n"     // 4
      "  <origin xyz='0 1e-400 0'/></inertial>\n"                            // 5
      "  <inertial/><!--massprops: silence x--><visual/>\n"                  // 6
      "</link><gazebo><link name='g'/></gazebo>\n"                           // 7
      "<link><collision><!-- massprops:ignore a,b --></collision></link>\n"  // 8
      "<joint name='j'><axis/><axis xyz='1 0 0'/></joint>\n"                 // 9
      "<link name='a'/></robot>\n";                                          // 10
  const std::string expected =
      "robot 2\n"
      "link 'a' named 3 inertials 3 6 mass 4 inertia 0 origin 4 holders 6v ignored\n"
      "link '' unnamed 8 inertials mass 0 inertia 0 origin 0 holders 8c ignored a b\n"
      "link 'a' named 10 inertials mass 0 inertia 0 origin 0 holders ignored\n"
      "joint 'j' named 9 type '' axis 9\n"
      "underflow link 0 line 4 <origin xyz=\"0 1e-320 0\"> 9.9998886718268301e-321 number 2\n"
      "first link '' 1\nfirst link 'a' 0\n"
      "first joint 'j' 0\n"
      "warning 6 comment in link 'a': a massprops comment must read 'massprops: ignore rule-id "
      "[rule-id...]'; this one is ignored\n";
  EXPECT_EQ(Dom(xml), expected);
  EXPECT_EQ(Scan(xml), expected);
}

// Text the scan does not read (it gives up, and the reader uses tinyxml2), whether tinyxml2
// accepts it or not.
TEST(UrdfIndexTest, ScanGivesUpOnTextOutsideItsXml) {
  const char* const texts[] = {
      "<!DOCTYPE robot><robot/>",                  // a DOCTYPE
      "<robot><![CDATA[x]]></robot>",              // CDATA
      "<!-- c --><?xml version='1.0'?><robot/>",   // a declaration too late
      "<robot><link name='a&amp;b'/></robot>",     // an entity in a name
      "<robot><link name='a\rb'/></robot>",        // a carriage return in it
      "< robot/>",                                 // space after '<'
      "<robot></robot >x",                         // text after the root
      "<robot/><robot/>",                          // two roots
      "<urdf/>",                                   // not <robot>
      "<robot><link name='a' name='b'/></robot>",  // a duplicate attribute
      "<robot><link></joint></robot>",             // a mismatched end tag
      "<robot><link>",                             // unclosed
      "<robot a='1></robot>",                      // an unclosed value
      "<robot><!-- open </robot>",                 // an unclosed comment
      "",                                          // empty
      "   \n ",                                    // white space only
  };
  for (const char* text : texts) EXPECT_EQ(Scan(text), std::nullopt) << text;
  // tinyxml2 reads the first and fourth as XML, and the index is the same as the scan would give.
  EXPECT_NE(Dom("<!DOCTYPE robot><robot/>"), std::nullopt);
  EXPECT_EQ(Dom("<robot><link name='a&amp;b'/></robot>"),
            "robot 1\nlink 'a&b' named 1 inertials mass 0 inertia 0 origin 0 holders ignored\n"
            "first link 'a&b' 0\n");
}

std::vector<std::string> UrdfFiles() {
  std::vector<std::string> files;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("urdf")) {
    files.push_back(test_support::CorpusDir() + "/" + row.file);
  }
  return files;
}

// Every URDF of the corpus: the scan reads nearly all of them, each with the tinyxml2 index.
TEST(UrdfIndexTest, ScanEqualsTinyxml2OnEveryCorpusUrdf) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<std::string> files = UrdfFiles();
  ASSERT_GT(files.size(), 100u);
  std::size_t scanned = 0;
  for (const std::string& file : files) {
    const std::string xml = ReadText(file);
    if (xml.find('\0') != std::string::npos) continue;  // not text: the reader stops before
    const std::optional<std::string> scan = Scan(xml);
    if (!scan) continue;
    ++scanned;
    EXPECT_EQ(scan, Dom(xml)) << file;
  }
  // Those it leaves to tinyxml2 hold entities in indexed values, a DOCTYPE, or are not XML.
  EXPECT_GE(scanned * 10, files.size() * 9) << scanned << " of " << files.size();
}

// Random edits of the fixtures (a byte deleted, replaced or inserted from the characters that
// make XML, a span repeated): whatever the scan accepts, tinyxml2 accepts and indexes the same.
TEST(UrdfIndexTest, ScanNeverDisagreesWithTinyxml2OnMutatedText) {
  std::vector<std::string> seeds;
  for (const char* name : {"features.urdf", "bad_numbers.urdf", "inertia_unreadable.urdf",
                           "two_parents.urdf", "malformed.urdf"}) {
    seeds.push_back(ReadText(kDir + name));
  }
  seeds.push_back(
      "<?xml version='1.0'?>\n<robot name='r'><link name='a'><inertial><origin xyz='0 0 1e-400'/>"
      "<mass value='1e-310'/></inertial><!-- massprops: ignore x --></link>\n"
      "<joint name='j' type='fixed'><axis xyz='0 0 1'/></joint></robot>\n");
  const std::string alphabet = "<>/!-?&;='\" \n\r\tabx1e:.[]";
  std::mt19937 random(33);
  int scanned = 0, checked = 0;
  for (int iteration = 0; iteration < 30000; ++iteration) {
    std::string text = seeds[random() % seeds.size()];
    const int edits = 1 + static_cast<int>(random() % 3);
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = random() % text.size();
      const char c = alphabet[random() % alphabet.size()];
      switch (random() % 4) {
        case 0:
          text.erase(at, 1);
          break;
        case 1:
          text[at] = c;
          break;
        case 2:
          text.insert(at, 1, c);
          break;
        default:
          text.insert(at, text.substr(at, random() % 24));
          break;
      }
    }
    const std::optional<std::string> scan = Scan(text);
    ++checked;
    if (!scan) continue;
    ++scanned;
    const std::optional<std::string> dom = Dom(text);
    ASSERT_EQ(scan, dom) << "text:\n" << text;
  }
  // Most single edits leave well-formed text (in a value, in text, in a comment).
  EXPECT_GT(scanned, checked / 4);
}

}  // namespace
}  // namespace massprops
