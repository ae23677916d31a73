// textDocument/hover (lsp_server.h): the mass properties of the link under the cursor, and of its
// welded group, in Markdown.
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "lsp_protocol.h"
#include "lsp_server.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/format_number.h"
#include "massprops/core/principal_axes.h"
#include "massprops/output/reporters.h"

namespace massprops::cli::lsp {
namespace {

using nlohmann::json;

// The link of `model` whose <link>/<body> or <inertial> (or a child of it) starts on `line`
// (1-based); when several do, the last one that starts at or before `column` (1-based bytes;
// 0 when unknown). Null when none.
const Link* LinkAt(const Model& model, int line, int column) {
  const Link* best = nullptr;
  int best_column = -1;
  for (const Link& link : model.links) {
    std::vector<SourceLocation> places = {link.location};
    if (link.inertial) {
      const Inertial& inertial = *link.inertial;
      places.insert(places.end(), {inertial.location, inertial.mass_location,
                                   inertial.inertia_location, inertial.pose_location});
    }
    for (const SourceLocation& place : places) {
      if (place.line != line || place.line == 0) continue;
      const bool before_cursor = place.column <= column || place.column == 0;
      if (best == nullptr || (before_cursor && place.column > best_column)) {
        best = &link;
        best_column = before_cursor ? place.column : -1;
      }
    }
  }
  return best;
}

std::string Vector(const Eigen::Vector3d& v) {
  return "(" + FormatShortest(v.x()) + ", " + FormatShortest(v.y()) + ", " + FormatShortest(v.z()) +
         ")";
}

// "0.0116, 0.0116, 0.000625 kg·m²" (ascending), or why there are none.
std::string PrincipalMoments(const Eigen::Matrix3d& I) {
  if (!I.allFinite()) return "unknown (a number is not finite)";
  const Eigen::Vector3d moments = CalcSymmetricEigenvalues(I);
  return FormatSignificant(moments.x(), 4) + ", " + FormatSignificant(moments.y(), 4) + ", " +
         FormatSignificant(moments.z(), 4) + " kg·m²";
}

std::string LinkTable(const Link& link, const Model& model) {
  std::string text;
  if (!link.inertial && !link.inertial_unreadable) {
    text += model.format == Model::Format::kUrdf
                ? "no `<inertial>`: massless (mass 0, as URDF loaders take it)\n\n"
                : "no `<inertial>`: the format's defaults apply\n\n";
    if (model.format == Model::Format::kUrdf) return text;
  }
  if (link.inertial_unreadable) text += "the `<inertial>` could not be read wholly\n\n";
  const MassProperties props = LinkMassProperties(link, model.format);
  // A Markdown table needs a header row: the mass is it (an empty one renders as a blank band).
  text += "| mass | " + FormatShortest(props.mass) + " kg |\n|---|---|\n";
  const char* frame = model.format == Model::Format::kMjcf ? "body" : "link";
  text += "| center of mass | " + Vector(props.p_FoScm_F) + " m in the " + frame + " frame |\n";
  text += "| principal moments | " + PrincipalMoments(props.I_SScm_F) + " |\n";
  if (link.inertial) {
    const Inertial& in = *link.inertial;
    text += "| inertia (as written) | ixx " + FormatShortest(in.ixx) + ", iyy " +
            FormatShortest(in.iyy) + ", izz " + FormatShortest(in.izz) + ", ixy " +
            FormatShortest(in.ixy) + ", ixz " + FormatShortest(in.ixz) + ", iyz " +
            FormatShortest(in.iyz) + " kg·m² |\n";
  }
  return text;
}

// The composite of the welded group that holds link `index`, when it has other members.
std::string GroupTable(const Model& model, int index) {
  for (const WeldedGroup& group : FindWeldedGroups(model)) {
    if (std::find(group.links.begin(), group.links.end(), index) == group.links.end()) continue;
    if (group.links.size() < 2) return {};
    const std::string& root = model.links[group.links.front()].name;
    std::string members;
    for (int member : group.links) {
      members += (members.empty() ? "`" : ", `") + model.links[member].name + "`";
    }
    const CompositeInertia composite = CalcCompositeInertia(model, group);
    std::string text = "\n**welded group** (fixed joints) rooted at `" + root + "`: " + members +
                       "\n\n| composite mass | " + FormatSignificant(composite.mass, 6) +
                       " kg |\n|---|---|\n";
    text +=
        "| center of mass | " + Vector(composite.p_RoScm_R) + " m in `" + root + "`'s frame |\n";
    text += "| principal moments | " + PrincipalMoments(composite.I_SScm_R) + " |\n";
    return text;
  }
  return {};
}

}  // namespace

json Hover(const Document& document, int line, int utf16_column) {
  if (!document.analysis || document.analysis->xacro) return nullptr;
  const Analysis& analysis = *document.analysis;
  // The cursor's byte column (1-based) on its line.
  std::size_t start = 0;
  for (int i = 0; i < line; ++i) {
    const std::size_t newline = analysis.text.find('\n', start);
    if (newline == std::string::npos) return nullptr;
    start = newline + 1;
  }
  const std::size_t end = std::min(analysis.text.find('\n', start), analysis.text.size());
  const std::size_t byte =
      ByteOfUtf16Column(std::string_view(analysis.text).substr(start, end - start),
                        static_cast<std::size_t>(std::max(0, utf16_column)));
  for (const Model& model : analysis.read.models) {
    const Link* link = LinkAt(model, line + 1, static_cast<int>(byte) + 1);
    if (link == nullptr) continue;
    const int index = static_cast<int>(link - model.links.data());
    const std::string kind = model.format == Model::Format::kMjcf ? "body" : "link";
    const std::string markdown = "**" + kind + " `" + link->name + "`** (model `" + model.name +
                                 "`)\n\n" + LinkTable(*link, model) + GroupTable(model, index);
    return {{"contents", {{"kind", "markdown"}, {"value", ShortenLongWords(markdown)}}},
            {"range", LineRange(analysis.text, line + 1)}};
  }
  return nullptr;
}

}  // namespace massprops::cli::lsp
