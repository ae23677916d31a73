#include "massprops/output/merge_fixed.h"

#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "massprops/analysis/target_profile.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/io/model_reader.h"
#include "merge_fixed_sdf.h"

namespace massprops {
namespace {

std::string Number(double value) {
  if (value == 0) value = 0;  // no "-0"
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", std::numeric_limits<double>::max_digits10, value);
  return buffer;
}

std::string Triple(const Eigen::Vector3d& v) {
  return Number(v(0)) + " " + Number(v(1)) + " " + Number(v(2));
}

// Three numbers of an attribute ("0 0 0" when absent). The reader has validated them already.
Eigen::Vector3d ParseTriple(const tinyxml2::XMLElement* element, const char* name) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  const char* text = element == nullptr ? nullptr : element->Attribute(name);
  if (text == nullptr) return v;
  std::istringstream in{std::string(text)};
  std::string piece;
  for (int i = 0; i < 3 && in >> piece; ++i) {
    // The reader (urdfdom) has read this text already: a plain decimal, perhaps with '+'.
    const std::size_t skip = !piece.empty() && piece[0] == '+' ? 1 : 0;
    double value = 0;
    const std::from_chars_result r =
        std::from_chars(piece.data() + skip, piece.data() + piece.size(), value);
    if (r.ec == std::errc() && r.ptr == piece.data() + piece.size()) v(i) = value;
  }
  return v;
}

Eigen::Matrix3d RotationFromRollPitchYaw(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy(2), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy(1), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy(0), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// The pose written by an element's <origin> child (identity when absent).
Pose OriginOf(const tinyxml2::XMLElement* element) {
  const tinyxml2::XMLElement* origin = element->FirstChildElement("origin");
  Pose X;
  X.p_AB = ParseTriple(origin, "xyz");
  X.R_AB = RotationFromRollPitchYaw(ParseTriple(origin, "rpy"));
  return X;
}

// Writes X as the element's <origin> (created as its first child when absent).
void SetOrigin(tinyxml2::XMLElement* element, const Pose& X) {
  tinyxml2::XMLElement* origin = element->FirstChildElement("origin");
  if (origin == nullptr) {
    origin = element->GetDocument()->NewElement("origin");
    element->InsertFirstChild(origin);
  }
  origin->SetAttribute("xyz", Triple(X.p_AB).c_str());
  origin->SetAttribute("rpy", Triple(RotationToRollPitchYaw(X.R_AB)).c_str());
}

// The named <link> elements of a <robot> by name, and its named <joint> elements in order.
struct RobotElements {
  std::unordered_map<std::string, tinyxml2::XMLElement*> links;
  std::vector<tinyxml2::XMLElement*> joints;
};

// Collects the <robot>'s top-level named links and joints.
RobotElements CollectRobotElements(tinyxml2::XMLElement* robot) {
  RobotElements elements;
  for (tinyxml2::XMLElement* e = robot->FirstChildElement(); e != nullptr;
       e = e->NextSiblingElement()) {
    const char* name = e->Attribute("name");
    if (name == nullptr) continue;
    if (std::string(e->Name()) == "link") elements.links.emplace(name, e);
    if (std::string(e->Name()) == "joint") elements.joints.push_back(e);
  }
  return elements;
}

// Which group, and at which pose in its root, a merged (non-root) link is.
struct Merged {
  const std::string* root;
  Pose X_RL;
};
using MergedLinks = std::unordered_map<std::string, Merged>;

// Maps each merged link's name to its group's root and pose; counts the groups merged.
MergedLinks MapMergedLinks(const Model& model, const std::vector<WeldedGroup>& groups,
                           int* groups_merged) {
  MergedLinks merged;
  for (const WeldedGroup& group : groups) {
    if (group.links.size() < 2) continue;
    ++*groups_merged;
    for (std::size_t k = 1; k < group.links.size(); ++k) {
      merged.emplace(model.links[group.links[k]].name, Merged{&group.root_link, group.X_RL[k]});
    }
  }
  return merged;
}

// Joints: removes the fixed ones that hold a merged link; re-parents those leaving a merged link.
void RewireJoints(const Model& model, const MergedLinks& merged,
                  const std::vector<tinyxml2::XMLElement*>& joint_elements,
                  tinyxml2::XMLElement* robot) {
  std::unordered_map<std::string, const Joint*> joint_by_name;
  for (const Joint& joint : model.joints) joint_by_name.emplace(joint.name, &joint);
  for (tinyxml2::XMLElement* joint_element : joint_elements) {
    const auto joint_it = joint_by_name.find(joint_element->Attribute("name"));
    if (joint_it == joint_by_name.end()) continue;
    const Joint& joint = *joint_it->second;
    const auto child = merged.find(joint.child);
    const auto parent = merged.find(joint.parent);
    const bool internal = joint.type == Joint::Type::kFixed && child != merged.end() &&
                          (parent != merged.end() ? *parent->second.root == *child->second.root
                                                  : joint.parent == *child->second.root);
    if (internal) {
      robot->DeleteChild(joint_element);
      continue;
    }
    if (parent != merged.end()) {
      tinyxml2::XMLElement* parent_element = joint_element->FirstChildElement("parent");
      if (parent_element != nullptr) {
        parent_element->SetAttribute("link", parent->second.root->c_str());
      }
      SetOrigin(joint_element, parent->second.X_RL * joint.X_PC);
    }
  }
}

// Moves a link's visuals and collisions into the root element, re-posed by X_RL.
void MoveGeometriesToRoot(tinyxml2::XMLElement* link_element, const Pose& X_RL,
                          tinyxml2::XMLElement* root_element) {
  std::vector<tinyxml2::XMLElement*> geometries;
  for (tinyxml2::XMLElement* e = link_element->FirstChildElement(); e != nullptr;
       e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "visual" || name == "collision") geometries.push_back(e);
  }
  for (tinyxml2::XMLElement* geometry : geometries) {
    SetOrigin(geometry, X_RL * OriginOf(geometry));
    root_element->InsertEndChild(geometry);  // Moves the element.
  }
}

// Replaces the root element's <inertial> children with one holding the group's composite.
void WriteCompositeInertial(const CompositeInertia& composite, tinyxml2::XMLElement* root_element) {
  while (tinyxml2::XMLElement* old = root_element->FirstChildElement("inertial")) {
    root_element->DeleteChild(old);
  }
  tinyxml2::XMLElement* inertial = root_element->GetDocument()->NewElement("inertial");
  root_element->InsertFirstChild(inertial);
  tinyxml2::XMLElement* origin = inertial->InsertNewChildElement("origin");
  origin->SetAttribute("xyz", Triple(composite.p_RoScm_R).c_str());
  origin->SetAttribute("rpy", "0 0 0");
  inertial->InsertNewChildElement("mass")->SetAttribute("value", Number(composite.mass).c_str());
  tinyxml2::XMLElement* inertia = inertial->InsertNewChildElement("inertia");
  const Eigen::Matrix3d& I = composite.I_SScm_R;
  inertia->SetAttribute("ixx", Number(I(0, 0)).c_str());
  inertia->SetAttribute("ixy", Number(I(0, 1)).c_str());
  inertia->SetAttribute("ixz", Number(I(0, 2)).c_str());
  inertia->SetAttribute("iyy", Number(I(1, 1)).c_str());
  inertia->SetAttribute("iyz", Number(I(1, 2)).c_str());
  inertia->SetAttribute("izz", Number(I(2, 2)).c_str());
}

// Whether a link's inertial adds anything to a composite: a mass or an inertia (a massless link
// may still carry one; libsdformat's lumping adds it too).
bool Contributes(const Link& link) {
  if (!link.inertial) return false;
  const Inertial& i = *link.inertial;
  return i.mass != 0 || i.ixx != 0 || i.iyy != 0 || i.izz != 0 || i.ixy != 0 || i.ixz != 0 ||
         i.iyz != 0;
}

// Links of one group: moves geometry into the root, removes the merged links, and writes the
// composite inertial when any member has a mass or an inertia.
void MergeGroupLinks(const Model& model, const WeldedGroup& group,
                     const std::unordered_map<std::string, tinyxml2::XMLElement*>& link_elements,
                     tinyxml2::XMLElement* robot, int* merged_links) {
  tinyxml2::XMLElement* root_element = link_elements.at(group.root_link);
  bool members_contribute = false;
  for (std::size_t k = 1; k < group.links.size(); ++k) {
    const Link& link = model.links[group.links[k]];
    members_contribute = members_contribute || Contributes(link);
    tinyxml2::XMLElement* link_element = link_elements.at(link.name);
    MoveGeometriesToRoot(link_element, group.X_RL[k], root_element);
    robot->DeleteChild(link_element);
    ++*merged_links;
  }
  if (!members_contribute) return;
  WriteCompositeInertial(CalcCompositeInertia(model, group), root_element);
}

// Why `target` has no merge-fixed, or nullptr when it has one.
const char* UnsupportedTarget(Target target) {
  switch (target) {
    case Target::kMujoco:
      return "merge-fixed --target mujoco is not supported: MuJoCo's fusestatic also fuses the "
             "root link into the world and drops bodies lighter than mjMINVAL, which a URDF "
             "cannot say (use --target generic: every fixed joint merged)";
    case Target::kDrake:
      return "merge-fixed --target drake is not supported: Drake keeps every link as a body "
             "(fixed joints are welds), so there is nothing to merge";
    case Target::kGeneric:
    case Target::kGazebo:
      break;
  }
  return nullptr;
}

}  // namespace

Eigen::Vector3d RotationToRollPitchYaw(const Eigen::Matrix3d& R) {
  const double cos_pitch = std::hypot(R(0, 0), R(1, 0));
  const double pitch = std::atan2(-R(2, 0), cos_pitch);
  if (cos_pitch < 1e-12) {
    // Gimbal lock: only roll − yaw (or roll + yaw) is defined; put it all in roll.
    return {std::atan2(-R(1, 2), R(1, 1)), pitch, 0.0};
  }
  return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

namespace {

// The URDF edit (see merge_fixed.h).
MergeFixedResult MergeUrdf(const std::string& xml, const std::string& file_name, const Model& model,
                           Target target) {
  MergeFixedResult result;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    result.errors.push_back(MakeReadError(file_name, doc.ErrorLineNum(), "", doc.ErrorStr()));
    return result;
  }
  tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) {
    result.errors.push_back(MakeReadError(file_name, 0, "", "no <robot> element"));
    return result;
  }
  const RobotElements elements = CollectRobotElements(robot);
  const std::vector<WeldedGroup> groups =
      target == Target::kGazebo ? GazeboLumpedGroups(model, xml) : FindWeldedGroups(model);
  const MergedLinks merged = MapMergedLinks(model, groups, &result.groups_merged);
  RewireJoints(model, merged, elements.joints, robot);
  for (const WeldedGroup& group : groups) {
    if (group.links.size() < 2) continue;
    MergeGroupLinks(model, group, elements.links, robot, &result.merged_links);
  }

  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  result.text = printer.CStr();
  return result;
}

std::size_t CountLinks(const ReadResult& read) {
  std::size_t links = 0;
  for (const Model& model : read.models) links += model.links.size();
  return links;
}

// The merged text must read again with the merged links gone, or nothing is written: tinyxml2
// re-prints some malformed input it accepted (text after the root element) as text it refuses.
void CheckReadsBack(const ReadResult& read, const std::string& file_name,
                    MergeFixedResult* result) {
  const ReadResult again = ReadModelString(result->text, file_name);
  if (again.ok() &&
      CountLinks(again) + static_cast<std::size_t>(result->merged_links) == CountLinks(read)) {
    return;
  }
  std::string why =
      "merge-fixed cannot write this file: the merged model does not read back with " +
      std::to_string(CountLinks(read) - static_cast<std::size_t>(result->merged_links)) + " links";
  if (!again.errors.empty()) {
    const ReadError& e = again.errors.front();
    why += " (the merged text, line " + std::to_string(e.location.line) + ": " +
           (e.element.empty() ? "" : e.element + ": ") + e.message + ")";
  }
  result->text.clear();
  result->errors.push_back(MakeReadError(file_name, 0, "", why));
}

}  // namespace

MergeFixedResult MergeFixedJoints(const std::string& xml, const std::string& file_name,
                                  Target target) {
  MergeFixedResult result;
  if (const char* why = UnsupportedTarget(target)) {
    result.errors.push_back(MakeReadError(file_name, 0, "", why));
    return result;
  }
  ReadResult read = ReadModelString(xml, file_name);
  if (!read.ok() || read.models.empty()) {
    result.errors = read.errors;
    if (result.errors.empty()) {
      result.errors.push_back(MakeReadError(file_name, 0, "", "the file holds no model"));
    }
    return result;
  }
  const Model& model = read.models.front();
  if (model.format == Model::Format::kSdf && target == Target::kGazebo) {
    // gz-sim builds every SDF link as a body of its own and a fixed joint as a weld
    // (docs/targets.md): nothing is lumped.
    result.text = xml;
    result.notes.push_back(
        "Gazebo does not lump the fixed joints of an SDF model (each link stays a body, a fixed "
        "joint is a weld): written unchanged");
    return result;
  }
  result = model.format == Model::Format::kSdf ? internal::MergeFixedSdf(xml, file_name, read)
                                               : MergeUrdf(xml, file_name, model, target);
  if (result.errors.empty()) CheckReadsBack(read, file_name, &result);
  return result;
}

}  // namespace massprops
