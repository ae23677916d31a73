// The SDF reader's poses and frames (reader.h): each node's pose in its model's frame, resolved
// lazily through relative_to, attached_to and placement_frame, with cycles and missing frames
// reported; the link a frame is attached to.
#include "io/sdf/reader.h"

namespace massprops::internal::sdf_reader {

std::optional<Pose> Reader::PoseInScope(int target, int scope, int depth) {
  Pose X;
  while (target != scope) {
    if (target == kWorld || target == kNotFound) return std::nullopt;
    const std::optional<Pose> X_local = Resolve(target, depth + 1);
    if (!X_local) return std::nullopt;
    X = *X_local * X;
    target = nodes_[target].scope;
  }
  return X;
}

std::optional<Pose> Reader::Resolve(int i, int depth) {
  Node& n = nodes_[i];
  if (n.state == 2) return n.X_SF;
  if (n.state == 3) return std::nullopt;
  const std::string file = n.location.file;
  if (n.state == 1 || depth > kMaxResolveDepth) {
    Error(file, n.element, Describe(n),
          n.state == 1 ? "the poses form a cycle through '" + n.name + "' (relative_to)"
                       : "relative_to chain deeper than " + std::to_string(kMaxResolveDepth));
    n.state = 3;
    return std::nullopt;
  }
  n.state = 1;
  std::string ref = n.relative_to;
  if (ref.empty()) {
    if (n.kind == Node::Kind::kFrame) ref = n.attached_to;
    if (n.kind == Node::Kind::kJoint) ref = n.child;
  }
  int target = ref.empty() ? n.scope : Lookup(ref, n.scope);
  std::string which;
  if (target == kNotFound && InUnresolvedInclude(ref, n.scope, &which)) {
    ReportUnresolvedReference(i, ref, which);
    nodes_[i].state = 3;
    return std::nullopt;
  }
  if (target == kNotFound) {
    Error(file, n.element, Describe(n),
          "the frame '" + ref + "' named by its pose (relative_to/attached_to/child) is not found");
    nodes_[i].state = 3;
    return std::nullopt;
  }
  if (target == i) {
    Error(file, nodes_[i].element, Describe(nodes_[i]), "its pose is relative to itself");
    nodes_[i].state = 3;
    return std::nullopt;
  }
  std::optional<Pose> X_ST = PoseInScope(target, nodes_[i].scope, depth);
  if (!X_ST) {
    nodes_[i].state = 3;
    return std::nullopt;
  }
  Pose X_SF = *X_ST * nodes_[i].X_raw;
  if (nodes_[i].kind == Node::Kind::kModel && !nodes_[i].placement_frame.empty()) {
    const int p = Lookup(nodes_[i].placement_frame, i);
    std::optional<Pose> X_MP;
    if (p == kNotFound) {
      Error(file, nodes_[i].element, Describe(nodes_[i]),
            "the placement_frame '" + nodes_[i].placement_frame + "' is not found");
    } else {
      X_MP = PoseInScope(p, i, depth);
    }
    if (!X_MP) {
      nodes_[i].state = 3;
      return std::nullopt;
    }
    X_SF = X_SF * X_MP->Inverse();
  }
  nodes_[i].X_SF = X_SF;
  nodes_[i].state = 2;
  return X_SF;
}

int Reader::AttachedLink(int i, int depth) const {
  if (i < 0 || depth > kMaxResolveDepth) return kNotFound;
  const Node& n = nodes_[i];
  switch (n.kind) {
    case Node::Kind::kLink:
      return i;
    case Node::Kind::kJoint:
      return AttachedLink(Lookup(n.child, n.scope), depth + 1);
    case Node::Kind::kFrame: {
      if (n.attached_to.empty()) {
        return n.scope == kWorld ? kNotFound : AttachedLink(n.scope, depth + 1);
      }
      return AttachedLink(Lookup(n.attached_to, n.scope), depth + 1);
    }
    case Node::Kind::kModel: {
      if (!n.canonical_link.empty()) {
        return AttachedLink(Lookup(n.canonical_link, i), depth + 1);
      }
      for (int m : n.members) {
        if (nodes_[m].kind == Node::Kind::kLink) return m;
      }
      for (int m : n.members) {  // No link: the first nested model's canonical link.
        const int l = AttachedLink(m, depth + 1);
        if (l >= 0) return l;
      }
      return kNotFound;
    }
  }
  return kNotFound;
}

bool Reader::ResolveInLink(const XMLElement* pose, int link_index, int top, const Pose& X_TB,
                           const Context& ctx, const std::string& what, Pose* X_BF) {
  const Pose X_raw = ParsePose(pose, ctx, "<pose> of " + what);
  const std::string rel = RelativeTo(pose, ctx.version);
  if (rel.empty()) {
    *X_BF = X_raw;
    return true;
  }
  const int scope = nodes_[link_index].scope;
  const int target = Lookup(rel, scope);
  if (target == kNotFound) {
    Error(ctx.file, pose, "<pose> of " + what, "the frame '" + rel + "' is not found");
    return false;
  }
  const std::optional<Pose> X_TR = PoseInScope(target, top, 0);
  if (!X_TR) return false;
  *X_BF = X_TB.Inverse() * *X_TR * X_raw;
  return true;
}

// A frame's pose in T; for a frame outside the model (a world joint's) through the world.
std::optional<Pose> Reader::PoseInModel(const ModelBuild& b, int f) {
  if (f == kNotFound) return std::nullopt;
  if (b.top == kWorld) return PoseInScope(f, kWorld, 0);
  if (f != kWorld && TopOf(f) == b.top) return PoseInScope(f, b.top, 0);
  const std::optional<Pose> X_WF = f == kWorld ? Pose() : PoseInScope(f, kWorld, 0);
  if (!X_WF || !b.X_WT) return std::nullopt;
  return b.X_WT->Inverse() * *X_WF;
}

}  // namespace massprops::internal::sdf_reader
