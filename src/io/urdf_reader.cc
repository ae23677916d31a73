#include "massprops/io/urdf_reader.h"

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_exception/exception.h>
#include <urdf_model/pose.h>
#include <urdf_model/utils.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <shared_mutex>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "massprops/io/model_reader.h"

// The Model comes from urdf::parseURDF (urdfdom) whenever urdfdom returns a model; a tinyxml2 index
// of the same text gives the line of each element. Only when urdfdom refuses the file does
// massprops read the elements that carry mass properties itself (LenientReader below).

namespace massprops {
namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

constexpr const char* kUrdfNotLoadable = "urdf-not-loadable";
constexpr const char* kInertialUnreadable = "inertial-unreadable";

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

int LineOf(const XMLNode* node) { return node != nullptr ? node->GetLineNum() : 0; }

// ------------------------------------------------------------------ the index

struct IndexedLink {
  std::string name;
  bool has_name = false;
  int line = 0;
  std::vector<int> inertial_lines;  // every <inertial> child (urdfdom reads the first)
  int mass_line = 0, inertia_line = 0, origin_line = 0;  // of the first <inertial>
  struct Holder {
    int line;
    bool is_collision;
  };
  std::vector<Holder> holders;  // <visual>/<collision> children in file order
  std::vector<std::string> ignored_rules;
};

struct IndexedJoint {
  std::string name;
  bool has_name = false;
  int line = 0;
  std::string type;
  int axis_line = 0;  // 0: no <axis>
  bool axis_has_xyz = false;
};

// A number of a link's first <inertial> that urdfdom reads, but not as written: nonzero text below
// the smallest normal double, which urdfdom reads as 0 or as a subnormal (see Underflows).
struct Underflow {
  int link = 0;  // index in UrdfIndex::links
  int line = 0;
  std::string what;     // `<mass value="1e-400">`
  double value = 0;     // what urdfdom reads
  unsigned number = 0;  // which number (an Inertial::unknown bit)
};

// The lines of the elements that carry mass properties, by name and order. Decides nothing.
struct UrdfIndex {
  int robot_line = 0;
  std::vector<IndexedLink> links;
  std::vector<Underflow> underflows;  // at most one per link, the first in urdfdom's order
  std::vector<IndexedJoint> joints;
  std::unordered_map<std::string, int> first_link;   // name -> index in links
  std::unordered_map<std::string, int> first_joint;  // name -> index in joints
};

class Reader {
 public:
  explicit Reader(std::string file_name) : file_(std::move(file_name)) {}
  ReadResult Read(const std::string& xml);

 private:
  SourceLocation Loc(int line) const { return SourceLocation{file_, line, 0}; }
  void Warning(int line, std::string element, std::string message) {
    result_.warnings.push_back(ReadError{Loc(line), std::move(element), std::move(message)});
  }
  void Error(int line, std::string element, std::string message) {
    result_.errors.push_back(ReadError{Loc(line), std::move(element), std::move(message)});
  }
  bool ParseDom(const std::string& xml, XMLDocument* doc);
  void BuildIndex(const XMLElement* robot);
  void IndexUnderflow(const XMLElement* inertial, int link);
  void CollectIgnoreComments(const XMLNode* node, const std::string& link, IndexedLink* out);
  void WarnAboutTextUrdfdomSkips();
  Model FromUrdfdom(const urdf::ModelInterface& urdf, const std::vector<std::string>& errors,
                    const std::string& xml);
  Link LinkFromUrdfdom(const IndexedLink& indexed, const urdf::Link& source);
  void ReportUnreadableInertials(const std::vector<std::string>& unreadable, const std::string& xml,
                                 Model* model);
  Joint JointFromUrdfdom(const IndexedJoint& indexed, const urdf::Joint& source);
  void UseUrdfdomsParentJoints(const urdf::ModelInterface& urdf, Model* model);
  void WarnAboutSecondParents(const Link& link, const std::vector<const Joint*>& joints,
                              const Joint& kept);
  void ReportUnreadableInertial(const XMLElement* link_xml, Link* link);
  void ReportUnderflows(Model* model);
  void InertialUnreadable(int line, Link* link, std::string message, unsigned unknown);
  void ReportNotLoadable(const std::vector<std::string>& errors);
  int LineOfNamed(std::string_view message) const;

  std::string file_;
  ReadResult result_;
  UrdfIndex index_;
};

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

// ------------------------------------------------------------------ console_bridge

// urdfdom reports what it cannot read through console_bridge, which keeps ONE output handler and
// ONE log level for the whole process (console_bridge 1.0.1, src/console.cpp: a function-local
// static DefaultOutputHandler; log() filters by the level, then calls the handler while holding
// that object's mutex). massprops installs one handler of its own, once, in front of the one it
// finds; it captures what a thread logs while that thread is inside ParseWithUrdfdom (a
// thread_local list) and forwards everything else to the handler it found, so several threads
// read URDF at once and a library user's logging still arrives. Nothing else in urdf::parseURDF
// is shared between threads (urdfdom 3.0.1, urdf_parser/src/{model,link,joint,pose}.cpp: no
// static or global state, numbers through urdf::strToDouble of urdf_model/utils.h, a local
// stringstream imbued with std::locale::classic(); TinyXML 2.6.2, tinyxml.h: a local
// TiXmlDocument, its only mutable static, condenseWhiteSpace, written by SetCondenseWhiteSpace
// alone, which neither urdfdom nor massprops calls).
thread_local std::vector<std::string>* t_urdfdom_errors = nullptr;

class UrdfdomRouter final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* file,
           int line) override {
    if (t_urdfdom_errors != nullptr) {  // a massprops read: keep its errors, print nothing
      if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) t_urdfdom_errors->push_back(text);
      return;
    }
    console_bridge::OutputHandler* next = next_.load();
    if (next != nullptr && level >= forward_from_.load()) next->log(text, level, file, line);
  }
  std::atomic<console_bridge::OutputHandler*> next_{nullptr};
  // Messages of other code below this level are dropped: CONSOLE_BRIDGE_LOG_NONE while a read has
  // lowered the process's level from NONE to ERROR (the caller asked for no output).
  std::atomic<console_bridge::LogLevel> forward_from_{console_bridge::CONSOLE_BRIDGE_LOG_DEBUG};
};

// Never destroyed: console_bridge may call it until the process ends.
UrdfdomRouter& Router() {
  static UrdfdomRouter* const router = new UrdfdomRouter;
  return *router;
}

// Readers that find the router in front and the level at ERROR or below parse at once, together
// (shared); a reader that must change the handler or the level for its read does it alone
// (exclusive), and puts both back afterwards.
std::shared_mutex& UrdfdomSetupMutex() {
  static std::shared_mutex mutex;
  return mutex;
}

bool RouterReady() {
  return console_bridge::getOutputHandler() == &Router() &&
         console_bridge::getLogLevel() <= console_bridge::CONSOLE_BRIDGE_LOG_ERROR;
}

urdf::ModelInterfaceSharedPtr ParseCapturing(const std::string& xml,
                                             std::vector<std::string>* errors) {
  struct Scope {
    explicit Scope(std::vector<std::string>* e) { t_urdfdom_errors = e; }
    ~Scope() { t_urdfdom_errors = nullptr; }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
  } scope(errors);
  try {
    return urdf::parseURDF(xml);
  } catch (const std::exception& e) {  // urdfdom does not throw today; be safe if it does
    errors->push_back(e.what());
    return nullptr;
  }
}

// The caller replaced massprops' handler, or set the level to NONE: one read with the router in
// front and the level at ERROR, then the caller's handler and level again.
urdf::ModelInterfaceSharedPtr ParseAlone(const std::string& xml, std::vector<std::string>* errors) {
  const std::unique_lock<std::shared_mutex> lock(UrdfdomSetupMutex());
  if (RouterReady()) return ParseCapturing(xml, errors);
  UrdfdomRouter& router = Router();
  const bool swap_handler = console_bridge::getOutputHandler() != &router;
  const console_bridge::LogLevel level = console_bridge::getLogLevel();
  const bool lower_level = level > console_bridge::CONSOLE_BRIDGE_LOG_ERROR;
  if (swap_handler) {
    router.next_ = console_bridge::getOutputHandler();
    console_bridge::useOutputHandler(&router);
  }
  if (lower_level) {
    router.forward_from_ = level;
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
  }
  struct Restore {
    bool handler_swapped;
    bool level_lowered;
    console_bridge::LogLevel level_was;
    ~Restore() {
      if (level_lowered) {
        console_bridge::setLogLevel(level_was);
        Router().forward_from_ = console_bridge::CONSOLE_BRIDGE_LOG_DEBUG;
      }
      if (handler_swapped) console_bridge::restorePreviousOutputHandler();
    }
  } restore{swap_handler, lower_level, level};
  return ParseCapturing(xml, errors);
}

urdf::ModelInterfaceSharedPtr ParseWithUrdfdom(const std::string& xml,
                                               std::vector<std::string>* errors) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    const std::unique_lock<std::shared_mutex> lock(UrdfdomSetupMutex());
    Router().next_ = console_bridge::getOutputHandler();
    console_bridge::useOutputHandler(&Router());
  });
  errors->clear();
  {
    const std::shared_lock<std::shared_mutex> lock(UrdfdomSetupMutex());
    if (RouterReady()) return ParseCapturing(xml, errors);
  }
  return ParseAlone(xml, errors);
}

// urdfdom's links hold their children by shared_ptr (parents by weak_ptr). A file whose joints
// form a loop beside the root (which urdfdom accepts) makes a cycle of shared_ptrs that is never
// freed: clear the child lists so that the whole model goes with its last owner.
void ReleaseUrdfdomModel(urdf::ModelInterfaceSharedPtr model) {
  if (!model) return;
  for (auto& [name, link] : model->links_) {
    if (!link) continue;
    link->child_links.clear();
    link->child_joints.clear();
  }
}

// ------------------------------------------------------------------ from urdfdom's model

Pose ToPose(const urdf::Pose& pose) {
  Pose X;
  X.p_AB = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  X.R_AB = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
               .toRotationMatrix();
  return X;
}

Geometry ToGeometry(const urdf::Geometry& g, const urdf::Pose& origin, bool is_collision) {
  Geometry out;
  out.is_collision = is_collision;
  out.X_BG = ToPose(origin);
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const urdf::Vector3& d = static_cast<const urdf::Box&>(g).dim;
      out.type = Geometry::Type::kBox;
      out.size = Eigen::Vector3d(d.x, d.y, d.z);
      break;
    }
    case urdf::Geometry::CYLINDER:
      out.type = Geometry::Type::kCylinder;
      out.radius = static_cast<const urdf::Cylinder&>(g).radius;
      out.length = static_cast<const urdf::Cylinder&>(g).length;
      break;
    case urdf::Geometry::SPHERE:
      out.type = Geometry::Type::kSphere;
      out.radius = static_cast<const urdf::Sphere&>(g).radius;
      break;
    case urdf::Geometry::MESH: {
      const urdf::Mesh& m = static_cast<const urdf::Mesh&>(g);
      out.type = Geometry::Type::kMesh;
      out.uri = m.filename;
      out.scale = Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z);
      break;
    }
    default:
      out.type = Geometry::Type::kOther;
  }
  return out;
}

Joint::Type JointTypeOf(int urdf_type) {
  switch (urdf_type) {
    case urdf::Joint::REVOLUTE:
      return Joint::Type::kRevolute;
    case urdf::Joint::CONTINUOUS:
      return Joint::Type::kContinuous;
    case urdf::Joint::PRISMATIC:
      return Joint::Type::kPrismatic;
    case urdf::Joint::FLOATING:
      return Joint::Type::kFloating;
    case urdf::Joint::PLANAR:
      return Joint::Type::kPlanar;
    case urdf::Joint::FIXED:
      return Joint::Type::kFixed;
    default:
      return Joint::Type::kOther;
  }
}

// The link names of urdfdom's "Could not parse inertial element for Link [NAME]" messages.
std::vector<std::string> LinksWithUnreadableInertial(const std::vector<std::string>& errors) {
  constexpr std::string_view kPrefix = "Could not parse inertial element for Link [";
  std::vector<std::string> names;
  for (const std::string& e : errors) {
    if (e.compare(0, kPrefix.size(), kPrefix) == 0 && e.back() == ']') {
      names.push_back(e.substr(kPrefix.size(), e.size() - kPrefix.size() - 1));
    }
  }
  return names;
}

const XMLElement* NthChild(const XMLElement* parent, const char* name, int n) {
  const XMLElement* e = parent->FirstChildElement(name);
  for (int k = 0; k < n && e != nullptr; ++k) e = e->NextSiblingElement(name);
  return e;
}

// Whether urdf::strToDouble reads the text (the grammar of every URDF number).
bool UrdfdomReads(const char* text) {
  try {
    (void)urdf::strToDouble(text);
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

bool UrdfdomReadsVector(const char* text) {
  try {
    urdf::Vector3 v;
    v.init(text);
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

// urdfdom could not read the link's first <inertial>: say what, in urdfdom's order of reading,
// and what urdfdom loads instead. urdfdom 3.0.1 keeps the link and its inertial as far as it got:
// an unreadable <origin> leaves all of it zero; an unreadable <mass> keeps the origin, with mass
// and inertia zero; an unreadable <inertia> keeps the origin and the mass, with all six inertia
// numbers zero (measured with urdf::parseURDF: tests/urdf_reader_test.cc,
// WhatUrdfdomLoadsOfAPartlyReadInertialIsKeptWithItsUnknownsMarked).
void Reader::ReportUnreadableInertial(const XMLElement* link_xml, Link* link) {
  const XMLElement* inertial = link_xml->FirstChildElement("inertial");
  if (inertial == nullptr) return;
  int line = LineOf(inertial);
  std::string what;
  unsigned unknown = kInertialAll;
  const XMLElement* origin = inertial->FirstChildElement("origin");
  const XMLElement* mass = inertial->FirstChildElement("mass");
  const XMLElement* inertia = inertial->FirstChildElement("inertia");
  for (const char* attribute : {"xyz", "rpy"}) {
    const char* text = origin != nullptr ? origin->Attribute(attribute) : nullptr;
    if (what.empty() && text != nullptr && !UrdfdomReadsVector(text)) {
      what = std::string("<origin ") + attribute + "=" + Quote(text) + "> (three numbers)";
      line = LineOf(origin);
    }
  }
  if (what.empty()) unknown = kInertialMass | kInertialMoments;
  if (what.empty() && mass == nullptr) what = "<inertial> without <mass>";
  if (what.empty() && mass->Attribute("value") == nullptr) {
    what = "<mass> without 'value'";
    line = LineOf(mass);
  }
  if (what.empty() && !UrdfdomReads(mass->Attribute("value"))) {
    what = std::string("<mass value=") + Quote(mass->Attribute("value")) + ">";
    line = LineOf(mass);
  }
  if (what.empty()) unknown = kInertialMoments;
  if (what.empty() && inertia == nullptr) what = "<inertial> without <inertia>";
  for (const char* attribute : {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}) {
    if (!what.empty()) break;
    const char* text = inertia->Attribute(attribute);
    if (text == nullptr || !UrdfdomReads(text)) {
      what = text == nullptr ? std::string("<inertia> without '") + attribute + "'"
                             : std::string("<inertia ") + attribute + "=" + Quote(text) + ">";
      line = LineOf(inertia);
    }
  }
  if (what.empty()) {
    what = "its <inertial>";
    unknown = kInertialAll;
  }
  const char* loads =
      unknown == kInertialMoments
          ? "' and loads the link with its mass and center of mass as written but an inertia of "
            "zero (all six numbers)"
      : unknown == (kInertialMass | kInertialMoments)
          ? "' and loads the link with its center of mass as written but mass and inertia "
            "zero"
          : "' and loads the link's <inertial> as all zeros";
  InertialUnreadable(line, link,
                     "ROS's URDF parser cannot read " + what + " of link '" + link->name + loads +
                         "; write one decimal number per attribute, nothing around it",
                     unknown);
}

// The link's inertial is not the one written: an error finding, and the link is not judged. What
// the loader loaded moves to Link::loaded_inertial, `unknown` marking what is not the author's.
void Reader::InertialUnreadable(int line, Link* link, std::string message, unsigned unknown) {
  ReadFinding finding;
  finding.rule = kInertialUnreadable;
  finding.link = link->name;
  finding.location = Loc(line);
  finding.message = std::move(message);
  result_.findings.push_back(std::move(finding));
  if (link->inertial) {
    link->loaded_inertial = std::move(link->inertial);
    link->loaded_inertial->unknown = unknown;
  }
  link->inertial.reset();
  link->inertial_unreadable = true;
}

// A number urdfdom reads as 0 or a subnormal from nonzero text (1e-400): an error, as in SDF,
// where libsdformat and massprops refuse it. A link whose inertial urdfdom could not read at all
// has its finding already.
void Reader::ReportUnderflows(Model* model) {
  for (const Underflow& u : index_.underflows) {
    const int i = model->FindLink(index_.links[u.link].name);
    if (i < 0 || model->links[i].inertial_unreadable || !model->links[i].inertial) continue;
    char number[32];
    std::snprintf(number, sizeof number, "%g", u.value);
    const std::string value = (u.value == 0 ? "" : "the subnormal ") + std::string(number);
    Link* link = &model->links[i];
    InertialUnreadable(u.line, link,
                       "ROS's URDF parser reads " + u.what + " of link '" + link->name + "' as " +
                           value +
                           ": the number is not zero but below the smallest normal double "
                           "(2.2e-308), so it underflows (SDF readers refuse it); write 0, or a "
                           "value of at least 2.2e-308",
                       u.number);
  }
}

// The Model of what urdfdom read, in the file's order, with the index's lines.
Model Reader::FromUrdfdom(const urdf::ModelInterface& urdf, const std::vector<std::string>& errors,
                          const std::string& xml) {
  Model model;
  model.format = Model::Format::kUrdf;
  model.file = file_;
  model.name = urdf.name_;
  model.location = Loc(index_.robot_line);
  if (urdf.getRoot()) model.root_link = urdf.getRoot()->name;
  model.links.reserve(index_.links.size());
  for (const IndexedLink& indexed : index_.links) {
    const auto found = urdf.links_.find(indexed.name);
    if (found == urdf.links_.end() || !found->second) continue;
    model.links.push_back(LinkFromUrdfdom(indexed, *found->second));
  }
  ReportUnreadableInertials(LinksWithUnreadableInertial(errors), xml, &model);
  ReportUnderflows(&model);
  model.joints.reserve(index_.joints.size());
  for (const IndexedJoint& indexed : index_.joints) {
    const auto found = urdf.joints_.find(indexed.name);
    if (found == urdf.joints_.end() || !found->second) continue;
    model.joints.push_back(JointFromUrdfdom(indexed, *found->second));
  }
  UseUrdfdomsParentJoints(urdf, &model);
  return model;
}

// One link as urdfdom read it: its inertial and the geometries it kept, located by the index.
Link Reader::LinkFromUrdfdom(const IndexedLink& indexed, const urdf::Link& source) {
  Link link;
  link.name = source.name;
  link.location = Loc(indexed.line);
  link.ignored_rules = indexed.ignored_rules;
  if (source.inertial) {
    const urdf::Inertial& i = *source.inertial;
    Inertial& inertial = link.inertial.emplace();
    inertial.mass = i.mass;
    inertial.X_BBi = ToPose(i.origin);
    inertial.ixx = i.ixx;
    inertial.iyy = i.iyy;
    inertial.izz = i.izz;
    inertial.ixy = i.ixy;
    inertial.ixz = i.ixz;
    inertial.iyz = i.iyz;
    inertial.location = Loc(indexed.inertial_lines.empty() ? 0 : indexed.inertial_lines[0]);
    inertial.mass_location = Loc(indexed.mass_line);
    inertial.inertia_location = Loc(indexed.inertia_line);
    inertial.pose_location = Loc(indexed.origin_line);
  }
  // urdfdom keeps the <visual>s (then the <collision>s) it read before the first it could not:
  // the k-th kept one is the k-th element of its kind.
  std::size_t visuals = 0, collisions = 0;
  for (const IndexedLink::Holder& holder : indexed.holders) {
    const urdf::GeometrySharedPtr* geometry = nullptr;
    const urdf::Pose* origin = nullptr;
    if (holder.is_collision && collisions < source.collision_array.size()) {
      geometry = &source.collision_array[collisions]->geometry;
      origin = &source.collision_array[collisions]->origin;
      ++collisions;
    } else if (!holder.is_collision && visuals < source.visual_array.size()) {
      geometry = &source.visual_array[visuals]->geometry;
      origin = &source.visual_array[visuals]->origin;
      ++visuals;
    }
    if (geometry == nullptr || !*geometry) continue;
    Geometry g = ToGeometry(**geometry, *origin, holder.is_collision);
    g.location = Loc(holder.line);
    link.geometries.push_back(std::move(g));
  }
  return link;
}

// inertial-unreadable on the links whose <inertial> urdfdom could only partly read, quoting the
// text (from a DOM of the same text: the index keeps no attribute values).
void Reader::ReportUnreadableInertials(const std::vector<std::string>& unreadable,
                                       const std::string& xml, Model* model) {
  if (unreadable.empty()) return;
  XMLDocument doc;
  if (!ParseDom(xml, &doc)) return;
  const XMLElement* robot = doc.FirstChildElement("robot");
  for (const std::string& name : unreadable) {
    const auto indexed = index_.first_link.find(name);
    const int i = model->FindLink(name);
    if (indexed == index_.first_link.end() || i < 0 || robot == nullptr) continue;
    const XMLElement* link_xml = NthChild(robot, "link", indexed->second);
    if (link_xml != nullptr) ReportUnreadableInertial(link_xml, &model->links[i]);
  }
}

// One joint as urdfdom read it (its axis normalized; a zero axis is a read warning).
Joint Reader::JointFromUrdfdom(const IndexedJoint& indexed, const urdf::Joint& source) {
  Joint joint;
  joint.name = source.name;
  joint.type = JointTypeOf(source.type);
  joint.type_name = indexed.type;
  joint.parent = source.parent_link_name;
  joint.child = source.child_link_name;
  joint.X_PC = ToPose(source.parent_to_joint_origin_transform);
  joint.location = Loc(indexed.line);
  if (joint.type != Joint::Type::kFixed && joint.type != Joint::Type::kFloating) {
    const Eigen::Vector3d axis(source.axis.x, source.axis.y, source.axis.z);
    const double norm = axis.norm();
    joint.axis = norm > 0 ? Eigen::Vector3d(axis / norm) : axis;
    if (!(norm > 0)) {
      Warning(indexed.axis_line > 0 ? indexed.axis_line : indexed.line,
              "<axis> of joint '" + joint.name + "'",
              indexed.axis_line > 0 && !indexed.axis_has_xyz
                  ? "no 'xyz' attribute: ROS's URDF parser leaves the axis (0, 0, 0)"
                  : "the axis is zero");
    }
  }
  return joint;
}

// urdfdom's initTree (urdf_model/model.h) walks the joints in name order (a std::map) and sets
// each child's parent_joint, so a link that is the child of several joints hangs from the last of
// them by name. The checks hang a link from the first joint in Model::joints that names it as
// child (FindParentJoint, FindWeldedGroups): put urdfdom's joint first among that link's joints
// (the others keep their file order in the remaining places) and say so.
void Reader::UseUrdfdomsParentJoints(const urdf::ModelInterface& urdf, Model* model) {
  std::unordered_map<std::string, std::vector<int>> joints_of_child;
  for (std::size_t j = 0; j < model->joints.size(); ++j) {
    joints_of_child[model->joints[j].child].push_back(static_cast<int>(j));
  }
  std::vector<Joint> ordered = model->joints;
  for (const Link& link : model->links) {
    const auto joints = joints_of_child.find(link.name);
    const auto source = urdf.links_.find(link.name);
    if (joints == joints_of_child.end() || joints->second.size() < 2) continue;
    if (source == urdf.links_.end() || !source->second || !source->second->parent_joint) continue;
    const std::vector<int>& places = joints->second;  // ascending: file order
    std::vector<int> order = places;
    const auto kept = std::find_if(order.begin(), order.end(), [&](int j) {
      return model->joints[j].name == source->second->parent_joint->name;
    });
    if (kept == order.end()) continue;
    std::rotate(order.begin(), kept, kept + 1);
    std::vector<const Joint*> in_file_order;
    for (std::size_t k = 0; k < places.size(); ++k) {
      ordered[places[k]] = model->joints[order[k]];
      in_file_order.push_back(&model->joints[places[k]]);
    }
    WarnAboutSecondParents(link, in_file_order, model->joints[order[0]]);
  }
  model->joints = std::move(ordered);
}

// At the line of the second joint (the one that makes the link a child twice), naming them all.
void Reader::WarnAboutSecondParents(const Link& link, const std::vector<const Joint*>& joints,
                                    const Joint& kept) {
  std::string listed;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    if (k > 0) listed += k + 1 == joints.size() ? " and " : ", ";
    listed += "'" + joints[k]->name + "' (line " + std::to_string(joints[k]->location.line) + ")";
  }
  Warning(joints[1]->location.line, "link '" + link.name + "'",
          "the child of " + std::to_string(joints.size()) + " joints, " + listed +
              "; ROS's URDF parser hangs it from '" + kept.name + "' (line " +
              std::to_string(kept.location.line) +
              ", the last of them in name order), and so does massprops, which leaves the "
              "others out of the tree (they close a loop)");
}

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

// Numbers as written, with surrounding white space, a leading '+', "nan" and "inf" allowed.
std::optional<double> LenientNumber(std::string_view text) {
  while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && IsSpace(text.back())) text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0;
  const std::from_chars_result r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

// Three numbers separated by white space or commas ("0.07, 0, -0.69").
std::optional<Eigen::Vector3d> LenientVector(std::string_view text) {
  const auto separator = [](char c) { return IsSpace(c) || c == ','; };
  Eigen::Vector3d v;
  int count = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    while (pos < text.size() && separator(text[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < text.size() && !separator(text[pos])) ++pos;
    if (pos == start) break;
    const std::optional<double> number = LenientNumber(text.substr(start, pos - start));
    if (!number || count == 3) return std::nullopt;
    v(count++) = *number;
  }
  if (count != 3) return std::nullopt;
  return v;
}

// The reading of only what carries mass properties, for files urdfdom refuses.
class LenientReader {
 public:
  LenientReader(const std::string& file, ReadResult* result) : file_(file), result_(result) {}

  Model Read(const XMLElement* robot) {
    Model model;
    model.format = Model::Format::kUrdf;
    model.file = file_;
    model.location = Loc(robot);
    if (const char* name = robot->Attribute("name")) model.name = name;
    std::unordered_map<std::string, int> links;
    for (const XMLElement* e = robot->FirstChildElement("link"); e != nullptr;
         e = e->NextSiblingElement("link")) {
      const char* name = e->Attribute("name");
      if (name == nullptr || links.count(name) > 0) continue;
      links.emplace(name, static_cast<int>(model.links.size()));
      model.links.push_back(ReadLink(e));
    }
    // Joints between known links that keep the links a forest (a link has one parent joint, no
    // loops); a joint to an undefined parent (Drake's "world") is kept: it fixes or frees the
    // child.
    std::vector<int> set(model.links.size());
    std::iota(set.begin(), set.end(), 0);
    const auto find = [&](int i) {
      while (set[i] != i) i = set[i] = set[set[i]];
      return i;
    };
    std::vector<bool> has_parent(model.links.size(), false);
    std::vector<bool> has_link_parent(model.links.size(), false);
    for (const XMLElement* e = robot->FirstChildElement("joint"); e != nullptr;
         e = e->NextSiblingElement("joint")) {
      std::optional<Joint> joint = ReadJoint(e);
      if (!joint) continue;
      const auto child = links.find(joint->child);
      if (child == links.end() || has_parent[child->second]) continue;
      const auto parent = links.find(joint->parent);
      if (parent != links.end()) {
        const int a = find(parent->second), b = find(child->second);
        if (a == b) continue;  // would close a loop
        set[b] = a;
        has_link_parent[child->second] = true;
      }
      has_parent[child->second] = true;
      model.joints.push_back(std::move(*joint));
    }
    // As for SDF: the first link that no joint from another link has as child.
    for (std::size_t i = 0; i < model.links.size() && model.root_link.empty(); ++i) {
      if (!has_link_parent[i]) model.root_link = model.links[i].name;
    }
    return model;
  }

 private:
  SourceLocation Loc(const XMLNode* node) const { return SourceLocation{file_, LineOf(node), 0}; }

  // The numbers of the link's inertial that cannot be read (`what`, the first at `element`): an
  // error finding; every other number is kept in Link::loaded_inertial, the unread ones (held as
  // 0) marked in Inertial::unknown.
  void Unreadable(Link* link, const XMLElement* element, const std::string& what,
                  unsigned unknown) {
    ReadFinding finding;
    finding.rule = kInertialUnreadable;
    finding.link = link->name;
    finding.location = Loc(element);
    finding.message = "neither ROS's URDF parser nor a lenient reading can read " + what +
                      " of link '" + link->name +
                      "' as numbers; its mass properties are not checked, and the report leaves "
                      "the numbers that depend on them unknown";
    result_->findings.push_back(std::move(finding));
    link->loaded_inertial = std::move(link->inertial);
    link->loaded_inertial->unknown = unknown;
    link->inertial.reset();
    link->inertial_unreadable = true;
  }

  // A pose from <origin xyz rpy>; nullopt (after a message in *what) when unreadable.
  static std::optional<Pose> ReadOrigin(const XMLElement* origin, std::string* what) {
    Pose X;
    if (origin == nullptr) return X;
    for (const char* attribute : {"xyz", "rpy"}) {
      const char* text = origin->Attribute(attribute);
      if (text == nullptr) continue;
      const std::optional<Eigen::Vector3d> v = LenientVector(text);
      if (!v) {
        *what = std::string("<origin ") + attribute + "=" + Quote(text) + ">";
        return std::nullopt;
      }
      if (attribute[0] == 'x') {
        X.p_AB = *v;
      } else {
        X.R_AB = RotationFromRollPitchYaw(v->x(), v->y(), v->z());
      }
    }
    return X;
  }

  Link ReadLink(const XMLElement* e) {
    Link link;
    link.name = e->Attribute("name");
    link.location = Loc(e);
    if (const XMLElement* i = e->FirstChildElement("inertial")) {
      Inertial& inertial = link.inertial.emplace();
      inertial.location = Loc(i);
      // Every number is read that can be; those that cannot are listed (the first's element
      // locates the finding) and marked unknown.
      std::string what;
      const XMLElement* first_bad = nullptr;
      unsigned unknown = 0;
      const auto bad = [&](const XMLElement* element, const std::string& text, unsigned number) {
        what += (what.empty() ? "" : ", ") + text;
        if (first_bad == nullptr) first_bad = element;
        unknown |= number;
      };
      if (const XMLElement* origin = i->FirstChildElement("origin")) {
        inertial.pose_location = Loc(origin);
        const std::pair<const char*, unsigned> parts[] = {{"xyz", kInertialPosition},
                                                          {"rpy", kInertialOrientation}};
        for (const auto& [attribute, number] : parts) {
          const char* text = origin->Attribute(attribute);
          if (text == nullptr) continue;
          const std::optional<Eigen::Vector3d> v = LenientVector(text);
          if (!v) {
            bad(origin, std::string("<origin ") + attribute + "=" + Quote(text) + ">", number);
          } else if (number == kInertialPosition) {
            inertial.X_BBi.p_AB = *v;
          } else {
            inertial.X_BBi.R_AB = RotationFromRollPitchYaw(v->x(), v->y(), v->z());
          }
        }
      }
      if (const XMLElement* mass = i->FirstChildElement("mass")) {
        inertial.mass_location = Loc(mass);
        if (const char* text = mass->Attribute("value")) {
          const std::optional<double> value = LenientNumber(text);
          if (value) {
            inertial.mass = *value;
          } else {
            bad(mass, std::string("<mass value=") + Quote(text) + ">", kInertialMass);
          }
        }
      }
      if (const XMLElement* inertia = i->FirstChildElement("inertia")) {
        inertial.inertia_location = Loc(inertia);
        const std::tuple<const char*, double*, unsigned> entries[] = {
            {"ixx", &inertial.ixx, kInertialIxx}, {"ixy", &inertial.ixy, kInertialIxy},
            {"ixz", &inertial.ixz, kInertialIxz}, {"iyy", &inertial.iyy, kInertialIyy},
            {"iyz", &inertial.iyz, kInertialIyz}, {"izz", &inertial.izz, kInertialIzz}};
        for (const auto& [attribute, target, number] : entries) {
          const char* text = inertia->Attribute(attribute);
          if (text == nullptr) continue;
          const std::optional<double> value = LenientNumber(text);
          if (value) {
            *target = *value;
          } else {
            bad(inertia, std::string("<inertia ") + attribute + "=" + Quote(text) + ">", number);
          }
        }
      }
      if (unknown != 0) Unreadable(&link, first_bad, what, unknown);
    }
    for (const XMLElement* child = e->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const bool visual = std::strcmp(child->Name(), "visual") == 0;
      if (!visual && std::strcmp(child->Name(), "collision") != 0) continue;
      if (std::optional<Geometry> g = ReadGeometry(child, !visual)) {
        link.geometries.push_back(std::move(*g));
      }
    }
    return link;
  }

  // A geometry that cannot be read is left out (no inertial number depends on it).
  std::optional<Geometry> ReadGeometry(const XMLElement* holder, bool is_collision) {
    Geometry g;
    g.is_collision = is_collision;
    g.location = Loc(holder);
    std::string what;
    const std::optional<Pose> X = ReadOrigin(holder->FirstChildElement("origin"), &what);
    if (!X) return std::nullopt;
    g.X_BG = *X;
    const XMLElement* geometry = holder->FirstChildElement("geometry");
    const XMLElement* shape = geometry != nullptr ? geometry->FirstChildElement() : nullptr;
    if (shape == nullptr) return std::nullopt;
    const auto number = [&](const char* attribute, double* out) {
      const char* text = shape->Attribute(attribute);
      const std::optional<double> v = text != nullptr ? LenientNumber(text) : std::nullopt;
      if (v) *out = *v;
      return v.has_value();
    };
    const std::string_view type = shape->Name();
    if (type == "box") {
      const char* text = shape->Attribute("size");
      const std::optional<Eigen::Vector3d> size =
          text != nullptr ? LenientVector(text) : std::nullopt;
      if (!size) return std::nullopt;
      g.type = Geometry::Type::kBox;
      g.size = *size;
    } else if (type == "cylinder" || type == "capsule") {
      g.type = type == "cylinder" ? Geometry::Type::kCylinder : Geometry::Type::kCapsule;
      if (!number("radius", &g.radius) || !number("length", &g.length)) return std::nullopt;
    } else if (type == "sphere") {
      g.type = Geometry::Type::kSphere;
      if (!number("radius", &g.radius)) return std::nullopt;
    } else if (type == "mesh") {
      const char* filename = shape->Attribute("filename");
      if (filename == nullptr) return std::nullopt;
      g.type = Geometry::Type::kMesh;
      g.uri = filename;
      if (const char* text = shape->Attribute("scale")) {
        const std::optional<Eigen::Vector3d> scale = LenientVector(text);
        if (!scale) return std::nullopt;
        g.scale = *scale;
      }
    } else {
      return std::nullopt;
    }
    return g;
  }

  std::optional<Joint> ReadJoint(const XMLElement* e) {
    Joint joint;
    const char* name = e->Attribute("name");
    const XMLElement* parent = e->FirstChildElement("parent");
    const XMLElement* child = e->FirstChildElement("child");
    const char* parent_link = parent != nullptr ? parent->Attribute("link") : nullptr;
    const char* child_link = child != nullptr ? child->Attribute("link") : nullptr;
    if (name == nullptr || parent_link == nullptr || child_link == nullptr) return std::nullopt;
    joint.name = name;
    joint.parent = parent_link;
    joint.child = child_link;
    joint.location = Loc(e);
    if (const char* type = e->Attribute("type")) joint.type_name = type;
    static const std::pair<const char*, Joint::Type> kTypes[] = {
        {"revolute", Joint::Type::kRevolute},   {"continuous", Joint::Type::kContinuous},
        {"prismatic", Joint::Type::kPrismatic}, {"fixed", Joint::Type::kFixed},
        {"floating", Joint::Type::kFloating},   {"planar", Joint::Type::kPlanar},
        {"ball", Joint::Type::kBall},           {"universal", Joint::Type::kUniversal},
        {"screw", Joint::Type::kScrew}};
    for (const auto& [type_name, type] : kTypes) {
      if (joint.type_name == type_name) joint.type = type;
    }
    std::string what;
    const XMLElement* origin = e->FirstChildElement("origin");
    if (const std::optional<Pose> X = ReadOrigin(origin, &what)) {
      joint.X_PC = *X;
    } else {
      result_->warnings.push_back(
          ReadError{Loc(origin), "<origin> of joint '" + joint.name + "'",
                    "cannot read " + what +
                        "; the joint is taken at the identity pose, so "
                        "composite inertias across it are not what the author meant"});
    }
    const XMLElement* axis = e->FirstChildElement("axis");
    const char* xyz = axis != nullptr ? axis->Attribute("xyz") : nullptr;
    if (xyz != nullptr && joint.type != Joint::Type::kFixed &&
        joint.type != Joint::Type::kFloating) {
      const std::optional<Eigen::Vector3d> v = LenientVector(xyz);
      if (!v) {
        result_->warnings.push_back(
            ReadError{Loc(axis), "<axis> of joint '" + joint.name + "'",
                      "cannot read xyz=" + Quote(xyz) + "; the URDF default (1, 0, 0) is used"});
      } else if (v->norm() > 0) {
        joint.axis = *v / v->norm();
      } else {
        joint.axis = *v;
        result_->warnings.push_back(
            ReadError{Loc(axis), "<axis> of joint '" + joint.name + "'", "the axis is zero"});
      }
    }
    return joint;
  }

  const std::string& file_;
  ReadResult* result_;
};

ReadResult Reader::Read(const std::string& xml) {
  if (xml.size() > kMaxUrdfFileBytes) {
    Error(0, "file", "the input is larger than the limit of 256 MiB");
    return std::move(result_);
  }
  if (const void* nul = std::memchr(xml.data(), '\0', xml.size())) {
    const std::size_t offset = static_cast<std::size_t>(static_cast<const char*>(nul) - xml.data());
    Error(1 + static_cast<int>(std::count(xml.data(), xml.data() + offset, '\n')), "file",
          "contains a NUL byte at offset " + std::to_string(offset) +
              ": this is not a text (XML) file");
    return std::move(result_);
  }
  {
    // The index is built and the DOM freed before urdfdom builds its own, to keep the peak low.
    XMLDocument doc(/*processEntities=*/true, tinyxml2::PRESERVE_WHITESPACE);
    if (!ParseDom(xml, &doc)) return std::move(result_);
    const XMLElement* robot = doc.FirstChildElement("robot");
    if (robot == nullptr) {
      const XMLElement* root = doc.RootElement();
      Error(LineOf(root), "document",
            root != nullptr ? std::string("the root element is <") + root->Name() +
                                  ">, not <robot>: this is not a URDF file"
                            : std::string("no <robot> element: this is not a URDF file"));
      return std::move(result_);
    }
    BuildIndex(robot);
  }

  std::vector<std::string> errors;
  const urdf::ModelInterfaceSharedPtr urdf = ParseWithUrdfdom(xml, &errors);
  WarnAboutTextUrdfdomSkips();
  if (urdf) {
    result_.models.push_back(FromUrdfdom(*urdf, errors, xml));
    ReleaseUrdfdomModel(urdf);
    return std::move(result_);
  }
  ReportNotLoadable(errors);
  XMLDocument doc(/*processEntities=*/true, tinyxml2::PRESERVE_WHITESPACE);
  if (!ParseDom(xml, &doc)) return std::move(result_);
  result_.models.push_back(LenientReader(file_, &result_).Read(doc.FirstChildElement("robot")));
  return std::move(result_);
}

}  // namespace

ReadResult ReadUrdfString(const std::string& xml, const std::string& file_name) {
  return Reader(file_name).Read(xml);
}

ReadResult ReadUrdfFile(const std::string& path) {
  std::string contents;
  if (std::optional<ReadError> error = ReadInputFile(path, kMaxUrdfFileBytes, &contents)) {
    ReadResult result;
    result.errors.push_back(std::move(*error));
    return result;
  }
  return ReadUrdfString(contents, path == "-" ? "<stdin>" : path);
}

}  // namespace massprops
