// The SDF reader's <include> (reader.h): the model paths (options, SDF_PATH and Gazebo's
// variables), reading a file, model:// and relative URIs, merged includes, and the includes that
// cannot be resolved (named once, with what refers into them).
#include "io/sdf/reader.h"

namespace massprops::internal::sdf_reader {

Reader::Reader(const SdfReadOptions& options, std::string top_file)
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

bool ReadWholeFile(const std::string& path, std::size_t max_bytes, std::string* text,
                   std::string* why) {
  if (path == "-") {
    std::string data;
    char buffer[65536];
    while (std::cin.read(buffer, sizeof buffer) || std::cin.gcount() > 0) {
      data.append(buffer, static_cast<size_t>(std::cin.gcount()));
      if (data.size() > max_bytes) {
        *why = "standard input is larger than the limit of " + std::to_string(max_bytes) + " bytes";
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
  if (size > max_bytes) {
    *why = "the file has " + std::to_string(size) + " bytes, more than the limit of " +
           std::to_string(max_bytes);
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *why = "cannot open the file";
    return false;
  }
  text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (text->size() > max_bytes) {
    *why = "the file is larger than the limit of " + std::to_string(max_bytes) + " bytes";
    return false;
  }
  return true;
}

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
      if (ReadWholeFile(config.string(), options_.max_file_bytes, &text, &config_why) &&
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
    if (!ReadWholeFile(*path, options_.max_file_bytes, &text, &why)) {
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
  f.location = PlaceOf(ctx.file, include);
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
  frame.location = PlaceOf(ctx.file, model);
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

}  // namespace massprops::internal::sdf_reader
