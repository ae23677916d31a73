#pragma once
/// @file
/// What `massprops fix` says, in `check`'s form (finding_text.h): a headline of at most
/// kMaxHeadlineChars characters that says what happened to which link, evidence lines and help
/// lines of at most kMaxDetailChars characters each, whole (words and numbers never cut, no
/// "…"). A refused repair gets its reason and the ways forward (repair_routes.h); `--dry-run`
/// gets, per link, what each available repair would write (old → new mass, COM, principal
/// moments).

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/repair_routes.h"

namespace massprops {

/// One message of `fix`: `LOCATION: SEVERITY: HEADLINE [RULE]`, then `  = evidence: ...` and
/// `  = help: ...` lines (help lines may have indented continuation lines `    ...`).
struct FixMessage {
  std::string location;  ///< "robot.urdf:12"
  std::string severity;  ///< "error", "warning" or "note"
  std::string headline;  ///< at most kMaxHeadlineChars characters
  std::string rule;
  std::vector<std::string> evidence;  ///< each at most kMaxDetailChars − 14 characters
  std::vector<std::string> help;      ///< whole lines as printed ("  = help: ...", "    ...")
};

/// The message's lines, each ending in '\n'.
std::string RenderFixMessage(const FixMessage& message);

/// "radius of gyration 89 m, half diagonal 15.4 cm": the named numbers (finding_text.h's labels
/// and units) in order, as many as fit whole in `max_chars`; the others are left out, without
/// "…". Empty when none fits.
std::string FormatWholeEvidence(const std::vector<std::pair<std::string, double>>& values,
                                std::size_t max_chars);

/// The principal moments (ascending) of an inertial's six numbers; zeros when they are not
/// finite.
Eigen::Vector3d PrincipalMomentsOf(const Inertial& inertial);

/// "0.00833, 0.0167, 0.0217": three numbers at 3 significant digits.
std::string FormatTriple(const Eigen::Vector3d& v);

/// `text` broken at spaces into lines of at most `width` characters (a word longer than
/// `width` stands alone on its line, whole).
std::vector<std::string> WrapWords(std::string_view text, std::size_t width);

/// The message for a refused repair: `link 'NAME': not repaired: REASON` (or about "this link"
/// when the name makes it too long), the refusal's evidence, and one help entry per route,
/// each naming the `massprops` command (FILE as `file`, or "FILE" where the line would be too
/// long) with the values it would write and whether physics backs it or it is a guess.
FixMessage RefusedRepairMessage(const RefusedRepair& refused, Severity severity,
                                const std::string& file, const std::vector<RepairRoute>& routes);

/// The help lines of `routes` for `link` of `file` (as RefusedRepairMessage writes them).
std::vector<std::string> RouteHelpLines(const std::vector<RepairRoute>& routes,
                                        const std::string& link, const std::string& file);

/// --dry-run: "  = choices for link 'NAME' (old → new):" and, per route, its command and
/// physics or guess, then the mass, COM and principal moments it writes, each line at most
/// kMaxDetailChars characters. Empty when no route has repairs.
std::string RenderRouteChoices(const std::vector<RepairRoute>& routes, const std::string& link,
                               const std::string& file);

}  // namespace massprops
