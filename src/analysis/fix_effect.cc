#include "massprops/analysis/fix_effect.h"

#include <algorithm>
#include <string>
#include <vector>

namespace massprops {

bool CalcFixEffect(const Model& before, const Model& after,
                   const std::vector<std::string>& changed_links, FixEffect* effect,
                   std::string* error) {
  ModelMassReport report_before, report_after;
  if (!ComputeMassReport(before, {}, &report_before, error)) return false;
  if (!ComputeMassReport(after, {}, &report_after, error)) return false;
  effect->model = before.name;
  effect->total = BodyEffect{"model", {}, report_before.total, report_after.total};
  effect->groups.clear();
  for (const GroupMassReport& group : report_before.welded_groups) {
    const bool changed = std::any_of(group.links.begin(), group.links.end(), [&](const auto& l) {
      return std::find(changed_links.begin(), changed_links.end(), l) != changed_links.end();
    });
    if (!changed) continue;
    BodyEffect body{group.root_link, group.links, group.properties, std::nullopt};
    for (const GroupMassReport& g : report_after.welded_groups) {
      if (g.root_link == group.root_link) body.after = g.properties;
    }
    effect->groups.push_back(std::move(body));
  }
  return true;
}

}  // namespace massprops
