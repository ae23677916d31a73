// The URDF reader's index (reader.h): the lines of the elements that carry mass properties, by
// name and order, the massprops:ignore comments, and the numbers urdfdom reads but not as written.
#include "io/urdf/reader.h"

namespace massprops::internal::urdf_reader {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// The text quoted in messages: at most 60 characters, control characters made visible.
std::string Quote(std::string_view text) {
  std::string out = "\"";
  const std::size_t shown = std::min<std::size_t>(text.size(), 60);
  for (std::size_t i = 0; i < shown; ++i) {
    const char c = text[i];
    if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      out += c;
    }
  }
  if (shown < text.size()) out += "...";
  out += '"';
  return out;
}

bool Reader::ParseDom(const std::string& xml, XMLDocument* doc) {
  doc->Parse(xml.data(), xml.size());
  if (!doc->Error()) return true;
  Error(doc->ErrorLineNum(), "XML",
        xml.find_first_not_of(" \t\r\n") == std::string::npos
            ? std::string("the file is empty")
            : std::string("malformed XML: ") + doc->ErrorStr());
  return false;
}

// `<!-- massprops: ignore rule-id [rule-id...] -->` anywhere inside the link.
void Reader::CollectIgnoreComments(const XMLNode* node, const std::string& link, IndexedLink* out) {
  for (const XMLNode* child = node->FirstChild(); child != nullptr; child = child->NextSibling()) {
    if (const tinyxml2::XMLComment* comment = child->ToComment()) {
      std::string_view text(comment->Value());
      while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
      constexpr std::string_view kPrefix = "massprops:";
      if (text.substr(0, kPrefix.size()) != kPrefix) continue;
      text.remove_prefix(kPrefix.size());
      std::vector<std::string> words;
      std::size_t pos = 0;
      while (pos < text.size()) {
        while (pos < text.size() && (IsSpace(text[pos]) || text[pos] == ',')) ++pos;
        const std::size_t start = pos;
        while (pos < text.size() && !IsSpace(text[pos]) && text[pos] != ',') ++pos;
        if (pos > start) words.emplace_back(text.substr(start, pos - start));
      }
      if (words.size() < 2 || words[0] != "ignore") {
        Warning(LineOf(comment), "comment in link '" + link + "'",
                "a massprops comment must read 'massprops: ignore rule-id [rule-id...]'; "
                "this one is ignored");
        continue;
      }
      for (std::size_t w = 1; w < words.size(); ++w) {
        out->ignored_rules.push_back(std::move(words[w]));
      }
    } else if (child->ToElement() != nullptr) {
      CollectIgnoreComments(child, link, out);
    }
  }
}

// Whether urdfdom (urdf::strToDouble: std::stringstream >> double, classic locale) reads `text`
// and gets a value below the smallest normal double (2.2e-308) from a number that is not zero as
// written: 0 for 1e-400, a subnormal for 1e-310. strtod sets ERANGE for both, and std::stod (as
// libsdformat reads SDF) throws; libstdc++'s stream ignores ERANGE. On success *value is what
// urdfdom reads.
bool Underflows(std::string_view text, double* value) {
  while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  if (digits.empty()) return false;
  double exact = 0;
  const std::from_chars_result r =
      std::from_chars(digits.data(), digits.data() + digits.size(), exact);
  if (r.ptr != digits.data() + digits.size()) return false;
  // from_chars gives out_of_range for 1e-400 and for 1e400 (which urdfdom refuses), and reads
  // subnormals without complaint.
  const bool tiny =
      r.ec == std::errc() && exact != 0 && std::abs(exact) < std::numeric_limits<double>::min();
  if (!tiny && r.ec != std::errc::result_out_of_range) return false;
  try {
    *value = urdf::strToDouble(std::string(text).c_str());
  } catch (const std::runtime_error&) {
    return false;  // 1e400: urdfdom refuses it, and says so
  }
  return std::abs(*value) < std::numeric_limits<double>::min();
}

// The first number of a link's first <inertial> that underflows, in urdfdom's order of reading
// (origin xyz, rpy, mass, inertia ixx ... izz; vectors split at spaces as urdf::Vector3::init).
void Reader::IndexUnderflow(const XMLElement* inertial, int link) {
  const auto check = [&](const XMLElement* e, const char* attribute, unsigned number) {
    const char* text = e != nullptr ? e->Attribute(attribute) : nullptr;
    if (text == nullptr) return false;
    const bool vector = std::strcmp(e->Name(), "origin") == 0;
    const std::string_view all(text);
    for (std::size_t begin = 0; begin <= all.size();) {
      const std::size_t end = vector ? std::min(all.find(' ', begin), all.size()) : all.size();
      double value = 0;
      if (Underflows(all.substr(begin, end - begin), &value)) {
        index_.underflows.push_back(
            {link, LineOf(e),
             std::string("<") + e->Name() + " " + attribute + "=" + Quote(text) + ">", value,
             number});
        return true;
      }
      begin = end + 1;
    }
    return false;
  };
  const XMLElement* origin = inertial->FirstChildElement("origin");
  if (check(origin, "xyz", kInertialPosition) || check(origin, "rpy", kInertialOrientation)) {
    return;
  }
  if (check(inertial->FirstChildElement("mass"), "value", kInertialMass)) return;
  const XMLElement* inertia = inertial->FirstChildElement("inertia");
  const std::pair<const char*, unsigned> entries[] = {{"ixx", kInertialIxx}, {"ixy", kInertialIxy},
                                                      {"ixz", kInertialIxz}, {"iyy", kInertialIyy},
                                                      {"iyz", kInertialIyz}, {"izz", kInertialIzz}};
  for (const auto& [attribute, number] : entries) {
    if (check(inertia, attribute, number)) return;
  }
}

void Reader::BuildIndex(const XMLElement* robot) {
  index_.robot_line = LineOf(robot);
  for (const XMLElement* e = robot->FirstChildElement("link"); e != nullptr;
       e = e->NextSiblingElement("link")) {
    IndexedLink link;
    link.line = LineOf(e);
    if (const char* name = e->Attribute("name")) {
      link.name = name;
      link.has_name = true;
    }
    for (const XMLElement* i = e->FirstChildElement("inertial"); i != nullptr;
         i = i->NextSiblingElement("inertial")) {
      if (link.inertial_lines.empty()) {
        link.mass_line = LineOf(i->FirstChildElement("mass"));
        link.inertia_line = LineOf(i->FirstChildElement("inertia"));
        link.origin_line = LineOf(i->FirstChildElement("origin"));
        IndexUnderflow(i, static_cast<int>(index_.links.size()));
      }
      link.inertial_lines.push_back(LineOf(i));
    }
    for (const XMLElement* child = e->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const char* tag = child->Name();
      const bool visual = std::strcmp(tag, "visual") == 0;
      if (visual || std::strcmp(tag, "collision") == 0) {
        link.holders.push_back({LineOf(child), !visual});
      }
    }
    CollectIgnoreComments(e, link.name, &link);
    index_.first_link.emplace(link.name, static_cast<int>(index_.links.size()));
    index_.links.push_back(std::move(link));
  }
  for (const XMLElement* e = robot->FirstChildElement("joint"); e != nullptr;
       e = e->NextSiblingElement("joint")) {
    IndexedJoint joint;
    joint.line = LineOf(e);
    if (const char* name = e->Attribute("name")) {
      joint.name = name;
      joint.has_name = true;
    }
    if (const char* type = e->Attribute("type")) joint.type = type;
    if (const XMLElement* axis = e->FirstChildElement("axis")) {
      joint.axis_line = LineOf(axis);
      joint.axis_has_xyz = axis->Attribute("xyz") != nullptr;
    }
    index_.first_joint.emplace(joint.name, static_cast<int>(index_.joints.size()));
    index_.joints.push_back(std::move(joint));
  }
}

// Where urdfdom reads one element and the text holds more that changes mass properties.
void Reader::WarnAboutTextUrdfdomSkips() {
  for (const IndexedLink& link : index_.links) {
    for (std::size_t k = 1; k < link.inertial_lines.size(); ++k) {
      Warning(link.inertial_lines[k], "<inertial> of link '" + link.name + "'",
              "a second <inertial> (line " + std::to_string(link.inertial_lines[k]) +
                  "); ROS's URDF parser reads only the first (line " +
                  std::to_string(link.inertial_lines[0]) + "), and so does massprops");
    }
  }
}

}  // namespace massprops::internal::urdf_reader
