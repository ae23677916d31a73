// The URDF reader's finding when urdfdom refuses the file (reader.h): urdf-not-loadable at the
// line of the element urdfdom's message names.
#include "io/urdf/reader.h"

namespace massprops::internal::urdf_reader {

// ------------------------------------------------------------------ urdfdom refuses the file

// The line of the element urdfdom's message names: a joint ("joint [j]", "joint 'j'"), else a
// link ("Link [l]", "link 'l'", the second of "Two root links found: [a] and [b]").
int Reader::LineOfNamed(std::string_view message) const {
  std::string lower(message);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto name_after = [&](std::string_view marker, char open, char close,
                              bool last) -> std::optional<std::string> {
    const std::size_t at = last ? lower.rfind(marker) : lower.find(marker);
    if (at == std::string::npos) return std::nullopt;
    const std::size_t begin = lower.find(open, at + marker.size() - 1);
    if (begin == std::string::npos) return std::nullopt;
    const std::size_t end = message.find(close, begin + 1);
    if (end == std::string::npos) return std::nullopt;
    return std::string(message.substr(begin + 1, end - begin - 1));
  };
  const auto joint_line = [&](const std::optional<std::string>& name, bool second) {
    if (!name) return 0;
    int found = 0;
    for (const IndexedJoint& j : index_.joints) {
      if (j.name == *name && (!second || found++ > 0)) return j.line;
    }
    return 0;
  };
  const auto link_line = [&](const std::optional<std::string>& name, bool second) {
    if (!name) return 0;
    int found = 0;
    for (const IndexedLink& l : index_.links) {
      if (l.name == *name && (!second || found++ > 0)) return l.line;
    }
    return 0;
  };
  const bool duplicate = lower.find("is not unique") != std::string::npos;
  int line = 0;
  if (lower.find("links found: [") != std::string::npos) {
    line = link_line(name_after("] and [", '[', ']', true), false);
  }
  if (line == 0) line = joint_line(name_after("joint [", '[', ']', true), false);
  if (line == 0) line = joint_line(name_after("joint '", '\'', '\'', false), duplicate);
  if (line == 0) line = link_line(name_after("link [", '[', ']', false), false);
  if (line == 0) line = link_line(name_after("link '", '\'', '\'', false), duplicate);
  if (line == 0 && lower.find("unnamed joint") != std::string::npos) {
    for (const IndexedJoint& j : index_.joints) {
      if (!j.has_name) return j.line;
    }
  }
  return line > 0 ? line : index_.robot_line;
}

// Generic follow-ups urdfdom logs after the message that says why.
bool IsWrapUp(const std::string& message) {
  return message.find("xml is not initialized correctly") != std::string::npos;
}

void Reader::ReportNotLoadable(const std::vector<std::string>& errors) {
  std::vector<std::string> said;
  for (const std::string& e : errors) {
    if (!IsWrapUp(e)) said.push_back(e);
  }
  std::string reason = "urdfdom gave no reason";
  int line = index_.robot_line;
  if (!said.empty()) {
    // The last message says why urdfdom stopped; a "Malformed ..." or "Could not parse ..." one
    // names the element, and the message before it says what in it was wrong.
    reason = said.back();
    line = LineOfNamed(reason);
    const bool wrapper =
        reason.rfind("Malformed", 0) == 0 || reason.rfind("Could not parse", 0) == 0;
    if (wrapper && said.size() >= 2) reason += ": " + said[said.size() - 2];
  }
  ReadFinding finding;
  finding.rule = kUrdfNotLoadable;
  finding.location = Loc(line);
  finding.message = "ROS's URDF parser will not load this file: " + reason +
                    "; massprops checks its mass properties from a lenient reading";
  result_.findings.push_back(std::move(finding));
}

}  // namespace massprops::internal::urdf_reader
