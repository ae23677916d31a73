// The CI formats of reporters.h: RenderJunit (read back with tinyxml2, an XML parser of its own)
// and RenderGitlab (fingerprints checked against Python's hashlib), and a welded group's members
// in JSON and SARIF. tests/ci_formats_test.py judges both formats on the corpus against JSON.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "massprops/output/reporters.h"

namespace massprops {
namespace {

using nlohmann::json;

Finding MakeFinding(const std::string& rule, Severity severity, const std::string& link, int line) {
  Finding f;
  f.rule = rule;
  f.severity = severity;
  f.model = "arm";
  f.link = link;
  f.location = {"robot.urdf", line, 0};
  f.message = "the reasoning of " + link;
  f.headline = "link '" + link + "': " + rule;
  f.help = "the help of " + link;
  f.evidence = {{"mass_kg", 2.0}};
  return f;
}

// robot.urdf with an error, a warning and a note; a file that could not be read; a clean file.
std::vector<FileResult> SampleResults() {
  FileResult robot;
  robot.path = "robot.urdf";
  robot.format = "urdf";
  robot.models = {"arm"};
  robot.findings = {MakeFinding("inertia-not-physical", Severity::kError, "forearm", 42),
                    MakeFinding("units-suspect", Severity::kWarning, "upper_arm", 30),
                    MakeFinding("com-outside-geometry", Severity::kNote, "gripper", 50)};
  FileResult broken;
  broken.path = "dir/bad file.sdf";
  ReadError error;
  error.location = {"dir/bad file.sdf", 3, 5};
  error.element = "<link>";
  error.message = "unclosed element";
  broken.errors.push_back(error);
  FileResult clean;
  clean.path = "clean.urdf";
  clean.format = "urdf";
  clean.models = {"gripper"};
  return {robot, broken, clean};
}

// A testcase read back from JUnit XML.
struct Case {
  std::string suite, name, classname, file, line;
  std::string result;  // "failure", "error", "" (passed)
  std::string message, text, output;
};

std::string Attr(const tinyxml2::XMLElement* e, const char* name) {
  const char* value = e->Attribute(name);
  return value ? value : "";
}

std::vector<Case> ParseJunit(const std::string& xml) {
  tinyxml2::XMLDocument doc;
  EXPECT_EQ(doc.Parse(xml.c_str(), xml.size()), tinyxml2::XML_SUCCESS) << xml;
  std::vector<Case> cases;
  const tinyxml2::XMLElement* root = doc.FirstChildElement("testsuites");
  if (root == nullptr) return cases;
  for (auto* suite = root->FirstChildElement("testsuite"); suite;
       suite = suite->NextSiblingElement("testsuite")) {
    for (auto* tc = suite->FirstChildElement("testcase"); tc;
         tc = tc->NextSiblingElement("testcase")) {
      Case c;
      c.suite = Attr(suite, "name");
      c.name = Attr(tc, "name");
      c.classname = Attr(tc, "classname");
      c.file = Attr(tc, "file");
      c.line = Attr(tc, "line");
      for (const char* kind : {"failure", "error"}) {
        if (const tinyxml2::XMLElement* r = tc->FirstChildElement(kind)) {
          c.result = kind;
          c.message = Attr(r, "message");
          c.text = r->GetText() ? r->GetText() : "";
        }
      }
      if (const tinyxml2::XMLElement* out = tc->FirstChildElement("system-out")) {
        c.output = out->GetText() ? out->GetText() : "";
      }
      cases.push_back(c);
    }
  }
  return cases;
}

TEST(CiReportersTest, ParsesJunitAndGitlabAndRendersThem) {
  EXPECT_EQ(ParseReportFormat("junit"), ReportFormat::kJunit);
  EXPECT_EQ(ParseReportFormat("gitlab"), ReportFormat::kGitlab);
  EXPECT_FALSE(ParseReportFormat("xunit").has_value());
  const std::vector<FileResult> results = SampleResults();
  EXPECT_EQ(Render(ReportFormat::kJunit, results), RenderJunit(results));
  EXPECT_EQ(Render(ReportFormat::kGitlab, results), RenderGitlab(results));
}

TEST(CiReportersTest, JunitFailsFindingsAtTheFailLevelAndPassesTheOthersWithTheirText) {
  const std::vector<Case> cases = ParseJunit(RenderJunit(SampleResults()));
  // robot.urdf: 3 findings; the unreadable file: 1 read error; the clean file: 1 passing case.
  ASSERT_EQ(cases.size(), 5u);
  const Case& error = cases[0];
  EXPECT_EQ(error.suite, "robot.urdf");
  EXPECT_EQ(error.name, "inertia-not-physical: forearm");
  EXPECT_EQ(error.classname, "massprops.arm");
  EXPECT_EQ(error.file, "robot.urdf");
  EXPECT_EQ(error.line, "42");
  EXPECT_EQ(error.result, "failure");
  EXPECT_EQ(error.message, "link 'forearm': inertia-not-physical");
  EXPECT_EQ(error.text,
            "robot.urdf:42: error: link 'forearm': inertia-not-physical [inertia-not-physical]\n"
            "evidence: mass 2 kg\nhelp: the help of forearm\n");
  // Below the default fail level (error): passing, the text as the test's output.
  EXPECT_EQ(cases[1].result, "");
  EXPECT_EQ(cases[1].name, "units-suspect: upper_arm");
  EXPECT_NE(cases[1].output.find("robot.urdf:30: warning: link 'upper_arm'"), std::string::npos);
  EXPECT_EQ(cases[2].result, "");
  EXPECT_NE(cases[2].output.find("robot.urdf:50: note:"), std::string::npos);
  EXPECT_EQ(cases[3].suite, "dir/bad file.sdf");
  EXPECT_EQ(cases[3].name, "read-error: <link>");
  EXPECT_EQ(cases[3].result, "error");
  EXPECT_EQ(cases[3].message, "<link>: unclosed element");
  EXPECT_EQ(cases[4].suite, "clean.urdf");
  EXPECT_EQ(cases[4].name, "massprops check");
  EXPECT_EQ(cases[4].classname, "massprops.gripper");
  EXPECT_EQ(cases[4].result, "");
}

TEST(CiReportersTest, JunitCountsFollowEachFilesFailLevel) {
  std::vector<FileResult> results = SampleResults();
  results[0].fail_on = Severity::kWarning;
  const std::string xml = RenderJunit(results);
  int failures = 0;
  for (const Case& c : ParseJunit(xml)) failures += c.result == "failure" ? 1 : 0;
  EXPECT_EQ(failures, 2);
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* root = doc.FirstChildElement("testsuites");
  EXPECT_EQ(Attr(root, "tests"), "5");
  EXPECT_EQ(Attr(root, "failures"), "2");
  EXPECT_EQ(Attr(root, "errors"), "1");
  const tinyxml2::XMLElement* robot = root->FirstChildElement("testsuite");
  EXPECT_EQ(Attr(robot, "tests"), "3");
  EXPECT_EQ(Attr(robot, "failures"), "2");
  EXPECT_EQ(Attr(robot, "errors"), "0");
}

TEST(CiReportersTest, JunitEscapesMarkupAndReplacesWhatXmlCannotHold) {
  FileResult result;
  result.path = "r&d.urdf";
  // A link name with markup, a control character and a byte that is not UTF-8; a headline with
  // a carriage return and a two-byte character (°) that must stay as it is.
  Finding f = MakeFinding("inertia-not-physical", Severity::kError, "a<b&\"c'\x01\xff", 7);
  f.headline = "angle 90\xc2\xb0\r<bad>";
  result.findings = {f};
  const std::vector<Case> cases = ParseJunit(RenderJunit({result}));
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].suite, "r&d.urdf");
  EXPECT_EQ(cases[0].name, "inertia-not-physical: a<b&\"c'\xef\xbf\xbd\xef\xbf\xbd");
  EXPECT_EQ(cases[0].message, "angle 90\xc2\xb0\r<bad>");
}

TEST(CiReportersTest, JunitPointsATracedFindingAtItsSourceAndSaysTheGeneratedLine) {
  Finding f = MakeFinding("inertia-not-physical", Severity::kError, "arm", 40);
  f.location = {"gen.urdf", 40, 7};
  FindingSource source;
  source.number = "inertia ixx";
  SourcePlace place;
  place.file = "pkg/urdf/arm.xacro";
  place.line = 12;
  place.how = "literal";
  source.places = {place};
  source.generated = {"gen.urdf", 40, 0};
  f.source = source;
  FileResult result;
  result.path = "gen.urdf";
  result.findings = {f};
  const std::vector<Case> cases = ParseJunit(RenderJunit({result}));
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].file, "pkg/urdf/arm.xacro");
  EXPECT_EQ(cases[0].line, "12");
  EXPECT_EQ(cases[0].text.rfind("pkg/urdf/arm.xacro:12: error:", 0), 0u) << cases[0].text;
  EXPECT_NE(cases[0].text.find("generated: gen.urdf:40 (inertia ixx)"), std::string::npos);
  const json gitlab = json::parse(RenderGitlab({result}));
  EXPECT_EQ(gitlab[0]["location"]["path"], "pkg/urdf/arm.xacro");
  EXPECT_EQ(gitlab[0]["location"]["lines"]["begin"], 12);
}

TEST(CiReportersTest, AWeldedGroupsMembersAreInJunitJsonAndSarifAndALinksAreNot) {
  std::vector<FileResult> results = SampleResults();
  results[0].findings[0].group = {"forearm", "hand"};
  const std::vector<Case> cases = ParseJunit(RenderJunit(results));
  EXPECT_NE(cases[0].text.find("\nwelded group of 2 links: forearm, hand\n"), std::string::npos)
      << cases[0].text;
  const json document = json::parse(RenderJson(results));
  const json& findings = document["files"][0]["findings"];
  EXPECT_EQ(findings[0]["group"], json({"forearm", "hand"}));
  EXPECT_FALSE(findings[1].contains("group"));
  const json sarif = json::parse(RenderSarif(results));
  const json& sarif_results = sarif["runs"][0]["results"];
  // robot.urdf's findings are the first results, in order.
  EXPECT_EQ(sarif_results[0]["properties"]["group"], json({"forearm", "hand"}));
  EXPECT_FALSE(sarif_results[1]["properties"].contains("group"));
}

TEST(CiReportersTest, GitlabItemsHaveTheFiveFieldsAndGitlabsSeverities) {
  const json items = json::parse(RenderGitlab(SampleResults()));
  ASSERT_EQ(items.size(), 4u);  // the clean file has none
  EXPECT_EQ(items[0]["description"], "link 'forearm': inertia-not-physical");
  EXPECT_EQ(items[0]["check_name"], "inertia-not-physical");
  EXPECT_EQ(items[0]["location"]["path"], "robot.urdf");
  EXPECT_EQ(items[0]["location"]["lines"]["begin"], 42);
  const std::vector<std::string> severities = {items[0]["severity"], items[1]["severity"],
                                               items[2]["severity"], items[3]["severity"]};
  EXPECT_EQ(severities, (std::vector<std::string>{"major", "minor", "info", "critical"}));
  EXPECT_EQ(items[3]["check_name"], "read-error");
  EXPECT_EQ(items[3]["description"], "<link>: unclosed element");
  EXPECT_EQ(items[3]["location"]["path"], "dir/bad file.sdf");
  EXPECT_EQ(items[3]["location"]["lines"]["begin"], 3);
}

// The expected digests are Python's: hashlib.sha256(b"".join(p.encode() + b"\0" for p in
// (rule, file, model, link, str(index)))).hexdigest().
TEST(CiReportersTest, GitlabFingerprintsHashRuleFileModelLinkAndOccurrence) {
  std::vector<FileResult> results = SampleResults();
  json items = json::parse(RenderGitlab(results));
  EXPECT_EQ(items[0]["fingerprint"],
            "bb3d7c76ed7b5721e808962cc4dd5bfde0220460b1c9fcdb1fa55fe60e155f74");
  EXPECT_EQ(items[3]["fingerprint"],
            "b5d90d3e5c09891a7e579d992135f60ca95976770244e2130062797158af47e0");
  // Lines moved, headline reworded: the same fingerprint.
  results[0].findings[0].location.line = 43;
  results[0].findings[0].headline = "another wording";
  EXPECT_EQ(json::parse(RenderGitlab(results))[0]["fingerprint"], items[0]["fingerprint"]);
  // A second finding of the same rule on the same link: the next occurrence index.
  results[0].findings.push_back(results[0].findings[0]);
  items = json::parse(RenderGitlab(results));
  EXPECT_EQ(items[3]["fingerprint"],
            "a7095d44e53502d8b0f9de96762b7d1760a1e0e96239b43b250c0a620cd92a5f");
}

TEST(CiReportersTest, GitlabPathsLoseALeadingDotSlashAndAnUnknownLineIsOne) {
  FileResult result;
  result.path = "./urdf/robot.urdf";
  Finding f = MakeFinding("inertial-missing", Severity::kWarning, "camera", 0);
  f.location = {"", 0, 0};
  result.findings = {f};
  const json items = json::parse(RenderGitlab({result}));
  EXPECT_EQ(items[0]["location"]["path"], "urdf/robot.urdf");
  EXPECT_EQ(items[0]["location"]["lines"]["begin"], 1);
}

}  // namespace
}  // namespace massprops
