// The SDF reader's elements and values (reader.h): the nodes of the pose graph read from <world>,
// <model>, <link>, <joint> and <frame>, numbers and poses as written, and a link's contents: its
// written <inertial>, its geometries and its massprops:ignore comments.
#include <cctype>

#include "io/sdf/reader.h"

namespace massprops::internal::sdf_reader {

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

void Reader::Error(const std::string& file, const XMLElement* e, const std::string& element,
                   const std::string& message) {
  if (diversion_.active) {
    if (!diversion_.failed) {
      diversion_.failed = true;
      diversion_.location = {file, LineOf(e), 0};
      diversion_.element = element;
      diversion_.message = message;
    }
    return;
  }
  result_.errors.push_back(MakeReadError(file, LineOf(e), element, message));
}

void Reader::Warning(const std::string& file, const XMLElement* e, const std::string& element,
                     const std::string& message) {
  result_.warnings.push_back(MakeReadError(file, LineOf(e), element, message));
}

double Reader::Number(const XMLElement* e, double fallback, const Context& ctx,
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

Eigen::Vector3d Reader::Vector(const XMLElement* e, const Eigen::Vector3d& fallback,
                               const Context& ctx, const std::string& element) {
  if (e == nullptr) return fallback;
  std::vector<double> v;
  std::string why;
  if (!internal::ParseSdfNumbers(Text(e), 3, 3, &v, &why)) {
    Error(ctx.file, e, element, why);
    return fallback;
  }
  return {v[0], v[1], v[2]};
}

Pose Reader::ParsePose(const XMLElement* e, const Context& ctx, const std::string& element) {
  if (e == nullptr) return Pose();
  const std::string text = Text(e);
  if (text.empty()) return Pose();
  const bool v19 = ctx.version.AtLeast(1, 9);
  const std::string degrees = v19 ? Attr(e, "degrees") : "";
  std::string why;
  const std::optional<Pose> X = internal::ParseSdfPose(text, v19 ? Attr(e, "rotation_format") : "",
                                                       degrees == "true" || degrees == "1", &why);
  if (!X) {
    Error(ctx.file, e, element, why);
    return Pose();
  }
  return *X;
}

std::string Reader::RelativeTo(const XMLElement* pose, const Version& v) {
  if (pose == nullptr) return "";
  if (!v.AtLeast(1, 7) && pose->Attribute("frame") != nullptr) return Attr(pose, "frame");
  return Attr(pose, "relative_to");
}

int Reader::AddNode(Node node, const Context& ctx) {
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

void Reader::ApplyMerge(Node* node, const std::string& proxy) {
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

void Reader::ReadWorld(const XMLElement* world, const Context& ctx) {
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

int Reader::ReadModel(const XMLElement* model, int scope, const Context& ctx,
                      const XMLElement* include) {
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
  node.location = PlaceOf(ctx.file, model);
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

void Reader::ReadModelChildren(const XMLElement* model, int scope, const Context& ctx) {
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

void Reader::ReadFrame(const XMLElement* frame, int scope, const Context& ctx) {
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
  node.location = PlaceOf(ctx.file, frame);
  node.attached_to = Attr(frame, "attached_to");
  const XMLElement* pose = frame->FirstChildElement("pose");
  node.X_raw = ParsePose(pose, ctx, "<pose> of <frame> '" + name + "'");
  node.relative_to = RelativeTo(pose, ctx.version);
  AddNode(std::move(node), ctx);
}

void Reader::ReadJoint(const XMLElement* joint, int scope, const Context& ctx) {
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
  node.location = PlaceOf(ctx.file, joint);
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

void Reader::ReadLink(const XMLElement* link, int scope, const Context& ctx) {
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
  node.location = PlaceOf(ctx.file, link);
  const XMLElement* pose = link->FirstChildElement("pose");
  node.X_raw = ParsePose(pose, ctx, "<pose> of <link> '" + name + "'");
  node.relative_to = RelativeTo(pose, ctx.version);
  const int index = AddNode(std::move(node), ctx);
  if (index < 0) return;
  nodes_[scope].members.push_back(index);
  link_files_.emplace(index, ctx);
}

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
  inertial.location = PlaceOf(ctx.file, in);
  const XMLElement* pose = in->FirstChildElement("pose");
  if (pose != nullptr) inertial.pose_location = PlaceOf(ctx.file, pose);
  ResolveInLink(pose, link_index, top, X_TB, ctx, "<inertial> of link " + lname, &inertial.X_BBi);
  const XMLElement* mass = in->FirstChildElement("mass");
  if (mass != nullptr) inertial.mass_location = PlaceOf(ctx.file, mass);
  // SDF defaults (sdf/1.x/inertial.sdf): mass 1, ixx = iyy = izz = 1, products 0.
  inertial.mass = Number(mass, 1.0, ctx, "<mass> of link " + lname);
  const XMLElement* inertia = in->FirstChildElement("inertia");
  if (inertia != nullptr) inertial.inertia_location = PlaceOf(ctx.file, inertia);
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
  g.location = PlaceOf(ctx.file, c);
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
    SetMeshReference(Text(shape->FirstChildElement("uri")),
                     Vector(shape->FirstChildElement("scale"), Eigen::Vector3d::Ones(), ctx, swhat),
                     g);
    const XMLElement* submesh = shape->FirstChildElement("submesh");
    if (submesh != nullptr) ReadSubmesh(submesh, ctx, swhat, g);
  }
}

// Reads a mesh's <submesh> as libsdformat's sdf::Mesh::Load does (its Submesh() and
// CenterSubmesh()): the <name> as written without surrounding blanks; a missing or empty name, or
// the default "__default__", is libsdformat's error and leaves the whole file in use (a warning
// here); <center> is an SDF boolean (true/1, false/0, in any case), false when absent or empty,
// and a value libsdformat cannot read leaves it false (a warning).
void Reader::ReadSubmesh(const XMLElement* submesh, const Context& ctx, const std::string& swhat,
                         Geometry* g) {
  g->submesh_location = PlaceOf(ctx.file, submesh);
  const std::string name = Text(submesh->FirstChildElement("name"));
  if (name.empty() || name == "__default__") {
    Warning(ctx.file, submesh, "<submesh> of " + swhat,
            "no submesh <name>: the whole mesh file is used, as libsdformat leaves it");
  } else {
    g->submesh = name;
  }
  const XMLElement* center = submesh->FirstChildElement("center");
  if (center == nullptr) return;
  std::string value = Text(center);
  std::transform(value.begin(), value.end(), value.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (value == "true" || value == "1") {
    g->center_submesh = true;
  } else if (!value.empty() && value != "false" && value != "0") {
    Warning(ctx.file, center, "<submesh><center> of " + swhat,
            "'" + Text(center) + "' is not a boolean: the submesh is not recentred");
  }
}

}  // namespace massprops::internal::sdf_reader
