#pragma once
// `massprops fix` on a xacro package (docs/xacro.md, "Fix"): the repairs planned on the expansion
// are written into the sources where the trace says each number was written. Defined in
// xacro_fix.cc.
#include <string>
#include <vector>

#include "massprops/analysis/repair.h"
#include "xacro_cli.h"

namespace massprops::cli {

struct XacroFixRequest {
  bool in_place = false;
  bool dry_run = false;
  bool diff = false;
  std::string backup;  ///< --backup SUFFIX
};

/// Writes `repairs` (planned on run.expansion's text; `patched_expansion` is that text with them
/// applied) into the source files: a literal or YAML value used only by numbers that the repairs
/// change to the same value is replaced (atomically, only its bytes); anything else (a value shared
/// with a link that needs no repair, a computed or parameter value, a number not traced to one
/// place) is printed with the reason and the line to change by hand. After writing, the
/// expansion is made again and checked. Returns the exit code: 0 every repair written and
/// verified, 1 some repair left to do by hand, 2 a write or verification failure.
int FixXacroSources(const XacroOptions& options, const std::string& top, const XacroRun& run,
                    const std::vector<Repair>& repairs, const std::string& patched_expansion,
                    const XacroFixRequest& request);

}  // namespace massprops::cli
