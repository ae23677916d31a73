// --target gazebo: libsdformat's URDF conversion lumps links across fixed joints
// (GazeboLumpedGroups, GazeboBodies); the finding that says so (CheckGazebo), and the lumped body's
// verdict on the inertia of its members (AnnotateGazebo).
#include <tinyxml2.h>

#include <algorithm>
#include <set>
#include <string>

#include "analysis/targets/target_layer.h"
#include "massprops/analysis/welded_groups.h"

namespace massprops {
namespace {

// Gazebo (libsdformat's URDF conversion) lumps a link into its parent across a fixed joint
// unless the joint is named by <gazebo reference="JOINT"> with <disableFixedJointLumping>true or
// <preserveFixedJoint>true.
std::set<std::string> PreservedFixedJoints(std::string_view urdf_text) {
  std::set<std::string> joints;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_text.data(), urdf_text.size()) != tinyxml2::XML_SUCCESS) return joints;
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (robot == nullptr) return joints;
  for (const tinyxml2::XMLElement* g = robot->FirstChildElement("gazebo"); g;
       g = g->NextSiblingElement("gazebo")) {
    const char* reference = g->Attribute("reference");
    if (reference == nullptr) continue;
    for (const char* tag : {"disableFixedJointLumping", "preserveFixedJoint"}) {
      const tinyxml2::XMLElement* e = g->FirstChildElement(tag);
      if (e && e->GetText() && std::string(e->GetText()).find("true") != std::string::npos) {
        joints.insert(reference);
      }
    }
  }
  return joints;
}

}  // namespace

std::vector<WeldedGroup> GazeboLumpedGroups(const Model& model, std::string_view urdf_text) {
  const bool urdf = model.format == Model::Format::kUrdf;
  const std::set<std::string> preserved =
      urdf ? PreservedFixedJoints(urdf_text) : std::set<std::string>();
  // Links joined by a fixed joint that is not preserved form one body (SDF models are not
  // lumped: lumping is part of the URDF conversion). A root link named "world" is libsdformat's
  // world: what is welded to it stays a link of its own, attached by a fixed joint.
  const bool world_root = urdf && model.root_link == "world";
  Model lumping = model;
  for (Joint& j : lumping.joints) {
    if (j.type != Joint::Type::kFixed) continue;
    if (!urdf || preserved.count(j.name) || (world_root && j.parent == "world")) {
      j.type = Joint::Type::kOther;
    }
  }
  return FindWeldedGroups(lumping);
}

std::vector<GazeboBody> GazeboBodies(const Model& model, std::string_view urdf_text) {
  std::vector<GazeboBody> bodies;
  const bool world_root = model.format == Model::Format::kUrdf && model.root_link == "world";
  for (const WeldedGroup& group : GazeboLumpedGroups(model, urdf_text)) {
    if (world_root && group.root_link == "world") continue;  // the world, not a body
    GazeboBody body;
    body.name = model.links[group.links.front()].name;
    body.links = group.links;
    body.inertia = CalcCompositeInertia(model, group);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

namespace targets {

void CheckGazebo(const Model& model, const CheckOptions& options, std::string_view text,
                 FindingSink* sink) {
  for (const GazeboBody& body : GazeboBodies(model, text)) {
    if (body.links.size() < 2) continue;
    std::string names;
    for (std::size_t i = 1; i < body.links.size(); ++i) {
      names += (i > 1 ? ", '" : "'") + model.links[body.links[i]].name + "'";
    }
    const int root = body.links.front();
    const bool valid = body.inertia.I_SScm_R.allFinite() &&
                       PhysicallyValid(body.inertia.I_SScm_R, options.tolerance);
    sink->Emit(kGazeboLumped, root, model.links[root].location,
               "Gazebo lumps " + names + " into link '" + body.name +
                   "' across fixed joints (add <gazebo reference=\"JOINT\"><preserveFixedJoint>"
                   "true</preserveFixedJoint></gazebo> to keep one): it simulates one body of "
                   "mass " +
                   Num(body.inertia.mass) + " kg whose inertia is " +
                   (valid ? "physically valid" : "NOT physically valid"),
               {{"mass", body.inertia.mass}, {"lumped_links", double(body.links.size() - 1)}});
  }
}

void AnnotateGazebo(const Model& model, const CheckOptions& options, std::string_view text,
                    std::vector<Finding>* findings) {
  // Gazebo simulates the lumped body: an invalid member of a valid lumped body is a warning.
  for (const GazeboBody& body : GazeboBodies(model, text)) {
    if (body.links.size() < 2 || !body.inertia.I_SScm_R.allFinite() ||
        !PhysicallyValid(body.inertia.I_SScm_R, options.tolerance)) {
      continue;
    }
    for (Finding& f : *findings) {
      if (f.rule != "inertia-not-physical" || f.severity != Severity::kError) continue;
      const int index = model.FindLink(f.link);
      if (std::find(body.links.begin(), body.links.end(), index) == body.links.end()) continue;
      if (f.message.find("composite inertia") != std::string::npos) continue;
      f.severity = Severity::kWarning;
      f.message += " (Gazebo lumps it into '" + body.name +
                   "', whose composite inertia is valid: that is the body it simulates)";
    }
  }
}

}  // namespace targets
}  // namespace massprops
