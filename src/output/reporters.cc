#include "massprops/output/reporters.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/fix_text.h"

namespace massprops {
namespace {

using json = nlohmann::ordered_json;

// ANSI SGR sequences used by the text reporter.
constexpr const char* kBold = "\x1b[1m";
constexpr const char* kRed = "\x1b[1;31m";
constexpr const char* kYellow = "\x1b[1;33m";
constexpr const char* kCyan = "\x1b[1;36m";
constexpr const char* kDim = "\x1b[2m";
constexpr const char* kReset = "\x1b[0m";

// The file a finding or error points at: its own location's file when it has one (not the
// stdin marker "-"), else the path of the file that was checked.
const std::string& FileOf(const SourceLocation& location, const FileResult& result) {
  if (location.file.empty() || location.file == "-") return result.path;
  return location.file;
}

std::string FormatLocation(const std::string& file, int line, int column) {
  std::string out = file;
  if (line > 0) {
    out += ':' + std::to_string(line);
    if (column > 0) out += ':' + std::to_string(column);
  }
  return out;
}

const char* SeverityColor(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return kRed;
    case Severity::kWarning:
      return kYellow;
    case Severity::kNote:
      return kCyan;
  }
  return kReset;
}

std::string Plural(int count, const char* word) {
  return std::to_string(count) + " " + word + (count == 1 ? "" : "s");
}

// JSON number, or null when not finite (JSON has no NaN or Inf).
json Number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

// Percent-encodes everything but RFC 3986 unreserved characters and '/'.
std::string PercentEncodePath(std::string_view path) {
  static const char* kHex = "0123456789ABCDEF";
  std::string out;
  for (char c : path) {
    const auto u = static_cast<unsigned char>(c);
    const bool unreserved = (u >= 'A' && u <= 'Z') || (u >= 'a' && u <= 'z') ||
                            (u >= '0' && u <= '9') || u == '-' || u == '.' || u == '_' ||
                            u == '~' || u == '/';
    if (unreserved) {
      out += c;
    } else {
      out += '%';
      out += kHex[u >> 4];
      out += kHex[u & 15];
    }
  }
  return out;
}

// A SARIF artifact URI for a path as the user gave it.
std::string ArtifactUri(const std::string& path) {
  if (path == "<stdin>" || path == "-") return "stdin";
  if (!path.empty() && path[0] == '/') return "file://" + PercentEncodePath(path);
  std::string_view relative = path;
  while (relative.size() > 2 && relative.substr(0, 2) == "./") relative.remove_prefix(2);
  return PercentEncodePath(relative);
}

const char* SarifLevel(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "error";
    case Severity::kWarning:
      return "warning";
    case Severity::kNote:
      return "note";
  }
  return "none";
}

const char* GithubCommand(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "error";
    case Severity::kWarning:
      return "warning";
    case Severity::kNote:
      return "notice";
  }
  return "notice";
}

std::string Escape(std::string_view text, bool property) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '%':
        out += "%25";
        break;
      case '\r':
        out += "%0D";
        break;
      case '\n':
        out += "%0A";
        break;
      case ':':
        out += property ? "%3A" : ":";
        break;
      case ',':
        out += property ? "%2C" : ",";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string GithubLine(const char* command, const std::string& file, int line, int column,
                       const std::string& title, const std::string& message) {
  std::string out = "::";
  out += command;
  out += " file=" + EscapeGithubProperty(file);
  if (line > 0) {
    out += ",line=" + std::to_string(line);
    if (column > 0) out += ",col=" + std::to_string(column);
  }
  out += ",title=" + EscapeGithubProperty(title);
  out += "::" + EscapeGithubData(message) + "\n";
  return out;
}

// Where a traced finding's numbers were written, for the text formats: " (mass: literal; generated
// F:L)", " (inertia ixx: computed from mass=0.17, y=0.1 by the call here; ...)", or with several
// places " (mass: literal at 2 places: a:1, b:2; ...)".
std::string SourceNote(const FindingSource& source) {
  const SourcePlace& first = source.places.front();
  std::string out = " (" + source.number + ": " + first.how;
  if (first.how == "computed" && !first.inputs.empty()) {
    out += " from ";
    for (std::size_t i = 0; i < first.inputs.size(); ++i) out += (i ? ", " : "") + first.inputs[i];
    out += " by the call here";
  }
  if (source.places.size() > 1) {
    out += " at " + std::to_string(source.places.size()) + " places:";
    for (std::size_t i = 0; i < source.places.size(); ++i) {
      out += (i ? ", " : " ") + source.places[i].file + ":" + std::to_string(source.places[i].line);
    }
  }
  out += "; generated " + FormatLocation(source.generated.file, source.generated.line, 0) + ")";
  return out;
}

// The finding's evidence as {name: number} (null when not finite).
json EvidenceJson(const Finding& finding) {
  json evidence = json::object();
  for (const auto& [name, value] : finding.evidence) evidence[name] = Number(value);
  return evidence;
}

// The first paragraph of a rule's long form, after its heading line.
std::string FirstParagraph(const std::string& long_form) {
  std::size_t start = long_form.find('\n');
  start = start == std::string::npos ? 0 : start + 1;
  std::size_t end = long_form.find("\n\n", start);
  if (end == std::string::npos) end = long_form.size();
  std::string text = long_form.substr(start, end - start);
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.empty() ? long_form : text;
}

// A GitHub annotation's second line: "\nhelp: HELP", or "" without help.
std::string HelpText(const Finding& finding) {
  return finding.help.empty() ? "" : "\nhelp: " + finding.help;
}

json SourcePlaceJson(const SourcePlace& place) {
  json out = {{"file", place.file}, {"line", place.line}, {"how", place.how}, {"text", place.text}};
  if (!place.inputs.empty()) out["inputs"] = place.inputs;
  return out;
}

}  // namespace

std::optional<ReportFormat> ParseReportFormat(std::string_view text) {
  if (text == "text") return ReportFormat::kText;
  if (text == "json") return ReportFormat::kJson;
  if (text == "sarif") return ReportFormat::kSarif;
  if (text == "github") return ReportFormat::kGithub;
  if (text == "junit") return ReportFormat::kJunit;
  if (text == "gitlab") return ReportFormat::kGitlab;
  return std::nullopt;
}

ReportSummary Summarize(const std::vector<FileResult>& results) {
  ReportSummary summary;
  summary.files = static_cast<int>(results.size());
  for (const FileResult& result : results) {
    for (const Finding& finding : result.findings) {
      switch (finding.severity) {
        case Severity::kError:
          ++summary.errors;
          break;
        case Severity::kWarning:
          ++summary.warnings;
          break;
        case Severity::kNote:
          ++summary.notes;
          break;
      }
    }
    summary.read_errors += static_cast<int>(result.errors.size());
    summary.mesh_links += result.mesh_links;
    summary.mesh_links_unresolved += result.mesh_links_unresolved;
    if (summary.first_unresolved_mesh.empty()) {
      summary.first_unresolved_mesh = result.first_unresolved_mesh;
    }
    for (const MeshUriResolution& mesh : result.mesh_uris) {
      ++summary.mesh_resolution.at(static_cast<std::size_t>(mesh.found_by));
    }
  }
  return summary;
}

namespace {

// How many mesh URIs resolved each way: {"flag": n, ..., "unresolved": n}.
json MeshResolutionJson(const std::vector<int>& counts) {
  json out = json::object();
  for (std::size_t i = 1; i < counts.size(); ++i) {
    out[ToString(static_cast<MeshFoundBy>(i))] = counts[i];
  }
  out["unresolved"] = counts.at(0);
  return out;
}

// The summary's line on meshes that did not resolve; empty when there are none.
std::string UnresolvedMeshesLine(const ReportSummary& s) {
  if (s.mesh_links_unresolved == 0) return "";
  const std::string& uri = s.first_unresolved_mesh;
  const bool package = uri.rfind("package://", 0) == 0, model = uri.rfind("model://", 0) == 0;
  const std::string hint = package ? "use --package-path DIR; "
                           : model ? "use --model-path DIR; "
                                   : "";
  return "massprops: " + std::to_string(s.mesh_links_unresolved) +
         (s.mesh_links_unresolved == 1 ? " link's mesh" : " links' meshes") +
         " did not resolve or could not be read: their size is unknown to the geometry rules (" +
         hint + "first: '" + ShortenLongWords(uri) + "')\n";
}

}  // namespace

namespace {

// The evidence of a group of findings of one rule and cause: each number of the first finding,
// as its range over the group ("ratio 577x to 1200x"), or its value when all agree; as whole
// lines of at most `max_chars` characters, the first starting "2 links: ".
std::vector<std::string> GroupEvidence(const std::vector<const Finding*>& group,
                                       std::size_t max_chars) {
  std::vector<std::string> items;
  for (const auto& [name, value] : group.front()->evidence) {
    double low = value, high = value;
    for (const Finding* f : group) {
      for (const auto& [other, v] : f->evidence) {
        if (other == name && std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
      }
    }
    std::string text = FormatEvidenceValue(name, low);
    const std::string high_text = FormatEvidenceValue(name, high);
    if (high_text != text) text += " to " + high_text;
    items.push_back(EvidenceLabel(name) + " " + text);
  }
  if (items.empty()) return {};
  items.front().insert(0, std::to_string(group.size()) + " links: ");
  return JoinIntoLines(items, max_chars);
}

// The findings of one file as groups: those of one rule with the same non-empty help (one
// cause) together, each group in the order of its first finding; every other finding alone.
std::vector<std::vector<const Finding*>> GroupFindings(const std::vector<Finding>& findings,
                                                       bool group) {
  std::vector<std::vector<const Finding*>> groups;
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  for (const Finding& finding : findings) {
    // A welded group's finding stands alone: its members are its own.
    if (!group || finding.help.empty() || !finding.group.empty()) {
      groups.push_back({&finding});
      continue;
    }
    const auto [at, added] = index.try_emplace({finding.rule, finding.help}, groups.size());
    if (added) groups.emplace_back();
    groups[at->second].push_back(&finding);
  }
  return groups;
}

// `file:line: severity: HEADLINE [rule]` (and the xacro source note) for one finding.
std::string HeadlineLine(const Finding& finding, const FileResult& result, bool color) {
  // A finding traced to xacro sources points at the source first (docs/xacro.md).
  const bool traced = finding.source && !finding.source->places.empty();
  const std::string where = traced ? FormatLocation(finding.source->places.front().file,
                                                    finding.source->places.front().line, 0)
                                   : FormatLocation(FileOf(finding.location, result),
                                                    finding.location.line, finding.location.column);
  const std::string note = traced ? ShortenLongWords(SourceNote(*finding.source)) : "";
  const std::string severity = std::string(ToString(finding.severity)) + ":";
  // Whole, as the rule wrote it: a headline is a sentence of at most kMaxHeadlineChars
  // characters (finding_text.h), so no word of it needs shortening.
  const std::string headline = HeadlineOf(finding);
  if (color) {
    return std::string(kBold) + where + ":" + kReset + " " + SeverityColor(finding.severity) +
           severity + kReset + " " + headline + " " + kDim + "[" + finding.rule + "]" + note +
           kReset + "\n";
  }
  return where + ": " + severity + " " + headline + " [" + finding.rule + "]" + note + "\n";
}

// `  = LABEL: TEXT` for each of `lines`: a list split into whole lines (evidence, members)
// repeats its label on each.
std::string LabelledLines(const std::string& label, const std::vector<std::string>& lines,
                          bool color) {
  std::string out;
  for (const std::string& line : lines) {
    out += (color ? std::string(kDim) : "") + "  = " + label + ": " + line +
           (color ? std::string(kReset) : "") + "\n";
  }
  return out;
}

// `  = why: TEXT` for prose (a reader's message, a finding's reasoning), split at spaces into
// whole lines of at most kMaxDetailChars characters, the lines after the first indented under
// its text.
std::string WhyLines(const std::string& text, bool color) {
  const std::string first = "  = why: ", next(CountChars(first), ' ');
  std::string out;
  std::string prose = ShortenLongWords(text);
  std::replace(prose.begin(), prose.end(), '\n', ' ');
  for (const std::string& line : WrapWords(prose, kMaxDetailChars - CountChars(first))) {
    out += (color ? std::string(kDim) : "") + (out.empty() ? first : next) + line +
           (color ? std::string(kReset) : "") + "\n";
  }
  return out;
}

// The lines under a group's headlines, each whole and at most kMaxDetailChars characters where
// the rules keep to their limits: `  = evidence: ...` (as many lines as its numbers need),
// `  = members: ...` (a welded group's links), `  = help: ...` (and with explain, `  = why: ...`,
// the full reasoning).
std::string DetailLines(const std::vector<const Finding*>& group, const ReportOptions& options) {
  const Finding& first = *group.front();
  const bool color = options.color;
  std::string out;
  const std::size_t evidence_room = kMaxDetailChars - CountChars("  = evidence: ");
  out += LabelledLines(
      "evidence",
      group.size() > 1 ? GroupEvidence(group, evidence_room) : FormatEvidenceLines(first.evidence),
      color);
  if (!first.group.empty()) {
    std::vector<std::string> names;
    for (const std::string& name : first.group) names.push_back(ShortenLongWords(name));
    out += LabelledLines(
        "members", JoinIntoLines(names, kMaxDetailChars - CountChars("  = members: ")), color);
  }
  // Whole, as the rule wrote it: a help is at most kMaxDetailChars characters with its label
  // (the rules' tests and the corpus's, headline_form_test.cc, hold them to it).
  if (!first.help.empty()) out += LabelledLines("help", {ShortenLongWords(first.help)}, color);
  if (options.explain && !first.message.empty() && first.message != first.headline) {
    out += WhyLines(first.message, color);
  }
  return out;
}

// `--statistics`: the number of findings per rule, most first (then by rule id), like ruff.
std::string StatisticsLines(const std::vector<FileResult>& results) {
  std::map<std::pair<std::string, std::string>, int> counts;  // (rule, severity) -> count
  for (const FileResult& result : results) {
    for (const ReadError& error : result.errors) {
      (void)error;
      ++counts[{kReadErrorRule, "error"}];
    }
    for (const Finding& finding : result.findings) {
      ++counts[{finding.rule, ToString(finding.severity)}];
    }
  }
  std::vector<std::pair<int, std::pair<std::string, std::string>>> rows;
  for (const auto& [key, count] : counts) rows.push_back({count, key});
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string out;
  for (const auto& [count, key] : rows) {
    std::string number = std::to_string(count);
    if (number.size() < 5) number.insert(0, 5 - number.size(), ' ');
    std::string severity = key.second;
    severity.resize(8, ' ');
    out += number + "  " + severity + key.first + "\n";
  }
  return out;
}

}  // namespace

std::string RenderText(const std::vector<FileResult>& results, const ReportOptions& options) {
  const bool color = options.color;
  std::string out;
  for (const FileResult& result : options.statistics ? std::vector<FileResult>{} : results) {
    for (const ReadError& error : result.errors) {
      const std::string where = FormatLocation(FileOf(error.location, result), error.location.line,
                                               error.location.column);
      out += color ? std::string(kBold) + where + ":" + kReset + " " + kRed + "error:" + kReset
                   : where + ": error:";
      const std::string headline = ReadErrorHeadline(error);
      out += " " + headline + " ";
      out += color ? std::string(kDim) + "[" + kReadErrorRule + "]" + kReset
                   : std::string("[") + kReadErrorRule + "]";
      out += "\n";
      // A read error has no --explain: its whole message goes under a shorter headline.
      if (headline != ReadErrorText(error) && !options.brief) {
        out += WhyLines(ReadErrorText(error), color);
      }
    }
    const bool group = !options.explain && !options.brief;
    for (const std::vector<const Finding*>& members : GroupFindings(result.findings, group)) {
      for (const Finding* finding : members) out += HeadlineLine(*finding, result, color);
      if (!options.brief) out += DetailLines(members, options);
    }
  }
  if (options.statistics) out += StatisticsLines(results);
  if (!options.quiet) {
    const ReportSummary s = Summarize(results);
    out += "massprops: checked " + Plural(s.files, "file") + ": " + Plural(s.errors, "error") +
           ", " + Plural(s.warnings, "warning") + ", " + Plural(s.notes, "note");
    if (s.read_errors > 0) out += ", " + Plural(s.read_errors, "read error");
    if (options.skipped_files > 0) {
      out += "; " + Plural(options.skipped_files, "other file") + " in the folders skipped";
    }
    out += "\n";
    out += UnresolvedMeshesLine(s);
  }
  return out;
}

std::string RenderJson(const std::vector<FileResult>& results, const ReportOptions& options) {
  json files = json::array();
  for (const FileResult& result : results) {
    json findings = json::array();
    for (const Finding& finding : result.findings) {
      json values = json::object();
      for (const auto& [name, value] : finding.values) values[name] = Number(value);
      findings.push_back({{"rule", finding.rule},
                          {"severity", ToString(finding.severity)},
                          {"model", finding.model},
                          {"link", finding.link},
                          {"file", FileOf(finding.location, result)},
                          {"line", finding.location.line},
                          {"column", finding.location.column},
                          {"message", ShortenLongWords(finding.message)},
                          {"headline", HeadlineOf(finding)},
                          {"evidence", EvidenceJson(finding)},
                          {"help", ShortenLongWords(finding.help)},
                          {"values", values}});
      if (!finding.group.empty()) findings.back()["group"] = finding.group;
      if (finding.source && !finding.source->places.empty()) {
        const FindingSource& source = *finding.source;
        json entry = SourcePlaceJson(source.places.front());
        entry["number"] = source.number;
        if (source.places.size() > 1) {
          entry["places"] = json::array();
          for (const SourcePlace& place : source.places) {
            entry["places"].push_back(SourcePlaceJson(place));
          }
        }
        entry["generated"] = {{"file", source.generated.file}, {"line", source.generated.line}};
        findings.back()["source"] = entry;
      }
    }
    json errors = json::array();
    for (const ReadError& error : result.errors) {
      errors.push_back({{"file", FileOf(error.location, result)},
                        {"line", error.location.line},
                        {"column", error.location.column},
                        {"element", ShortenLongWords(error.element)},
                        {"message", ShortenLongWords(error.message)},
                        {"headline", ReadErrorHeadline(error)}});
    }
    std::vector<int> counts(8, 0);
    json mesh_uris = json::array();
    for (const MeshUriResolution& mesh : result.mesh_uris) {
      ++counts.at(static_cast<std::size_t>(mesh.found_by));
      mesh_uris.push_back({{"uri", mesh.uri},
                           {"found_by", ToString(mesh.found_by)},
                           {"path", mesh.path.empty() ? json(nullptr) : json(mesh.path)}});
    }
    files.push_back({{"path", result.path},
                     {"format", result.format.empty() ? json(nullptr) : json(result.format)},
                     {"models", result.models},
                     {"findings", findings},
                     {"errors", errors},
                     {"mesh_links", result.mesh_links},
                     {"mesh_links_unresolved", result.mesh_links_unresolved},
                     {"mesh_resolution", MeshResolutionJson(counts)},
                     {"mesh_uris", mesh_uris}});
  }
  const ReportSummary s = Summarize(results);
  const json document = {
      {"version", options.tool_version},
      {"files", files},
      {"summary",
       {{"files", s.files},
        {"errors", s.errors},
        {"warnings", s.warnings},
        {"notes", s.notes},
        {"read_errors", s.read_errors},
        {"skipped_files", options.skipped_files},
        {"mesh_links", s.mesh_links},
        {"mesh_links_unresolved", s.mesh_links_unresolved},
        {"first_unresolved_mesh",
         s.first_unresolved_mesh.empty() ? json(nullptr) : json(s.first_unresolved_mesh)},
        {"mesh_resolution", MeshResolutionJson(s.mesh_resolution)}}}};
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

namespace {

// The SARIF rules (every rule of `massprops check`, then the read error and warning) and their
// ids in the same order (a result's ruleIndex).
json SarifRules(const ReportOptions& options, std::vector<std::string>* rule_ids) {
  json rules = json::array();
  auto add_rule = [&](const std::string& id, const std::string& summary, Severity level) {
    json rule = {{"id", id}, {"shortDescription", {{"text", summary}}}};
    if (const std::optional<std::string> long_form = RuleLongForm(id)) {
      rule["fullDescription"] = {{"text", FirstParagraph(*long_form)}};
      rule["help"] = {{"text", *long_form}, {"markdown", *long_form}};
    }
    rule["defaultConfiguration"] = {{"level", SarifLevel(level)}};
    if (!options.information_uri.empty()) rule["helpUri"] = options.information_uri + "#" + id;
    rules.push_back(rule);
    rule_ids->push_back(id);
  };
  for (const RuleInfo& info : AllRules()) {
    add_rule(std::string(info.id), std::string(info.summary), info.default_severity);
  }
  add_rule(kReadErrorRule, "The file could not be read or parsed as URDF or SDF.",
           Severity::kError);
  add_rule(kReadWarningRule, "Part of the file could not be understood and was skipped.",
           Severity::kWarning);
  return rules;
}

int SarifRuleIndex(const std::vector<std::string>& rule_ids, const std::string& id) {
  for (std::size_t i = 0; i < rule_ids.size(); ++i) {
    if (rule_ids[i] == id) return static_cast<int>(i);
  }
  return -1;
}

// A SARIF `locations` array of one physical location (the region only with a line).
json SarifLocation(const std::string& file, int line, int column) {
  json physical = {{"artifactLocation", {{"uri", ArtifactUri(file)}}}};
  if (line > 0) {
    json region = {{"startLine", line}};
    if (column > 0) region["startColumn"] = column;
    physical["region"] = region;
  }
  return json::array({{{"physicalLocation", physical}}});
}

// The SARIF result of one finding: at its source place when it was traced to one (the generated
// line and the other candidate places as related locations), else at its own.
json SarifFinding(const Finding& finding, const FileResult& result,
                  const std::vector<std::string>& rule_ids) {
  json entry = {{"ruleId", finding.rule}};
  const int index = SarifRuleIndex(rule_ids, finding.rule);
  if (index >= 0) entry["ruleIndex"] = index;
  entry["level"] = SarifLevel(finding.severity);
  entry["message"] = {{"text", HeadlineOf(finding)}};
  if (finding.source && !finding.source->places.empty()) {
    // The source file is the artifact; the generated line and any other candidate place are
    // related locations.
    const FindingSource& source = *finding.source;
    entry["locations"] = SarifLocation(source.places.front().file, source.places.front().line, 0);
    json related = json::array();
    json generated = SarifLocation(FileOf(finding.location, result), finding.location.line,
                                   finding.location.column)[0];
    generated["id"] = 1;
    generated["message"] = {{"text", "generated " + source.number}};
    related.push_back(generated);
    for (std::size_t i = 1; i < source.places.size(); ++i) {
      json other = SarifLocation(source.places[i].file, source.places[i].line, 0)[0];
      other["id"] = static_cast<int>(i) + 1;
      other["message"] = {{"text", "also writes " + source.number}};
      related.push_back(other);
    }
    entry["relatedLocations"] = related;
  } else {
    entry["locations"] = SarifLocation(FileOf(finding.location, result), finding.location.line,
                                       finding.location.column);
  }
  json values = json::object();
  for (const auto& [name, value] : finding.values) values[name] = Number(value);
  entry["properties"] = {{"model", finding.model},
                         {"link", finding.link},
                         {"evidence", EvidenceJson(finding)},
                         {"help", ShortenLongWords(finding.help)},
                         {"message", ShortenLongWords(finding.message)},
                         {"values", values}};
  if (!finding.group.empty()) entry["properties"]["group"] = finding.group;
  if (finding.source && !finding.source->places.empty()) {
    entry["properties"]["source"] = {{"number", finding.source->number},
                                     {"how", finding.source->places.front().how},
                                     {"places", finding.source->places.size()}};
  }
  return entry;
}

}  // namespace

std::string RenderSarif(const std::vector<FileResult>& results, const ReportOptions& options) {
  std::vector<std::string> rule_ids;
  const json rules = SarifRules(options, &rule_ids);
  json sarif_results = json::array();
  for (const FileResult& result : results) {
    for (const ReadError& error : result.errors) {
      sarif_results.push_back(
          {{"ruleId", kReadErrorRule},
           {"ruleIndex", SarifRuleIndex(rule_ids, kReadErrorRule)},
           {"level", "error"},
           {"message", {{"text", ReadErrorHeadline(error)}}},
           {"locations", SarifLocation(FileOf(error.location, result), error.location.line,
                                       error.location.column)},
           {"properties", {{"message", ShortenLongWords(ReadErrorText(error))}}}});
    }
    for (const Finding& finding : result.findings) {
      sarif_results.push_back(SarifFinding(finding, result, rule_ids));
    }
  }

  json driver = {{"name", "massprops"}, {"version", options.tool_version}};
  if (!options.information_uri.empty()) driver["informationUri"] = options.information_uri;
  driver["rules"] = rules;
  json run = {{"tool", {{"driver", driver}}}, {"results", sarif_results}};
  const ReportSummary s = Summarize(results);
  if (s.mesh_links > 0) {
    run["properties"] = {
        {"mesh_links", s.mesh_links},
        {"mesh_links_unresolved", s.mesh_links_unresolved},
        {"first_unresolved_mesh",
         s.first_unresolved_mesh.empty() ? json(nullptr) : json(s.first_unresolved_mesh)},
        {"mesh_resolution", MeshResolutionJson(s.mesh_resolution)}};
  }
  const json log = {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
                    {"version", "2.1.0"},
                    {"runs", json::array({run})}};
  return log.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string RenderGithub(const std::vector<FileResult>& results, const ReportOptions& options) {
  (void)options;
  std::string out;
  for (const FileResult& result : results) {
    for (const ReadError& error : result.errors) {
      const std::string headline = ReadErrorHeadline(error);
      const std::string text = ReadErrorText(error);
      out += GithubLine("error", FileOf(error.location, result), error.location.line,
                        error.location.column, kReadErrorRule,
                        headline == text ? headline : headline + "\n" + ShortenLongWords(text));
    }
    for (const Finding& finding : result.findings) {
      if (finding.source && !finding.source->places.empty()) {
        const SourcePlace& place = finding.source->places.front();
        out += GithubLine(GithubCommand(finding.severity), place.file, place.line, 0, finding.rule,
                          ShortenLongWords(HeadlineOf(finding) + SourceNote(*finding.source) +
                                           HelpText(finding)));
        continue;
      }
      out += GithubLine(GithubCommand(finding.severity), FileOf(finding.location, result),
                        finding.location.line, finding.location.column, finding.rule,
                        ShortenLongWords(HeadlineOf(finding) + HelpText(finding)));
    }
  }
  return out;
}

std::string Render(ReportFormat format, const std::vector<FileResult>& results,
                   const ReportOptions& options) {
  switch (format) {
    case ReportFormat::kText:
      return RenderText(results, options);
    case ReportFormat::kJson:
      return RenderJson(results, options);
    case ReportFormat::kSarif:
      return RenderSarif(results, options);
    case ReportFormat::kGithub:
      return RenderGithub(results, options);
    case ReportFormat::kJunit:
      return RenderJunit(results, options);
    case ReportFormat::kGitlab:
      return RenderGitlab(results, options);
  }
  return {};
}

void WriteReport(std::ostream& out, ReportFormat format, const std::vector<FileResult>& results,
                 const ReportOptions& options) {
  out << Render(format, results, options);
}

std::string ReadErrorText(const ReadError& error) {
  if (error.element.empty()) return error.message;
  return error.element + ": " + error.message;
}

std::string FindingHeadlineLine(const Finding& finding) {
  return FormatLocation(finding.location.file, finding.location.line, finding.location.column) +
         ": " + ToString(finding.severity) + ": " + HeadlineOf(finding) + " [" + finding.rule + "]";
}

Finding ReadWarningFinding(const ReadError& warning) {
  Finding finding;
  finding.rule = kReadWarningRule;
  finding.severity = Severity::kWarning;
  finding.location = warning.location;
  finding.message = ReadErrorText(warning);
  // The readers' messages say what is wrong, then "; " and what follows from it.
  finding.headline = HeadlineFromMessage(finding.message.substr(0, finding.message.find("; ")),
                                         "an element was skipped (--explain says why)",
                                         "skipped (--explain says why)");
  finding.help = "the element was skipped: fix it so that the file reads whole";
  return finding;
}

std::string ReadErrorHeadline(const ReadError& error) {
  return HeadlineFromMessage(ReadErrorText(error),
                             "the file cannot be read: its message is too long for a headline");
}

std::string ShortenLongWords(std::string_view text, std::size_t max_word) {
  auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  // A position moved back (or forward) off UTF-8 continuation bytes (10xxxxxx).
  auto boundary = [&](std::size_t pos, bool forward) {
    while (pos > 0 && pos < text.size() && (static_cast<unsigned char>(text[pos]) & 0xC0) == 0x80) {
      pos += forward ? 1 : -1;
    }
    return pos;
  };
  const std::size_t keep_head = max_word / 2, keep_tail = max_word / 4;
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = i;
    while (end < text.size() && !is_space(text[end])) ++end;
    if (end - i > max_word) {
      const std::size_t head = boundary(i + keep_head, false);
      const std::size_t tail = boundary(end - keep_tail, true);
      out.append(text.substr(i, head - i));
      out += "\u2026[" + std::to_string(end - i) + " bytes]\u2026";
      out.append(text.substr(tail, end - tail));
    } else {
      out.append(text.substr(i, end - i));
    }
    i = end;
    while (i < text.size() && is_space(text[i])) out += text[i++];
  }
  return out;
}

std::string EscapeGithubData(std::string_view text) { return Escape(text, false); }

std::string EscapeGithubProperty(std::string_view text) { return Escape(text, true); }

}  // namespace massprops
