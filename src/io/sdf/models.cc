// The SDF reader's Models (reader.h): the top-level models grouped by world joints, each built
// into one Model with its links (poses in the model frame), joints, axes and root link.
#include "io/sdf/reader.h"

namespace massprops::internal::sdf_reader {

Joint::Type JointType(const std::string& t) {
  if (t == "fixed") return Joint::Type::kFixed;
  if (t == "revolute") return Joint::Type::kRevolute;
  if (t == "continuous") return Joint::Type::kContinuous;
  if (t == "prismatic") return Joint::Type::kPrismatic;
  if (t == "ball") return Joint::Type::kBall;
  if (t == "universal") return Joint::Type::kUniversal;
  if (t == "screw") return Joint::Type::kScrew;
  return Joint::Type::kOther;  // revolute2, gearbox, ...
}

/// Groups the top-level models joined by world joints (SDF 1.10+) and builds one Model per group:
/// a lone model as before; models joined by a world joint as one Model named "A+B" whose links
/// and joints keep their scoped names ("A::link") and whose frame is the world's. A world joint
/// whose parent is "world" (or in the child's own model) goes into the child's model.
void Reader::BuildModels() {
  std::unordered_map<int, int> group;  // top -> representative top
  for (int top : top_models_) group[top] = top;
  std::function<int(int)> find = [&](int t) {
    while (group[t] != t) t = group[t] = group[group[t]];
    return t;
  };
  std::vector<std::pair<int, int>> joint_child_top;  // (joint node, child's top)
  for (int j : world_joints_) {
    const Node& n = nodes_[j];
    std::string which;
    const int c = AttachedLink(Lookup(n.child, kWorld), 0);
    const int p = n.parent == "world" ? kWorld : AttachedLink(Lookup(n.parent, kWorld), 0);
    if (c < 0 || (n.parent != "world" && p < 0)) {
      const std::string& bad = c < 0 ? n.child : n.parent;
      if (InUnresolvedInclude(bad, kWorld, &which)) {
        ReportUnresolvedReference(j, bad, which);
      } else {
        Error(n.location.file, n.element, Describe(n),
              "the " + std::string(c < 0 ? "child" : "parent") + " '" + bad +
                  "' is not a link, a model or a frame of the world");
      }
      continue;
    }
    const int ct = TopOf(c);
    const int pt = p == kWorld ? kWorld : TopOf(p);
    if (!group.count(ct) || (pt != kWorld && !group.count(pt))) continue;
    if (pt != kWorld && find(pt) != find(ct)) group[find(pt)] = find(ct);
    joint_child_top.emplace_back(j, ct);
  }
  if (!result_.errors.empty()) return;
  std::vector<int> roots;
  std::unordered_map<int, std::vector<int>> members, joints;
  for (int top : top_models_) {
    const int r = find(top);
    if (!members.count(r)) roots.push_back(r);
    members[r].push_back(top);
  }
  for (const auto& [j, ct] : joint_child_top) joints[find(ct)].push_back(j);
  for (int r : roots) BuildModel(members[r], joints[r]);
}

void Reader::BuildModel(const std::vector<int>& tops, const std::vector<int>& world_joints) {
  const size_t errors_before = result_.errors.size();
  const bool single = tops.size() == 1;
  ModelBuild b;
  b.top = single ? tops[0] : kWorld;
  b.prefix = single ? nodes_[b.top].name + "::" : "";
  Model model = StartModel(tops);
  current_model_name_ = model.name;
  b.order = ModelNodeOrder(tops);
  SdfModelFrames frames;
  ReadModelLinks(&b, &model, &frames);
  // Every frame is resolved, used or not, so that cycles and dangling names are reported as
  // libsdformat reports them.
  for (int i : b.order) Resolve(i, 0);
  for (int j : world_joints) Resolve(j, 0);
  if (result_.errors.size() != errors_before) return;
  b.X_WT = single ? PoseInScope(b.top, kWorld, 0) : std::optional<Pose>(Pose());
  if (b.X_WT) frames.X_WM = *b.X_WT;
  ReadModelJoints(b, world_joints, &model);
  SetRootLink(b, tops, &model);
  if (result_.errors.size() == errors_before) {
    result_.models.push_back(std::move(model));
    frames_.push_back(std::move(frames));
  }
}

// A Model with the format, file, name ("A+B" when joined), static flag and location of `tops`.
Model Reader::StartModel(const std::vector<int>& tops) const {
  Model model;
  model.format = Model::Format::kSdf;
  model.file = top_file_;
  model.is_static = true;
  for (int t : tops) {
    model.name += (model.name.empty() ? "" : "+") + nodes_[t].name;
    model.is_static = model.is_static && nodes_[t].is_static;
  }
  model.location = nodes_[tops[0]].location;
  return model;
}

// The nodes of the models `tops`, in file order (each model's contiguous, itself first).
std::vector<int> Reader::ModelNodeOrder(const std::vector<int>& tops) const {
  std::vector<int> order;
  for (int t : tops) {
    const std::string own = nodes_[t].name + "::";
    order.push_back(t);
    for (int i = t + 1; i < static_cast<int>(nodes_.size()) && nodes_[i].name.rfind(own, 0) == 0;
         ++i) {
      order.push_back(i);
    }
  }
  return order;
}

// Node i's name in the Model: scoped from the model (prefix stripped).
std::string Reader::LocalName(const ModelBuild& b, int i) const {
  const std::string& name = nodes_[i].name;
  return name.rfind(b.prefix, 0) == 0 ? name.substr(b.prefix.size()) : name;
}

// Reads the links whose pose resolves: into the model, their poses into b->X_TB and frames.
void Reader::ReadModelLinks(ModelBuild* b, Model* model, SdfModelFrames* frames) {
  for (int i : b->order) {
    if (nodes_[i].kind != Node::Kind::kLink) continue;
    const std::optional<Pose> X = PoseInScope(i, b->top, 0);
    if (!X) continue;
    b->X_TB[i] = *X;
    frames->X_MB.push_back(*X);
    Link link;
    link.name = LocalName(*b, i);
    link.location = nodes_[i].location;
    if (nodes_[i].element != nullptr && Attr(nodes_[i].element, "name") == "world") {
      // libsdformat: "The supplied link name [world] is reserved." (it refuses the file). Here
      // the link is read like any other, so a joint whose <parent> is world hangs from it, where
      // SDFormat means the world frame: say so (bullet3's wsg50 gripper, written for PyBullet).
      Warning(nodes_[i].location.file, nodes_[i].element, "<link> 'world'",
              "the name 'world' is reserved in SDFormat (libsdformat refuses the file); massprops "
              "reads it as an ordinary link, so a joint whose <parent> is world hangs from this "
              "link, not from the world frame: rename the link");
    }
    ReadLinkContents(i, b->top, *X, &link);
    model->links.push_back(std::move(link));
  }
}

// Reads the models' joints in file order, then the world joints, into the model.
void Reader::ReadModelJoints(const ModelBuild& b, const std::vector<int>& world_joints,
                             Model* model) {
  std::vector<int> joint_nodes;
  for (int i : b.order) {
    if (nodes_[i].kind == Node::Kind::kJoint) joint_nodes.push_back(i);
  }
  joint_nodes.insert(joint_nodes.end(), world_joints.begin(), world_joints.end());
  for (int i : joint_nodes) {
    Joint joint;
    if (ReadJoint(b, i, &joint)) model->joints.push_back(std::move(joint));
  }
}

// Reads joint node i: its type, links, pose and axis. False (reported, or skipped when the
// model's pose in the world is unknown) if the joint cannot be built.
bool Reader::ReadJoint(const ModelBuild& b, int i, Joint* joint) {
  const Node& n = nodes_[i];
  joint->name = LocalName(b, i);
  joint->location = n.location;
  joint->type_name = Attr(n.element, "type");
  joint->type = JointType(joint->type_name);
  const std::string what = Describe(n);
  const int c = AttachedLink(Lookup(n.child, n.scope), 0);
  std::string which;
  if (c < 0 && InUnresolvedInclude(n.child, n.scope, &which)) {
    ReportUnresolvedReference(i, n.child, which);
    return false;
  }
  if (n.parent != "world" && AttachedLink(Lookup(n.parent, n.scope), 0) < 0 &&
      InUnresolvedInclude(n.parent, n.scope, &which)) {
    ReportUnresolvedReference(i, n.parent, which);
    return false;
  }
  if (n.child == "world" || c < 0 || !b.X_TB.count(c)) {
    Error(n.location.file, n.element, what, "the child '" + n.child + "' is not a link");
    return false;
  }
  joint->child = LocalName(b, c);
  const Pose& X_TC = b.X_TB.at(c);
  if (n.parent == "world") {
    joint->parent = "world";
    if (!b.X_WT) return false;
    joint->X_PC = *b.X_WT * X_TC;
  } else {
    const int p = AttachedLink(Lookup(n.parent, n.scope), 0);
    if (p < 0 || !b.X_TB.count(p)) {
      Error(n.location.file, n.element, what, "the parent '" + n.parent + "' is not a link");
      return false;
    }
    joint->parent = LocalName(b, p);
    joint->X_PC = b.X_TB.at(p).Inverse() * X_TC;
  }
  const std::optional<Eigen::Vector3d> axis_C = ReadJointAxis(b, i, what, X_TC);
  if (!axis_C) return false;
  joint->axis = *axis_C;
  return true;
}

// Axis: <axis><xyz> (default 0 0 1) in the frame E it is expressed in, re-expressed in the child
// link C and normalized. Nothing (reported) if the frame E is not found.
std::optional<Eigen::Vector3d> Reader::ReadJointAxis(const ModelBuild& b, int i,
                                                     const std::string& what, const Pose& X_TC) {
  const Node& n = nodes_[i];
  Context ctx{n.location.file, n.version, 0, n.merge_proxy};
  const XMLElement* axis = n.element->FirstChildElement("axis");
  const XMLElement* xyz = axis ? axis->FirstChildElement("xyz") : nullptr;
  const Eigen::Vector3d axis_E =
      Vector(xyz, Eigen::Vector3d::UnitZ(), ctx, "<axis><xyz> of " + what);
  int expressed_in = i;  // The joint frame.
  const std::string e = xyz ? Attr(xyz, "expressed_in") : "";
  if (!e.empty()) {
    expressed_in = Lookup(e == "__model__" && !n.merge_proxy.empty() ? n.merge_proxy : e, n.scope);
  }
  if (!n.version.AtLeast(1, 7) && axis != nullptr) {
    // The 1.6->1.7 converter maps use_parent_model_frame=true to expressed_in="__model__".
    const std::string f = Text(axis->FirstChildElement("use_parent_model_frame"));
    if (n.axis_in_model_frame_1_4 || f == "true" || f == "1" || f == "True" || f == "TRUE") {
      expressed_in = n.scope;
    }
  }
  const std::optional<Pose> X_TE = PoseInModel(b, expressed_in);
  if (!X_TE) {
    Error(n.location.file, xyz, "<axis><xyz> of " + what,
          "the frame named by expressed_in is not found");
    return std::nullopt;
  }
  Eigen::Vector3d axis_C = X_TC.R_AB.transpose() * X_TE->R_AB * axis_E;
  if (axis_C.norm() == 0) {
    Warning(n.location.file, xyz, "<axis><xyz> of " + what, "the axis has zero length");
  } else {
    axis_C.normalize();
  }
  return axis_C;
}

// Root: the canonical link if it is no joint's child, else the first link that is none. Joints
// to the world do not count (they fix the model in the world; its tree still starts there).
void Reader::SetRootLink(const ModelBuild& b, const std::vector<int>& tops, Model* model) const {
  std::unordered_set<std::string> children;
  for (const Joint& j : model->joints) {
    if (j.parent != "world") children.insert(j.child);
  }
  auto is_child = [&](const std::string& name) { return children.count(name) > 0; };
  auto inside = [&](int i) { return std::find(tops.begin(), tops.end(), TopOf(i)) != tops.end(); };
  const int canonical = AttachedLink(tops[0], 0);
  if (canonical >= 0 && inside(canonical) && !is_child(LocalName(b, canonical))) {
    model->root_link = LocalName(b, canonical);
  } else {
    for (const Link& l : model->links) {
      if (!is_child(l.name)) {
        model->root_link = l.name;
        break;
      }
    }
  }
}

}  // namespace massprops::internal::sdf_reader
