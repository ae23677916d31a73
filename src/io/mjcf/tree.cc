// The MJCF document as one tree (includes expanded, file:line kept), its <compiler>, <default>
// classes and <asset> meshes, and the numbers and orientations of attributes, read as MuJoCo
// 2.2.2's XML reader and compiler read them (src/xml/xml_native_reader.cc, and
// mjCAlternative::Set and mjuu_z2quat in src/user/).

#include "io/mjcf/tree.h"

#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "io/mjcf/mujoco_numbers.h"

namespace massprops {
namespace mjcf {
namespace {

namespace fs = std::filesystem;

struct Loader {
  Document* document;
  std::vector<ReadError>* errors;
  std::string base_folder;
  int max_depth;
  std::vector<std::string> stack;  // Files being read, for recursion.
  int element_depth = 0;           // Elements nested, across includes (the readers recurse).
  std::size_t elements = 0;        // Elements read, across includes (each may repeat a file).
  int includes = 0;                // Files included, counting repeats.

  bool Fail(int file, int line, const std::string& element, const std::string& message) {
    errors->push_back(MakeReadError(document->files[file], line, element, message));
    return false;
  }

  // Appends the children of `parent` (of file `file`) to *out, expanding <include>s.
  bool Convert(const tinyxml2::XMLElement& parent, int file, int depth, std::vector<Node>* out) {
    constexpr int kMaxElementDepth = 1000;
    if (element_depth >= kMaxElementDepth) {
      return Fail(file, parent.GetLineNum(), "<" + std::string(parent.Name()) + ">",
                  "elements nested deeper than " + std::to_string(kMaxElementDepth) +
                      " levels (through includes)");
    }
    ++element_depth;
    const bool ok = ConvertChildren(parent, file, depth, out);
    --element_depth;
    return ok;
  }

  bool ConvertChildren(const tinyxml2::XMLElement& parent, int file, int depth,
                       std::vector<Node>* out) {
    for (const tinyxml2::XMLElement* e = parent.FirstChildElement(); e != nullptr;
         e = e->NextSiblingElement()) {
      if (std::string(e->Name()) == "include") {
        if (!Include(*e, file, depth, out)) return false;
        continue;
      }
      constexpr std::size_t kMaxElements = 1000000;
      if (++elements > kMaxElements) {
        return Fail(file, e->GetLineNum(), "<" + std::string(e->Name()) + ">",
                    "more than " + std::to_string(kMaxElements) +
                        " elements once includes are expanded; refusing to read further");
      }
      Node node;
      node.name = e->Name();
      node.file = file;
      node.line = e->GetLineNum();
      for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
        node.attributes.emplace_back(a->Name(), a->Value());
      }
      if (!Convert(*e, file, depth, &node.children)) return false;
      out->push_back(std::move(node));
    }
    return true;
  }

  bool Include(const tinyxml2::XMLElement& include, int file, int depth, std::vector<Node>* out) {
    const char* name = include.Attribute("file");
    const int line = include.GetLineNum();
    if (name == nullptr) return Fail(file, line, "<include>", "has no file attribute");
    if (depth >= max_depth) {
      return Fail(file, line, "<include>",
                  "includes nested deeper than " + std::to_string(max_depth) + " levels");
    }
    constexpr int kMaxIncludes = 10000;
    if (++includes > kMaxIncludes) {
      return Fail(file, line, "<include>",
                  "more than " + std::to_string(kMaxIncludes) +
                      " files read once includes are expanded; refusing to read further");
    }
    const fs::path path = fs::path(base_folder) / name;
    const std::string shown = path.lexically_normal().string();
    for (const std::string& open : stack) {
      if (open == shown) {
        return Fail(file, line, "<include file=\"" + std::string(name) + "\">",
                    "includes itself (recursive include of " + shown + ")");
      }
    }
    std::ifstream stream(path, std::ios::binary);
    std::error_code ec;
    if (!stream || fs::is_directory(path, ec)) {
      return Fail(file, line, "<include file=\"" + std::string(name) + "\">",
                  "cannot open " + shown + " (includes are relative to the folder of the " +
                      "main model file)");
    }
    std::stringstream text;
    text << stream.rdbuf();
    document->files.push_back(shown);
    const int index = static_cast<int>(document->files.size()) - 1;
    tinyxml2::XMLDocument xml;
    const std::string contents = text.str();
    if (xml.Parse(contents.data(), contents.size()) != tinyxml2::XML_SUCCESS) {
      return Fail(index, xml.ErrorLineNum(), "document",
                  std::string("XML parse error: ") + xml.ErrorStr());
    }
    const tinyxml2::XMLElement* root = xml.RootElement();
    if (root == nullptr || std::string(root->Name()) != "mujoco") {
      return Fail(index, root ? root->GetLineNum() : 1, "document",
                  "an included file's root element must be <mujoco>");
    }
    stack.push_back(shown);
    const bool ok = Convert(*root, index, depth + 1, out);
    stack.pop_back();
    return ok;
  }
};

bool ParseBool(const std::string& text, bool* value) {
  if (text == "true")
    *value = true;
  else if (text == "false")
    *value = false;
  else
    return false;
  return true;
}

void ReadCompiler(const Node& node, Context* context) {
  Compiler& c = context->compiler;
  for (const auto& [key, attribute] : node.attributes) {
    const std::string& value = attribute;  // a lambda may not capture a structured binding
    bool ok = true;
    char* end = nullptr;
    const auto number = [&](double* out) {
      *out = std::strtod(value.c_str(), &end);
      ok = end != value.c_str() && *end == '\0' && std::isfinite(*out);
    };
    if (key == "angle") {
      ok = value == "degree" || value == "radian";
      c.degree = value != "radian";
    } else if (key == "eulerseq") {
      ok = value.size() == 3 && value.find_first_not_of("xyzXYZ") == std::string::npos;
      if (ok) c.eulerseq = value;
    } else if (key == "meshdir") {
      c.meshdir = value;
    } else if (key == "assetdir") {
      c.assetdir = value;
    } else if (key == "inertiafromgeom") {
      ok = value == "false" || value == "true" || value == "auto";
      c.inertiafromgeom = value == "false" ? 0 : value == "true" ? 1 : 2;
    } else if (key == "boundmass") {
      number(&c.boundmass);
    } else if (key == "boundinertia") {
      number(&c.boundinertia);
    } else if (key == "settotalmass") {
      number(&c.settotalmass);
    } else if (key == "balanceinertia") {
      ok = ParseBool(value, &c.balanceinertia);
    } else if (key == "exactmeshinertia") {
      ok = ParseBool(value, &c.exactmeshinertia);
    } else if (key == "discardvisual") {
      ok = ParseBool(value, &c.discardvisual);
    } else if (key == "fusestatic") {
      ok = ParseBool(value, &c.fusestatic);
    } else if (key == "coordinate") {
      ok = value == "local" || value == "global";
      c.global = value == "global";
    } else if (key == "inertiagrouprange") {
      std::istringstream in(value);
      ok = static_cast<bool>(in >> c.inertiagrouprange[0] >> c.inertiagrouprange[1]);
    }
    if (!ok) {
      context->Error(node, "<compiler " + key + "=\"" + value + "\">",
                     "not a value MuJoCo accepts for " + key);
    }
  }
}

// Reads a <default> element (class `name`, whose parent class has `inherited`) and its children.
void ReadDefault(const Node& node, const std::string& name, const ClassAttributes& inherited,
                 Context* context) {
  if (context->classes.count(name) != 0) {
    context->Error(node, "<default class=\"" + name + "\">", "repeated default class name");
    return;
  }
  ClassAttributes attributes = inherited;
  for (const Node& child : node.children) {
    if (child.name == "default") continue;
    for (const auto& [key, value] : child.attributes) attributes[child.name][key] = value;
  }
  context->classes[name] = attributes;
  context->class_lines[name] = node.line;
  for (const Node& child : node.children) {
    if (child.name != "default") continue;
    const std::string* child_name = child.Find("class");
    if (child_name == nullptr) {
      context->Error(child, "<default>", "a nested default needs a class attribute");
      continue;
    }
    ReadDefault(child, *child_name, attributes, context);
  }
}

std::string StripExtension(const std::string& file) {
  const fs::path path(file);
  return path.stem().string();
}

}  // namespace

const std::string* Node::Find(const std::string& key) const {
  for (const auto& attribute : attributes) {
    if (attribute.first == key) return &attribute.second;
  }
  return nullptr;
}

bool LoadDocument(const std::string& xml, const std::string& file_name, int max_depth,
                  Document* document, std::vector<ReadError>* errors) {
  document->files = {file_name};
  tinyxml2::XMLDocument parsed;
  if (parsed.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    errors->push_back(MakeReadError(file_name, parsed.ErrorLineNum(), "document",
                                    std::string("XML parse error: ") + parsed.ErrorStr()));
    return false;
  }
  const tinyxml2::XMLElement* root = parsed.RootElement();
  if (root == nullptr || std::string(root->Name()) != "mujoco") {
    errors->push_back(MakeReadError(file_name, root ? root->GetLineNum() : 1, "document",
                                    "the root element is not <mujoco>"));
    return false;
  }
  Loader loader{document, errors, "", max_depth, {}};
  const fs::path main(file_name);
  loader.base_folder = file_name == "<stdin>" ? "" : main.parent_path().string();
  loader.stack.push_back(main.lexically_normal().string());
  document->root.name = "mujoco";
  document->root.line = root->GetLineNum();
  for (const tinyxml2::XMLAttribute* a = root->FirstAttribute(); a != nullptr; a = a->Next()) {
    document->root.attributes.emplace_back(a->Name(), a->Value());
  }
  return loader.Convert(*root, 0, 0, &document->root.children);
}

void Context::Error(const Node& node, const std::string& element, const std::string& message) {
  errors.push_back(MakeReadError(document->files[node.file], node.line, element, message));
}

void Context::Warning(const Node& node, const std::string& element, const std::string& message) {
  warnings.push_back(MakeReadError(document->files[node.file], node.line, element, message));
}

void ReadSections(const Document& document, Context* context) {
  context->document = &document;
  for (const Node& section : document.root.children) {
    if (section.name == "compiler") ReadCompiler(section, context);
  }
  for (const Node& section : document.root.children) {
    if (section.name != "default") continue;
    const std::string* name = section.Find("class");
    ReadDefault(section, name ? *name : "main", {}, context);
  }
  if (context->classes.count("main") == 0) context->classes["main"] = {};
  for (const Node& section : document.root.children) {
    if (section.name != "asset") continue;
    for (const Node& asset : section.children) {
      if (asset.name != "mesh") continue;
      const std::string* name = asset.Find("name");
      const std::string* file = asset.Find("file");
      const std::string key = name ? *name : file ? StripExtension(*file) : "";
      if (key.empty()) {
        context->Error(asset, "<mesh>", "has neither name nor file");
        continue;
      }
      if (!context->meshes.emplace(key, &asset).second) {
        context->Error(asset, "<mesh name=\"" + key + "\">", "repeated mesh name");
      }
    }
  }
}

const std::string* Element::Get(const std::string& key, bool* from_class) const {
  if (from_class) *from_class = false;
  if (const std::string* own = node->Find(key)) return own;
  if (defaults == nullptr) return nullptr;
  const auto it = defaults->find(key);
  if (it == defaults->end()) return nullptr;
  if (from_class) *from_class = true;
  return &it->second;
}

Element MakeElement(const Context& context, const Node& node, const std::string& childclass) {
  Element element;
  element.node = &node;
  const std::string* own = node.Find("class");
  element.class_name = own ? *own : childclass.empty() ? "main" : childclass;
  const auto it = context.classes.find(element.class_name);
  if (it != context.classes.end()) {
    const auto kind = it->second.find(node.name);
    if (kind != it->second.end()) element.defaults = &kind->second;
  }
  return element;
}

std::optional<std::vector<double>> Numbers(Context* context, const Element& element,
                                           const std::string& key, int count, int min_count,
                                           const std::string& what) {
  bool from_class = false;
  const std::string* text = element.Get(key, &from_class);
  if (text == nullptr) return std::nullopt;
  std::vector<double> values;
  const char* p = text->c_str();
  for (;;) {
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
    if (*p == '\0') break;
    char* end = nullptr;
    const double value = std::strtod(p, &end);
    if (end == p || !std::isfinite(value)) {
      values.clear();
      break;
    }
    values.push_back(value);
    p = end;
  }
  const int low = min_count > 0 ? min_count : count;
  const int n = static_cast<int>(values.size());
  if (n < low || n > count) {
    const std::string where =
        from_class ? " (from default class '" + element.class_name + "')" : std::string();
    context->Error(*element.node, "<" + element.node->name + "> " + what,
                   key + "=\"" + *text + "\"" + where + ": expected " +
                       (low == count ? std::to_string(count)
                                     : std::to_string(low) + " to " + std::to_string(count)) +
                       " finite numbers");
    return std::nullopt;
  }
  return values;
}

Eigen::Quaterniond RotationFromZ(const Eigen::Vector3d& vec) {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ().cross(vec);
  const double s = axis.norm();
  if (s < 1e-10) {
    axis = Eigen::Vector3d::UnitX();
  } else {
    axis /= s;
  }
  const double angle = std::atan2(s, vec.z());
  const double sa = std::sin(angle / 2);
  return Eigen::Quaterniond(std::cos(angle / 2), axis.x() * sa, axis.y() * sa, axis.z() * sa);
}

namespace {

// The element's own orientation attributes if it has any, else its class's: an element that
// writes one orientation replaces the class's.
Element OrientationSource(const Element& element) {
  static const char* const kKeys[] = {"quat", "axisangle", "euler", "xyaxes", "zaxis"};
  for (const char* key : kKeys) {
    if (element.node->Find(key)) {
      Element own = element;
      own.defaults = nullptr;
      return own;
    }
  }
  return element;
}

}  // namespace

Eigen::Quaterniond Orientation(Context* context, const Element& in, const std::string& what) {
  const Element element = OrientationSource(in);
  const std::string tag = "<" + element.node->name + "> " + what;
  const double to_radians = context->compiler.degree ? M_PI / 180.0 : 1.0;
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  if (auto v = Numbers(context, element, "quat", 4, -1, what)) {
    q = Eigen::Quaterniond((*v)[0], (*v)[1], (*v)[2], (*v)[3]);
  }
  if (auto v = Numbers(context, element, "axisangle", 4, -1, what)) {
    Eigen::Vector3d axis((*v)[0], (*v)[1], (*v)[2]);
    if (axis.norm() < kMjEps) {
      context->Error(*element.node, tag, "axisangle too small");
    } else {
      axis.normalize();
      const double half = (*v)[3] * to_radians / 2;
      q = Eigen::Quaterniond(std::cos(half), std::sin(half) * axis.x(), std::sin(half) * axis.y(),
                             std::sin(half) * axis.z());
    }
  }
  if (auto v = Numbers(context, element, "xyaxes", 6, -1, what)) {
    Eigen::Vector3d x((*v)[0], (*v)[1], (*v)[2]), y((*v)[3], (*v)[4], (*v)[5]);
    if (x.norm() < kMjEps) {
      context->Error(*element.node, tag, "xyaxes: x axis too small");
      return q;
    }
    x.normalize();
    y -= x * x.dot(y);
    if (y.norm() < kMjEps) {
      context->Error(*element.node, tag, "xyaxes: y axis too small");
      return q;
    }
    y.normalize();
    Eigen::Matrix3d R;
    R.col(0) = x;
    R.col(1) = y;
    R.col(2) = x.cross(y).normalized();
    q = Eigen::Quaterniond(R);
  }
  if (auto v = Numbers(context, element, "zaxis", 3, -1, what)) {
    const Eigen::Vector3d z((*v)[0], (*v)[1], (*v)[2]);
    if (z.norm() < kMjEps) {
      context->Error(*element.node, tag, "zaxis too small");
    } else {
      q = RotationFromZ(z.normalized());
    }
  }
  if (auto v = Numbers(context, element, "euler", 3, -1, what)) {
    q = Eigen::Quaterniond::Identity();
    const std::string& seq = context->compiler.eulerseq;
    for (int i = 0; i < 3; ++i) {
      const double half = (*v)[i] * to_radians / 2;
      const char axis = static_cast<char>(std::tolower(seq[i]));
      Eigen::Quaterniond r(std::cos(half), 0, 0, 0);
      (axis == 'x' ? r.x() : axis == 'y' ? r.y() : r.z()) = std::sin(half);
      q = std::islower(seq[i]) ? q * r : r * q;
    }
  }
  if (q.norm() < kMjEps) {
    context->Error(*element.node, tag, "quat has zero length");
    return Eigen::Quaterniond::Identity();
  }
  return q.normalized();
}

}  // namespace mjcf
}  // namespace massprops
