#pragma once
/// @file
/// Reporters: render the results of `massprops check` (per file: its models, its findings and the
/// errors that kept it from being read) as text, JSON, SARIF 2.1.0, GitHub workflow commands,
/// JUnit XML or a GitLab Code Quality report.
/// Reporters only render; the tool decides exit codes.

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"

namespace massprops {

/// How one mesh URI of a checked file resolved.
struct MeshUriResolution {
  std::string uri;   ///< As written.
  std::string path;  ///< The file found; empty when it did not resolve.
  MeshFoundBy found_by = MeshFoundBy::kNone;
};

/// Everything `check` learned about one input file.
struct FileResult {
  std::string path;                 ///< As given by the user; "<stdin>" for standard input.
  std::string format;               ///< "urdf" or "sdf"; empty when the file could not be read.
  std::vector<std::string> models;  ///< Names of the models read from the file.
  std::vector<Finding> findings;    ///< In the order CheckModel returned them.
  std::vector<ReadError> errors;    ///< Why the file (or part of it) could not be read.
  /// Links whose geometry includes a mesh, when `check` read the meshes' bounding boxes (its
  /// default; 0 with --no-geometry or --geometry) ...
  int mesh_links = 0;
  /// ... of which those with a mesh that did not resolve or could not be read (their extent is
  /// unknown: said once in the summary, not per link), and the first such mesh's URI.
  int mesh_links_unresolved = 0;
  std::string first_unresolved_mesh;
  /// Each distinct mesh URI of the file's links (per file holding it), in file order, with how
  /// it resolved, when `check` read meshes (not with --no-geometry).
  std::vector<MeshUriResolution> mesh_uris;
  /// The file's fail level (--fail-on, or its configuration's fail-on): JUnit makes the findings
  /// at or above it failing testcases.
  Severity fail_on = Severity::kError;
};

/// Counts over a list of results. `errors`, `warnings` and `notes` count findings by severity;
/// `read_errors` counts ReadErrors.
struct ReportSummary {
  int files = 0;
  int errors = 0;
  int warnings = 0;
  int notes = 0;
  int read_errors = 0;
  int mesh_links = 0;                 ///< Sum of FileResult::mesh_links.
  int mesh_links_unresolved = 0;      ///< Sum of FileResult::mesh_links_unresolved.
  std::string first_unresolved_mesh;  ///< The first file's first_unresolved_mesh that is set.
  /// FileResult::mesh_uris counted by found_by (index: the MeshFoundBy value; kNone counts those
  /// that did not resolve).
  std::vector<int> mesh_resolution = std::vector<int>(8, 0);
};

enum class ReportFormat { kText, kJson, kSarif, kGithub, kJunit, kGitlab };

/// Parses "text", "json", "sarif", "github", "junit", "gitlab"; nullopt otherwise.
std::optional<ReportFormat> ParseReportFormat(std::string_view text);

/// How to render.
struct ReportOptions {
  /// Text only: wrap locations, severities and rule ids in ANSI colour escapes.
  bool color = false;
  /// Text only: leave out the closing summary line.
  bool quiet = false;
  /// Text only: each finding's headline alone (no evidence or help lines).
  bool brief = false;
  /// Text only: under each finding, its evidence, its help and its full reasoning (the message:
  /// the causes considered and what the numbers say of each); repeats are not grouped.
  bool explain = false;
  /// Text only: instead of the findings, the number of findings per rule (like ruff).
  bool statistics = false;
  /// Files of the folders given that were not taken as models (text summary line, JSON
  /// summary "skipped_files").
  int skipped_files = 0;
  /// The tool's version, written into JSON and SARIF.
  std::string tool_version = MASSPROPS_VERSION;
  /// SARIF `tool.driver.informationUri` (and the base of each rule's helpUri, as
  /// `information_uri + "#" + rule id`); omitted when empty. Must be an absolute URI.
  std::string information_uri;
};

/// The rule id given to ReadErrors in every format.
inline constexpr const char* kReadErrorRule = "read-error";
/// The rule id the tool gives to a reader's warnings (elements it skipped), reported as findings.
inline constexpr const char* kReadWarningRule = "read-warning";

/// A ReadError's whole text: "element: message" (the message alone without an element).
std::string ReadErrorText(const ReadError& error);
/// A ReadError's headline in every format: its whole text when it has at most
/// kMaxHeadlineChars characters, else a shorter whole sentence (HeadlineFromMessage in
/// finding_text.h: its leading clauses, or its element and "the full message says what cannot
/// be read"); the whole text is then under it (text: `  = why: ...`; JSON: "message"; SARIF:
/// properties.message; GitHub: the next line).
std::string ReadErrorHeadline(const ReadError& error);

/// A reader's warning (an element it skipped) as the finding every command reports: rule
/// kReadWarningRule, its text as the message, its first clause as the headline
/// (HeadlineFromMessage), and the help.
Finding ReadWarningFinding(const ReadError& warning);

/// `file:line:col: severity: HEADLINE [rule]` of one finding at its own location, as `check`'s
/// text prints it (no colour, no xacro note, no new line): how `fix` names a finding.
std::string FindingHeadlineLine(const Finding& finding);

/// Counts findings by severity, and read errors, over `results`. Cost: linear.
ReportSummary Summarize(const std::vector<FileResult>& results);

/// One line per finding, `file:line:col: severity: HEADLINE [rule-id]` (`:col` left out when the
/// column is unknown, `:line` too when the line is; the headline whole: at most kMaxHeadlineChars
/// characters, finding_text.h), and under it whole lines (never cut) of at most kMaxDetailChars
/// characters: `  = evidence: ...` (on as many lines as its numbers need), for a finding about a
/// welded group `  = members: ...` (its links, on as many lines as they need), and
/// `  = help: ...` (one line, as the rule wrote it). Findings of one rule in one file with the
/// same help (one cause) are a group, unless they are about welded groups: each keeps its
/// headline line, and the evidence (each number's range over the group) and the help are
/// printed once, under the last. `options.brief`: headlines only; `options.explain`: no
/// grouping, and `  = why: MESSAGE` wrapped at spaces (its next lines indented under its text);
/// `options.statistics`:
/// counts per rule instead of the findings. One line per ReadError,
/// `file:line:col: error: HEADLINE [read-error]` (ReadErrorHeadline), followed by
/// `  = why: element: message` (wrapped alike) when the headline is shorter than that (not with
/// `brief`), then
/// (unless quiet) a summary line,
/// and when some links' meshes did not resolve, one more line that says how many (and the first
/// URI), e.g. `massprops: 12 links' meshes did not resolve or could not be read: their size is
/// unknown to the geometry rules (use --package-path DIR; first: 'package://x/y.stl')`.
/// The file named is the finding's own location file when it has one (an SDF <include> may point
/// into another file), else the FileResult's path.
std::string RenderText(const std::vector<FileResult>& results, const ReportOptions& options = {});

/// The JSON document described in docs/cli.md:
/// {"version", "files": [{"path", "format", "models", "findings": [{"rule", "severity", "model",
/// "link", "file", "line", "column", "message", "headline", "evidence": {name: number}, "help",
/// "values": {name: number}, and for a finding about a welded group "group": [member link names,
/// the root first]}], "errors": [{"file", "line", "column", "element", "message", "headline"}]}],
/// "summary": {"files", "errors", "warnings", "notes", "read_errors", "skipped_files",
/// "mesh_links", "mesh_links_unresolved",
/// "first_unresolved_mesh" (a string, or null when none), "mesh_resolution"}}. Each file also
/// has "mesh_links", "mesh_links_unresolved", "mesh_resolution" ({"flag", "repository-package",
/// "ancestor", "environment", "beside-file", "relative", "absolute", "unresolved"}: its distinct
/// mesh URIs counted by how they resolved; the summary's sums them) and "mesh_uris" ([{"uri",
/// "found_by", "path"}], path null when unresolved). Non-finite values are written as null.
/// Indented by two spaces.
std::string RenderJson(const std::vector<FileResult>& results, const ReportOptions& options = {});

/// A SARIF 2.1.0 log with one run: the driver lists every rule of AllRules(), "read-error" and
/// "read-warning";
/// each rule's fullDescription (the first paragraph of its long form) and help (the long form:
/// RuleLongForm in finding_text.h) when docs/rules.md has one;
/// each finding and ReadError is a result with ruleId, ruleIndex, level, message (a finding's
/// headline; its "properties" hold "evidence", "help", the full "message" and, for a finding
/// about a welded group, "group": its members' names) and a physical
/// location (artifact URI relative to the working directory when the path is relative, a
/// file:// URI when absolute; region only when the line is known). When meshes were read, the
/// run's "properties" hold "mesh_links", "mesh_links_unresolved", "first_unresolved_mesh" and
/// "mesh_resolution" (as in JSON's summary).
std::string RenderSarif(const std::vector<FileResult>& results, const ReportOptions& options = {});

/// One GitHub Actions workflow command per finding and ReadError:
/// `::error file=F,line=L,col=C,title=RULE::HEADLINE` followed, when the finding has help, by a
/// new line and `help: HELP` (warning for warnings, notice for notes),
/// escaped per the workflow-command rules (EscapeGithubData / EscapeGithubProperty).
std::string RenderGithub(const std::vector<FileResult>& results, const ReportOptions& options = {});

/// JUnit XML as colcon test-result, GitLab and Jenkins read it (docs/cli.md, "junit"): a
/// <testsuites> holding one <testsuite> per file (name: the path); in it one <testcase> per
/// finding at or above the file's fail_on, named "RULE: LINK" (classname "massprops.MODEL", file
/// and line attributes), failing with message = the headline and as text the file:line, the
/// evidence, the help and a welded group's members; one per ReadError, with an <error> element;
/// and when the file has neither, one passing testcase "massprops check". A finding below the
/// fail level is a passing testcase of the same name whose <system-out> holds that text (it is
/// seen, and fails nothing). Names and texts are XML-escaped; characters XML 1.0 cannot hold are
/// written as U+FFFD.
std::string RenderJunit(const std::vector<FileResult>& results, const ReportOptions& options = {});

/// GitLab's Code Quality report (docs/cli.md, "gitlab"): a JSON array with one item per finding
/// and ReadError: {"description" (the headline), "check_name" (the rule id), "fingerprint",
/// "severity" (error: "major", warning: "minor", note: "info"; a ReadError: "critical"),
/// "location": {"path", "lines": {"begin"}}}. The fingerprint is the SHA-256 (hex) of the rule,
/// the file, the model, the link (a ReadError: its element) and the occurrence index among the
/// run's items that share those four: it does not change when lines move, and is unique within
/// the run. A line that is unknown is written as 1 (GitLab requires one).
std::string RenderGitlab(const std::vector<FileResult>& results, const ReportOptions& options = {});

/// Dispatches to the Render* function of `format`.
std::string Render(ReportFormat format, const std::vector<FileResult>& results,
                   const ReportOptions& options = {});

/// Writes Render(format, results, options) to `out`.
void WriteReport(std::ostream& out, ReportFormat format, const std::vector<FileResult>& results,
                 const ReportOptions& options = {});

/// Messages for people: every run of more than `max_word` bytes without white space (a hostile
/// 10 MB link name) is shortened to its first and last bytes around "…[N bytes]…", cut at UTF-8
/// character boundaries. Text up to that length comes back unchanged. Used for the messages of
/// every format and the names in `report`'s tables; JSON and SARIF keep the full names in their
/// "link" and "model" fields. Cost: linear.
std::string ShortenLongWords(std::string_view text, std::size_t max_word = 200);

/// Workflow-command escaping of a message: % → %25, CR → %0D, LF → %0A.
std::string EscapeGithubData(std::string_view text);
/// Workflow-command escaping of a property value: as EscapeGithubData, plus : → %3A and , → %2C.
std::string EscapeGithubProperty(std::string_view text);

}  // namespace massprops
