#include "massprops/urdf_reader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "massprops/model_reader.h"

// One tinyxml2 pass that builds the same model as urdfdom 3.0 (urdf_parser/src/{model,link,joint,
// pose}.cpp and urdf_model/{pose,model,utils}.h): the same elements are read (the first <inertial>,
// <origin>, <mass>, <inertia>, <geometry> shape, <limit>, ... of their parent), with the same
// number grammar and the same rejections, plus the source line of each element.

namespace massprops {
namespace {

using tinyxml2::XMLComment;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

bool StartsWithNoCase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    char c = text[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != prefix[i]) return false;
  }
  return true;
}

// The text quoted in messages: at most 60 characters, control characters made visible.
std::string Quote(std::string_view text) {
  std::string out = "\"";
  const std::size_t shown = text.size() > 60 ? 60 : text.size();
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

// R = Rz(yaw) * Ry(pitch) * Rx(roll): the rotation urdf::Rotation::setFromRPY stands for (fixed
// axes x, y, z; hand-expanded product of the three elementary rotations).
Eigen::Matrix3d RotationFromRpy(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll), sr = std::sin(roll);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  Eigen::Matrix3d R;
  R << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  return R;
}

// Names the element an error is about, e.g. "<inertia> of link 'arm'" or
// "<box> of <collision> #2 of link 'arm'". Built only when a message is needed.
struct Where {
  const char* element;            // "inertia"
  const char* owner_kind;         // "link", "joint", "robot" or nullptr
  const std::string* owner_name;  // may be nullptr
  const char* middle = nullptr;   // "collision" / "visual" or nullptr
  int middle_index = 0;           // 1-based ordinal of the middle element

  std::string ToString() const {
    std::string text = std::string("<") + element + ">";
    if (middle != nullptr) {
      text += std::string(" of <") + middle + ">";
      if (middle_index > 0) text += " #" + std::to_string(middle_index);
    }
    if (owner_kind != nullptr) {
      text += std::string(" of ") + owner_kind;
      if (owner_name != nullptr) text += " '" + *owner_name + "'";
    }
    return text;
  }
};

class UrdfParser {
 public:
  explicit UrdfParser(const std::string& file_name) : file_(file_name) {}

  ReadResult Parse(const std::string& xml);

 private:
  SourceLocation Loc(const XMLNode* node) const {
    return SourceLocation{file_, node != nullptr ? node->GetLineNum() : 0, 0};
  }
  void Error(const XMLNode* node, std::string element, std::string message) {
    result_.errors.push_back(ReadError{Loc(node), std::move(element), std::move(message)});
  }
  void Warning(const XMLNode* node, std::string element, std::string message) {
    result_.warnings.push_back(ReadError{Loc(node), std::move(element), std::move(message)});
  }

  bool Number(const XMLElement* e, const char* attribute, const Where& where, bool required,
              double* value);
  bool Vector3(const XMLElement* e, const char* attribute, const Where& where,
               Eigen::Vector3d* value);
  bool Origin(const XMLElement* e, const Where& where, Pose* pose);
  bool ParseInertial(const XMLElement* e, const std::string& link, Inertial* inertial);
  bool ParseGeometryHolder(const XMLElement* e, const std::string& link, bool is_collision,
                           int index, Geometry* geometry);
  bool ParseLink(const XMLElement* e, Link* link);
  bool ParseJoint(const XMLElement* e, Joint* joint);
  bool CheckJointExtras(const XMLElement* e, const Joint& joint);
  void CollectIgnoreComments(const XMLNode* node, Link* link);
  void ParseMaterials(const XMLElement* robot);
  bool CheckVersion(const XMLElement* robot);
  bool BuildTree(Model* model, const std::vector<const XMLElement*>& link_xml,
                 const std::vector<const XMLElement*>& joint_xml);

  std::string file_;
  ReadResult result_;
  std::unordered_set<std::string> material_names_;
};

bool UrdfParser::Number(const XMLElement* e, const char* attribute, const Where& where,
                        bool required, double* value) {
  const char* text = e->Attribute(attribute);
  if (text == nullptr) {
    if (required) {
      Error(e, where.ToString(), std::string("missing required attribute '") + attribute + "'");
    }
    return !required;
  }
  switch (ParseUrdfNumber(text, value)) {
    case UrdfNumberStatus::kOk:
      return true;
    case UrdfNumberStatus::kNotANumber:
      Error(e, where.ToString(),
            std::string("attribute '") + attribute + "' = " + Quote(text) + " is not a number");
      return false;
    case UrdfNumberStatus::kNotFinite:
      Error(e, where.ToString(),
            std::string("attribute '") + attribute + "' = " + Quote(text) +
                " is not a finite number (NaN and infinity are not allowed)");
      return false;
    case UrdfNumberStatus::kOutOfRange:
      Error(e, where.ToString(),
            std::string("attribute '") + attribute + "' = " + Quote(text) +
                " is out of the range of a double");
      return false;
  }
  return false;
}

// urdf::Vector3::init: split on ' ' only, skip empty pieces, each piece a number, exactly three.
bool UrdfParser::Vector3(const XMLElement* e, const char* attribute, const Where& where,
                         Eigen::Vector3d* value) {
  const char* text = e->Attribute(attribute);
  if (text == nullptr) return true;
  const std::string_view all(text);
  double numbers[3];
  int count = 0;
  std::size_t start = 0;
  while (start <= all.size()) {
    std::size_t end = all.find(' ', start);
    if (end == std::string_view::npos) end = all.size();
    const std::string_view piece = all.substr(start, end - start);
    if (!piece.empty()) {
      double number = 0;
      const UrdfNumberStatus status = ParseUrdfNumber(piece, &number);
      if (status != UrdfNumberStatus::kOk) {
        std::string why = status == UrdfNumberStatus::kNotFinite ? "is not a finite number"
                          : status == UrdfNumberStatus::kOutOfRange
                              ? "is out of the range of a double"
                              : "is not a number";
        if (piece.find_first_of("\t\n\r") != std::string_view::npos) {
          why += " (numbers must be separated by spaces, not tabs or line breaks)";
        }
        Error(e, where.ToString(),
              std::string("attribute '") + attribute + "' = " + Quote(all) + ": component " +
                  Quote(piece) + " " + why);
        return false;
      }
      if (count < 3) numbers[count] = number;
      ++count;
    }
    start = end + 1;
  }
  if (count != 3) {
    Error(e, where.ToString(),
          std::string("attribute '") + attribute + "' = " + Quote(all) + " has " +
              std::to_string(count) + " numbers, 3 expected");
    return false;
  }
  *value = Eigen::Vector3d(numbers[0], numbers[1], numbers[2]);
  return true;
}

bool UrdfParser::Origin(const XMLElement* e, const Where& where, Pose* pose) {
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  // Both attributes are read, so that both are reported when both are wrong.
  const bool xyz_ok = Vector3(e, "xyz", where, &xyz);
  const bool rpy_ok = Vector3(e, "rpy", where, &rpy);
  if (!xyz_ok || !rpy_ok) return false;
  pose->p_AB = xyz;
  pose->R_AB = e->Attribute("rpy") != nullptr ? RotationFromRpy(rpy.x(), rpy.y(), rpy.z())
                                              : Eigen::Matrix3d::Identity();
  return true;
}

bool UrdfParser::ParseInertial(const XMLElement* e, const std::string& link, Inertial* inertial) {
  inertial->location = Loc(e);
  bool ok = true;
  if (const XMLElement* origin = e->FirstChildElement("origin")) {
    inertial->pose_location = Loc(origin);
    ok &= Origin(origin, Where{"origin", "link", &link, "inertial", 0}, &inertial->X_BBi);
  }
  const XMLElement* mass = e->FirstChildElement("mass");
  if (mass == nullptr) {
    Error(e, Where{"inertial", "link", &link}.ToString(), "missing required element <mass>");
    ok = false;
  } else {
    inertial->mass_location = Loc(mass);
    ok &= Number(mass, "value", Where{"mass", "link", &link}, true, &inertial->mass);
  }
  const XMLElement* inertia = e->FirstChildElement("inertia");
  if (inertia == nullptr) {
    Error(e, Where{"inertial", "link", &link}.ToString(), "missing required element <inertia>");
    ok = false;
  } else {
    inertial->inertia_location = Loc(inertia);
    const Where where{"inertia", "link", &link};
    ok &= Number(inertia, "ixx", where, true, &inertial->ixx);
    ok &= Number(inertia, "ixy", where, true, &inertial->ixy);
    ok &= Number(inertia, "ixz", where, true, &inertial->ixz);
    ok &= Number(inertia, "iyy", where, true, &inertial->iyy);
    ok &= Number(inertia, "iyz", where, true, &inertial->iyz);
    ok &= Number(inertia, "izz", where, true, &inertial->izz);
  }
  if (e->NextSiblingElement("inertial") != nullptr) {
    Warning(e->NextSiblingElement("inertial"), Where{"inertial", "link", &link}.ToString(),
            "a second <inertial> is ignored (URDF reads only the first)");
  }
  return ok;
}

// A <visual> or <collision>: its <origin>, its <geometry> (the first child element is the shape).
bool UrdfParser::ParseGeometryHolder(const XMLElement* e, const std::string& link,
                                     bool is_collision, int index, Geometry* geometry) {
  const char* holder = is_collision ? "collision" : "visual";
  geometry->is_collision = is_collision;
  geometry->location = Loc(e);
  bool ok = true;
  if (const XMLElement* origin = e->FirstChildElement("origin")) {
    ok &= Origin(origin, Where{"origin", "link", &link, holder, index}, &geometry->X_BG);
  }
  const XMLElement* geometry_xml = e->FirstChildElement("geometry");
  const XMLElement* shape = geometry_xml != nullptr ? geometry_xml->FirstChildElement() : nullptr;
  if (geometry_xml == nullptr) {
    Error(e, std::string("<") + holder + "> #" + std::to_string(index) + " of link '" + link + "'",
          "missing required element <geometry>");
    return false;
  }
  if (shape == nullptr) {
    Error(geometry_xml, Where{"geometry", "link", &link, holder, index}.ToString(),
          "<geometry> has no shape element (box, cylinder, sphere, mesh or capsule)");
    return false;
  }
  const char* type = shape->Name();
  const Where where{type, "link", &link, holder, index};
  if (std::strcmp(type, "box") == 0) {
    geometry->type = Geometry::Type::kBox;
    if (shape->Attribute("size") == nullptr) {
      Error(shape, where.ToString(), "missing required attribute 'size'");
      return false;
    }
    ok &= Vector3(shape, "size", where, &geometry->size);
  } else if (std::strcmp(type, "cylinder") == 0 || std::strcmp(type, "capsule") == 0) {
    geometry->type = type[1] == 'y' ? Geometry::Type::kCylinder : Geometry::Type::kCapsule;
    ok &= Number(shape, "length", where, true, &geometry->length);
    ok &= Number(shape, "radius", where, true, &geometry->radius);
  } else if (std::strcmp(type, "sphere") == 0) {
    geometry->type = Geometry::Type::kSphere;
    ok &= Number(shape, "radius", where, true, &geometry->radius);
  } else if (std::strcmp(type, "mesh") == 0) {
    geometry->type = Geometry::Type::kMesh;
    const char* filename = shape->Attribute("filename");
    if (filename == nullptr) {
      Error(shape, where.ToString(), "missing required attribute 'filename'");
      return false;
    }
    geometry->uri = filename;
    if (!Vector3(shape, "scale", where, &geometry->scale)) {
      // A mesh's scale changes no inertial number: urdfdom logs it and drops the element; we keep
      // reading the model and say so (the mesh keeps scale 1).
      ReadError error = std::move(result_.errors.back());
      result_.errors.pop_back();
      error.message += " (urdfdom drops this element; massprops reads the mesh with scale 1)";
      result_.warnings.push_back(std::move(error));
      geometry->scale = Eigen::Vector3d::Ones();
    }
  } else {
    Error(shape, where.ToString(),
          std::string("unknown geometry type <") + type +
              "> (URDF knows box, cylinder, sphere and mesh; massprops also reads capsule)");
    return false;
  }
  if (!is_collision) {
    if (const XMLElement* material = e->FirstChildElement("material")) {
      const char* name = material->Attribute("name");
      if (name == nullptr) {
        // No inertial number depends on a material: a warning (urdfdom logs an error and drops
        // the <visual>), and the model is still checked.
        Warning(material, Where{"material", "link", &link, holder, index}.ToString(),
                "missing required attribute 'name' (urdfdom drops this <visual>)");
      } else if (material->FirstChildElement("color") == nullptr &&
                 material->FirstChildElement("texture") == nullptr &&
                 material_names_.count(name) == 0) {
        Warning(material, Where{"material", "link", &link, holder, index}.ToString(),
                std::string("material '") + name + "' is not defined");
      }
    }
  }
  return ok;
}

// `<!-- massprops: ignore rule-id [rule-id...] -->` anywhere inside the link.
void UrdfParser::CollectIgnoreComments(const XMLNode* node, Link* link) {
  for (const XMLNode* child = node->FirstChild(); child != nullptr; child = child->NextSibling()) {
    if (const XMLComment* comment = child->ToComment()) {
      std::string_view text(comment->Value());
      std::size_t i = 0;
      while (i < text.size() && IsSpace(text[i])) ++i;
      text.remove_prefix(i);
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
      if (words.empty() || words[0] != "ignore" || words.size() == 1) {
        Warning(comment, "comment in link '" + link->name + "'",
                "a massprops comment must read 'massprops: ignore rule-id [rule-id...]'; "
                "this one is ignored");
        continue;
      }
      for (std::size_t w = 1; w < words.size(); ++w) {
        link->ignored_rules.push_back(std::move(words[w]));
      }
    } else if (child->ToElement() != nullptr) {
      CollectIgnoreComments(child, link);
    }
  }
}

bool UrdfParser::ParseLink(const XMLElement* e, Link* link) {
  link->location = Loc(e);
  const char* name = e->Attribute("name");
  if (name == nullptr) {
    Error(e, "<link>", "missing required attribute 'name'");
    return false;
  }
  link->name = name;
  bool ok = true;
  if (const XMLElement* inertial = e->FirstChildElement("inertial")) {
    link->inertial.emplace();
    ok &= ParseInertial(inertial, link->name, &*link->inertial);
  }
  // Visuals and collisions, each group in file order (as urdfdom's visual_array and
  // collision_array); Link::geometries keeps them in file order across both.
  int visuals = 0, collisions = 0;
  for (const XMLElement* child = e->FirstChildElement(); child != nullptr;
       child = child->NextSiblingElement()) {
    const char* tag = child->Name();
    const bool is_visual = std::strcmp(tag, "visual") == 0;
    if (!is_visual && std::strcmp(tag, "collision") != 0) continue;
    Geometry geometry;
    ok &= ParseGeometryHolder(child, link->name, !is_visual, is_visual ? ++visuals : ++collisions,
                              &geometry);
    link->geometries.push_back(std::move(geometry));
  }
  CollectIgnoreComments(e, link);
  return ok;
}

bool UrdfParser::CheckJointExtras(const XMLElement* e, const Joint& joint) {
  bool ok = true;
  double ignored = 0;
  if (const XMLElement* limit = e->FirstChildElement("limit")) {
    const Where where{"limit", "joint", &joint.name};
    ok &= Number(limit, "lower", where, false, &ignored);
    ok &= Number(limit, "upper", where, false, &ignored);
    ok &= Number(limit, "effort", where, true, &ignored);
    ok &= Number(limit, "velocity", where, true, &ignored);
  } else if (joint.type == Joint::Type::kRevolute || joint.type == Joint::Type::kPrismatic) {
    Error(e, Where{"joint", nullptr, nullptr}.ToString() + " '" + joint.name + "'",
          "a " + joint.type_name + " joint needs a <limit> element");
    ok = false;
  }
  if (const XMLElement* safety = e->FirstChildElement("safety_controller")) {
    const Where where{"safety_controller", "joint", &joint.name};
    ok &= Number(safety, "soft_lower_limit", where, false, &ignored);
    ok &= Number(safety, "soft_upper_limit", where, false, &ignored);
    ok &= Number(safety, "k_position", where, false, &ignored);
    ok &= Number(safety, "k_velocity", where, true, &ignored);
  }
  if (const XMLElement* calibration = e->FirstChildElement("calibration")) {
    const Where where{"calibration", "joint", &joint.name};
    ok &= Number(calibration, "rising", where, false, &ignored);
    ok &= Number(calibration, "falling", where, false, &ignored);
  }
  if (const XMLElement* mimic = e->FirstChildElement("mimic")) {
    const Where where{"mimic", "joint", &joint.name};
    if (mimic->Attribute("joint") == nullptr) {
      Error(mimic, where.ToString(), "missing required attribute 'joint'");
      ok = false;
    }
    ok &= Number(mimic, "multiplier", where, false, &ignored);
    ok &= Number(mimic, "offset", where, false, &ignored);
  }
  if (const XMLElement* dynamics = e->FirstChildElement("dynamics")) {
    const Where where{"dynamics", "joint", &joint.name};
    if (dynamics->Attribute("damping") == nullptr && dynamics->Attribute("friction") == nullptr) {
      Error(dynamics, where.ToString(), "needs a 'damping' or a 'friction' attribute");
      ok = false;
    }
    ok &= Number(dynamics, "damping", where, false, &ignored);
    ok &= Number(dynamics, "friction", where, false, &ignored);
  }
  return ok;
}

bool UrdfParser::ParseJoint(const XMLElement* e, Joint* joint) {
  joint->location = Loc(e);
  const char* name = e->Attribute("name");
  if (name == nullptr) {
    Error(e, "<joint>", "missing required attribute 'name'");
    return false;
  }
  joint->name = name;
  const std::string self = "<joint> '" + joint->name + "'";
  bool ok = true;
  if (const XMLElement* origin = e->FirstChildElement("origin")) {
    ok &= Origin(origin, Where{"origin", "joint", &joint->name}, &joint->X_PC);
  }
  if (const XMLElement* parent = e->FirstChildElement("parent")) {
    if (const char* link = parent->Attribute("link")) joint->parent = link;
  }
  if (const XMLElement* child = e->FirstChildElement("child")) {
    if (const char* link = child->Attribute("link")) joint->child = link;
  }
  const char* type = e->Attribute("type");
  if (type == nullptr) {
    Error(e, self, "missing required attribute 'type'");
    return false;
  }
  joint->type_name = type;
  static const std::pair<const char*, Joint::Type> kTypes[] = {
      {"revolute", Joint::Type::kRevolute},   {"continuous", Joint::Type::kContinuous},
      {"prismatic", Joint::Type::kPrismatic}, {"fixed", Joint::Type::kFixed},
      {"floating", Joint::Type::kFloating},   {"planar", Joint::Type::kPlanar}};
  bool known = false;
  for (const auto& [type_name, type_value] : kTypes) {
    if (std::strcmp(type, type_name) == 0) {
      joint->type = type_value;
      known = true;
    }
  }
  if (!known) {
    Error(e, self,
          "unknown joint type " + Quote(type) +
              " (URDF knows revolute, continuous, prismatic, fixed, floating and planar)");
    return false;
  }
  if (joint->type != Joint::Type::kFixed && joint->type != Joint::Type::kFloating) {
    if (const XMLElement* axis = e->FirstChildElement("axis")) {
      if (axis->Attribute("xyz") == nullptr) {
        Warning(axis, Where{"axis", "joint", &joint->name}.ToString(),
                "no 'xyz' attribute; the URDF default (1, 0, 0) is used");
      } else {
        Eigen::Vector3d xyz;
        if (Vector3(axis, "xyz", Where{"axis", "joint", &joint->name}, &xyz)) {
          const double norm = xyz.norm();
          if (norm > 0) {
            joint->axis = xyz / norm;
          } else {
            joint->axis = xyz;
            Warning(axis, Where{"axis", "joint", &joint->name}.ToString(), "the axis is zero");
          }
        } else {
          ok = false;
        }
      }
    }
  }
  ok &= CheckJointExtras(e, *joint);
  return ok;
}

void UrdfParser::ParseMaterials(const XMLElement* robot) {
  for (const XMLElement* material = robot->FirstChildElement("material"); material != nullptr;
       material = material->NextSiblingElement("material")) {
    const char* name = material->Attribute("name");
    if (name == nullptr) {
      Warning(material, "<material>", "missing attribute 'name'");
    }
    const std::string key = name != nullptr ? name : "";
    if (!material_names_.insert(key).second) {
      Error(material, "<material> '" + key + "'", "a material of that name is already defined");
    }
    const XMLElement* color = material->FirstChildElement("color");
    const XMLElement* texture = material->FirstChildElement("texture");
    const bool has_rgba = color != nullptr && color->Attribute("rgba") != nullptr;
    const bool has_texture = texture != nullptr && texture->Attribute("filename") != nullptr;
    if (!has_rgba && !has_texture) {
      Warning(material, "<material> '" + key + "'", "has neither a color rgba nor a texture");
    }
  }
}

// urdf_export_helpers::URDFVersion: absent, or "<major>.<minor>" equal to 1.0.
bool UrdfParser::CheckVersion(const XMLElement* robot) {
  const char* version = robot->Attribute("version");
  if (version == nullptr) return true;
  const std::string text(version);
  const std::size_t dot = text.find('.');
  bool ok = dot != std::string::npos && text.find('.', dot + 1) == std::string::npos &&
            dot + 1 < text.size();
  long parts[2] = {-1, -1};
  if (ok) {
    const std::string pieces[2] = {text.substr(0, dot), text.substr(dot + 1)};
    for (int i = 0; i < 2 && ok; ++i) {
      char* end = nullptr;
      parts[i] = std::strtol(pieces[i].c_str(), &end, 10);
      ok = !pieces[i].empty() && end != pieces[i].c_str() && *end == '\0';
    }
  }
  if (ok && parts[0] == 1 && parts[1] == 0) return true;
  Error(robot, "<robot>",
        "attribute 'version' = " + Quote(text) + ": only URDF version 1.0 is supported");
  return false;
}

bool UrdfParser::BuildTree(Model* model, const std::vector<const XMLElement*>& link_xml,
                           const std::vector<const XMLElement*>& joint_xml) {
  const std::size_t n = model->links.size();
  std::unordered_map<std::string, int> link_index;
  link_index.reserve(n * 2);
  for (std::size_t i = 0; i < n; ++i) {
    link_index.emplace(model->links[i].name, static_cast<int>(i));
  }
  std::vector<int> parent(n, -1);        // parent link of each link
  std::vector<int> parent_joint(n, -1);  // the joint that made it so
  bool ok = true;
  for (std::size_t j = 0; j < model->joints.size(); ++j) {
    const Joint& joint = model->joints[j];
    const std::string self = "<joint> '" + joint.name + "'";
    if (joint.parent.empty() || joint.child.empty()) {
      Error(joint_xml[j], self,
            std::string("missing ") + (joint.parent.empty() ? "<parent link=...>" : "") +
                (joint.parent.empty() && joint.child.empty() ? " and " : "") +
                (joint.child.empty() ? "<child link=...>" : ""));
      ok = false;
      continue;
    }
    const auto child = link_index.find(joint.child);
    const auto parent_link = link_index.find(joint.parent);
    if (child == link_index.end()) {
      Error(joint_xml[j], self, "child link '" + joint.child + "' is not defined");
      ok = false;
    }
    if (parent_link == link_index.end()) {
      Error(joint_xml[j], self, "parent link '" + joint.parent + "' is not defined");
      ok = false;
    }
    if (child == link_index.end() || parent_link == link_index.end()) continue;
    if (child->second == parent_link->second) {
      Error(joint_xml[j], self, "joins link '" + joint.child + "' to itself");
      ok = false;
      continue;
    }
    if (parent[child->second] >= 0) {
      Error(joint_xml[j], self,
            "link '" + joint.child + "' is already the child of joint '" +
                model->joints[parent_joint[child->second]].name + "' (line " +
                std::to_string(joint_xml[parent_joint[child->second]]->GetLineNum()) +
                "); a link has at most one parent joint");
      ok = false;
      continue;
    }
    parent[child->second] = parent_link->second;
    parent_joint[child->second] = static_cast<int>(j);
  }
  if (!ok) return false;

  std::vector<int> roots;
  for (std::size_t i = 0; i < n; ++i) {
    if (parent[i] < 0) roots.push_back(static_cast<int>(i));
  }
  if (roots.size() > 1) {
    std::string names;
    for (std::size_t r = 0; r < roots.size() && r < 10; ++r) {
      names += (r > 0 ? ", '" : "'") + model->links[roots[r]].name + "' (line " +
               std::to_string(link_xml[roots[r]]->GetLineNum()) + ")";
    }
    if (roots.size() > 10) names += ", ...";
    Error(link_xml[roots[1]], "<robot> '" + model->name + "'",
          std::to_string(roots.size()) + " root links (links that are no joint's child): " + names +
              "; a URDF has exactly one");
    return false;
  }
  // Every link must reach the root by following parents; a walk that meets itself is a loop.
  // state: 0 = not seen, 1 = on the current walk, 2 = reaches the root.
  std::vector<char> state(n, 0);
  if (!roots.empty()) state[roots[0]] = 2;
  for (std::size_t start = 0; start < n; ++start) {
    int i = static_cast<int>(start);
    while (state[i] == 0) {
      state[i] = 1;
      i = parent[i];
    }
    if (state[i] == 1) {
      // i is on a loop: list it.
      std::string names = "'" + model->links[i].name + "'";
      for (int k = parent[i]; k != i; k = parent[k]) names += " -> '" + model->links[k].name + "'";
      names += " -> '" + model->links[i].name + "'";
      Error(joint_xml[parent_joint[i]], "<joint> '" + model->joints[parent_joint[i]].name + "'",
            "the joints form a kinematic loop (child -> parent): " + names);
      return false;
    }
    for (int k = static_cast<int>(start); state[k] == 1; k = parent[k]) state[k] = 2;
  }
  if (roots.empty()) {  // Unreachable: no root means every walk ends in a loop, reported above.
    Error(link_xml.empty() ? nullptr : link_xml[0], "<robot>", "no root link");
    return false;
  }
  model->root_link = model->links[roots[0]].name;
  return true;
}

ReadResult UrdfParser::Parse(const std::string& xml) {
  if (xml.size() > kMaxUrdfFileBytes) {
    Error(nullptr, "file", "the input is larger than the limit of 256 MiB");
    return std::move(result_);
  }
  if (const void* nul = std::memchr(xml.data(), '\0', xml.size())) {
    const std::size_t offset = static_cast<const char*>(nul) - xml.data();
    ReadError error;
    error.location = SourceLocation{
        file_, 1 + static_cast<int>(std::count(xml.data(), xml.data() + offset, '\n')), 0};
    error.element = "file";
    error.message = "contains a NUL byte at offset " + std::to_string(offset) +
                    ": this is not a text (XML) file";
    result_.errors.push_back(std::move(error));
    return std::move(result_);
  }
  XMLDocument doc(/*processEntities=*/true, tinyxml2::PRESERVE_WHITESPACE);
  doc.Parse(xml.data(), xml.size());
  if (doc.Error()) {
    ReadError error;
    error.location = SourceLocation{file_, doc.ErrorLineNum(), 0};
    error.element = "XML";
    error.message = xml.find_first_not_of(" \t\r\n") == std::string::npos
                        ? std::string("the file is empty")
                        : std::string("malformed XML: ") + doc.ErrorStr();
    result_.errors.push_back(std::move(error));
    return std::move(result_);
  }
  const XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) {
    const XMLElement* root = doc.RootElement();
    Error(root, "document",
          root != nullptr ? std::string("the root element is <") + root->Name() +
                                ">, not <robot>: this is not a URDF file"
                          : std::string("no <robot> element: this is not a URDF file"));
    return std::move(result_);
  }
  Model model;
  model.format = Model::Format::kUrdf;
  model.file = file_;
  model.location = Loc(robot);
  bool ok = true;
  if (const char* name = robot->Attribute("name")) {
    model.name = name;
  } else {
    Error(robot, "<robot>", "missing required attribute 'name'");
    ok = false;
  }
  ok &= CheckVersion(robot);
  ParseMaterials(robot);

  std::vector<const XMLElement*> link_xml;
  std::unordered_map<std::string, int> link_lines;
  for (const XMLElement* e = robot->FirstChildElement("link"); e != nullptr;
       e = e->NextSiblingElement("link")) {
    Link link;
    if (!ParseLink(e, &link)) {
      ok = false;
      if (link.name.empty()) continue;
    }
    const auto [it, inserted] = link_lines.emplace(link.name, e->GetLineNum());
    if (!inserted) {
      Error(e, "<link> '" + link.name + "'",
            "a link of that name is already defined at line " + std::to_string(it->second));
      ok = false;
      continue;
    }
    link_xml.push_back(e);
    model.links.push_back(std::move(link));
  }
  if (model.links.empty() && ok) {
    Error(robot, "<robot> '" + model.name + "'", "has no <link> elements");
    ok = false;
  }

  std::vector<const XMLElement*> joint_xml;
  std::unordered_map<std::string, int> joint_lines;
  for (const XMLElement* e = robot->FirstChildElement("joint"); e != nullptr;
       e = e->NextSiblingElement("joint")) {
    Joint joint;
    if (!ParseJoint(e, &joint)) {
      ok = false;
      if (joint.name.empty()) continue;
    }
    const auto [it, inserted] = joint_lines.emplace(joint.name, e->GetLineNum());
    if (!inserted) {
      Error(e, "<joint> '" + joint.name + "'",
            "a joint of that name is already defined at line " + std::to_string(it->second));
      ok = false;
      continue;
    }
    joint_xml.push_back(e);
    model.joints.push_back(std::move(joint));
  }
  if (ok) ok = BuildTree(&model, link_xml, joint_xml);
  if (ok && result_.errors.empty()) result_.models.push_back(std::move(model));
  return std::move(result_);
}

}  // namespace

UrdfNumberStatus ParseUrdfNumber(std::string_view text, double* value) {
  std::size_t i = 0;
  while (i < text.size() && IsSpace(text[i])) ++i;
  std::size_t begin = i;  // where std::from_chars starts (it takes '-', not '+')
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    negative = text[i] == '-';
    ++i;
    if (!negative) begin = i;
  }
  if (StartsWithNoCase(text.substr(i), "nan") || StartsWithNoCase(text.substr(i), "inf")) {
    return UrdfNumberStatus::kNotFinite;
  }
  // digits [. digits] [(e|E) [+|-] digits], at least one mantissa digit, nothing after.
  int leading_exponent = 0;  // decimal exponent of the first non-zero digit, roughly
  bool seen_nonzero = false;
  int mantissa_digits = 0;
  int integer_digits_after_first_nonzero = 0;
  int fraction_zeros_before_first_nonzero = 0;
  while (i < text.size() && IsDigit(text[i])) {
    if (text[i] != '0') seen_nonzero = true;
    if (seen_nonzero) ++integer_digits_after_first_nonzero;
    ++mantissa_digits;
    ++i;
  }
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && IsDigit(text[i])) {
      if (text[i] != '0') seen_nonzero = true;
      if (!seen_nonzero) ++fraction_zeros_before_first_nonzero;
      ++mantissa_digits;
      ++i;
    }
  }
  if (mantissa_digits == 0) return UrdfNumberStatus::kNotANumber;
  long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool exponent_negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
      exponent_negative = text[i] == '-';
      ++i;
    }
    if (i >= text.size() || !IsDigit(text[i])) return UrdfNumberStatus::kNotANumber;
    while (i < text.size() && IsDigit(text[i])) {
      if (exponent < 100000000) exponent = exponent * 10 + (text[i] - '0');
      ++i;
    }
    if (exponent_negative) exponent = -exponent;
  }
  if (i != text.size()) return UrdfNumberStatus::kNotANumber;

  double parsed = 0;
  const char* first = text.data() + begin;
  const char* last = text.data() + text.size();
  const std::from_chars_result r = std::from_chars(first, last, parsed);
  if (r.ec == std::errc::result_out_of_range) {
    // Overflow or underflow: they lie hundreds of decades apart, so a rough exponent decides.
    leading_exponent = integer_digits_after_first_nonzero > 0
                           ? integer_digits_after_first_nonzero - 1
                           : -(fraction_zeros_before_first_nonzero + 1);
    if (static_cast<long>(leading_exponent) + exponent < 0) {
      *value = negative ? -0.0 : 0.0;  // below the smallest subnormal: rounds to zero
      return UrdfNumberStatus::kOk;
    }
    return UrdfNumberStatus::kOutOfRange;
  }
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(parsed)) {
    return UrdfNumberStatus::kNotANumber;
  }
  *value = parsed;
  return UrdfNumberStatus::kOk;
}

ReadResult ReadUrdfString(const std::string& xml, const std::string& file_name) {
  return UrdfParser(file_name).Parse(xml);
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
