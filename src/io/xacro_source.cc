#include "io/xacro_source.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include "io/yaml_scalars.h"

namespace massprops::xacro {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxFiles = 20000;
constexpr std::uintmax_t kMaxFileBytes = 16u << 20;
constexpr int kMaxYamlVisits = 200000;  // aliases make a YAML graph; this bounds its unfolding

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Byte offsets where each line starts.
std::vector<std::size_t> LineStarts(const std::string& text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts.push_back(i + 1);
  }
  return starts;
}

int LineOf(const std::vector<std::size_t>& starts, std::size_t offset) {
  return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), offset) - starts.begin());
}

bool IsSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Reads the start tag `<tag ...>` that begins at `at`: the position of each attribute's value.
// Returns the offset just past the tag (or `at` when it is not a start tag there).
std::size_t ScanStartTag(const std::string& text, std::size_t at,
                         const std::vector<std::size_t>& starts,
                         std::map<std::string, std::pair<std::size_t, std::size_t>>* ranges,
                         std::map<std::string, int>* lines) {
  std::size_t i = at + 1;
  while (i < text.size() && !IsSpace(text[i]) && text[i] != '>' && text[i] != '/') ++i;
  while (i < text.size()) {
    while (i < text.size() && IsSpace(text[i])) ++i;
    if (i >= text.size() || text[i] == '>' || text[i] == '/') break;
    const std::size_t name_start = i;
    while (i < text.size() && !IsSpace(text[i]) && text[i] != '=' && text[i] != '>') ++i;
    const std::string name = text.substr(name_start, i - name_start);
    while (i < text.size() && IsSpace(text[i])) ++i;
    if (i >= text.size() || text[i] != '=') break;
    ++i;
    while (i < text.size() && IsSpace(text[i])) ++i;
    if (i >= text.size() || (text[i] != '"' && text[i] != '\'')) break;
    const char quote = text[i++];
    const std::size_t end = text.find(quote, i);
    if (end == std::string::npos) break;
    (*ranges)[name] = {i, end - i};
    (*lines)[name] = LineOf(starts, i);
    i = end + 1;
  }
  return i;
}

class XmlIndexer {
 public:
  XmlIndexer(SourceIndex* index, int file) : index_(index), file_(file) {
    const std::string& text = index_->files[static_cast<std::size_t>(file)].text;
    starts_ = LineStarts(text);
  }

  void Add(const tinyxml2::XMLElement* element, int parent) {
    const std::string& text = index_->files[static_cast<std::size_t>(file_)].text;
    XNode node;
    node.tag = element->Name();
    node.line = element->GetLineNum();
    node.file = file_;
    node.parent = parent;
    // Find the start tag in the text: at or after the cursor, not before its line.
    const std::size_t line_start =
        node.line >= 1 && static_cast<std::size_t>(node.line) <= starts_.size()
            ? starts_[static_cast<std::size_t>(node.line - 1)]
            : 0;
    std::size_t at = text.find("<" + node.tag, std::max(cursor_, line_start));
    std::map<std::string, std::pair<std::size_t, std::size_t>> ranges;
    std::map<std::string, int> lines;
    if (at != std::string::npos) cursor_ = ScanStartTag(text, at, starts_, &ranges, &lines);
    for (const tinyxml2::XMLAttribute* a = element->FirstAttribute(); a; a = a->Next()) {
      XAttr attr;
      attr.name = a->Name();
      attr.value = a->Value();
      auto range = ranges.find(attr.name);
      if (range != ranges.end()) {
        attr.offset = range->second.first;
        attr.length = range->second.second;
        attr.line = lines[attr.name];
      } else {
        attr.line = node.line;
      }
      node.attrs.push_back(std::move(attr));
    }
    const int id = static_cast<int>(index_->nodes.size());
    index_->nodes.push_back(node);
    if (parent >= 0) index_->nodes[static_cast<std::size_t>(parent)].children.push_back(id);
    Register(id);
    for (const tinyxml2::XMLElement* child = element->FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      Add(child, id);
    }
  }

 private:
  void Register(int id) {
    const XNode& node = index_->nodes[static_cast<std::size_t>(id)];
    const XAttr* name = node.Attr("name");
    if (node.tag == "xacro:macro" && name) {
      index_->macros[name->value].push_back(id);
    } else if (node.tag == "xacro:property" && name) {
      index_->properties[name->value].push_back(id);
    } else if (node.tag == "xacro:arg" && name) {
      const XAttr* def = node.Attr("default");
      if (def && !index_->args.count(name->value)) index_->args[name->value] = def->value;
    } else {
      const std::string macro = CalledMacro(node.tag);
      if (!macro.empty()) index_->calls[macro].push_back(id);
    }
  }

  SourceIndex* index_;
  int file_;
  std::vector<std::size_t> starts_;
  std::size_t cursor_ = 0;
};

bool ReadFile(const fs::path& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *out = buffer.str();
  return true;
}

}  // namespace

const XAttr* XNode::Attr(const std::string& name) const {
  for (const XAttr& attr : attrs) {
    if (attr.name == name) return &attr;
  }
  return nullptr;
}

std::string CalledMacro(const std::string& tag) {
  if (tag.rfind("xacro:", 0) != 0) return "";
  std::string name = tag.substr(6);
  static const std::set<std::string> kDirectives = {
      "macro",   "property",  "arg",  "include",       "if",       "unless", "insert_block",
      "element", "attribute", "call", "eval-comments", "load_yaml"};
  if (kDirectives.count(name)) return "";
  const std::size_t dot = name.rfind('.');
  if (dot != std::string::npos) name = name.substr(dot + 1);
  return name;
}

int EnclosingMacro(const SourceIndex& index, int node) {
  while (node >= 0) {
    if (index.nodes[static_cast<std::size_t>(node)].tag == "xacro:macro") return node;
    node = index.nodes[static_cast<std::size_t>(node)].parent;
  }
  return -1;
}

SourceIndex IndexSources(const std::vector<std::string>& roots,
                         const std::map<std::string, std::string>& args,
                         const std::vector<std::string>& exclude, std::string_view generated) {
  SourceIndex index;
  auto excluded = [&](const fs::path& path) {
    for (const std::string& e : exclude) {
      std::error_code ec;
      if (fs::equivalent(path, e, ec)) return true;
    }
    return false;
  };
  index.args = args;
  std::vector<std::pair<std::string, fs::path>> found;  // (reported path, real path)
  for (const std::string& root : roots) {
    std::error_code ec;
    fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
      index.errors.push_back(
          MakeReadError(root, 0, "", "cannot read the source folder: " + ec.message()));
      continue;
    }
    std::vector<std::pair<std::string, fs::path>> here;
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const fs::path& path = it->path();
      const std::string name = path.filename().string();
      std::error_code type_ec;
      if (it->is_directory(type_ec)) {
        if (!name.empty() && name[0] == '.') it.disable_recursion_pending();
        continue;
      }
      const std::string ext = Lower(path.extension().string());
      if (ext != ".xacro" && ext != ".urdf" && ext != ".gazebo" && ext != ".yaml" &&
          ext != ".yml") {
        continue;
      }
      if (!it->is_regular_file(type_ec) || it->file_size(type_ec) > kMaxFileBytes) continue;
      if (excluded(path)) continue;
      here.emplace_back(
          (fs::path(root) / path.lexically_relative(root)).lexically_normal().string(), path);
      if (found.size() + here.size() >= kMaxFiles) break;
    }
    std::sort(here.begin(), here.end());
    found.insert(found.end(), here.begin(), here.end());
  }
  for (const auto& [shown, real] : found) {
    SourceFile file;
    file.path = shown;
    if (!ReadFile(real, &file.text)) {
      index.errors.push_back(MakeReadError(shown, 0, "", "cannot read the file"));
      continue;
    }
    if (!generated.empty() && file.text == generated) continue;
    const int id = static_cast<int>(index.files.size());
    index.files.push_back(std::move(file));
    const std::string ext = Lower(real.extension().string());
    const std::string& text = index.files.back().text;
    if (ext == ".yaml" || ext == ".yml") {
      std::string error;
      const internal::YamlReader* reader = internal::GetYamlReader(&error);
      std::vector<internal::YamlScalarFound> scalars;
      // What was walked before yaml-cpp threw is kept, then the error.
      const bool read =
          reader != nullptr && reader->read_scalars(text, kMaxYamlVisits, &scalars, &error);
      for (internal::YamlScalarFound& found_scalar : scalars) {
        YamlScalar scalar;
        scalar.file = id;
        scalar.line = found_scalar.line;
        scalar.offset = found_scalar.offset;
        scalar.length = found_scalar.text.size();
        scalar.editable = scalar.offset + scalar.length <= text.size() &&
                          text.compare(scalar.offset, scalar.length, found_scalar.text) == 0;
        scalar.text = std::move(found_scalar.text);
        scalar.paths = std::move(found_scalar.paths);
        index.yaml.push_back(std::move(scalar));
      }
      if (!read) index.errors.push_back(MakeReadError(shown, 0, "", "YAML not read: " + error));
      continue;
    }
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
      index.errors.push_back(MakeReadError(shown, doc.ErrorLineNum(), "", doc.ErrorStr()));
      continue;
    }
    XmlIndexer indexer(&index, id);
    if (const tinyxml2::XMLElement* root = doc.RootElement()) indexer.Add(root, -1);
  }
  return index;
}

}  // namespace massprops::xacro
