// textDocument/codeAction (lsp_server.h): for each finding under the range, the repair `massprops
// fix` would make for its link, as the smallest TextEdit that turns the buffer into what `fix`
// writes. Repairs that physics decides (fix's default) are preferred quick fixes; heuristic ones
// (`fix --apply RULE`) are offered as rewrites named for their rule, never preferred.
#include <algorithm>
#include <string>
#include <vector>

#include "geometry_cli.h"
#include "lsp_protocol.h"
#include "lsp_server.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/reporters.h"
#include "massprops/output/xml_patch.h"

namespace massprops::cli::lsp {
namespace {

using nlohmann::json;

constexpr const char* kQuickFix = "quickfix";
constexpr const char* kRewrite = "refactor.rewrite";

// A repair and whether it is a guess that must be named (`fix --apply RULE`).
struct PlannedRepair {
  Repair repair;
  bool heuristic = false;
};

// The repairs `fix` plans for `model` (its default ones, with the target's on top as `fix
// --target` adds them), then for each heuristic rule those `fix --apply RULE` would add.
std::vector<PlannedRepair> PlanAll(const Model& model, const Analysis& analysis,
                                   const CheckOptions& check, const RepairOptions& base) {
  std::vector<PlannedRepair> out;
  const std::vector<Finding> findings = CheckModel(model, check);
  std::vector<Repair> physics = PlanRepairs(model, findings, base);
  if (analysis.settings.target != Target::kGeneric) {
    physics = PlanTargetRepairs(model, analysis.settings.target,
                                ReadMujocoCompilerOptions(analysis.text), physics);
  }
  for (Repair& repair : physics) out.push_back({std::move(repair), false});
  for (const std::string& rule : HeuristicRepairRules()) {
    RepairOptions named = base;
    named.apply = {rule};
    for (Repair& repair : PlanRepairs(model, findings, named)) {
      if (repair.rule != rule) continue;
      out.push_back({std::move(repair), true});
    }
  }
  return out;
}

// The LSP position of byte `offset` of `text`.
json PositionOf(const std::string& text, std::size_t offset) {
  const std::size_t line_start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  const std::size_t start = offset == 0 || line_start == std::string::npos ? 0 : line_start + 1;
  const auto line =
      std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(start), '\n');
  return {{"line", line},
          {"character", Utf16Length(std::string_view(text).substr(start, offset - start))}};
}

// The one TextEdit that turns `before` into `after`: the span between their common prefix and
// common suffix (whole UTF-8 characters). Null when they are equal.
json MinimalEdit(const std::string& before, const std::string& after) {
  if (before == after) return nullptr;
  std::size_t prefix = 0;
  const std::size_t shorter = std::min(before.size(), after.size());
  while (prefix < shorter && before[prefix] == after[prefix]) ++prefix;
  while (prefix > 0 && (static_cast<unsigned char>(before[prefix]) & 0xC0) == 0x80) --prefix;
  std::size_t suffix = 0;
  while (suffix < shorter - prefix &&
         before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix]) {
    ++suffix;
  }
  while (suffix > 0 &&
         (static_cast<unsigned char>(before[before.size() - suffix]) & 0xC0) == 0x80) {
    --suffix;
  }
  return {{"range",
           {{"start", PositionOf(before, prefix)},
            {"end", PositionOf(before, before.size() - suffix)}}},
          {"newText", after.substr(prefix, after.size() - suffix - prefix)}};
}

bool KindWanted(const json& only, const std::string& kind) {
  if (!only.is_array() || only.empty()) return true;
  return std::any_of(only.begin(), only.end(), [&](const json& wanted) {
    if (!wanted.is_string()) return false;
    const std::string& prefix = wanted.get_ref<const std::string&>();
    return kind == prefix || kind.rfind(prefix + ".", 0) == 0;
  });
}

// Whether `repair` answers `finding` (same link; the finding's rule is the one it repairs, or
// one it resolves).
bool Answers(const Repair& repair, const Finding& finding) {
  if (repair.link != finding.link) return false;
  if (repair.rule == finding.rule) return true;
  return std::find(repair.resolves.begin(), repair.resolves.end(), finding.rule) !=
         repair.resolves.end();
}

}  // namespace

json CodeActions(const Document& document, const ServerOptions& options, int first_line,
                 int last_line, const json& only) {
  json actions = json::array();
  if (!document.analysis || document.analysis->xacro) return actions;
  const Analysis& analysis = *document.analysis;
  const json diagnostics = Diagnostics(document, options);
  // The findings under the range, with their diagnostics (same order as the findings: read
  // errors come first in `diagnostics`).
  const std::size_t skipped = analysis.result.errors.size();
  std::vector<std::size_t> wanted;
  for (std::size_t i = 0; i < analysis.result.findings.size(); ++i) {
    const int line = diagnostics[skipped + i]["range"]["start"]["line"].get<int>();
    if (line >= first_line && line <= last_line) wanted.push_back(i);
  }
  if (wanted.empty()) return actions;
  MeshCache cache;  // the meshes, read once for this answer
  const MeshResolveOptions resolve = MakeResolveOptions(
      analysis.settings.package_paths, analysis.settings.model_paths, document.path, &cache);
  CheckOptions check = analysis.settings.options;
  RepairOptions base;
  base.tolerance = check.tolerance;
  base.box = check.box = MakeLinkBoxFunction(resolve);
  base.points = check.points = MakeLinkPointsFunction(resolve);
  for (const Model& model : analysis.read.models) {
    for (const PlannedRepair& planned : PlanAll(model, analysis, check, base)) {
      json answered = json::array();
      for (std::size_t i : wanted) {
        const Finding& finding = analysis.result.findings[i];
        if (finding.model == model.name && Answers(planned.repair, finding)) {
          answered.push_back(diagnostics[skipped + i]);
        }
      }
      const std::string kind = planned.heuristic ? kRewrite : kQuickFix;
      if (answered.empty() || !KindWanted(only, kind)) continue;
      const PatchResult patched = PatchModelText(analysis.text, model.format, {planned.repair});
      if (patched.applied == 0 || !patched.errors.empty()) continue;
      const json edit = MinimalEdit(analysis.text, patched.text);
      if (edit.is_null()) continue;
      const Repair& repair = planned.repair;
      const std::string title = planned.heuristic
                                    ? "massprops fix --apply " + repair.rule + ": link '" +
                                          repair.link + "' (" + repair.method + ", a guess)"
                                    : "massprops fix: link '" + repair.link + "' " + repair.rule +
                                          " (" + repair.method + ")";
      actions.push_back({{"title", ShortenLongWords(title)},
                         {"kind", kind},
                         {"diagnostics", answered},
                         {"isPreferred", !planned.heuristic},
                         {"edit", {{"changes", {{document.uri, json::array({edit})}}}}}});
    }
  }
  return actions;
}

}  // namespace massprops::cli::lsp
