#include "massprops/output/fix_report.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace massprops {
namespace {

using json = nlohmann::ordered_json;

json Vec(const Eigen::Vector3d& v) { return {v(0), v(1), v(2)}; }
json Mat(const Eigen::Matrix3d& m) {
  return {Vec(m.row(0).transpose()), Vec(m.row(1).transpose()), Vec(m.row(2).transpose())};
}

json Body(const std::optional<BodyMassProperties>& body) {
  if (!body) return json();
  return {{"frame", body->frame},
          {"mass", body->mass},
          {"com", Vec(body->com)},
          {"inertia_about_com", Mat(body->inertia_about_com)},
          {"principal_moments", Vec(body->principal_moments)}};
}

std::string G6(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", x);
  return buffer;
}

std::string Triple(const Eigen::Vector3d& v) {
  return "(" + G6(v(0)) + ", " + G6(v(1)) + ", " + G6(v(2)) + ")";
}

// One row: "  LABEL  WHEN  mass  com  moments".
std::string Row(const std::string& label, const char* when,
                const std::optional<BodyMassProperties>& body) {
  char buffer[512];
  if (!body) {
    std::snprintf(buffer, sizeof(buffer), "  %-24s %-6s (not computed)\n", label.c_str(), when);
    return buffer;
  }
  std::snprintf(buffer, sizeof(buffer), "  %-24s %-6s %-12s %-38s %s\n", label.c_str(), when,
                G6(body->mass).c_str(), Triple(body->com).c_str(),
                Triple(body->principal_moments).c_str());
  return buffer;
}

}  // namespace

std::string RenderFixEffectText(const FixEffect& effect) {
  std::string text = "effect on model '" + effect.model + "' (as massprops report: frame of " +
                     (effect.total.before ? "link '" + effect.total.before->frame + "'"
                                          : std::string("the root link")) +
                     " for the model, of the root link for a welded group):\n";
  char header[256];
  std::snprintf(header, sizeof(header), "  %-24s %-6s %-12s %-38s %s\n", "body", "", "mass (kg)",
                "center of mass (m)", "principal moments (kg·m²)");
  text += header;
  text += Row("model", "before", effect.total.before);
  text += Row("", "after", effect.total.after);
  for (const BodyEffect& group : effect.groups) {
    std::string label = "group '" + group.name + "'";
    if (group.links.size() > 1) label += " (" + std::to_string(group.links.size()) + " links)";
    text += Row(label, "before", group.before);
    text += Row("", "after", group.after);
  }
  return text;
}

std::string RenderFixJson(const std::string& file, bool changed, const std::vector<Repair>& repairs,
                          const std::vector<FixEffect>& effects) {
  json doc;
  doc["file"] = file;
  doc["changed"] = changed;
  doc["repairs"] = json::array();
  for (const Repair& r : repairs) {
    json changes = json::array();
    for (const FieldChange& c : r.changes) {
      changes.push_back({{"element", c.element},
                         {"attribute", c.attribute},
                         {"line", c.line},
                         {"old", c.old_values},
                         {"new", c.new_values}});
    }
    doc["repairs"].push_back({{"rule", r.rule},
                              {"link", r.link},
                              {"method", r.method},
                              {"why", r.why},
                              {"relative_change", r.relative_change},
                              {"inserts_inertial", r.inserts_inertial},
                              {"changes", changes}});
  }
  doc["effects"] = json::array();
  for (const FixEffect& e : effects) {
    json groups = json::array();
    for (const BodyEffect& g : e.groups) {
      groups.push_back({{"root_link", g.name},
                        {"links", g.links},
                        {"before", Body(g.before)},
                        {"after", Body(g.after)}});
    }
    doc["effects"].push_back(
        {{"model", e.model},
         {"total", {{"before", Body(e.total.before)}, {"after", Body(e.total.after)}}},
         {"groups", groups}});
  }
  return doc.dump(2) + "\n";
}

}  // namespace massprops
