#pragma once
// Where the machine formats of `check` (JUnit, GitLab Code Quality) point a finding or a read
// error, as RenderSarif and RenderGithub do: a finding traced to xacro sources at its first source
// place, else at its own location; the file is the location's own when it has one, else the
// checked file's path.

#include <string>

#include "massprops/output/reporters.h"

namespace massprops::internal {

/// A file and a 1-based line (0: unknown).
struct ReportPlace {
  std::string file;
  int line = 0;
};

/// The file a location points into: its own file when it has one (not the stdin marker "-"),
/// else the checked file's path.
inline const std::string& ReportedFile(const SourceLocation& location, const FileResult& result) {
  if (location.file.empty() || location.file == "-") return result.path;
  return location.file;
}

/// Where the finding is shown: its first xacro source place when it was traced to one, else its
/// own location.
inline ReportPlace PlaceOf(const Finding& finding, const FileResult& result) {
  if (finding.source && !finding.source->places.empty()) {
    return {finding.source->places.front().file, finding.source->places.front().line};
  }
  return {ReportedFile(finding.location, result), finding.location.line};
}

}  // namespace massprops::internal
