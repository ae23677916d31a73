// `massprops check --format gitlab` (reporters.h, RenderGitlab; docs/cli.md): GitLab's Code
// Quality report, whose fingerprints let a merge request tell new findings from fixed ones.

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "massprops/analysis/finding_text.h"
#include "massprops/output/reporters.h"
#include "output/report_place.h"
#include "output/sha256.h"

namespace massprops {
namespace {

using json = nlohmann::ordered_json;
using internal::PlaceOf;
using internal::ReportedFile;
using internal::ReportPlace;

// GitLab's severities are info, minor, major, critical and blocker.
const char* GitlabSeverity(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "major";
    case Severity::kWarning:
      return "minor";
    case Severity::kNote:
      return "info";
  }
  return "info";
}

// A path as GitLab matches it against the repository's files: without leading "./".
std::string GitlabPath(std::string path) {
  while (path.size() > 2 && path.compare(0, 2, "./") == 0) path.erase(0, 2);
  return path;
}

// Fingerprints: the SHA-256 of the identity's parts and its occurrence index among the run's
// items of the same identity, each followed by a NUL byte.
class Fingerprints {
 public:
  std::string Next(const std::string& rule, const std::string& file, const std::string& model,
                   const std::string& subject) {
    const int occurrence = seen_[{rule, file, model, subject}]++;
    std::string data;
    for (const std::string* part : {&rule, &file, &model, &subject}) {
      data += *part;
      data += '\0';
    }
    data += std::to_string(occurrence);
    data += '\0';
    return internal::Sha256Hex(data);
  }

 private:
  std::map<std::tuple<std::string, std::string, std::string, std::string>, int> seen_;
};

json Item(const std::string& description, const std::string& rule, const std::string& fingerprint,
          const char* severity, const ReportPlace& place) {
  return {{"description", ShortenLongWords(description)},
          {"check_name", rule},
          {"fingerprint", fingerprint},
          {"severity", severity},
          {"location",
           {{"path", GitlabPath(place.file)}, {"lines", {{"begin", std::max(place.line, 1)}}}}}};
}

}  // namespace

std::string RenderGitlab(const std::vector<FileResult>& results, const ReportOptions& options) {
  (void)options;
  Fingerprints fingerprints;
  json items = json::array();
  for (const FileResult& result : results) {
    for (const ReadError& error : result.errors) {
      const ReportPlace place{ReportedFile(error.location, result), error.location.line};
      const std::string path = GitlabPath(place.file);
      // The headline, whole and within kMaxHeadlineChars, as in every format (the full text is
      // in the other formats' `why`).
      items.push_back(Item(ReadErrorHeadline(error), kReadErrorRule,
                           fingerprints.Next(kReadErrorRule, path, "", error.element), "critical",
                           place));
    }
    for (const Finding& finding : result.findings) {
      const ReportPlace place = PlaceOf(finding, result);
      const std::string path = GitlabPath(place.file);
      items.push_back(Item(HeadlineOf(finding), finding.rule,
                           fingerprints.Next(finding.rule, path, finding.model, finding.link),
                           GitlabSeverity(finding.severity), place));
    }
  }
  return items.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace massprops
