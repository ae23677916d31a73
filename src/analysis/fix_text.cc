// What `massprops fix` says, in `check`'s form (fix_text.h).
#include "massprops/analysis/fix_text.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "massprops/analysis/finding_text.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {
namespace {

constexpr std::size_t kEvidencePrefix = 14;  // "  = evidence: "

// `text` with every whole-word occurrence of `word` replaced by `by` (a file or link name in a
// command: "massprops fix --from-geometry=a a.urdf").
std::string ReplaceAll(std::string text, const std::string& word, const std::string& by) {
  if (word.empty()) return text;
  for (std::size_t at = text.find(word); at != std::string::npos;
       at = text.find(word, at + by.size())) {
    text.replace(at, word.size(), by);
  }
  return text;
}

// `prefix` + `command` where `command` names `file` and `link`: as it is when the line fits
// kMaxDetailChars, else with FILE for the file, else with LINK for the link too.
std::string CommandLine(const std::string& prefix, const std::string& command,
                        const std::string& file, const std::string& link) {
  std::string line = prefix + command;
  if (CountChars(line) <= kMaxDetailChars) return line;
  const std::string with_file = ReplaceAll(command, " " + file, " FILE");
  line = prefix + with_file;
  if (CountChars(line) <= kMaxDetailChars) return line;
  return prefix + ReplaceAll(with_file, link + "=", "LINK=");
}

// The items packed greedily into lines of at most kMaxDetailChars characters: the first line
// starts with `first`, the others with `next` (items are never cut).
std::vector<std::string> PackItems(const std::vector<std::string>& items, const std::string& first,
                                   const std::string& next) {
  std::vector<std::string> lines;
  std::string line = first;
  bool empty = true;
  for (const std::string& item : items) {
    const std::string joined = empty ? line + item : line + ", " + item;
    if (!empty && CountChars(joined) > kMaxDetailChars) {
      lines.push_back(line + ",");
      line = next + item;
    } else {
      line = joined;
    }
    empty = false;
  }
  if (!empty) lines.push_back(line);
  return lines;
}

std::string Com(const Inertial& inertial) { return "(" + FormatTriple(inertial.X_BBi.p_AB) + ")"; }

// "mass 2 kg", "COM (0, 0, 0.1) m", "principal moments a, b, c kg·m²": what `after` writes.
std::vector<std::string> WrittenItems(const Inertial& after) {
  return {"mass " + FormatMass(after.mass), "COM " + Com(after) + " m",
          "principal moments " + FormatTriple(PrincipalMomentsOf(after)) + " kg·m²"};
}

// "a guess (a uniform solid)" or "physics (the nearest valid inertia)".
std::string Basis(const RepairRoute& route) {
  return (route.physics ? "physics (" : "a guess (") + route.basis + ")";
}

// The repair of `link` among the route's repairs (the first one when the link has none).
const Repair* RepairOf(const RepairRoute& route, const std::string& link) {
  for (const Repair& r : route.repairs) {
    if (r.link == link) return &r;
  }
  return route.repairs.empty() ? nullptr : &route.repairs.front();
}

// A route's command: "massprops fix OPTIONS FILE", or the CAD route's words.
std::string RouteCommand(const RepairRoute& route, const std::string& file) {
  if (route.options.empty()) {
    return "write its inertial from CAD or a datasheet, then massprops check " + file;
  }
  return "massprops fix " + route.options + " " + file;
}

// Old → new lines of one repair for --dry-run (mass, COM, principal moments), indented.
std::vector<std::string> OldToNewLines(const Repair& repair, const std::string& indent) {
  std::vector<std::string> lines;
  const Inertial& after = repair.after;
  if (!repair.before) {
    lines.push_back(indent + "mass (no <inertial>) → " + FormatMass(after.mass) + ", COM " +
                    Com(after) + " m");
    lines.push_back(indent + "principal moments " + FormatTriple(PrincipalMomentsOf(after)) +
                    " kg·m²");
    return lines;
  }
  const Inertial& before = *repair.before;
  const std::string mass_before = FormatMass(before.mass), mass_after = FormatMass(after.mass);
  lines.push_back(
      indent + "mass " +
      (mass_before == mass_after ? mass_after + " (kept)" : mass_before + " → " + mass_after));
  const std::string com_before = Com(before), com_after = Com(after);
  lines.push_back(
      indent + "COM " +
      (com_before == com_after ? com_after + " m (kept)" : com_before + " → " + com_after + " m"));
  const std::string moments_before = FormatTriple(PrincipalMomentsOf(before));
  const std::string moments_after = FormatTriple(PrincipalMomentsOf(after));
  const std::string moments =
      indent + "principal moments " + moments_before + " → " + moments_after + " kg·m²";
  if (CountChars(moments) <= kMaxDetailChars) {
    lines.push_back(moments);
  } else {
    lines.push_back(indent + "principal moments " + moments_before + " kg·m²");
    lines.push_back(indent + "  → " + moments_after + " kg·m²");
  }
  return lines;
}

}  // namespace

std::string RenderFixMessage(const FixMessage& message) {
  std::string text = message.location + ": " + message.severity + ": " + message.headline;
  if (!message.rule.empty()) text += " [" + message.rule + "]";
  text += "\n";
  for (const std::string& e : message.evidence) text += "  = evidence: " + e + "\n";
  for (const std::string& h : message.help) text += h + "\n";
  return text;
}

std::string FormatWholeEvidence(const std::vector<std::pair<std::string, double>>& values,
                                std::size_t max_chars) {
  std::string out;
  for (const auto& [name, value] : values) {
    const std::string item = EvidenceLabel(name) + " " + FormatEvidenceValue(name, value);
    const std::string next = out.empty() ? item : out + ", " + item;
    if (CountChars(next) > max_chars) continue;  // a later, shorter one may fit
    out = next;
  }
  return out;
}

Eigen::Vector3d PrincipalMomentsOf(const Inertial& in) {
  const double entries[] = {in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz};
  for (double x : entries) {
    if (!std::isfinite(x)) return Eigen::Vector3d::Zero();
  }
  return internal::ScaledPrincipalMoments(in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz,
                                          PrincipalSolver::kAccurate);
}

std::string FormatTriple(const Eigen::Vector3d& v) {
  return FormatSignificant(v(0)) + ", " + FormatSignificant(v(1)) + ", " + FormatSignificant(v(2));
}

std::vector<std::string> WrapWords(std::string_view text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string word(text.substr(start, end - start));
    start = end + 1;
    if (word.empty()) continue;
    if (!line.empty() && CountChars(line) + 1 + CountChars(word) > width) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::vector<std::string> RouteHelpLines(const std::vector<RepairRoute>& routes,
                                        const std::string& link, const std::string& file) {
  std::vector<std::string> lines;
  for (const RepairRoute& route : routes) {
    if (route.options.empty() && !route.repairs.empty()) continue;  // this run's own repair
    lines.push_back(CommandLine("  = help: ", RouteCommand(route, file), file, link));
    const Repair* repair = RepairOf(route, link);
    lines.push_back("    " + Basis(route) + ": " + route.what);
    if (repair == nullptr) continue;
    for (const std::string& l : PackItems(WrittenItems(repair->after), "    writes ", "      ")) {
      lines.push_back(l);
    }
    if (route.repairs.size() > 1) {
      lines.push_back("    and " + std::to_string(route.repairs.size() - 1) +
                      " other link(s) of its group (--dry-run lists them)");
    }
  }
  return lines;
}

FixMessage RefusedRepairMessage(const RefusedRepair& refused, Severity severity,
                                const std::string& file, const std::vector<RepairRoute>& routes) {
  FixMessage message;
  message.location = file + ":" + std::to_string(refused.link_line);
  message.severity = ToString(severity);
  const std::string reason =
      refused.reason.empty() ? "no repair passes the checks" : refused.reason;
  message.headline = LinkHeadline(refused.link, ": not repaired: " + reason);
  message.rule = refused.rule;
  for (const std::string& e : refused.evidence) {
    for (const std::string& line : WrapWords(e, kMaxDetailChars - kEvidencePrefix)) {
      message.evidence.push_back(line);
    }
  }
  message.help = RouteHelpLines(routes, refused.link, file);
  return message;
}

std::string RenderRouteChoices(const std::vector<RepairRoute>& routes, const std::string& link,
                               const std::string& file) {
  const bool any = std::any_of(routes.begin(), routes.end(),
                               [](const RepairRoute& r) { return !r.repairs.empty(); });
  if (!any) return "";
  std::string text = "  = choices for link '" + link + "' (old → new):";
  if (CountChars(text) > kMaxDetailChars) text = "  = choices for this link (old → new):";
  text += "\n";
  for (const RepairRoute& route : routes) {
    const std::string command = route.options.empty() && !route.repairs.empty()
                                    ? "massprops fix " + file + " (this run: " + route.what + ")"
                                    : RouteCommand(route, file);
    text += CommandLine("    ", command, file, link) + "\n";
    text += "      " + Basis(route) + (route.repairs.empty() ? ": " + route.what : "") + "\n";
    if (const Repair* repair = RepairOf(route, link)) {
      for (const std::string& line : OldToNewLines(*repair, "      ")) text += line + "\n";
      for (const Repair& other : route.repairs) {
        if (&other == repair) continue;
        const std::string named = "      and link '" + other.link + "':";
        text += (CountChars(named) <= kMaxDetailChars ? named : "      and another link:") + "\n";
        for (const std::string& line : OldToNewLines(other, "        ")) text += line + "\n";
      }
    }
  }
  return text;
}

}  // namespace massprops
