#pragma once
/// @file
/// Applies Repairs to the ORIGINAL text of a URDF or SDF file: only the numbers that change are
/// rewritten (the characters of an attribute value or of an element's text; quotes, spacing,
/// comments, attribute order and every other byte are kept), and an <inertial> block (or an
/// inertial <origin>/<pose>) is inserted where a repair needs one, indented like its neighbours.
/// Also: a line-based unified diff. (Numbers are written with FormatShortest,
/// core/format_number.h.)

#include <string>
#include <string_view>
#include <vector>

#include "massprops/analysis/repair.h"
#include "massprops/core/format_number.h"
#include "massprops/model/model.h"

namespace massprops {

/// A repair that could not be written, and why (the element was not found where the model says).
struct PatchError {
  std::string link;
  int line = 0;
  std::string message;
};

struct PatchResult {
  std::string text;                ///< The patched text (the original where nothing applied).
  std::vector<PatchError> errors;  ///< Repairs skipped as a whole (none of their edits applied).
  int applied = 0;                 ///< Number of repairs written.
};

/// How PatchModelText finds links.
struct PatchOptions {
  /// The text is an SDF model included (<include>) by the file the repairs were planned on: a
  /// repair of link "cargo::body" (the include named "cargo") matches the element whose scoped
  /// name in this file is "body" (or "cargo::body"), at the repair's line.
  bool included = false;
};

/// Writes the repairs into `original` (the text the model was read from). Each link is found by
/// structure, never inside a comment: URDF robot/link, SDF sdf/[world/]model/[model/...]/link
/// with nested model names as its scope ("inner::link"), by its name and at the repair's
/// link_line (a link of the same name on the same line elsewhere in the tree, or in a comment, is
/// not it); its first <inertial> child, and in it <mass>, <inertia>, <origin> (URDF) or
/// <pose> (SDF), are found by structure, so several elements on one line are fine. URDF numbers are
/// attribute values; SDF numbers are element texts (<mass>2</mass>, <inertia><ixx>…</ixx>).
/// A repair that cannot be written exactly (element missing, a value with fewer numbers than
/// expected, an SDF <pose relative_to> that is not the link) is skipped and reported; the others
/// are applied. Never throws. Cost: linear in the text size plus the size of the patched links.
PatchResult PatchModelText(std::string_view original, Model::Format format,
                           const std::vector<Repair>& repairs, const PatchOptions& options = {});

/// A unified diff of two texts by lines (Myers' O(ND) algorithm, "An O(ND) Difference Algorithm
/// and Its Variations", Algorithmica 1986), with `context` lines of context and the headers
/// "--- a/NAME" / "+++ b/NAME". Empty when the texts are equal. A last line without a newline is
/// marked "\ No newline at end of file". Cost: O((N+M)·D) time, O(D²) memory for D changed lines.
std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name,
                        int context = 3);

/// The line numbers (1-based) of `before` that the diff removes or changes, and of `after` that it
/// adds, in order. Used to confirm that a fix touched only inertial lines.
struct LineChanges {
  std::vector<int> removed;  ///< Lines of `before`.
  std::vector<int> added;    ///< Lines of `after`.
};
LineChanges DiffLines(std::string_view before, std::string_view after);

}  // namespace massprops
