// Reading SDFormat into massprops Models (see sdf_reader.h).
//
// The reader walks the XML once (plus the files that <include> pulls in) and records every
// frame-bearing element (model, link, joint, frame) as a node of one pose graph, named by its scope
// from the file's root ("model::nested::link"). Poses are resolved lazily, each in the frame of the
// model that contains the element, following libsdformat 12:
//   - a link, a nested model and a frame without attached_to default to the containing model frame;
//   - a frame with attached_to defaults to that frame; a joint defaults to its child frame;
//   - a model's placement_frame P turns the given pose X_RP into X_RM = X_RP * X_MP^-1;
//   - SDF < 1.7: the pose attribute "frame" is read as relative_to (libsdformat's 1.6->1.7
//     converter renames it); the joint axis <xyz> is expressed in the model frame for SDF 1.4
//     joints of top-level models (the 1.4->1.5 converter adds use_parent_model_frame=true) and when
//     <use_parent_model_frame> is true (1.5, 1.6), else in the joint frame;
//   - SDF >= 1.7: <xyz expressed_in="..."> names the frame, default the joint frame.

#include "massprops/io/sdf_reader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "io/sdf_values.h"
#include "massprops/io/auto_inertia.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;
using internal::Attr;
using internal::Text;
using tinyxml2::XMLComment;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

constexpr int kWorld = -1;     // The world (or the root of a file holding a lone model).
constexpr int kNotFound = -2;  // A reference that names nothing.
constexpr int kMaxResolveDepth = 1000;
constexpr int kMaxNestingDepth = 100;

struct Version {
  int major = 1;
  int minor = 0;
  bool AtLeast(int a, int b) const { return major > a || (major == a && minor >= b); }
};

struct Node {
  enum class Kind { kModel, kLink, kJoint, kFrame };
  Kind kind = Kind::kLink;
  std::string name;  // Scoped from the root: "top::nested::link".
  int scope = kWorld;
  Version version;
  std::string relative_to;  // As written; "" = default.
  Pose X_raw;
  std::string attached_to;      // kFrame.
  std::string placement_frame;  // kModel.
  std::string canonical_link;   // kModel.
  bool is_static = false;       // kModel: <static>true</static> (of the model or its <include>).
  const XMLElement* element = nullptr;
  SourceLocation location;
  int state = 0;  // 0 = unresolved, 1 = resolving, 2 = resolved.
  Pose X_SF;      // Pose in the frame of the containing model (or the world).
  // kJoint:
  std::string parent, child;
  // kModel: the link and model nodes directly inside, in file order.
  std::vector<int> members;
  bool axis_in_model_frame_1_4 = false;  // kJoint of a top-level SDF 1.4 model.
  // Read from a model merged into its parent (<include merge="true">): "__model__" of the merged
  // model means this proxy frame of the parent scope.
  std::string merge_proxy;
};

std::string Describe(const Node& node) {
  switch (node.kind) {
    case Node::Kind::kModel:
      return "<model> '" + node.name + "'";
    case Node::Kind::kLink:
      return "<link> '" + node.name + "'";
    case Node::Kind::kJoint:
      return "<joint> '" + node.name + "'";
    case Node::Kind::kFrame:
      return "<frame> '" + node.name + "'";
  }
  return "";
}

std::string Trim(std::string_view s) {
  const char* ws = " \t\r\n";
  const size_t b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return "";
  const size_t e = s.find_last_not_of(ws);
  return std::string(s.substr(b, e - b + 1));
}

bool ParseVersion(const std::string& text, Version* v) {
  const std::string t = Trim(text);
  const char* b = t.data();
  const char* end = t.data() + t.size();
  auto r = std::from_chars(b, end, v->major);
  if (r.ec != std::errc() || r.ptr == end || *r.ptr != '.') return false;
  r = std::from_chars(r.ptr + 1, end, v->minor);
  return r.ec == std::errc() && r.ptr == end;
}

/// State of one read: the pose graph, the errors, the include stack.
class Reader {
 public:
  Reader(const SdfReadOptions& options, std::string top_file)
      : options_(options), top_file_(std::move(top_file)) {
    search_paths_ = options.model_paths;
    if (options.use_environment) {
      for (const char* var :
           {"SDF_PATH", "GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "GAZEBO_MODEL_PATH"}) {
        const char* value = std::getenv(var);
        if (value == nullptr) continue;
        std::stringstream ss(value);
        std::string item;
        while (std::getline(ss, item, ':')) {
          if (!item.empty()) search_paths_.push_back(item);
        }
      }
    }
  }

  ReadResult Read(const std::string& xml, const std::string& file_name,
                  std::vector<SdfModelFrames>* frames);

 private:
  struct Context {
    std::string file;
    Version version;
    int depth = 0;
    std::string merge_proxy;  // Reading the children of a merged include (see Node).
  };

  // While a link's <inertial> is read, number and pose errors are diverted here: they cost the
  // link (inertial-unreadable), not the file.
  struct Diversion {
    bool active = false;
    bool failed = false;
    SourceLocation location;
    std::string element;
    std::string message;
  };

  // ------------------------------------------------------------ errors
  void Error(const std::string& file, const XMLElement* e, const std::string& element,
             const std::string& message) {
    if (diversion_.active) {
      if (!diversion_.failed) {
        diversion_.failed = true;
        diversion_.location = {file, e ? e->GetLineNum() : 0, 0};
        diversion_.element = element;
        diversion_.message = message;
      }
      return;
    }
    result_.errors.push_back(MakeReadError(file, e ? e->GetLineNum() : 0, element, message));
  }
  void Warning(const std::string& file, const XMLElement* e, const std::string& element,
               const std::string& message) {
    result_.warnings.push_back(MakeReadError(file, e ? e->GetLineNum() : 0, element, message));
  }

  // ------------------------------------------------------------ numbers

  /// Reads one number from element `e` (text), or `fallback` when e is null.
  double Number(const XMLElement* e, double fallback, const Context& ctx,
                const std::string& element) {
    if (e == nullptr) return fallback;
    std::vector<double> v;
    std::string why;
    if (!internal::ParseSdfNumbers(Text(e), 1, 1, &v, &why)) {
      Error(ctx.file, e, element, why);
      return fallback;
    }
    return v[0];
  }

  Eigen::Vector3d Vector(const XMLElement* e, const Eigen::Vector3d& fallback, const Context& ctx,
                         const std::string& element) {
    if (e == nullptr) return fallback;
    std::vector<double> v;
    std::string why;
    if (!internal::ParseSdfNumbers(Text(e), 3, 3, &v, &why)) {
      Error(ctx.file, e, element, why);
      return fallback;
    }
    return {v[0], v[1], v[2]};
  }

  /// Parses a <pose> element (nullptr: identity).
  Pose ParsePose(const XMLElement* e, const Context& ctx, const std::string& element) {
    if (e == nullptr) return Pose();
    const std::string text = Text(e);
    if (text.empty()) return Pose();
    const bool v19 = ctx.version.AtLeast(1, 9);
    const std::string degrees = v19 ? Attr(e, "degrees") : "";
    std::string why;
    const std::optional<Pose> X = internal::ParseSdfPose(
        text, v19 ? Attr(e, "rotation_format") : "", degrees == "true" || degrees == "1", &why);
    if (!X) {
      Error(ctx.file, e, element, why);
      return Pose();
    }
    return *X;
  }

  /// relative_to of a pose element. SDF < 1.7: libsdformat's 1.6->1.7 converter moves the
  /// "frame" attribute to relative_to, and keeps a relative_to already written (honored too).
  static std::string RelativeTo(const XMLElement* pose, const Version& v) {
    if (pose == nullptr) return "";
    if (!v.AtLeast(1, 7) && pose->Attribute("frame") != nullptr) return Attr(pose, "frame");
    return Attr(pose, "relative_to");
  }

  // ------------------------------------------------------------ graph building
  std::string Prefix(int scope) const { return scope == kWorld ? "" : nodes_[scope].name + "::"; }

  int AddNode(Node node, const Context& ctx) {
    if (aborted_) return kNotFound;
    if (include_stack_.size() > 1 && ++included_elements_ > options_.max_included_elements) {
      aborted_ = true;
      const IncludeSite& outer = include_sites_.front();
      result_.errors.push_back(MakeReadError(
          outer.file, outer.line, "<include> '" + outer.uri + "'",
          "the includes bring in more than " + std::to_string(options_.max_included_elements) +
              " elements (links, joints, frames, models; the limit max_included_elements): " +
              OutermostInclude() + " expands without bound (models that include others " +
              "several times grow exponentially); reading stopped at " + Describe(node) + " of " +
              ctx.file));
      return kNotFound;
    }
    if (!ctx.merge_proxy.empty()) ApplyMerge(&node, ctx.merge_proxy);
    const int index = static_cast<int>(nodes_.size());
    auto [it, inserted] = by_name_.emplace(node.name, index);
    if (!inserted) {
      const Node& other = nodes_[it->second];
      const bool same_kind = other.kind == node.kind;
      if (same_kind || node.version.AtLeast(1, 7)) {
        Error(ctx.file, node.element, Describe(node),
              "the name '" + node.name + "' is already used by " + Describe(other) + " (line " +
                  std::to_string(other.location.line) + ")");
        return kNotFound;
      }
      // SDF < 1.7 lets a joint share a link's name: links win the lookup.
      if (node.kind == Node::Kind::kLink) it->second = index;
    }
    nodes_.push_back(std::move(node));
    return index;
  }

  /// A node read from a model merged into the enclosing one: its references to the merged model's
  /// frame ("__model__", or the default) name the proxy frame instead (libsdformat's
  /// "_merged__NAME__model__").
  static void ApplyMerge(Node* node, const std::string& proxy) {
    node->merge_proxy = proxy;
    for (std::string* ref : {&node->relative_to, &node->attached_to, &node->parent, &node->child}) {
      if (*ref == "__model__") *ref = proxy;
    }
    if (node->relative_to.empty()) {
      if (node->kind == Node::Kind::kLink || node->kind == Node::Kind::kModel) {
        node->relative_to = proxy;
      } else if (node->kind == Node::Kind::kFrame && node->attached_to.empty()) {
        node->attached_to = proxy;
      }
    }
  }

  void ReadWorld(const XMLElement* world, const Context& ctx) {
    for (const XMLElement* c = world->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "model") {
        const int m = ReadModel(c, kWorld, ctx, nullptr);
        if (m >= 0) top_models_.push_back(m);
      } else if (tag == "include") {
        const int m = ReadInclude(c, kWorld, ctx);
        if (m >= 0) top_models_.push_back(m);
      } else if (tag == "frame") {
        ReadFrame(c, kWorld, ctx);
      } else if (tag == "joint") {
        if (ctx.version.AtLeast(1, 10)) {  // World joints: SDF 1.10 (sdf/1.10/world.sdf).
          const size_t before = nodes_.size();
          ReadJoint(c, kWorld, ctx);
          if (nodes_.size() > before) world_joints_.push_back(static_cast<int>(before));
        } else {
          Warning(ctx.file, c, "<joint> '" + Attr(c, "name") + "'",
                  "joints directly in a <world> exist from SDF 1.10; not read in SDF " +
                      std::to_string(ctx.version.major) + "." + std::to_string(ctx.version.minor));
        }
      }
    }
  }

  /// Reads a <model>; `include` (may be null) is the <include> that brought it in, whose <name>,
  /// <pose> and <placement_frame> override the model's own. Returns the node index or kNotFound.
  int ReadModel(const XMLElement* model, int scope, const Context& ctx, const XMLElement* include) {
    if (aborted_) return kNotFound;
    if (ctx.depth > kMaxNestingDepth) {
      Error(ctx.file, model, "<model>",
            "models nested deeper than " + std::to_string(kMaxNestingDepth) + " levels");
      return kNotFound;
    }
    std::string name = Attr(model, "name");
    const XMLElement* pose = model->FirstChildElement("pose");
    const Version* pose_version = &ctx.version;
    std::string placement = Attr(model, "placement_frame");
    if (include != nullptr) {
      if (const XMLElement* n = include->FirstChildElement("name")) name = Text(n);
      if (const XMLElement* p = include->FirstChildElement("pose")) {
        pose = p;
        pose_version = &include_version_;
      }
      if (const XMLElement* pf = include->FirstChildElement("placement_frame")) {
        placement = Text(pf);
      }
    }
    if (name.empty()) {
      Error(ctx.file, model, "<model>", "a <model> needs a name attribute");
      return kNotFound;
    }
    Node node;
    node.kind = Node::Kind::kModel;
    node.name = Prefix(scope) + name;
    node.scope = scope;
    node.version = ctx.version;
    node.element = model;
    node.location = {ctx.file, model->GetLineNum(), 0};
    Context pose_ctx = ctx;
    pose_ctx.version = *pose_version;
    if (include != nullptr && pose != model->FirstChildElement("pose")) {
      pose_ctx.file = include_file_;
    }
    node.X_raw = ParsePose(pose, pose_ctx, "<pose> of <model> '" + name + "'");
    node.relative_to = RelativeTo(pose, *pose_version);
    node.placement_frame = placement;
    node.canonical_link = Attr(model, "canonical_link");
    // <static> of the <include> overrides the model's own; SDF booleans are "true"/"1".
    const XMLElement* static_element = model->FirstChildElement("static");
    if (include != nullptr && include->FirstChildElement("static") != nullptr) {
      static_element = include->FirstChildElement("static");
    }
    if (static_element != nullptr) {
      const std::string value = Text(static_element);
      node.is_static = value == "true" || value == "1";
    }
    const int index = AddNode(std::move(node), ctx);
    if (index < 0) return index;
    if (scope != kWorld) nodes_[scope].members.push_back(index);

    Context own = ctx;  // Inside the model, "__model__" is this model again.
    own.merge_proxy.clear();
    ReadModelChildren(model, index, own);
    return index;
  }

  void ReadModelChildren(const XMLElement* model, int scope, const Context& ctx) {
    Context inner = ctx;
    inner.depth = ctx.depth + 1;
    for (const XMLElement* c = model->FirstChildElement(); c && !aborted_;
         c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "link") {
        ReadLink(c, scope, ctx);
      } else if (tag == "joint") {
        ReadJoint(c, scope, ctx);
      } else if (tag == "frame") {
        ReadFrame(c, scope, ctx);
      } else if (tag == "model") {
        ReadModel(c, scope, inner, nullptr);
      } else if (tag == "include") {
        ReadInclude(c, scope, inner);
      }
    }
  }

  void ReadFrame(const XMLElement* frame, int scope, const Context& ctx) {
    Node node;
    node.kind = Node::Kind::kFrame;
    const std::string name = Attr(frame, "name");
    if (name.empty()) {
      Error(ctx.file, frame, "<frame>", "a <frame> needs a name attribute");
      return;
    }
    node.name = Prefix(scope) + name;
    node.scope = scope;
    node.version = ctx.version;
    node.element = frame;
    node.location = {ctx.file, frame->GetLineNum(), 0};
    node.attached_to = Attr(frame, "attached_to");
    const XMLElement* pose = frame->FirstChildElement("pose");
    node.X_raw = ParsePose(pose, ctx, "<pose> of <frame> '" + name + "'");
    node.relative_to = RelativeTo(pose, ctx.version);
    AddNode(std::move(node), ctx);
  }

  void ReadJoint(const XMLElement* joint, int scope, const Context& ctx) {
    Node node;
    node.kind = Node::Kind::kJoint;
    const std::string name = Attr(joint, "name");
    if (name.empty()) {
      Error(ctx.file, joint, "<joint>", "a <joint> needs a name attribute");
      return;
    }
    const std::string what = "<joint> '" + name + "'";
    if (joint->Attribute("type") == nullptr) {
      Error(ctx.file, joint, what, "a <joint> needs a type attribute");
      return;
    }
    node.name = Prefix(scope) + name;
    node.scope = scope;
    node.version = ctx.version;
    node.element = joint;
    node.location = {ctx.file, joint->GetLineNum(), 0};
    const XMLElement* parent = joint->FirstChildElement("parent");
    const XMLElement* child = joint->FirstChildElement("child");
    if (parent == nullptr || Text(parent).empty()) {
      Error(ctx.file, joint, what, "a <joint> needs a <parent>");
      return;
    }
    if (child == nullptr || Text(child).empty()) {
      Error(ctx.file, joint, what, "a <joint> needs a <child>");
      return;
    }
    node.parent = Text(parent);
    node.child = Text(child);
    const XMLElement* pose = joint->FirstChildElement("pose");
    node.X_raw = ParsePose(pose, ctx, "<pose> of " + what);
    node.relative_to = RelativeTo(pose, ctx.version);
    // libsdformat's 1.4->1.5 converter adds use_parent_model_frame=true to the joints of
    // //sdf/model and //world/model (not of deeper nested models).
    const XMLNode* model_parent = joint->Parent() ? joint->Parent()->Parent() : nullptr;
    const bool top_level = model_parent != nullptr && model_parent->ToElement() != nullptr &&
                           (std::string(model_parent->ToElement()->Name()) == "sdf" ||
                            std::string(model_parent->ToElement()->Name()) == "world");
    node.axis_in_model_frame_1_4 = top_level && !ctx.version.AtLeast(1, 5);
    AddNode(std::move(node), ctx);
  }

  void ReadLink(const XMLElement* link, int scope, const Context& ctx) {
    Node node;
    node.kind = Node::Kind::kLink;
    const std::string name = Attr(link, "name");
    if (name.empty()) {
      Error(ctx.file, link, "<link>", "a <link> needs a name attribute");
      return;
    }
    node.name = Prefix(scope) + name;
    node.scope = scope;
    node.version = ctx.version;
    node.element = link;
    node.location = {ctx.file, link->GetLineNum(), 0};
    const XMLElement* pose = link->FirstChildElement("pose");
    node.X_raw = ParsePose(pose, ctx, "<pose> of <link> '" + name + "'");
    node.relative_to = RelativeTo(pose, ctx.version);
    const int index = AddNode(std::move(node), ctx);
    if (index < 0) return;
    nodes_[scope].members.push_back(index);
    link_files_.emplace(index, ctx);
  }

  /// Resolves an <include>: returns the node of the model it brings in, or kNotFound.
  int ReadInclude(const XMLElement* include, int scope, const Context& ctx);

  std::optional<std::string> FindModelFile(const std::string& uri, const std::string& base_dir,
                                           std::string* why);

  // ------------------------------------------------------------ pose resolution
  /// The node named `ref` as seen from inside `scope`; kWorld for the scope's own frame
  /// ("__model__", or "world" at the root); kNotFound when it names nothing.
  int Lookup(const std::string& ref, int scope) const {
    if (ref == "__model__") return scope;
    if (scope == kWorld && ref == "world") return kWorld;
    const auto it = by_name_.find(Prefix(scope) + ref);
    return it == by_name_.end() ? kNotFound : it->second;
  }

  /// Pose of node (or scope) `target` in the frame of `scope`, which must contain it.
  std::optional<Pose> PoseInScope(int target, int scope, int depth) {
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

  /// Pose of node i in the frame of its containing model (or the world); nullopt after an error.
  std::optional<Pose> Resolve(int i, int depth) {
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
      Error(
          file, n.element, Describe(n),
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

  /// The link node that frame `i` is attached to (kNotFound if none).
  int AttachedLink(int i, int depth) const {
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

  void BuildModels();
  void BuildModel(const std::vector<int>& tops, const std::vector<int>& world_joints);
  // The models being built into one Model (see BuildModel), as its steps share them.
  struct ModelBuild {
    int top = kWorld;        // The model frame: the model's, or the world's.
    std::string prefix;      // Stripped from scoped names ("" for models joined in the world).
    std::vector<int> order;  // The nodes of the models, in file order (each contiguous).
    std::unordered_map<int, Pose> X_TB;  // Link poses in the model frame T.
    std::optional<Pose> X_WT;            // The model frame in the world (once resolved).
  };
  Model StartModel(const std::vector<int>& tops) const;
  std::vector<int> ModelNodeOrder(const std::vector<int>& tops) const;
  std::string LocalName(const ModelBuild& b, int i) const;
  void ReadModelLinks(ModelBuild* b, Model* model, SdfModelFrames* frames);
  std::optional<Pose> PoseInModel(const ModelBuild& b, int f);
  void ReadModelJoints(const ModelBuild& b, const std::vector<int>& world_joints, Model* model);
  bool ReadJoint(const ModelBuild& b, int i, Joint* joint);
  std::optional<Eigen::Vector3d> ReadJointAxis(const ModelBuild& b, int i, const std::string& what,
                                               const Pose& X_TC);
  void SetRootLink(const ModelBuild& b, const std::vector<int>& tops, Model* model) const;
  int TopOf(int i) const {
    if (i < 0) return i;
    while (nodes_[i].scope != kWorld) i = nodes_[i].scope;
    return i;
  }
  void ReadLinkContents(int link_index, int top, const Pose& X_TB, Link* link);
  void ReadExplicitInertial(const XMLElement* in, int link_index, int top, const Pose& X_TB,
                            const Context& ctx, Link* link);
  Geometry ReadGeometry(const XMLElement* c, int link_index, int top, const Pose& X_TB,
                        const Context& ctx, const std::string& lname);
  void ReadShape(const XMLElement* shape, const Context& ctx, const std::string& swhat,
                 Geometry* g);
  bool ResolveInLink(const XMLElement* pose, int link_index, int top, const Pose& X_TB,
                     const Context& ctx, const std::string& what, Pose* X_BF);

  struct IncludeSite {
    std::string file;
    int line = 0;
    std::string uri;
  };
  struct Unresolved {
    std::string scoped;  // The name the missing model would have had, scoped from the root.
    std::string uri;
    std::string file;
    int line = 0;
  };
  std::string OutermostInclude() const;
  void ReportUnresolvedInclude(const XMLElement* include, int scope, const Context& ctx,
                               const std::string& uri, const std::string& why);
  bool InUnresolvedInclude(const std::string& ref, int scope, std::string* which) const;
  void ReportUnresolvedReference(int i, const std::string& ref, const std::string& which);
  int ReadMergedModel(const XMLElement* model, int scope, const Context& ctx,
                      const XMLElement* include);
  void ReadAutoInertial(const XMLElement* inertial, int link_index, int top, const Pose& X_TB,
                        const Context& ctx, Link* link);

  SdfReadOptions options_;
  Diversion diversion_;
  bool aborted_ = false;
  long included_elements_ = 0;
  std::vector<IncludeSite> include_sites_;
  std::vector<Unresolved> unresolved_;
  std::set<int> reported_unresolved_;
  std::unordered_map<std::string, std::pair<std::optional<std::string>, std::string>> resolved_;
  std::unordered_map<std::string, std::string> canonical_;
  std::unordered_map<std::string, std::unique_ptr<XMLDocument>> included_docs_;
  std::unique_ptr<MeshCache> mesh_cache_;
  std::string current_model_name_;  // The Model being built (for findings).
  std::vector<int> world_joints_;   // <joint> nodes directly in a <world> (SDF 1.10+).
  std::string top_file_;
  std::vector<std::string> search_paths_;
  ReadResult result_;
  std::vector<Node> nodes_;
  std::unordered_map<std::string, int> by_name_;
  std::vector<int> top_models_;
  std::vector<SdfModelFrames> frames_;
  std::map<int, Context> link_files_;
  std::vector<std::unique_ptr<XMLDocument>> documents_;
  std::vector<std::string> include_stack_;
  Version include_version_;
  std::string include_file_;
};

bool ReadWholeFile(const std::string& path, std::string* text, std::string* why) {
  if (path == "-") {
    std::string data;
    char buffer[65536];
    while (std::cin.read(buffer, sizeof buffer) || std::cin.gcount() > 0) {
      data.append(buffer, static_cast<size_t>(std::cin.gcount()));
      if (data.size() > kMaxSdfFileBytes) {
        *why = "standard input is larger than the limit of " + std::to_string(kMaxSdfFileBytes) +
               " bytes";
        return false;
      }
    }
    *text = std::move(data);
    return true;
  }
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    *why = "is a directory, not a file";
    return false;
  }
  const auto size = fs::file_size(path, ec);
  if (ec) {
    *why = "cannot read the file: " + ec.message();
    return false;
  }
  if (size > kMaxSdfFileBytes) {
    *why = "the file has " + std::to_string(size) + " bytes, more than the limit of " +
           std::to_string(kMaxSdfFileBytes);
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *why = "cannot open the file";
    return false;
  }
  text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (text->size() > kMaxSdfFileBytes) {
    *why = "the file is larger than the limit of " + std::to_string(kMaxSdfFileBytes) + " bytes";
    return false;
  }
  return true;
}

/// Parses `xml` into `doc`; on failure returns the error (line in `line`).
bool ParseXml(const std::string& xml, XMLDocument* doc, std::string* why, int* line) {
  if (Trim(xml).empty()) {
    *why = "the file is empty";
    *line = 0;
    return false;
  }
  if (doc->Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    *why = std::string("malformed XML: ") + doc->ErrorName();
    const char* detail = doc->ErrorStr();
    if (detail != nullptr) *why += std::string(" (") + detail + ")";
    *line = doc->ErrorLineNum();
    return false;
  }
  return true;
}

std::optional<std::string> Reader::FindModelFile(const std::string& uri_in,
                                                 const std::string& base_dir, std::string* why) {
  std::string uri = uri_in;
  std::vector<fs::path> candidates;
  if (uri.rfind("http://", 0) == 0 || uri.rfind("https://", 0) == 0) {
    *why = "remote URIs (Fuel) are not fetched";
    return std::nullopt;
  }
  if (uri.rfind("file://", 0) == 0) uri = uri.substr(7);
  if (uri.rfind("model://", 0) == 0) {
    const std::string rest = uri.substr(8);
    for (const std::string& dir : search_paths_) candidates.push_back(fs::path(dir) / rest);
  } else if (fs::path(uri).is_absolute()) {
    candidates.emplace_back(uri);
  } else {
    candidates.push_back(fs::path(base_dir) / uri);
    for (const std::string& dir : search_paths_) candidates.push_back(fs::path(dir) / uri);
  }
  std::error_code ec;
  for (const fs::path& c : candidates) {
    if (fs::is_regular_file(c, ec)) return c.string();
    if (!fs::is_directory(c, ec)) continue;
    const fs::path config = c / "model.config";
    if (fs::is_regular_file(config, ec)) {
      std::string text;
      std::string config_why;
      XMLDocument doc;
      int line = 0;
      if (ReadWholeFile(config.string(), &text, &config_why) &&
          ParseXml(text, &doc, &config_why, &line) && doc.RootElement() != nullptr) {
        std::string best;
        Version best_version{-1, -1};
        for (const XMLElement* s = doc.RootElement()->FirstChildElement("sdf"); s;
             s = s->NextSiblingElement("sdf")) {
          Version v{0, 0};
          if (!ParseVersion(Attr(s, "version"), &v)) v = Version{0, 0};
          if (best.empty() || !best_version.AtLeast(v.major, v.minor) ||
              (v.major == best_version.major && v.minor == best_version.minor && best.empty())) {
            if (!Text(s).empty()) {
              best = Text(s);
              best_version = v;
            }
          }
        }
        if (!best.empty() && fs::is_regular_file(c / best, ec)) return (c / best).string();
      }
    }
    if (fs::is_regular_file(c / "model.sdf", ec)) return (c / "model.sdf").string();
    *why = "the folder '" + c.string() + "' has no model.config <sdf> file and no model.sdf";
    return std::nullopt;
  }
  std::string searched;
  for (const fs::path& c : candidates) {
    if (searched.size() > 400) {
      searched += ", ...";
      break;
    }
    searched += (searched.empty() ? "'" : ", '") + c.string() + "'";
  }
  if (searched.empty()) {
    *why = "no model path is set (model:// URIs are looked up only on the model paths)";
    return std::nullopt;
  }
  *why = "massprops looked for " + searched +
         " (the including file's folder for a relative path, then " +
         std::to_string(search_paths_.size()) + " model path" +
         (search_paths_.size() == 1 ? "" : "s") + ")";
  return std::nullopt;
}

int Reader::ReadInclude(const XMLElement* include, int scope, const Context& ctx) {
  if (aborted_) return kNotFound;
  const XMLElement* uri_element = include->FirstChildElement("uri");
  const std::string uri = Text(uri_element);
  const std::string what = "<include> '" + uri + "'";
  if (uri.empty()) {
    Error(ctx.file, include, "<include>", "an <include> needs a <uri>");
    return kNotFound;
  }
  if (ctx.depth > kMaxNestingDepth) {
    Error(ctx.file, include, what,
          "includes nested deeper than " + std::to_string(kMaxNestingDepth) + " levels");
    return kNotFound;
  }
  // include_stack_ holds the top file, then one entry per include being expanded.
  if (static_cast<int>(include_stack_.size()) > options_.max_include_depth) {
    Error(ctx.file, include, what,
          "includes nested deeper than " + std::to_string(options_.max_include_depth) +
              " files (the limit max_include_depth), starting at " + OutermostInclude());
    aborted_ = true;
    return kNotFound;
  }
  const std::string base_dir =
      ctx.file == "-" ? std::string(".") : fs::path(ctx.file).parent_path().string();
  std::string why;
  const std::string cache_key = base_dir + '\n' + uri;
  auto found = resolved_.find(cache_key);
  if (found == resolved_.end()) {
    std::optional<std::string> path = FindModelFile(uri, base_dir, &why);
    found = resolved_.emplace(cache_key, std::make_pair(path, why)).first;
  }
  const std::optional<std::string> path = found->second.first;
  why = found->second.second;
  if (!path) {
    ReportUnresolvedInclude(include, scope, ctx, uri, why);
    return kNotFound;
  }
  std::error_code ec;
  auto canonical_it = canonical_.find(*path);
  if (canonical_it == canonical_.end()) {
    fs::path canonical = fs::weakly_canonical(*path, ec);
    canonical_it = canonical_.emplace(*path, ec ? *path : canonical.string()).first;
  }
  const std::string& key = canonical_it->second;
  if (std::find(include_stack_.begin(), include_stack_.end(), key) != include_stack_.end()) {
    Error(ctx.file, include, what, "recursive include: '" + *path + "' includes itself");
    return kNotFound;
  }
  // Each included file is read and parsed once per read, however often it is included.
  auto doc_it = included_docs_.find(key);
  if (doc_it == included_docs_.end()) {
    std::string text;
    if (!ReadWholeFile(*path, &text, &why)) {
      Error(*path, nullptr, what, why);
      return kNotFound;
    }
    auto doc = std::make_unique<XMLDocument>();
    int line = 0;
    if (!ParseXml(text, doc.get(), &why, &line)) {
      result_.errors.push_back(MakeReadError(*path, line, what, why));
      return kNotFound;
    }
    doc_it = included_docs_.emplace(key, std::move(doc)).first;
  }
  const XMLElement* root = doc_it->second->RootElement();
  Context inner = ctx;
  inner.file = *path;
  if (root == nullptr || std::string(root->Name()) != "sdf" ||
      !ParseVersion(Attr(root, "version"), &inner.version)) {
    Error(*path, root, what, "the included file is not SDF (<sdf version=...> expected)");
    return kNotFound;
  }
  const XMLElement* model = root->FirstChildElement("model");
  if (model == nullptr) {
    Warning(ctx.file, include, what, "the included file '" + *path + "' has no <model> (skipped)");
    return kNotFound;
  }
  const std::string merge = ctx.version.AtLeast(1, 9) ? Attr(include, "merge") : "";
  const bool merged = merge == "true" || merge == "1";
  if (merged && scope == kWorld) {
    Error(ctx.file, include, what,
          "merge=\"true\" needs an enclosing <model> (libsdformat refuses it in a <world>)");
    return kNotFound;
  }
  include_stack_.push_back(key);
  include_sites_.push_back({ctx.file, include->GetLineNum(), uri});
  const Version saved_version = include_version_;
  const std::string saved_file = include_file_;
  include_version_ = ctx.version;
  include_file_ = ctx.file;
  const int index = merged ? ReadMergedModel(model, scope, inner, include)
                           : ReadModel(model, scope, inner, include);
  include_version_ = saved_version;
  include_file_ = saved_file;
  include_sites_.pop_back();
  include_stack_.pop_back();
  return index;
}

std::string Reader::OutermostInclude() const {
  if (include_sites_.empty()) return "";
  const IncludeSite& s = include_sites_.front();
  std::string text = "<include> '" + s.uri + "' at " + s.file + ":" + std::to_string(s.line);
  if (include_sites_.size() > 1) {
    const IncludeSite& last = include_sites_.back();
    text +=
        " (innermost: '" + last.uri + "' at " + last.file + ":" + std::to_string(last.line) + ")";
  }
  return text;
}

void Reader::ReportUnresolvedInclude(const XMLElement* include, int scope, const Context& ctx,
                                     const std::string& uri, const std::string& why) {
  // The name the missing model would have had: the include's <name>, else the last part of the
  // URI (model://create -> "create"), which is the folder name libsdformat would look up.
  std::string name = Text(include->FirstChildElement("name"));
  if (name.empty()) {
    std::string rest = uri;
    while (!rest.empty() && rest.back() == '/') rest.pop_back();
    const size_t slash = rest.find_last_of('/');
    name = slash == std::string::npos ? rest : rest.substr(slash + 1);
    const size_t dot = name.rfind(".sdf");
    if (dot != std::string::npos && dot + 4 == name.size()) name = name.substr(0, dot);
  }
  const std::string scoped = Prefix(scope) + name;
  unresolved_.push_back({scoped, uri, ctx.file, include->GetLineNum()});
  ReadFinding f;
  f.rule = "include-unresolved";
  int top = scope;
  while (top != kWorld && nodes_[top].scope != kWorld) top = nodes_[top].scope;
  f.model = top == kWorld ? "" : nodes_[top].name;
  f.location = {ctx.file, include->GetLineNum(), 0};
  const bool remote = uri.rfind("http://", 0) == 0 || uri.rfind("https://", 0) == 0;
  f.message = "<include> '" + uri + "' cannot be resolved: " + why + "; the model '" + name +
              "' is not checked, and joints naming its links are "
              "left out. " +
              (remote ? "Download the model (e.g. `gz fuel download -u URL`) and point massprops "
                        "at the folder that holds it"
                      : "Point massprops at the folder that holds it") +
              " with --model-path DIR or the SDF_PATH, GZ_SIM_RESOURCE_PATH or "
              "IGN_GAZEBO_RESOURCE_PATH environment variable";
  result_.findings.push_back(std::move(f));
}

bool Reader::InUnresolvedInclude(const std::string& ref, int scope, std::string* which) const {
  const std::string scoped = Prefix(scope) + ref;
  for (const Unresolved& u : unresolved_) {
    if (scoped == u.scoped || scoped.rfind(u.scoped + "::", 0) == 0) {
      *which = "'" + u.uri + "' (" + u.file + ":" + std::to_string(u.line) + ")";
      return true;
    }
  }
  return false;
}

void Reader::ReportUnresolvedReference(int i, const std::string& ref, const std::string& which) {
  if (!reported_unresolved_.insert(i).second) return;
  const Node& n = nodes_[i];
  int top = i;
  while (nodes_[top].scope != kWorld) top = nodes_[top].scope;
  ReadFinding f;
  f.rule = "include-unresolved";
  f.model = current_model_name_.empty() ? nodes_[top].name : current_model_name_;
  f.location = n.location;
  f.message = Describe(n) + " names '" + ref + "', which lies in the unresolved <include> " +
              which + "; it is left out";
  result_.findings.push_back(std::move(f));
}

int Reader::ReadMergedModel(const XMLElement* model, int scope, const Context& ctx,
                            const XMLElement* include) {
  std::string name = Attr(model, "name");
  if (const XMLElement* n = include->FirstChildElement("name")) name = Text(n);
  if (name.empty()) {
    Error(ctx.file, model, "<model>", "a <model> needs a name attribute");
    return kNotFound;
  }
  // libsdformat 12 (SDF 1.9 //include/@merge): the merged model's frame becomes the frame
  // "_merged__NAME__model__" of the enclosing model, attached to the merged model's canonical
  // link and placed by the include's (else the model's) <pose>; the merged model's links,
  // joints, frames and nested models become the enclosing model's, and what was relative to
  // the merged model's frame is relative to that frame.
  const std::string proxy = "_merged__" + name + "__model__";
  Node frame;
  frame.kind = Node::Kind::kFrame;
  frame.name = Prefix(scope) + proxy;
  frame.scope = scope;
  frame.version = ctx.version;
  frame.element = model;
  frame.location = {ctx.file, model->GetLineNum(), 0};
  const XMLElement* pose = model->FirstChildElement("pose");
  Context pose_ctx = ctx;
  if (const XMLElement* p = include->FirstChildElement("pose")) {
    pose = p;
    pose_ctx.version = include_version_;
    pose_ctx.file = include_file_;
  }
  frame.X_raw = ParsePose(pose, pose_ctx, "<pose> of merged <model> '" + name + "'");
  frame.relative_to = RelativeTo(pose, pose_ctx.version);
  if (frame.relative_to.empty()) frame.relative_to = "__model__";
  std::string canonical = Attr(model, "canonical_link");
  if (canonical.empty()) {
    if (const XMLElement* l = model->FirstChildElement("link")) canonical = Attr(l, "name");
  }
  if (canonical.empty()) {
    if (const XMLElement* m = model->FirstChildElement("model")) canonical = Attr(m, "name");
  }
  frame.attached_to = canonical;
  if (include->FirstChildElement("placement_frame") != nullptr ||
      model->Attribute("placement_frame") != nullptr) {
    Warning(ctx.file, include, "<include> of '" + name + "'",
            "placement_frame of a merged include is not read (the <pose> places the model "
            "frame)");
  }
  const int index = AddNode(std::move(frame), ctx);
  if (index < 0) return index;
  Context children = ctx;
  children.merge_proxy = proxy;
  ReadModelChildren(model, scope, children);
  return index;
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

// Appends the rules of every <!-- massprops: ignore rule-id ... --> comment anywhere inside the
// link element `e`.
void ReadIgnoredRules(const XMLElement* e, std::vector<std::string>* ignored_rules) {
  std::vector<const XMLNode*> stack{e};
  while (!stack.empty()) {
    const XMLNode* n = stack.back();
    stack.pop_back();
    for (const XMLNode* c = n->LastChild(); c; c = c->PreviousSibling()) {
      if (const XMLComment* comment = c->ToComment()) {
        std::istringstream words(comment->Value() ? comment->Value() : "");
        std::string w1, w2, rule;
        if (words >> w1 >> w2 && w1 == "massprops:" && w2 == "ignore") {
          while (words >> rule) ignored_rules->push_back(rule);
        }
      } else if (c->ToElement() != nullptr) {
        stack.push_back(c);
      }
    }
  }
}

void Reader::ReadLinkContents(int link_index, int top, const Pose& X_TB, Link* link) {
  const Context& ctx = link_files_.at(link_index);
  const XMLElement* e = nodes_[link_index].element;
  const std::string lname = "'" + link->name + "'";
  const XMLElement* in = e->FirstChildElement("inertial");
  const std::string auto_attr = in ? Attr(in, "auto") : "";
  const bool is_auto =
      in != nullptr && ctx.version.AtLeast(1, 11) && (auto_attr == "true" || auto_attr == "1");
  if (in != nullptr && !is_auto) ReadExplicitInertial(in, link_index, top, X_TB, ctx, link);
  for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag != "collision" && tag != "visual") continue;
    link->geometries.push_back(ReadGeometry(c, link_index, top, X_TB, ctx, lname));
  }
  if (is_auto) ReadAutoInertial(in, link_index, top, X_TB, ctx, link);
  ReadIgnoredRules(e, &link->ignored_rules);
}

// Reads a written (not automatic) <inertial>; a bad number or pose here costs this link only
// (inertial-unreadable, with a finding), not the file.
void Reader::ReadExplicitInertial(const XMLElement* in, int link_index, int top, const Pose& X_TB,
                                  const Context& ctx, Link* link) {
  const std::string lname = "'" + link->name + "'";
  diversion_ = Diversion();
  diversion_.active = true;
  Inertial inertial;
  inertial.location = {ctx.file, in->GetLineNum(), 0};
  const XMLElement* pose = in->FirstChildElement("pose");
  if (pose != nullptr) inertial.pose_location = {ctx.file, pose->GetLineNum(), 0};
  ResolveInLink(pose, link_index, top, X_TB, ctx, "<inertial> of link " + lname, &inertial.X_BBi);
  const XMLElement* mass = in->FirstChildElement("mass");
  if (mass != nullptr) inertial.mass_location = {ctx.file, mass->GetLineNum(), 0};
  // SDF defaults (sdf/1.x/inertial.sdf): mass 1, ixx = iyy = izz = 1, products 0.
  inertial.mass = Number(mass, 1.0, ctx, "<mass> of link " + lname);
  const XMLElement* inertia = in->FirstChildElement("inertia");
  if (inertia != nullptr) inertial.inertia_location = {ctx.file, inertia->GetLineNum(), 0};
  auto moment = [&](const char* tag, double fallback) {
    return Number(inertia ? inertia->FirstChildElement(tag) : nullptr, fallback, ctx,
                  std::string("<") + tag + "> of link " + lname);
  };
  inertial.ixx = moment("ixx", 1.0);
  inertial.iyy = moment("iyy", 1.0);
  inertial.izz = moment("izz", 1.0);
  inertial.ixy = moment("ixy", 0.0);
  inertial.ixz = moment("ixz", 0.0);
  inertial.iyz = moment("iyz", 0.0);
  diversion_.active = false;
  if (diversion_.failed) {
    link->inertial_unreadable = true;
    ReadFinding f;
    f.rule = "inertial-unreadable";
    f.model = current_model_name_;
    f.link = link->name;
    f.location = diversion_.location;
    f.message = diversion_.element + ": " + diversion_.message + "; the mass properties of link " +
                lname + " are unknown, so its welded group is not checked";
    result_.findings.push_back(std::move(f));
  } else {
    link->inertial = inertial;
  }
}

// Reads one <collision> or <visual> element `c` of the link named `lname` (quoted).
Geometry Reader::ReadGeometry(const XMLElement* c, int link_index, int top, const Pose& X_TB,
                              const Context& ctx, const std::string& lname) {
  const std::string tag = c->Name();
  Geometry g;
  g.is_collision = tag == "collision";
  g.location = {ctx.file, c->GetLineNum(), 0};
  const std::string what = "<" + tag + "> '" + Attr(c, "name") + "' of link " + lname;
  ResolveInLink(c->FirstChildElement("pose"), link_index, top, X_TB, ctx, what, &g.X_BG);
  const XMLElement* geometry = c->FirstChildElement("geometry");
  const XMLElement* shape = geometry ? geometry->FirstChildElement() : nullptr;
  if (shape != nullptr)
    ReadShape(shape, ctx, "<" + std::string(shape->Name()) + "> of " + what, &g);
  return g;
}

// Reads the type and dimensions of a <geometry>'s shape element (SDF defaults when absent);
// an unknown shape leaves g's type as it is.
void Reader::ReadShape(const XMLElement* shape, const Context& ctx, const std::string& swhat,
                       Geometry* g) {
  const std::string s = shape->Name();
  if (s == "box") {
    g->type = Geometry::Type::kBox;
    g->size = Vector(shape->FirstChildElement("size"), Eigen::Vector3d::Ones(), ctx, swhat);
  } else if (s == "cylinder" || s == "capsule") {
    g->type = s == "cylinder" ? Geometry::Type::kCylinder : Geometry::Type::kCapsule;
    g->radius = Number(shape->FirstChildElement("radius"), s == "cylinder" ? 1.0 : 0.5, ctx, swhat);
    g->length = Number(shape->FirstChildElement("length"), 1.0, ctx, swhat);
  } else if (s == "sphere") {
    g->type = Geometry::Type::kSphere;
    g->radius = Number(shape->FirstChildElement("radius"), 1.0, ctx, swhat);
  } else if (s == "ellipsoid") {
    g->type = Geometry::Type::kEllipsoid;
    g->radii = Vector(shape->FirstChildElement("radii"), Eigen::Vector3d::Ones(), ctx, swhat);
  } else if (s == "mesh") {
    g->type = Geometry::Type::kMesh;
    g->uri = Text(shape->FirstChildElement("uri"));
    g->scale = Vector(shape->FirstChildElement("scale"), Eigen::Vector3d::Ones(), ctx, swhat);
  }
}

void Reader::ReadAutoInertial(const XMLElement* in, int link_index, int /*top*/, const Pose& X_TB,
                              const Context& ctx, Link* link) {
  (void)X_TB;
  const XMLElement* e = nodes_[link_index].element;
  const std::string lname = "'" + link->name + "'";
  auto unreadable = [&](const SourceLocation& where, const std::string& why) {
    link->inertial_unreadable = true;
    ReadFinding f;
    f.rule = "inertial-unreadable";
    f.model = current_model_name_;
    f.link = link->name;
    f.location = where;
    f.message = "<inertial auto=\"true\"> of link " + lname + " cannot be computed: " + why +
                "; its mass properties are unknown, so its welded group is not checked";
    result_.findings.push_back(std::move(f));
  };
  const SourceLocation in_location{ctx.file, in->GetLineNum(), 0};
  if (!options_.compute_auto_inertials) {
    unreadable(in_location, "auto inertials are not computed (compute_auto_inertials is off)");
    return;
  }
  diversion_ = Diversion();
  diversion_.active = true;
  // Density precedence (libsdformat 14, Collision::CalculateInertial): the collision's
  // <density>, else the link's <inertial><density>, else 1000 kg/m³.
  const XMLElement* link_density = in->FirstChildElement("density");
  const double inertial_density =
      Number(link_density, kSdfDefaultDensity, ctx, "<inertial><density> of link " + lname);
  std::optional<double> mass;
  const XMLElement* mass_element = in->FirstChildElement("mass");
  if (mass_element != nullptr) mass = Number(mass_element, 0.0, ctx, "<mass> of link " + lname);
  std::vector<AutoInertiaCollision> collisions;
  size_t g = 0;
  for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag != "collision" && tag != "visual") continue;
    const size_t index = g++;
    if (tag != "collision" || index >= link->geometries.size()) continue;
    AutoInertiaCollision collision;
    collision.name = Attr(c, "name");
    collision.geometry = link->geometries[index];
    const XMLElement* density = c->FirstChildElement("density");
    if (density != nullptr) {
      collision.density = Number(density, kSdfDefaultDensity, ctx,
                                 "<density> of <collision> '" + collision.name + "'");
      collision.density_source = "collision <density>";
    } else if (link_density != nullptr) {
      collision.density = inertial_density;
      collision.density_source = "<inertial><density>";
    } else {
      collision.density = kSdfDefaultDensity;
      collision.density_source = "default density";
    }
    collisions.push_back(std::move(collision));
  }
  diversion_.active = false;
  if (diversion_.failed) {
    unreadable(diversion_.location, diversion_.element + ": " + diversion_.message);
    return;
  }
  if (!mesh_cache_) mesh_cache_ = std::make_unique<MeshCache>();
  MeshResolveOptions mesh_options;
  mesh_options.model_paths = options_.model_paths;
  mesh_options.use_environment = options_.use_environment;
  mesh_options.model_file = ctx.file;
  mesh_options.cache = mesh_cache_.get();
  std::string why;
  const std::optional<AutoInertiaResult> computed =
      CalcAutoInertial(collisions, mass, mesh_options, &why);
  if (!computed) {
    unreadable(in_location, why);
    return;
  }
  Inertial inertial = computed->inertial;
  inertial.location = in_location;
  if (mass_element != nullptr) inertial.mass_location = {ctx.file, mass_element->GetLineNum(), 0};
  link->inertial = inertial;
  ReadFinding f;
  f.rule = "inertial-auto";
  f.model = current_model_name_;
  f.link = link->name;
  f.location = in_location;
  f.message =
      "link " + lname + ": <inertial auto=\"true\"> (SDF 1.11) computed as " + computed->summary;
  f.values = {{"mass", inertial.mass},
              {"com_x", inertial.X_BBi.p_AB.x()},
              {"com_y", inertial.X_BBi.p_AB.y()},
              {"com_z", inertial.X_BBi.p_AB.z()},
              {"ixx", inertial.ixx},
              {"iyy", inertial.iyy},
              {"izz", inertial.izz},
              {"ixy", inertial.ixy},
              {"ixz", inertial.ixz},
              {"iyz", inertial.iyz},
              {"collisions", static_cast<double>(collisions.size())}};
  result_.findings.push_back(std::move(f));
}

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

// A frame's pose in T; for a frame outside the model (a world joint's) through the world.
std::optional<Pose> Reader::PoseInModel(const ModelBuild& b, int f) {
  if (f == kNotFound) return std::nullopt;
  if (b.top == kWorld) return PoseInScope(f, kWorld, 0);
  if (f != kWorld && TopOf(f) == b.top) return PoseInScope(f, b.top, 0);
  const std::optional<Pose> X_WF = f == kWorld ? Pose() : PoseInScope(f, kWorld, 0);
  if (!X_WF || !b.X_WT) return std::nullopt;
  return b.X_WT->Inverse() * *X_WF;
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

ReadResult Reader::Read(const std::string& xml, const std::string& file_name,
                        std::vector<SdfModelFrames>* frames) {
  if (xml.size() > kMaxSdfFileBytes) {
    result_.errors.push_back(MakeReadError(file_name, 0, "<sdf>",
                                           "the input has " + std::to_string(xml.size()) +
                                               " bytes, more than the limit of " +
                                               std::to_string(kMaxSdfFileBytes)));
    return std::move(result_);
  }
  auto doc = std::make_unique<XMLDocument>();
  std::string why;
  int line = 0;
  if (!ParseXml(xml, doc.get(), &why, &line)) {
    result_.errors.push_back(MakeReadError(file_name, line, "<sdf>", why));
    return std::move(result_);
  }
  const XMLElement* root = doc->RootElement();
  if (root == nullptr || std::string(root->Name()) != "sdf") {
    Error(file_name, root, root ? std::string("<") + root->Name() + ">" : "<sdf>",
          "the root element must be <sdf>");
    return std::move(result_);
  }
  Context ctx;
  ctx.file = file_name;
  const std::string version_text = Attr(root, "version");
  if (!ParseVersion(version_text, &ctx.version)) {
    Error(file_name, root, "<sdf>",
          "the version attribute '" + version_text + "' is not of the form MAJOR.MINOR");
    return std::move(result_);
  }
  if (!ctx.version.AtLeast(1, 4) || ctx.version.AtLeast(2, 0)) {
    Warning(file_name, root, "<sdf>",
            "SDF version " + version_text + " is outside 1.4-1.11; read with 1.x rules");
  }
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file_name, ec);
  include_stack_.push_back(ec ? file_name : canonical.string());
  for (const XMLElement* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag == "world") {
      ReadWorld(c, ctx);
    } else if (tag == "model") {
      const int m = ReadModel(c, kWorld, ctx, nullptr);
      if (m >= 0) top_models_.push_back(m);
    }
  }
  if (top_models_.empty() && result_.errors.empty()) {
    Warning(file_name, root, "<sdf>", "the file holds no <model>");
  }
  if (result_.errors.empty()) {
    BuildModels();
  }
  if (!result_.errors.empty()) {
    result_.models.clear();
    frames_.clear();
  }
  if (frames != nullptr) *frames = std::move(frames_);
  documents_.push_back(std::move(doc));
  return std::move(result_);
}

}  // namespace

ReadResult ReadSdfString(const std::string& xml, const std::string& file_name,
                         const SdfReadOptions& options, std::vector<SdfModelFrames>* frames) {
  Reader reader(options, file_name);
  return reader.Read(xml, file_name, frames);
}

ReadResult ReadSdfString(const std::string& xml, const std::string& file_name,
                         const SdfReadOptions& options) {
  return ReadSdfString(xml, file_name, options, nullptr);
}

ReadResult ReadSdfFile(const std::string& path, const SdfReadOptions& options) {
  return ReadSdfFile(path, options, nullptr);
}

ReadResult ReadSdfFile(const std::string& path, const SdfReadOptions& options,
                       std::vector<SdfModelFrames>* frames) {
  std::string text;
  std::string why;
  if (!ReadWholeFile(path, &text, &why)) {
    ReadResult result;
    result.errors.push_back(MakeReadError(path, 0, "<sdf>", why));
    return result;
  }
  return ReadSdfString(text, path, options, frames);
}

}  // namespace massprops
