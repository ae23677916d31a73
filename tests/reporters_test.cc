#include "massprops/output/reporters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "massprops/analysis/finding_text.h"

namespace massprops {
namespace {

using nlohmann::json;

// A hand-made list of results covering each severity, a location without column, one without
// line, a NaN value, and a file that could not be read (with a space in its path).
std::vector<FileResult> SampleResults() {
  FileResult robot;
  robot.path = "robot.urdf";
  robot.format = "urdf";
  robot.models = {"arm"};

  Finding not_physical;
  not_physical.rule = "inertia-not-physical";
  not_physical.severity = Severity::kError;
  not_physical.model = "arm";
  not_physical.link = "forearm";
  not_physical.location = {"robot.urdf", 42, 7};
  not_physical.message = "principal moments 1, 1, 3 break 3 <= 1 + 1";
  not_physical.values = {{"principal_min", 1.0}, {"principal_max", 3.0}};
  robot.findings.push_back(not_physical);

  Finding units;
  units.rule = "units-suspect";
  units.severity = Severity::kWarning;
  units.model = "arm";
  units.link = "upper_arm";
  units.location = {"robot.urdf", 30, 0};
  units.message = "radius of gyration 87.8 m, geometry 0.3 m";
  units.values = {{"radius_of_gyration", 87.8}, {"ratio", std::nan("")}};
  robot.findings.push_back(units);

  Finding com;
  com.rule = "com-outside-geometry";
  com.severity = Severity::kNote;
  com.model = "arm";
  com.link = "gripper";
  com.location = {"", 0, 0};
  com.message = "center of mass 1, 0, 0 outside the box";
  robot.findings.push_back(com);

  FileResult broken;
  broken.path = "dir/bad file.sdf";
  ReadError error;
  error.location = {"dir/bad file.sdf", 3, 5};
  error.element = "<link>";
  error.message = "unclosed element";
  broken.errors.push_back(error);
  return {robot, broken};
}

TEST(ReportersTest, ParsesEveryFormatNameAndRejectsOthers) {
  EXPECT_EQ(ParseReportFormat("text"), ReportFormat::kText);
  EXPECT_EQ(ParseReportFormat("json"), ReportFormat::kJson);
  EXPECT_EQ(ParseReportFormat("sarif"), ReportFormat::kSarif);
  EXPECT_EQ(ParseReportFormat("github"), ReportFormat::kGithub);
  EXPECT_FALSE(ParseReportFormat("xml").has_value());
  EXPECT_FALSE(ParseReportFormat("JSON").has_value());
}

TEST(ReportersTest, SummaryCountsFindingsBySeverityAndReadErrors) {
  // Hand-counted from SampleResults: one finding of each severity, one read error, two files.
  const ReportSummary s = Summarize(SampleResults());
  EXPECT_EQ(s.files, 2);
  EXPECT_EQ(s.errors, 1);
  EXPECT_EQ(s.warnings, 1);
  EXPECT_EQ(s.notes, 1);
  EXPECT_EQ(s.read_errors, 1);
}

TEST(ReportersTest, TextHasOneCompilerStyleLinePerFindingAndASummary) {
  // Expected lines written by hand from the format `file:line:col: severity: message [rule-id]`:
  // the column is left out when unknown, and the line too; an empty location file falls back to
  // the checked file's path.
  const std::string expected =
      "robot.urdf:42:7: error: principal moments 1, 1, 3 break 3 <= 1 + 1 [inertia-not-physical]\n"
      "robot.urdf:30: warning: radius of gyration 87.8 m, geometry 0.3 m [units-suspect]\n"
      "robot.urdf: note: center of mass 1, 0, 0 outside the box [com-outside-geometry]\n"
      "dir/bad file.sdf:3:5: error: <link>: unclosed element [read-error]\n"
      "massprops: checked 2 files: 1 error, 1 warning, 1 note, 1 read error\n";
  EXPECT_EQ(RenderText(SampleResults()), expected);
}

TEST(ReportersTest, QuietTextLeavesOutTheSummary) {
  ReportOptions options;
  options.quiet = true;
  const std::string text = RenderText(SampleResults(), options);
  EXPECT_EQ(text.find("massprops: checked"), std::string::npos);
  EXPECT_NE(text.find("[inertia-not-physical]\n"), std::string::npos);
}

TEST(ReportersTest, TextWithoutProblemsSaysSoInTheSummary) {
  FileResult clean;
  clean.path = "clean.urdf";
  clean.format = "urdf";
  clean.models = {"clean"};
  EXPECT_EQ(RenderText({clean}), "massprops: checked 1 file: 0 errors, 0 warnings, 0 notes\n");
}

TEST(ReportersTest, ColourTextWrapsSeveritiesInAnsiEscapesAndPlainTextHasNone) {
  ReportOptions options;
  options.color = true;
  const std::string colored = RenderText(SampleResults(), options);
  // SGR codes (ECMA-48): 1;31 bold red, 1;33 bold yellow, 1;36 bold cyan, 0 reset.
  EXPECT_NE(colored.find("\x1b[1;31merror:\x1b[0m"), std::string::npos);
  EXPECT_NE(colored.find("\x1b[1;33mwarning:\x1b[0m"), std::string::npos);
  EXPECT_NE(colored.find("\x1b[1;36mnote:\x1b[0m"), std::string::npos);
  EXPECT_EQ(RenderText(SampleResults()).find('\x1b'), std::string::npos);
}

TEST(ReportersTest, JsonCarriesEveryFieldOfTheDocumentedSchema) {
  ReportOptions options;
  options.tool_version = "9.8.7";
  const json doc = json::parse(RenderJson(SampleResults(), options));
  EXPECT_EQ(doc.at("version"), "9.8.7");
  ASSERT_EQ(doc.at("files").size(), 2u);

  const json& robot = doc["files"][0];
  EXPECT_EQ(robot.at("path"), "robot.urdf");
  EXPECT_EQ(robot.at("format"), "urdf");
  EXPECT_EQ(robot.at("models"), json::array({"arm"}));
  ASSERT_EQ(robot.at("findings").size(), 3u);
  EXPECT_TRUE(robot.at("errors").empty());

  const json& first = robot["findings"][0];
  EXPECT_EQ(first.at("rule"), "inertia-not-physical");
  EXPECT_EQ(first.at("severity"), "error");
  EXPECT_EQ(first.at("model"), "arm");
  EXPECT_EQ(first.at("link"), "forearm");
  EXPECT_EQ(first.at("file"), "robot.urdf");
  EXPECT_EQ(first.at("line"), 42);
  EXPECT_EQ(first.at("column"), 7);
  EXPECT_EQ(first.at("message"), "principal moments 1, 1, 3 break 3 <= 1 + 1");
  EXPECT_EQ(first.at("values").at("principal_min"), 1.0);
  EXPECT_EQ(first.at("values").at("principal_max"), 3.0);

  const json& second = robot["findings"][1];
  EXPECT_EQ(second.at("severity"), "warning");
  EXPECT_EQ(second.at("column"), 0);  // 0 = unknown, as in SourceLocation
  EXPECT_EQ(second.at("values").at("radius_of_gyration"), 87.8);
  EXPECT_TRUE(second.at("values").at("ratio").is_null());  // JSON has no NaN
  EXPECT_EQ(robot["findings"][2].at("severity"), "note");
  EXPECT_EQ(robot["findings"][2].at("file"), "robot.urdf");

  const json& broken = doc["files"][1];
  EXPECT_EQ(broken.at("path"), "dir/bad file.sdf");
  EXPECT_TRUE(broken.at("format").is_null());
  EXPECT_TRUE(broken.at("models").empty());
  ASSERT_EQ(broken.at("errors").size(), 1u);
  EXPECT_EQ(broken["errors"][0].at("line"), 3);
  EXPECT_EQ(broken["errors"][0].at("column"), 5);
  EXPECT_EQ(broken["errors"][0].at("element"), "<link>");
  EXPECT_EQ(broken["errors"][0].at("message"), "unclosed element");
  EXPECT_EQ(broken["errors"][0].at("headline"), "<link>: unclosed element");

  const json& summary = doc.at("summary");
  EXPECT_EQ(summary.at("files"), 2);
  EXPECT_EQ(summary.at("errors"), 1);
  EXPECT_EQ(summary.at("warnings"), 1);
  EXPECT_EQ(summary.at("notes"), 1);
  EXPECT_EQ(summary.at("read_errors"), 1);
}

TEST(ReportersTest, JsonOfNoFilesIsAValidEmptyReport) {
  const json doc = json::parse(RenderJson({}));
  EXPECT_TRUE(doc.at("files").empty());
  EXPECT_EQ(doc.at("summary").at("files"), 0);
}

TEST(ReportersTest, SarifHasTheRequiredFieldsOfVersion210) {
  // Required properties from the SARIF 2.1.0 specification (OASIS, 2020): sarifLog.version
  // (3.13.2) and runs (3.13.4); run.tool (3.14.6); toolComponent.name (3.19.8); result.message
  // (3.27.11); levels "error" | "warning" | "note" (3.27.10); region.startLine >= 1 (3.30.5).
  ReportOptions options;
  options.tool_version = "1.2.3";
  options.information_uri = "https://example.org/massprops";
  const json log = json::parse(RenderSarif(SampleResults(), options));
  EXPECT_EQ(log.at("version"), "2.1.0");
  EXPECT_NE(log.at("$schema").get<std::string>().find("sarif"), std::string::npos);
  ASSERT_EQ(log.at("runs").size(), 1u);
  const json& run = log["runs"][0];
  const json& driver = run.at("tool").at("driver");
  EXPECT_EQ(driver.at("name"), "massprops");
  EXPECT_EQ(driver.at("version"), "1.2.3");
  EXPECT_EQ(driver.at("informationUri"), "https://example.org/massprops");

  // Every rule of AllRules() is described, plus the tool's own read-error and read-warning.
  const json& rules = driver.at("rules");
  ASSERT_EQ(rules.size(), AllRules().size() + 2);
  for (std::size_t i = 0; i < AllRules().size(); ++i) {
    EXPECT_EQ(rules[i].at("id"), AllRules()[i].id);
    EXPECT_EQ(rules[i].at("shortDescription").at("text"), AllRules()[i].summary);
    EXPECT_EQ(rules[i].at("defaultConfiguration").at("level"),
              ToString(AllRules()[i].default_severity));
    EXPECT_EQ(rules[i].at("helpUri"),
              "https://example.org/massprops#" + std::string(AllRules()[i].id));
  }

  const json& results = run.at("results");
  ASSERT_EQ(results.size(), 4u);
  std::set<std::string> levels;
  for (const json& result : results) {
    const int index = result.at("ruleIndex");
    EXPECT_EQ(rules.at(index).at("id"), result.at("ruleId"));
    EXPECT_FALSE(result.at("message").at("text").get<std::string>().empty());
    levels.insert(result.at("level").get<std::string>());
  }
  EXPECT_EQ(levels, (std::set<std::string>{"error", "warning", "note"}));

  // Results come file by file, read errors first: the read error is last here.
  const json& first = results[0];
  EXPECT_EQ(first.at("ruleId"), "inertia-not-physical");
  EXPECT_EQ(first.at("level"), "error");
  const json& physical = first.at("locations")[0].at("physicalLocation");
  EXPECT_EQ(physical.at("artifactLocation").at("uri"), "robot.urdf");
  EXPECT_EQ(physical.at("region").at("startLine"), 42);
  EXPECT_EQ(physical.at("region").at("startColumn"), 7);

  const json& second = results[1].at("locations")[0].at("physicalLocation");
  EXPECT_EQ(second.at("region").at("startLine"), 30);
  EXPECT_FALSE(second.at("region").contains("startColumn"));
  // Line unknown: no region at all (startLine must be >= 1).
  EXPECT_FALSE(results[2].at("locations")[0].at("physicalLocation").contains("region"));

  const json& read_error = results[3];
  EXPECT_EQ(read_error.at("ruleId"), "read-error");
  EXPECT_EQ(read_error.at("level"), "error");
  EXPECT_EQ(read_error.at("message").at("text"), "<link>: unclosed element");
  // RFC 3986: a space in a URI path is percent-encoded as %20.
  EXPECT_EQ(read_error.at("locations")[0].at("physicalLocation").at("artifactLocation").at("uri"),
            "dir/bad%20file.sdf");
}

TEST(ReportersTest, SarifUrisAreRelativeForRelativePathsAndFileUrisForAbsoluteOnes) {
  FileResult absolute;
  absolute.path = "/models/arm.urdf";
  Finding finding;
  finding.rule = "inertia-not-physical";
  finding.location = {"/models/arm.urdf", 1, 1};
  finding.message = "m";
  absolute.findings.push_back(finding);
  FileResult dotted = absolute;
  dotted.path = "./arm.urdf";
  dotted.findings[0].location.file = "./arm.urdf";

  const json log = json::parse(RenderSarif({absolute, dotted}));
  const json& results = log["runs"][0]["results"];
  auto uri = [&](int i) {
    return results[i]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"];
  };
  EXPECT_EQ(uri(0), "file:///models/arm.urdf");
  EXPECT_EQ(uri(1), "arm.urdf");
  // No informationUri was given: the optional property is left out rather than invented.
  EXPECT_FALSE(log["runs"][0]["tool"]["driver"].contains("informationUri"));
}

TEST(ReportersTest, GithubWritesOneWorkflowCommandPerProblem) {
  // Format from GitHub's "Workflow commands for GitHub Actions" documentation:
  // ::error file={name},line={line},col={col},title={title}::{message}; notes use ::notice.
  const std::string expected =
      "::error file=robot.urdf,line=42,col=7,title=inertia-not-physical::principal moments 1, 1, "
      "3 break 3 <= 1 + 1\n"
      "::warning file=robot.urdf,line=30,title=units-suspect::radius of gyration 87.8 m, "
      "geometry 0.3 m\n"
      "::notice file=robot.urdf,title=com-outside-geometry::center of mass 1, 0, 0 outside the "
      "box\n"
      "::error file=dir/bad file.sdf,line=3,col=5,title=read-error::<link>: unclosed element\n";
  EXPECT_EQ(RenderGithub(SampleResults()), expected);
}

TEST(ReportersTest, GithubEscapesDataAndPropertiesPerTheWorkflowCommandRules) {
  // The escaping of actions/toolkit (packages/core/src/command.ts): data escapes % CR LF;
  // properties also escape : and ,.
  EXPECT_EQ(EscapeGithubData("50%, a:b\r\nc"), "50%25, a:b%0D%0Ac");
  EXPECT_EQ(EscapeGithubProperty("a,b:c%d\r\ne"), "a%2Cb%3Ac%25d%0D%0Ae");

  FileResult result;
  result.path = "dir,x/a:b.urdf";
  Finding finding;
  finding.rule = "mass-not-positive";
  finding.severity = Severity::kError;
  finding.location = {"", 2, 0};
  finding.message = "mass 0 (100% wrong)\nsecond line";
  result.findings.push_back(finding);
  EXPECT_EQ(RenderGithub({result}),
            "::error file=dir%2Cx/a%3Ab.urdf,line=2,title=mass-not-positive::mass 0 (100%25 "
            "wrong)%0Asecond line\n");
}

TEST(ReportersTest, FindingsInAnIncludedFileNameThatFile) {
  // An SDF <include> can put a finding in another file than the one checked.
  FileResult world;
  world.path = "world.sdf";
  Finding finding;
  finding.rule = "mass-not-positive";
  finding.severity = Severity::kError;
  finding.location = {"models/arm/model.sdf", 12, 3};
  finding.message = "mass -1";
  world.findings.push_back(finding);
  ReportOptions quiet;
  quiet.quiet = true;
  EXPECT_EQ(RenderText({world}, quiet),
            "models/arm/model.sdf:12:3: error: mass -1 [mass-not-positive]\n");
  EXPECT_EQ(json::parse(RenderJson({world}))["files"][0]["path"], "world.sdf");
  EXPECT_EQ(json::parse(RenderJson({world}))["files"][0]["findings"][0]["file"],
            "models/arm/model.sdf");
}

TEST(ReportersTest, RenderDispatchesOnTheFormat) {
  const std::vector<FileResult> results = SampleResults();
  EXPECT_EQ(Render(ReportFormat::kText, results), RenderText(results));
  EXPECT_EQ(Render(ReportFormat::kJson, results), RenderJson(results));
  EXPECT_EQ(Render(ReportFormat::kSarif, results), RenderSarif(results));
  EXPECT_EQ(Render(ReportFormat::kGithub, results), RenderGithub(results));
}

// A finding of an expanded xacro package whose ixx was written at two places (docs/xacro.md):
// every format names the first source place first and the generated line as well.
std::vector<FileResult> TracedResults() {
  Finding f;
  f.rule = "inertia-not-physical";
  f.link = "arm";
  f.location = {"gen.urdf", 40, 7};
  f.message = "bad";
  FindingSource source;
  source.number = "inertia ixx";
  SourcePlace a;
  a.file = "pkg/urdf/arm.xacro";
  a.line = 12;
  a.how = "literal";
  a.text = "0.25";
  SourcePlace b = a;
  b.file = "pkg/urdf/other.xacro";
  b.line = 3;
  source.places = {a, b};
  source.generated = {"gen.urdf", 40, 0};
  f.source = source;
  FileResult result;
  result.path = "gen.urdf";
  result.format = "urdf";
  result.findings = {f};
  return {result};
}

TEST(ReportersTest, TracedFindingsNameTheSourceFirstAndTheGeneratedLineToo) {
  ReportOptions quiet;
  quiet.quiet = true;
  EXPECT_EQ(RenderText(TracedResults(), quiet),
            "pkg/urdf/arm.xacro:12: error: bad [inertia-not-physical] (inertia ixx: literal at 2 "
            "places: pkg/urdf/arm.xacro:12, pkg/urdf/other.xacro:3; generated gen.urdf:40)\n");

  const json finding = json::parse(RenderJson(TracedResults())).at("files")[0].at("findings")[0];
  EXPECT_EQ(finding.at("file"), "gen.urdf");
  EXPECT_EQ(finding.at("line"), 40);
  EXPECT_EQ(finding.at("source").at("file"), "pkg/urdf/arm.xacro");
  EXPECT_EQ(finding.at("source").at("line"), 12);
  EXPECT_EQ(finding.at("source").at("how"), "literal");
  EXPECT_EQ(finding.at("source").at("places").size(), 2u);
  EXPECT_EQ(finding.at("source").at("generated").at("line"), 40);

  const json result = json::parse(RenderSarif(TracedResults())).at("runs")[0].at("results")[0];
  EXPECT_EQ(result.at("locations")[0].at("physicalLocation").at("artifactLocation").at("uri"),
            "pkg/urdf/arm.xacro");
  const json& related = result.at("relatedLocations");
  ASSERT_EQ(related.size(), 2u);
  EXPECT_EQ(related[0].at("id"), 1);
  EXPECT_EQ(related[0].at("physicalLocation").at("region").at("startLine"), 40);
  EXPECT_EQ(related[1].at("id"), 2);
  EXPECT_EQ(related[1].at("physicalLocation").at("artifactLocation").at("uri"),
            "pkg/urdf/other.xacro");

  const std::string github = RenderGithub(TracedResults());
  EXPECT_EQ(github.rfind("::error file=pkg/urdf/arm.xacro,line=12,title=inertia-not-physical::bad "
                         "(inertia ixx: literal at 2 places",
                         0),
            0u)
      << github;
}

}  // namespace
}  // namespace massprops

namespace massprops {
namespace {

// Three units-suspect findings on one file, two with the same help (one cause) and one with
// another; each with its headline, evidence and help (issue 32).
FileResult PartsResult() {
  FileResult result;
  result.path = "humanoid.urdf";
  result.format = "urdf";
  result.models = {"h"};
  auto add = [&](const std::string& link, int line, double ratio, const std::string& help) {
    Finding f;
    f.rule = "units-suspect";
    f.severity = Severity::kWarning;
    f.model = "h";
    f.link = link;
    f.location = {"humanoid.urdf", line, 0};
    f.message = "the whole reasoning about " + link;
    f.headline = "link '" + link + "': inertia too large (looks like kg·mm²)";
    f.evidence = {{"ratio", ratio}, {"mass_kg", 2}};
    f.help = help;
    result.findings.push_back(f);
  };
  add("thigh", 10, 1000, "multiply the inertia by 1e-6");
  add("foot", 20, 5, "check the mass");
  add("shin", 30, 1200, "multiply the inertia by 1e-6");
  return result;
}

TEST(ReportersPartsTest, RepeatsOfOneCauseShareOneEvidenceAndHelpLine) {
  // Written by hand: the two findings with the same help are a group (in the order of the first),
  // each with its headline line; the evidence gives each number's range over the group (1000x to
  // 1200x; the mass is 2 kg in both) and the help once. The other finding has its own lines.
  ReportOptions quiet;
  quiet.quiet = true;
  EXPECT_EQ(RenderText({PartsResult()}, quiet),
            "humanoid.urdf:10: warning: link 'thigh': inertia too large (looks like kg·mm²) "
            "[units-suspect]\n"
            "humanoid.urdf:30: warning: link 'shin': inertia too large (looks like kg·mm²) "
            "[units-suspect]\n"
            "  = evidence: 2 links: ratio 1000x to 1200x, mass 2 kg\n"
            "  = help: multiply the inertia by 1e-6\n"
            "humanoid.urdf:20: warning: link 'foot': inertia too large (looks like kg·mm²) "
            "[units-suspect]\n"
            "  = evidence: ratio 5x, mass 2 kg\n"
            "  = help: check the mass\n");
}

// Two findings of one rule with the same help about two welded groups (issue 52): each stands
// alone, since its members are its own, and lists them under it; an evidence too long for one
// line goes on two. Split by hand, counting characters: evidence items "mass 0 kg" (9),
// "outboard mass 0.25 kg" (21), "outboard moment 3.33e-5 kg·m²" (29) make 9 + 23 + 31 = 63 of
// the 86 after "  = evidence: "; ", radius of gyration 1.23 cm" (28) would make 91. Members
// "palm" (4), "finger_left_proximal" (20), "finger_left_distal" (18), "finger_right_proximal"
// (21) make 4 + 22 + 20 + 23 = 69 of the 87 after "  = members: "; ", finger_right_distal" (21)
// would make 90.
TEST(ReportersPartsTest, AWeldedGroupsMembersAndALongEvidenceAreListedOnWholeLines) {
  FileResult result;
  result.path = "g.urdf";
  auto add = [&](const std::string& root, int line, const std::vector<std::string>& members) {
    Finding f;
    f.rule = "massless-moving-body";
    f.severity = Severity::kError;
    f.link = root;
    f.group = members;
    f.location = {"g.urdf", line, 0};
    f.headline = "the welded group rooted at '" + root + "' is massless";
    f.evidence = {{"mass_kg", 0},
                  {"outboard_mass_kg", 0.25},
                  {"outboard_moment_kg_m2", 3.33e-5},
                  {"radius_of_gyration_m", 0.0123},
                  {"half_diagonal_m", 0.15},
                  {"links_count", static_cast<double>(members.size())}};
    f.help = "give one of its links a mass";
    result.findings.push_back(f);
  };
  add("palm", 5,
      {"palm", "finger_left_proximal", "finger_left_distal", "finger_right_proximal",
       "finger_right_distal", "camera_mount", "tool_center_point"});
  add("plate", 40, {"plate", "screw"});
  ReportOptions quiet;
  quiet.quiet = true;
  const std::string evidence =
      "  = evidence: mass 0 kg, outboard mass 0.25 kg, outboard moment 3.33e-5 kg·m²\n"
      "  = evidence: radius of gyration 1.23 cm, half diagonal 15 cm, links ";
  EXPECT_EQ(RenderText({result}, quiet),
            "g.urdf:5: error: the welded group rooted at 'palm' is massless "
            "[massless-moving-body]\n" +
                evidence +
                "7\n"
                "  = members: palm, finger_left_proximal, finger_left_distal, "
                "finger_right_proximal\n"
                "  = members: finger_right_distal, camera_mount, tool_center_point\n"
                "  = help: give one of its links a mass\n"
                "g.urdf:40: error: the welded group rooted at 'plate' is massless "
                "[massless-moving-body]\n" +
                evidence +
                "2\n"
                "  = members: plate, screw\n"
                "  = help: give one of its links a mass\n");
}

TEST(ReportersPartsTest, BriefPrintsHeadlinesAloneAndExplainAddsTheReasoning) {
  ReportOptions brief;
  brief.quiet = brief.brief = true;
  const std::string text = RenderText({PartsResult()}, brief);
  EXPECT_EQ(text.find("  = "), std::string::npos);
  EXPECT_NE(text.find("humanoid.urdf:20: warning: link 'foot'"), std::string::npos);
  ReportOptions explain;
  explain.quiet = explain.explain = true;
  const std::string explained = RenderText({PartsResult()}, explain);
  // Not grouped: each finding has its evidence, help and reasoning, in file order.
  EXPECT_NE(
      explained.find("[units-suspect]\n  = evidence: ratio 1000x, mass 2 kg\n  = help: multiply "
                     "the inertia by 1e-6\n  = why: the whole reasoning about thigh\n"),
      std::string::npos);
  EXPECT_NE(explained.find("  = why: the whole reasoning about shin\n"), std::string::npos);
  EXPECT_LT(explained.find("'foot'"), explained.find("'shin'"));
}

TEST(ReportersPartsTest, StatisticsCountFindingsPerRule) {
  std::vector<FileResult> results = SampleResults();
  results.push_back(PartsResult());
  ReportOptions options;
  options.statistics = true;
  // Hand-counted: 3 + 1 units-suspect, 1 each of the others, the read error; most first.
  EXPECT_EQ(RenderText(results, options),
            "    4  warning units-suspect\n"
            "    1  note    com-outside-geometry\n"
            "    1  error   inertia-not-physical\n"
            "    1  error   read-error\n"
            "massprops: checked 3 files: 1 error, 4 warnings, 1 note, 1 read error\n");
}

TEST(ReportersPartsTest, MachineFormatsCarryThePartsAndKeepTheMessage) {
  const json doc = json::parse(RenderJson({PartsResult()}));
  const json& first = doc["files"][0]["findings"][0];
  EXPECT_EQ(first.at("message"), "the whole reasoning about thigh");
  EXPECT_EQ(first.at("headline"), "link 'thigh': inertia too large (looks like kg·mm²)");
  EXPECT_EQ(first.at("evidence").at("ratio"), 1000);
  EXPECT_EQ(first.at("evidence").at("mass_kg"), 2);
  EXPECT_EQ(first.at("help"), "multiply the inertia by 1e-6");

  const json sarif = json::parse(RenderSarif({PartsResult()}));
  const json& result = sarif["runs"][0]["results"][0];
  EXPECT_EQ(result.at("message").at("text"), "link 'thigh': inertia too large (looks like kg·mm²)");
  EXPECT_EQ(result.at("properties").at("evidence").at("ratio"), 1000);
  EXPECT_EQ(result.at("properties").at("message"), "the whole reasoning about thigh");
  for (const json& rule : sarif["runs"][0]["tool"]["driver"]["rules"]) {
    if (rule.at("id") != "units-suspect") continue;
    // The long form is the rule's section of docs/rules.md.
    EXPECT_EQ(rule.at("help").at("text").get<std::string>().rfind("### `units-suspect`", 0), 0u);
    EXPECT_FALSE(rule.at("fullDescription").at("text").get<std::string>().empty());
  }

  // GitHub: the title is the rule, the text the headline and the help (%0A: a new line).
  const std::string github = RenderGithub({PartsResult()});
  EXPECT_NE(github.find("title=units-suspect::link 'thigh': inertia too large (looks like "
                        "kg·mm²)%0Ahelp: multiply the inertia by 1e-6\n"),
            std::string::npos);
}

// A read error whose text (element + message) is longer than a headline: its first clause is
// the headline in every format, whole (no "…"), and the whole text is beside it.
FileResult LongReadErrorResult() {
  FileResult result;
  result.path = "r.urdf";
  ReadError error;
  error.location = {"r.urdf", 9, 0};
  error.element = "<mesh>";
  // "<mesh>: " (8) + 70 = 78 characters before "; ", 78 + 2 + 80 = 160 in all.
  error.message = "filename '" + std::string(50, 'f') + "' is empty; " + std::string(80, 'w');
  result.errors.push_back(error);
  return result;
}

TEST(ReportersPartsTest, ALongReadErrorHasAWholeHeadlineInEveryFormatAndItsTextBeside) {
  const std::string headline = "<mesh>: filename '" + std::string(50, 'f') + "' is empty";
  ASSERT_EQ(CountChars(headline), 78u);
  const std::string whole = headline + "; " + std::string(80, 'w');
  ReportOptions quiet;
  quiet.quiet = true;
  // The whole text under it on whole lines of at most 100 characters: "  = why: " (9) and the
  // headline with its ";" (79) make 88, and the 80 w's would make 169: they go on the next line,
  // indented under the text (9 + 80 = 89).
  EXPECT_EQ(RenderText({LongReadErrorResult()}, quiet),
            "r.urdf:9: error: " + headline + " [read-error]\n  = why: " + headline + ";\n" +
                std::string(9, ' ') + std::string(80, 'w') + "\n");
  const json doc = json::parse(RenderJson({LongReadErrorResult()}));
  EXPECT_EQ(doc["files"][0]["errors"][0].at("headline"), headline);
  const json sarif = json::parse(RenderSarif({LongReadErrorResult()}));
  const json& result = sarif["runs"][0]["results"][0];
  EXPECT_EQ(result.at("message").at("text"), headline);
  EXPECT_EQ(result.at("properties").at("message"), whole);
  EXPECT_EQ(RenderGithub({LongReadErrorResult()}),
            "::error file=r.urdf,line=9,title=read-error::" + headline + "%0A" + whole + "\n");
}

// A finding of a rule whose headline names a long link (60 characters, one "word" longer than
// the 55 that messages shorten): printed whole, as the rule wrote it, in text and JSON.
TEST(ReportersPartsTest, AHeadlineThatFitsIsPrintedWholeWhateverItsWords) {
  FileResult result;
  result.path = "r.urdf";
  Finding f;
  f.rule = "mass-not-positive";
  f.severity = Severity::kError;
  f.link = std::string(60, 'l');
  f.location = {"r.urdf", 4, 0};
  f.message = "the reasoning";
  f.headline = LinkHeadline(f.link, ": mass -1 kg is negative");  // 6 + 60 + 1 + 24 = 91
  ASSERT_EQ(f.headline, "link '" + f.link + "': mass -1 kg is negative");
  result.findings.push_back(f);
  ReportOptions options;
  options.quiet = options.brief = true;
  EXPECT_EQ(RenderText({result}, options),
            "r.urdf:4: error: link '" + f.link + "': mass -1 kg is negative [mass-not-positive]\n");
  EXPECT_EQ(json::parse(RenderJson({result}))["files"][0]["findings"][0].at("headline"),
            f.headline);
  EXPECT_EQ(FindingHeadlineLine(f),
            "r.urdf:4: error: link '" + f.link + "': mass -1 kg is negative [mass-not-positive]");
}

}  // namespace
}  // namespace massprops
