// The URDF reader's lenient reading (reader.h): for files urdfdom refuses, the links, inertials,
// geometries and joints read as written, with the findings of what cannot be read.
#include "io/urdf/reader.h"

namespace massprops::internal::urdf_reader {

namespace {

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
  SourceLocation Loc(const XMLNode* node) const { return PlaceOf(file_, node); }

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
      Eigen::Vector3d scale = g.scale;  // as if not written
      if (const char* text = shape->Attribute("scale")) {
        const std::optional<Eigen::Vector3d> written = LenientVector(text);
        if (!written) return std::nullopt;
        scale = *written;
      }
      SetMeshReference(filename, scale, &g);
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

}  // namespace

Model ReadLeniently(const std::string& file, const XMLElement* robot, ReadResult* result) {
  return LenientReader(file, result).Read(robot);
}

}  // namespace massprops::internal::urdf_reader
