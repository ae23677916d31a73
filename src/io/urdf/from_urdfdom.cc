// The URDF reader's Model from urdfdom's model (reader.h): links, joints and geometries with the
// index's lines, the inertials urdfdom cannot read, underflows, and the parents urdfdom keeps.
#include "io/urdf/reader.h"

namespace massprops::internal::urdf_reader {

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
      SetMeshReference(m.filename, Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z), &out);
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

}  // namespace massprops::internal::urdf_reader
