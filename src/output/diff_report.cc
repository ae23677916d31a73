#include "massprops/output/diff_report.h"

#include <nlohmann/json.hpp>
#include <utility>

namespace massprops {
namespace {

nlohmann::json SideJson(const DiffSide& s) {
  if (!s.present) return nullptr;
  nlohmann::json inertia = nlohmann::json::array();
  for (int r = 0; r < 3; ++r)
    inertia.push_back({s.inertia(r, 0), s.inertia(r, 1), s.inertia(r, 2)});
  return {{"mass", s.mass},
          {"com", {s.com[0], s.com[1], s.com[2]}},
          {"inertia", inertia},
          {"file", s.location.file},
          {"line", s.location.line}};
}

}  // namespace

std::string RenderDiffJson(const ModelDiff& diff, const Model& a, const Model& b) {
  nlohmann::json entries = nlohmann::json::array();
  for (const DiffEntry& e : diff.entries) {
    nlohmann::json j = {{"kind", e.kind},
                        {"name", e.name},
                        {"a", SideJson(e.a)},
                        {"b", SideJson(e.b)},
                        {"differs", e.differs}};
    if (e.a.present && e.b.present) {
      j["mass_difference"] = e.mass_difference;
      j["com_difference"] = e.com_difference;
      j["inertia_difference"] = e.inertia_difference;
    } else {
      j["missing"] = e.missing_how;
    }
    entries.push_back(std::move(j));
  }
  const nlohmann::json out = {
      {"a", {{"file", a.file}, {"format", ToString(a.format)}, {"model", a.name}}},
      {"b", {{"file", b.file}, {"format", ToString(b.format)}, {"model", b.name}}},
      {"tolerance", diff.tolerance},
      {"differs", diff.differs},
      {"entries", std::move(entries)}};
  return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace massprops
