// The diagnostics of a checked document (lsp_server.h): each finding of `check` and each read
// error, at its element's line, in the words of finding_text.h.
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "lsp_protocol.h"
#include "lsp_server.h"
#include "massprops/analysis/finding_text.h"

namespace massprops::cli::lsp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// LSP DiagnosticSeverity: Error 1, Warning 2, Information 3, Hint 4.
int LspSeverity(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return 1;
    case Severity::kWarning:
      return 2;
    case Severity::kNote:
      return 3;
  }
  return 3;
}

// The folder of the executable ("" when unknown).
fs::path ExecutableFolder() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

// The docs folder's URL: options.docs_url, else the file:// URL of docs/ in the source tree the
// tool was built from, else of the installed share/massprops/docs; "" when none is found.
std::string DocsUrl(const ServerOptions& options) {
  if (!options.docs_url.empty()) {
    std::string url = options.docs_url;
    if (url.back() != '/') url += '/';
    return url;
  }
  static const std::string found = [] {
    std::vector<fs::path> candidates;
#ifdef MASSPROPS_EXAMPLES_DIR
    candidates.push_back(fs::path(MASSPROPS_EXAMPLES_DIR) / ".." / "docs");
#endif
    const fs::path dir = ExecutableFolder();
    if (!dir.empty()) candidates.push_back(dir / ".." / "share" / "massprops" / "docs");
    for (const fs::path& candidate : candidates) {
      std::error_code ec;
      if (fs::is_regular_file(candidate / "rules.md", ec)) {
        return UriFromPath(fs::weakly_canonical(candidate, ec).string()) + "/";
      }
    }
    return std::string();
  }();
  return found;
}

// The anchor of a rule's heading in docs/rules.md ("### `units-suspect` (warning)" is
// "#units-suspect-warning", as GitHub and most Markdown viewers make it); "" for an id that is
// not a rule of AllRules().
std::string RuleAnchor(const std::string& rule) {
  for (const RuleInfo& info : AllRules()) {
    if (info.id == rule) return rule + "-" + ToString(info.default_severity);
  }
  return {};
}

// headline, then "evidence: ..." and "help: ..." lines when the finding has them.
std::string FindingMessage(const Finding& finding) {
  std::string message = HeadlineOf(finding);
  // The lines of check's text output, each whole: a long evidence on several lines.
  for (const std::string& line : FormatEvidenceLines(finding.evidence)) {
    message += "\nevidence: " + line;
  }
  if (!finding.help.empty()) message += "\nhelp: " + finding.help;
  return message;
}

json Location(const std::string& file, int line, const std::string& text_if_open) {
  json range = text_if_open.empty()
                   ? json{{"start", {{"line", std::max(0, line - 1)}, {"character", 0}}},
                          {"end", {{"line", std::max(0, line - 1)}, {"character", 0}}}}
                   : LineRange(text_if_open, line);
  std::error_code ec;
  return {{"uri", UriFromPath(fs::absolute(file, ec).string())}, {"range", range}};
}

// The members of the welded group a group-rule finding is about, as relatedInformation (the
// <link> of each); empty when the finding is about one link.
json GroupMembers(const Finding& finding, const Analysis& analysis, const Document& document) {
  json related = json::array();
  // The finding names its welded group's members (Finding::group, set by the checks); the server
  // only finds each member's <link> line.
  if (finding.group.empty() || analysis.xacro) return related;
  for (const Model& model : analysis.read.models) {
    if (model.name != finding.model) continue;
    for (const std::string& name : finding.group) {
      const auto link = std::find_if(model.links.begin(), model.links.end(),
                                     [&](const Link& l) { return l.name == name; });
      if (link == model.links.end()) continue;
      const bool here = link->location.file.empty() || link->location.file == document.path;
      json location = here ? json{{"uri", document.uri},
                                  {"range", LineRange(document.text, link->location.line)}}
                           : Location(link->location.file, link->location.line, "");
      related.push_back({{"location", location},
                         {"message", ShortenLongWords("welded group member '" + name + "'")}});
    }
    return related;
  }
  return related;
}

json Diagnostic(const Document& document, int line, int severity, const std::string& code,
                const std::string& message) {
  // Names are shortened as in every report (a 10 MB link name is not sent whole).
  return {{"range", LineRange(document.text, line)},
          {"severity", severity},
          {"source", "massprops"},
          {"code", code},
          {"message", ShortenLongWords(message)}};
}

// The diagnostic of one finding: at its line in the document, or (a number written in another
// file: an SDF include, a xacro macro file, a YAML file) at the document's first line with that
// place as relatedInformation.
json FindingDiagnostic(const Finding& finding, const Document& document, const Analysis& analysis,
                       const std::string& docs_url) {
  std::string file = finding.location.file;
  int line = finding.location.line;
  if (analysis.xacro) {  // the generated text is in no file: the source place is the location
    file.clear();
    line = 0;
    if (finding.source && !finding.source->places.empty()) {
      file = finding.source->places.front().file;
      line = finding.source->places.front().line;
    }
  }
  std::error_code ec;
  const bool here = file.empty() || file == document.path || file == analysis.result.path ||
                    (!document.path.empty() && fs::equivalent(file, document.path, ec));
  json diagnostic = Diagnostic(document, here ? line : 0, LspSeverity(finding.severity),
                               finding.rule, FindingMessage(finding));
  const std::string anchor = RuleAnchor(finding.rule);
  if (!anchor.empty() && !docs_url.empty()) {
    diagnostic["codeDescription"] = {{"href", docs_url + "rules.md#" + anchor}};
  }
  json related = GroupMembers(finding, analysis, document);
  if (!here && !file.empty()) {
    related.push_back(
        {{"location", Location(file, line, "")}, {"message", "the numbers were written here"}});
  }
  if (!related.empty()) diagnostic["relatedInformation"] = related;
  return diagnostic;
}

// Information at each <collision>/<visual> whose mesh did not resolve or could not be read (what
// `check` says once in its closing summary): the geometry rules know nothing of its link's size.
void AddUnresolvedMeshes(const Document& document, const Analysis& analysis, json* out) {
  std::set<std::string> unresolved;
  for (const MeshUriResolution& mesh : analysis.result.mesh_uris) {
    if (mesh.path.empty()) unresolved.insert(mesh.uri);
  }
  if (!analysis.result.first_unresolved_mesh.empty()) {
    unresolved.insert(analysis.result.first_unresolved_mesh);  // found, but not readable
  }
  if (unresolved.empty() || analysis.xacro) return;
  for (const Model& model : analysis.read.models) {
    for (const Link& link : model.links) {
      for (const Geometry& geometry : link.geometries) {
        if (geometry.type != Geometry::Type::kMesh || unresolved.count(geometry.uri) == 0) continue;
        const bool here =
            geometry.location.file.empty() || geometry.location.file == analysis.result.path;
        out->push_back(Diagnostic(
            document, here ? geometry.location.line : 0, 3, "mesh-unresolved",
            "link '" + link.name + "': mesh '" + geometry.uri +
                "' did not resolve or could not be read: its size is unknown to the geometry "
                "rules\nhelp: give the folder of its package (packagePaths, or massprops lsp "
                "--package-path DIR)"));
      }
    }
  }
}

}  // namespace

json LineRange(const std::string& text, int line) {
  std::size_t start = 0;
  int index = std::max(0, line - 1);
  for (int i = 0; i < index; ++i) {
    const std::size_t newline = text.find('\n', start);
    if (newline == std::string::npos) {  // beyond the text: the first line
      start = 0;
      index = 0;
      break;
    }
    start = newline + 1;
  }
  std::size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  if (end > start && text[end - 1] == '\r') --end;
  const std::string_view content = std::string_view(text).substr(start, end - start);
  std::size_t first = content.find_first_not_of(" \t");
  if (first == std::string_view::npos) first = 0;
  const std::size_t from = Utf16Length(content.substr(0, first));
  const std::size_t to = Utf16Length(content);
  return {{"start", {{"line", index}, {"character", from}}},
          {"end", {{"line", index}, {"character", to}}}};
}

json Diagnostics(const Document& document, const ServerOptions& options) {
  json out = json::array();
  if (!document.analysis) return out;
  const Analysis& analysis = *document.analysis;
  if (analysis.not_a_model) return out;
  if (!analysis.setup_error.empty()) {
    // A bad configuration stops `check` (an error); a xacro document the server cannot expand
    // is only unchecked (a warning).
    out.push_back(Diagnostic(document, 0, analysis.xacro ? 2 : 1,
                             analysis.xacro ? "xacro-unchecked" : "config-error",
                             analysis.setup_error));
    return out;
  }
  const std::string docs_url = DocsUrl(options);
  for (const ReadError& error : analysis.result.errors) {
    const bool here = !analysis.xacro &&
                      (error.location.file.empty() || error.location.file == analysis.result.path);
    const std::string message = !here                   ? error.ToString()
                                : error.element.empty() ? error.message
                                                        : error.element + ": " + error.message;
    out.push_back(Diagnostic(document, here ? error.location.line : 0, 1, kReadErrorRule, message));
  }
  for (const Finding& finding : analysis.result.findings) {
    out.push_back(FindingDiagnostic(finding, document, analysis, docs_url));
  }
  AddUnresolvedMeshes(document, analysis, &out);
  return out;
}

}  // namespace massprops::cli::lsp
