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
      IndexComment(comment->Value(), LineOf(comment), link, out);
    } else if (child->ToElement() != nullptr) {
      CollectIgnoreComments(child, link, out);
    }
  }
}

// One comment inside link `link` (its text between <!-- and -->, at `line`): the rules of a
// massprops comment go to out->ignored_rules; another massprops comment is a warning.
void Reader::IndexComment(std::string_view text, int line, const std::string& link,
                          IndexedLink* out) {
  while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
  constexpr std::string_view kPrefix = "massprops:";
  if (text.substr(0, kPrefix.size()) != kPrefix) return;
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
    Warning(line, "comment in link '" + link + "'",
            "a massprops comment must read 'massprops: ignore rule-id [rule-id...]'; "
            "this one is ignored");
    return;
  }
  for (std::size_t w = 1; w < words.size(); ++w) {
    out->ignored_rules.push_back(std::move(words[w]));
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
  // Without an exponent, fewer than 300 characters are 0, or at least 1e-298 and below 1e300 in
  // magnitude (or inf, nan): nothing to convert (most numbers of a URDF).
  if (digits.size() < 300 && digits.find_first_of("eE") == std::string_view::npos) return false;
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

// The first number of a link's first <inertial> that underflows, in urdfdom's order of reading.
void Reader::IndexUnderflow(const XMLElement* inertial, int link) {
  for (const InertialNumber& n : kInertialNumbers) {
    const XMLElement* e = inertial->FirstChildElement(n.element);
    const char* text = e != nullptr ? e->Attribute(n.attribute) : nullptr;
    if (text != nullptr && IndexUnderflowOf(link, LineOf(e), n, text)) return;
  }
}

// Whether `text`, number n of link `link`'s first <inertial> (its element at `line`), underflows;
// if so it goes to the index. Vectors are split at spaces as urdf::Vector3::init splits them.
bool Reader::IndexUnderflowOf(int link, int line, const InertialNumber& n, std::string_view text) {
  const bool vector = std::strcmp(n.element, "origin") == 0;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t end = vector ? std::min(text.find(' ', begin), text.size()) : text.size();
    double value = 0;
    if (Underflows(text.substr(begin, end - begin), &value)) {
      index_.underflows.push_back(
          {link, line, std::string("<") + n.element + " " + n.attribute + "=" + Quote(text) + ">",
           value, n.number});
      return true;
    }
    begin = end + 1;
  }
  return false;
}

// The index from a tinyxml2 DOM of the text, freed before urdfdom builds its own (to keep the
// peak low); false, with the error, when the text is not XML or has no <robot>.
bool Reader::IndexWithTinyxml2(const std::string& xml) {
  XMLDocument doc(/*processEntities=*/true, tinyxml2::PRESERVE_WHITESPACE);
  if (!ParseDom(xml, &doc)) return false;
  const XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) {
    const XMLElement* root = doc.RootElement();
    Error(LineOf(root), "document",
          root != nullptr ? std::string("the root element is <") + root->Name() +
                                ">, not <robot>: this is not a URDF file"
                          : std::string("no <robot> element: this is not a URDF file"));
    return false;
  }
  BuildIndex(robot);
  return true;
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

std::optional<std::string> Reader::DescribeIndex(const std::string& xml, bool from_tinyxml2) {
  if (!(from_tinyxml2 ? IndexWithTinyxml2(xml) : ScanIndex(xml))) return std::nullopt;
  std::string out = "robot " + std::to_string(index_.robot_line) + "\n";
  const auto lines = [](const std::vector<int>& v) {
    std::string s;
    for (const int line : v) s += " " + std::to_string(line);
    return s;
  };
  for (const IndexedLink& l : index_.links) {
    out += "link '" + l.name + "' " + (l.has_name ? "named" : "unnamed") + " " +
           std::to_string(l.line) + " inertials" + lines(l.inertial_lines) + " mass " +
           std::to_string(l.mass_line) + " inertia " + std::to_string(l.inertia_line) + " origin " +
           std::to_string(l.origin_line) + " holders";
    for (const IndexedLink::Holder& h : l.holders) {
      out += " " + std::to_string(h.line) + (h.is_collision ? "c" : "v");
    }
    out += " ignored";
    for (const std::string& rule : l.ignored_rules) out += " " + rule;
    out += "\n";
  }
  for (const IndexedJoint& j : index_.joints) {
    out += "joint '" + j.name + "' " + (j.has_name ? "named" : "unnamed") + " " +
           std::to_string(j.line) + " type '" + j.type + "' axis " + std::to_string(j.axis_line) +
           (j.axis_has_xyz ? " xyz" : "") + "\n";
  }
  for (const Underflow& u : index_.underflows) {
    char value[32];
    std::snprintf(value, sizeof value, "%.17g", u.value);
    out += "underflow link " + std::to_string(u.link) + " line " + std::to_string(u.line) + " " +
           u.what + " " + value + " number " + std::to_string(u.number) + "\n";
  }
  const auto firsts = [&](const char* what, const std::unordered_map<std::string, int>& map) {
    std::vector<std::pair<std::string, int>> sorted(map.begin(), map.end());
    std::sort(sorted.begin(), sorted.end());
    for (const auto& [name, i] : sorted)
      out += what + (" '" + name + "' ") + std::to_string(i) + "\n";
  };
  firsts("first link", index_.first_link);
  firsts("first joint", index_.first_joint);
  for (const ReadError& w : result_.warnings) {
    out += "warning " + std::to_string(w.location.line) + " " + w.element + ": " + w.message + "\n";
  }
  return out;
}

}  // namespace massprops::internal::urdf_reader

namespace massprops::internal {

std::optional<std::string> DescribeUrdfIndex(const std::string& xml, bool from_tinyxml2) {
  if (std::memchr(xml.data(), '\0', xml.size()) != nullptr) return std::nullopt;
  return urdf_reader::Reader("index").DescribeIndex(xml, from_tinyxml2);
}

}  // namespace massprops::internal
