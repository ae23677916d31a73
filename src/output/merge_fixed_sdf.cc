// merge-fixed for SDF (see merge_fixed_sdf.h). SDF pose semantics (SDFormat 1.7+ "pose frame
// semantics", as libsdformat 12 resolves them; SDF < 1.7 names the frame with the pose attribute
// "frame", which libsdformat's 1.6 -> 1.7 converter turns into relative_to):
//   - a link's <pose> is in the model frame unless relative_to names a frame;
//   - a visual's, collision's, sensor's, light's ... <pose> is in its link's frame by default;
//   - a joint's <pose> is in its child link's frame by default;
//   - a <frame>'s <pose> is in its attached_to frame by default (the model frame without one).
// A member link L of a group with root R sits at X_RL in R; a pose written in L's frame becomes
// X_RL * pose in R's frame.
#include "merge_fixed_sdf.h"

#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "io/sdf_values.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/format_number.h"

namespace massprops::internal {
namespace {

using tinyxml2::XMLElement;

std::string Tag(const XMLElement* e) { return e->Name(); }

// What the SDF version of the file changes here: SDF >= 1.7 names a pose's frame with
// relative_to (before: the attribute frame), SDF >= 1.9 reads rotation_format and degrees.
struct SdfVersion {
  bool v17 = true;
  bool v19 = true;
};

// The version of <sdf version="MAJOR.MINOR"> (the reader has refused other text).
SdfVersion ReadVersion(const std::string& version) {
  int major = 0, minor = 0;
  if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) != 2) return {};
  return {major > 1 || (major == 1 && minor >= 7), major > 1 || (major == 1 && minor >= 9)};
}

// The value of a <pose> element (identity when absent or empty), as the SDF reader reads it:
// "x y z roll pitch yaw" (radians, or SDF 1.9 degrees with degrees="true"), or with SDF 1.9
// rotation_format="quat_xyzw" "x y z qx qy qz qw".
Pose PoseValue(const XMLElement* pose, const SdfVersion& version) {
  if (pose == nullptr) return Pose();
  const std::string degrees = version.v19 ? Attr(pose, "degrees") : "";
  std::string why;  // The reader has accepted the text; an empty one is the identity.
  return ParseSdfPose(Text(pose), version.v19 ? Attr(pose, "rotation_format") : "",
                      degrees == "true" || degrees == "1", &why)
      .value_or(Pose());
}

// Writes X into the <pose> element as "x y z roll pitch yaw" in radians, each number the shortest
// decimal that reads back exactly.
void SetPoseValue(XMLElement* pose, const Pose& X) {
  const Eigen::Vector3d rpy = RotationToRollPitchYaw(X.R_AB);
  std::string text;
  for (double v : {X.p_AB(0), X.p_AB(1), X.p_AB(2), rpy(0), rpy(1), rpy(2)}) {
    text += (text.empty() ? "" : " ") + FormatShortest(v);
  }
  pose->SetText(text.c_str());
  pose->DeleteAttribute("rotation_format");
  pose->DeleteAttribute("degrees");
}

// The member links of the merged groups of one model: each one's root and pose X_RL in it.
struct Member {
  std::string root;
  Pose X_RL;
};

// The edit of one <model> element: a top-level one or one nested in it, written in the file.
class ModelMerge {
 public:
  // `element` is the top-level <model> of `model` (prefix "") or a <model> nested in it, written
  // in the same file, whose links are named `prefix` + local name in `model` ("inner::").
  ModelMerge(const std::string& file, const Model& model, XMLElement* element,
             const std::string& prefix, SdfVersion version, std::vector<ReadError>* errors)
      : file_(file),
        model_(model),
        element_(element),
        prefix_(prefix),
        version_(version),
        errors_(errors) {}

  // Finds the groups and checks that the editor can merge them; false (errors added) if not.
  bool Plan(XMLElement* document_root);
  // Edits the document; returns the number of links merged.
  int Apply(const XMLElement* document_root);
  int groups() const { return groups_merged_; }

 private:
  void Unsupported(const XMLElement* e, const std::string& element, const std::string& why) {
    errors_->push_back(MakeReadError(file_, e == nullptr ? 0 : e->GetLineNum(), element,
                                     "merge-fixed does not support this: " + why));
  }
  // The frame named by a pose element's relative_to (SDF < 1.7: its frame attribute).
  std::string PoseRef(const XMLElement* pose) const {
    if (pose == nullptr) return "";
    if (!version_.v17 && pose->Attribute("frame") != nullptr) return Attr(pose, "frame");
    return Attr(pose, "relative_to");
  }
  // The attribute that names a new pose's frame: relative_to (SDF < 1.7: frame).
  const char* RefAttribute() const { return version_.v17 ? "relative_to" : "frame"; }
  void SetPoseRef(XMLElement* pose, const std::string& frame) const {
    if (!version_.v17 && pose->Attribute("frame") != nullptr) {
      pose->SetAttribute("frame", frame.c_str());
    } else {
      pose->SetAttribute("relative_to", frame.c_str());
    }
  }
  const Member* MemberOf(const std::string& name) const {
    const auto it = members_.find(name);
    return it == members_.end() ? nullptr : &it->second;
  }
  // The root of the merged group holding `name`, or "" when it is in none.
  std::string GroupOf(const std::string& name) const {
    if (const Member* m = MemberOf(name)) return m->root;
    return roots_.count(name) ? name : "";
  }
  bool PlanGroups();
  std::string BodyOf(const std::string& name, int depth = 0) const;
  void CheckJoints();
  void CheckOutsideReferences(XMLElement* e);
  void ReposeDefault(XMLElement* owner, const Member& m);
  void RewriteExplicitReferences(XMLElement* e);
  void ReplaceByFrame(XMLElement* joint);
  void RewireJoints(const XMLElement* document_root);
  void RewireFrames();
  void MoveChildren(XMLElement* link, const Member& m, XMLElement* root);
  void WriteInertial(const WeldedGroup& group, XMLElement* root);

  // The name of a link of model_ in this scope ("inner::x" -> "x").
  std::string Local(const std::string& name) const { return name.substr(prefix_.size()); }

  const std::string& file_;
  const Model& model_;
  XMLElement* element_;
  std::string prefix_;
  SdfVersion version_;
  std::vector<ReadError>* errors_;
  std::vector<WeldedGroup> groups_;
  std::unordered_map<std::string, Member> members_;
  std::unordered_set<std::string> roots_;
  std::unordered_map<std::string, XMLElement*> links_;  // Direct <link> children by name.
  std::vector<XMLElement*> removed_joints_;             // Fixed joints inside a group.
  int groups_merged_ = 0;
};

// The scope of a link name of a Model: "" for "x", "inner::" for "inner::x".
std::string ScopeOf(const std::string& name) {
  const std::size_t colons = name.rfind("::");
  return colons == std::string::npos ? "" : name.substr(0, colons + 2);
}

bool ModelMerge::PlanGroups() {
  for (XMLElement* e = element_->FirstChildElement("link"); e != nullptr;
       e = e->NextSiblingElement("link")) {
    links_.emplace(Attr(e, "name"), e);
  }
  const std::size_t errors_before = errors_->size();
  for (const WeldedGroup& group : FindWeldedGroups(model_)) {
    if (group.links.size() < 2 || ScopeOf(group.root_link) != prefix_) continue;
    for (std::size_t k = 0; k < group.links.size(); ++k) {
      const Link& link = model_.links[group.links[k]];
      const auto it = links_.find(Local(link.name));
      if (ScopeOf(link.name) != prefix_ || it == links_.end() || link.location.file != file_ ||
          it->second->GetLineNum() != link.location.line) {
        errors_->push_back(MakeReadError(
            link.location.file, link.location.line, "<link> '" + link.name + "'",
            "merge-fixed does not support this: the link is welded by fixed joints to links of "
            "another <model> scope ('" +
                group.root_link + "'), or comes from an <include>"));
        continue;
      }
      if (link.inertial_unreadable) {
        Unsupported(it->second, "<link> '" + link.name + "'",
                    "its <inertial> cannot be read, so the composite of its welded group is "
                    "unknown");
      }
      if (k > 0) members_[Local(link.name)] = Member{Local(group.root_link), group.X_RL[k]};
    }
    roots_.insert(Local(group.root_link));
    groups_.push_back(group);
  }
  return errors_->size() == errors_before;
}

// The link the frame `name` of this model is attached to: a link itself, a <frame> along its
// attached_to (none: the model frame, attached to the canonical link), a joint its child; "" when
// unknown (a nested model's frame) or circular.
std::string ModelMerge::BodyOf(const std::string& name, int depth) const {
  if (depth > 64) return "";
  if (links_.count(name)) return name;
  if (name.empty() || name == "__model__") {
    const std::string canonical = Attr(element_, "canonical_link");
    if (!canonical.empty()) return canonical;
    const XMLElement* first = element_->FirstChildElement("link");
    return first == nullptr ? "" : Attr(first, "name");
  }
  for (const XMLElement* f = element_->FirstChildElement("frame"); f != nullptr;
       f = f->NextSiblingElement("frame")) {
    if (Attr(f, "name") == name) return BodyOf(Attr(f, "attached_to"), depth + 1);
  }
  for (const XMLElement* j = element_->FirstChildElement("joint"); j != nullptr;
       j = j->NextSiblingElement("joint")) {
    if (Attr(j, "name") == name) return BodyOf(Text(j->FirstChildElement("child")), depth + 1);
  }
  return "";
}

// The joints inside a group: fixed ones are removed (RewireJoints); a moving one cannot be kept
// (its parent would be its child).
void ModelMerge::CheckJoints() {
  for (XMLElement* j = element_->FirstChildElement("joint"); j != nullptr;
       j = j->NextSiblingElement("joint")) {
    const std::string parent = GroupOf(BodyOf(Text(j->FirstChildElement("parent"))));
    if (parent.empty() || parent != GroupOf(BodyOf(Text(j->FirstChildElement("child"))))) {
      continue;
    }
    if (Attr(j, "type") == "fixed") {
      removed_joints_.push_back(j);
    } else {
      Unsupported(j, "<joint> '" + Attr(j, "name") + "'",
                  "this " + Attr(j, "type") +
                      " joint joins two links that fixed joints weld into one body");
    }
  }
  const std::string placement = Attr(element_, "placement_frame");
  if (MemberOf(placement) != nullptr) {
    Unsupported(element_, "<model> '" + model_.name + "'",
                "its placement_frame names the link '" + placement + "', which is merged");
  }
}

// Elements outside this <model> element that name a member by a scoped name: "MODEL::LINK"
// from the world, "NESTED::LINK" (or longer) from an enclosing model.
void ModelMerge::CheckOutsideReferences(XMLElement* e) {
  const std::string scope = prefix_.empty() ? model_.name + "::" : prefix_;
  auto names_member = [&](const std::string& value) {
    const std::size_t at = value.rfind("::");
    if (at == std::string::npos || MemberOf(value.substr(at + 2)) == nullptr) return false;
    const std::string head = value.substr(0, at + 2);
    return head.size() >= scope.size() &&
           head.compare(head.size() - scope.size(), scope.size(), scope) == 0;
  };
  for (; e != nullptr; e = e->NextSiblingElement()) {
    if (e == element_) continue;
    bool named = names_member(Text(e));
    for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
      named = named || names_member(a->Value());
    }
    if (named) {
      Unsupported(e, "<" + Tag(e) + ">",
                  "it names a link of model '" + model_.name +
                      "' that is merged, from outside the <model> that holds it");
    }
    CheckOutsideReferences(e->FirstChildElement());
  }
}

bool ModelMerge::Plan(XMLElement* document_root) {
  if (!PlanGroups()) return false;
  if (groups_.empty()) return true;
  const std::size_t errors_before = errors_->size();
  CheckJoints();
  CheckOutsideReferences(document_root->FirstChildElement());
  return errors_->size() == errors_before;
}

// The <pose> of `owner` was in the frame of member m by default and is now in m's root's frame:
// composed (created when absent). A pose that names its frame is left to
// RewriteExplicitReferences.
void ModelMerge::ReposeDefault(XMLElement* owner, const Member& m) {
  XMLElement* pose = owner->FirstChildElement("pose");
  if (pose != nullptr && !PoseRef(pose).empty()) return;
  if (pose == nullptr) {
    pose = owner->GetDocument()->NewElement("pose");
    owner->InsertFirstChild(pose);
  }
  SetPoseValue(pose, m.X_RL * PoseValue(pose, version_));
}

// Every pose (relative_to) and axis (expressed_in) in the model's scope that names a member is
// re-expressed in its root: `e` and what it holds. A nested model's or include's own <pose> is in
// this scope, what else they hold is not.
void ModelMerge::RewriteExplicitReferences(XMLElement* e) {
  const std::string tag = Tag(e);
  if (tag == "pose") {
    if (const Member* m = MemberOf(PoseRef(e))) {
      SetPoseValue(e, m->X_RL * PoseValue(e, version_));
      SetPoseRef(e, m->root);
    }
    return;
  }
  if (const Member* m = MemberOf(Attr(e, "expressed_in"))) {
    std::vector<double> v;
    std::string why;
    if (ParseSdfNumbers(Text(e), 3, 3, &v, &why)) {
      const Eigen::Vector3d x = m->X_RL.R_AB * Eigen::Vector3d(v[0], v[1], v[2]);
      e->SetText(
          (FormatShortest(x(0)) + " " + FormatShortest(x(1)) + " " + FormatShortest(x(2))).c_str());
    }
    e->SetAttribute("expressed_in", m->root.c_str());
  }
  const bool other_scope = e != element_ && (tag == "model" || tag == "include");
  for (XMLElement* c = other_scope ? e->FirstChildElement("pose") : e->FirstChildElement();
       c != nullptr; c = other_scope ? nullptr : c->NextSiblingElement()) {
    RewriteExplicitReferences(c);
  }
}

// Whether an element of the document names `name` as a frame, or `scoped` (a name ending in
// "SCOPE::name", from an enclosing model or the world): in relative_to, attached_to,
// expressed_in, a pose's frame (SDF < 1.7) or a <parent>, <child> or <placement_frame>.
bool NamesFrame(const XMLElement* e, const std::string& name, const std::string& scoped) {
  auto names = [&](const std::string& value) {
    return value == name ||
           (value.size() >= scoped.size() &&
            value.compare(value.size() - scoped.size(), scoped.size(), scoped) == 0);
  };
  for (; e != nullptr; e = e->NextSiblingElement()) {
    for (const char* attribute : {"relative_to", "attached_to", "expressed_in", "frame"}) {
      if (names(Attr(e, attribute))) return true;
    }
    const std::string tag = Tag(e);
    if ((tag == "parent" || tag == "child" || tag == "placement_frame") && names(Text(e))) {
      return true;
    }
    if (NamesFrame(e->FirstChildElement(), name, scoped)) return true;
  }
  return false;
}

// A fixed joint inside a group that something names as a frame becomes a <frame> of that name
// where the joint frame was, attached to the group's root, so that every reference stays valid
// (as libsdformat keeps the frames of the joints it lumps in URDF, gazebosim/sdformat#1148).
void ModelMerge::ReplaceByFrame(XMLElement* joint) {
  const std::string child = Text(joint->FirstChildElement("child"));
  XMLElement* frame = joint->GetDocument()->NewElement("frame");
  frame->SetAttribute("name", Attr(joint, "name").c_str());
  frame->SetAttribute("attached_to", GroupOf(BodyOf(child)).c_str());
  XMLElement* pose = frame->InsertNewChildElement("pose");
  const XMLElement* old = joint->FirstChildElement("pose");
  const std::string ref = PoseRef(old);
  if (!ref.empty()) {  // Already re-expressed in a frame that stays (RewriteExplicitReferences).
    pose->SetText(Text(old).c_str());
    for (const char* a : {"rotation_format", "degrees"}) {
      if (old->Attribute(a) != nullptr) pose->SetAttribute(a, old->Attribute(a));
    }
    pose->SetAttribute(RefAttribute(), ref.c_str());
  } else if (const Member* m = MemberOf(child)) {
    SetPoseValue(pose,
                 m->X_RL * PoseValue(old, version_));  // In the root, the frame's attached_to.
  } else {
    SetPoseValue(pose, PoseValue(old, version_));  // In the child frame, which stays.
    pose->SetAttribute(RefAttribute(), child.c_str());
  }
  element_->InsertAfterChild(joint, frame);
}

// Joints: the fixed ones inside a group go (or become frames, ReplaceByFrame); the others' parent
// and child are re-pointed.
void ModelMerge::RewireJoints(const XMLElement* document_root) {
  for (XMLElement* j : removed_joints_) {
    const std::string name = Attr(j, "name");
    const std::string scoped = (prefix_.empty() ? model_.name + "::" : prefix_) + name;
    if (NamesFrame(document_root, name, scoped)) ReplaceByFrame(j);
    element_->DeleteChild(j);
  }
  for (XMLElement* j = element_->FirstChildElement("joint"); j != nullptr;
       j = j->NextSiblingElement("joint")) {
    XMLElement* parent = j->FirstChildElement("parent");
    XMLElement* child = j->FirstChildElement("child");
    if (const Member* m = MemberOf(Text(child))) {
      ReposeDefault(j, *m);  // A joint's pose is in its child's frame by default.
      child->SetText(m->root.c_str());
    }
    if (const Member* m = MemberOf(Text(parent))) parent->SetText(m->root.c_str());
  }
}

// Frames attached to a member are attached to its root.
void ModelMerge::RewireFrames() {
  for (XMLElement* f = element_->FirstChildElement("frame"); f != nullptr;
       f = f->NextSiblingElement("frame")) {
    if (const Member* m = MemberOf(Attr(f, "attached_to"))) {
      ReposeDefault(f, *m);  // A frame's pose is in its attached_to frame by default.
      f->SetAttribute("attached_to", m->root.c_str());
    }
  }
}

// Moves the posed children of member link `link` into `root`; a name its root already uses for
// an element of the same kind gets the prefix "LINK__" (libsdformat refuses duplicates).
void ModelMerge::MoveChildren(XMLElement* link, const Member& m, XMLElement* root) {
  static const std::unordered_set<std::string> kMoved = {
      "visual",  "collision",        "sensor",       "light",     "projector",
      "battery", "particle_emitter", "audio_source", "audio_sink"};
  std::vector<XMLElement*> moved;
  for (XMLElement* e = link->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    if (kMoved.count(Tag(e))) moved.push_back(e);
  }
  for (XMLElement* e : moved) {
    if (Tag(e) != "battery" && Tag(e) != "audio_sink") ReposeDefault(e, m);
    std::unordered_set<std::string> used;
    for (XMLElement* s = root->FirstChildElement(e->Name()); s != nullptr;
         s = s->NextSiblingElement(e->Name())) {
      used.insert(Attr(s, "name"));
    }
    const std::string name = Attr(e, "name");
    if (e->Attribute("name") != nullptr && used.count(name)) {
      std::string renamed = Attr(link, "name") + "__" + name;
      for (int k = 2; used.count(renamed); ++k) {
        renamed = Attr(link, "name") + "__" + name + "_" + std::to_string(k);
      }
      e->SetAttribute("name", renamed.c_str());
    }
    root->InsertEndChild(e);  // Moves the element.
  }
}

// Replaces the root's <inertial> by the group's composite: center of mass as the pose (no
// rotation), inertia about it in the link frame.
void ModelMerge::WriteInertial(const WeldedGroup& group, XMLElement* root) {
  const CompositeInertia c = CalcCompositeInertia(model_, group);
  tinyxml2::XMLDocument* doc = root->GetDocument();
  XMLElement* inertial = doc->NewElement("inertial");
  XMLElement* old = root->FirstChildElement("inertial");
  if (old != nullptr) {
    root->InsertAfterChild(old, inertial);
  } else {
    root->InsertEndChild(inertial);
  }
  while (XMLElement* e = root->FirstChildElement("inertial")) {
    if (e == inertial) break;
    root->DeleteChild(e);
  }
  for (XMLElement* e = inertial->NextSiblingElement("inertial"); e != nullptr;) {
    XMLElement* next = e->NextSiblingElement("inertial");
    root->DeleteChild(e);
    e = next;
  }
  const Eigen::Vector3d& p = c.p_RoScm_R;
  inertial->InsertNewChildElement("pose")->SetText(
      (FormatShortest(p(0)) + " " + FormatShortest(p(1)) + " " + FormatShortest(p(2)) + " 0 0 0")
          .c_str());
  inertial->InsertNewChildElement("mass")->SetText(FormatShortest(c.mass).c_str());
  XMLElement* inertia = inertial->InsertNewChildElement("inertia");
  const Eigen::Matrix3d& I = c.I_SScm_R;
  const char* names[] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  const double values[] = {I(0, 0), I(0, 1), I(0, 2), I(1, 1), I(1, 2), I(2, 2)};
  for (int k = 0; k < 6; ++k) {
    inertia->InsertNewChildElement(names[k])->SetText(FormatShortest(values[k]).c_str());
  }
}

int ModelMerge::Apply(const XMLElement* document_root) {
  if (groups_.empty()) return 0;
  // Explicit references first: they read poses as written, before defaults are composed.
  RewriteExplicitReferences(element_);
  RewireJoints(document_root);
  RewireFrames();
  const std::string canonical = Attr(element_, "canonical_link");
  if (const Member* m = MemberOf(canonical)) {
    element_->SetAttribute("canonical_link", m->root.c_str());
  }
  int merged = 0;
  for (const WeldedGroup& group : groups_) {
    ++groups_merged_;
    XMLElement* root = links_.at(Local(group.root_link));
    WriteInertial(group, root);
    for (std::size_t k = 1; k < group.links.size(); ++k) {
      const std::string name = Local(model_.links[group.links[k]].name);
      XMLElement* link = links_.at(name);
      MoveChildren(link, members_.at(name), root);
      element_->DeleteChild(link);
      ++merged;
    }
  }
  return merged;
}

// The top-level <model> elements of the document: <sdf><model> and <sdf><world><model>.
std::vector<XMLElement*> TopLevelModels(XMLElement* sdf) {
  std::vector<XMLElement*> models;
  for (XMLElement* e = sdf->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    if (Tag(e) == "model") models.push_back(e);
    if (Tag(e) != "world") continue;
    for (XMLElement* m = e->FirstChildElement("model"); m != nullptr;
         m = m->NextSiblingElement("model")) {
      models.push_back(m);
    }
  }
  return models;
}

// Appends `model` (whose links are named `prefix` + NAME in the Model) and the <model>s nested
// in it, depth first.
void AddScopes(XMLElement* model, const std::string& prefix,
               std::vector<std::pair<XMLElement*, std::string>>* scopes) {
  scopes->emplace_back(model, prefix);
  for (XMLElement* e = model->FirstChildElement("model"); e != nullptr;
       e = e->NextSiblingElement("model")) {
    AddScopes(e, prefix + Attr(e, "name") + "::", scopes);
  }
}

}  // namespace

MergeFixedResult MergeFixedSdf(const std::string& xml, const std::string& file_name,
                               const ReadResult& read) {
  MergeFixedResult result;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    result.errors.push_back(MakeReadError(file_name, doc.ErrorLineNum(), "", doc.ErrorStr()));
    return result;
  }
  XMLElement* sdf = doc.FirstChildElement("sdf");
  if (sdf == nullptr) {
    result.errors.push_back(MakeReadError(file_name, 0, "<sdf>", "no <sdf> element"));
    return result;
  }
  const SdfVersion version = ReadVersion(Attr(sdf, "version"));
  const std::vector<XMLElement*> elements = TopLevelModels(sdf);
  std::vector<ModelMerge> merges;
  for (const Model& model : read.models) {
    XMLElement* element = nullptr;
    for (XMLElement* e : elements) {
      if (Attr(e, "name") == model.name && e->GetLineNum() == model.location.line &&
          model.location.file == file_name) {
        element = e;
      }
    }
    // The model and its nested models written inline, each with the prefix of its links.
    std::vector<std::pair<XMLElement*, std::string>> scopes;
    if (element != nullptr) AddScopes(element, "", &scopes);
    for (const WeldedGroup& g : FindWeldedGroups(model)) {
      if (g.links.size() < 2) continue;
      bool known = false;
      for (const auto& scope : scopes) known = known || scope.second == ScopeOf(g.root_link);
      if (known) continue;
      const Link& root = model.links[g.links.front()];
      result.errors.push_back(MakeReadError(
          root.location.file, root.location.line, "<link> '" + root.name + "'",
          "merge-fixed does not support this: the link is welded to others by fixed joints but "
          "its <model> is not written in this file (an <include>, or models joined by a "
          "world's joints)"));
    }
    for (const auto& [e, prefix] : scopes) {
      merges.emplace_back(file_name, model, e, prefix, version, &result.errors);
      merges.back().Plan(sdf);
    }
  }
  if (!result.errors.empty()) return result;
  for (ModelMerge& merge : merges) {
    result.merged_links += merge.Apply(sdf);
    result.groups_merged += merge.groups();
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  result.text = printer.CStr();
  return result;
}

}  // namespace massprops::internal
