#pragma once
/// @file
/// The JSON document of `massprops diff --format json` (docs/cli.md, "diff"), shared by the tool
/// and Python's massprops.diff.

#include <string>

#include "massprops/analysis/model_diff.h"
#include "massprops/model/model.h"

namespace massprops {

/// {"a": {"file", "format", "model"}, "b": {...}, "tolerance", "differs", "entries": [{"kind",
/// "name", "a", "b" (each {"mass", "com", "inertia", "file", "line"} or null when absent),
/// "differs", and "mass_difference", "com_difference", "inertia_difference" when both have the
/// body, else "missing"}]}, indented by two spaces, ending in a newline. `diff` must be
/// DiffModels(a, b, tolerance). Never throws (invalid UTF-8 in a name becomes U+FFFD).
std::string RenderDiffJson(const ModelDiff& diff, const Model& a, const Model& b);

}  // namespace massprops
