#include "massprops/io/xacro_trace.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <set>
#include <utility>

#include "io/xacro_eval.h"
#include "io/xacro_source.h"

// How the trace works (docs/xacro.md): every place in the sources that writes an inertial
// attribute (<mass value>, <inertia ixx..izz>, <origin xyz|rpy> of an <inertial>) is expanded
// along each chain of macro calls that reaches it, with the expression subset of xacro_eval.h:
// each chain gives the link it lands in and the value it writes. A number of the expanded URDF
// is traced to the chains that give its link and its value; values the subset cannot evaluate
// (YAML dictionaries) are matched against the YAML scalars of the package by value, key and key
// path instead.

namespace massprops {
namespace {

using xacro::EvaluateText;
using xacro::SourceIndex;
using xacro::Value;
using xacro::XAttr;
using xacro::XNode;

constexpr std::size_t kMaxChains = 512;  // per site: macro calls multiply
constexpr int kMaxChainDepth = 12;
constexpr int kMaxLookupDepth = 40;
constexpr int kMaxLookups = 20000;  // per evaluation of one attribute

// One level of a chain of calls: the macro a node is in, and the call that expanded it.
struct Level {
  int macro = -1;
  int call = -1;
};
using Chain = std::vector<Level>;  // innermost first; empty: the site is at file level

struct Param {
  std::string name;
  std::optional<std::string> default_text;  // "^" inherits from the caller
  bool block = false;
};

std::vector<Param> ParamsOf(const XNode& macro) {
  std::vector<Param> out;
  const XAttr* params = macro.Attr("params");
  if (!params) return out;
  std::size_t i = 0;
  const std::string& s = params->value;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i >= s.size()) break;
    std::size_t j = i;
    // a default may be quoted ('0 0 0') and hold blanks
    std::string word;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) {
      if (s[j] == '\'' || s[j] == '"') {
        const std::size_t end = s.find(s[j], j + 1);
        if (end == std::string::npos) break;
        word += s.substr(j + 1, end - j - 1);
        j = end + 1;
      } else {
        word += s[j++];
      }
    }
    i = j;
    Param p;
    if (!word.empty() && word[0] == '*') {
      p.block = true;
      word.erase(0, word[1] == '*' ? 2 : 1);
    }
    const std::size_t eq = word.find(":=");
    if (eq != std::string::npos) {
      p.default_text = word.substr(eq + 2);
      word = word.substr(0, eq);
    } else if (word.find('=') != std::string::npos) {
      p.default_text = word.substr(word.find('=') + 1);
      word = word.substr(0, word.find('='));
    }
    p.name = word;
    out.push_back(std::move(p));
  }
  return out;
}

bool ParseBool(const Value& v, bool* out) {
  if (v.is_number) {
    *out = v.number != 0;
    return true;
  }
  std::string t = v.text;
  t.erase(0, t.find_first_not_of(' '));
  t.erase(t.find_last_not_of(' ') + 1);
  if (t == "true" || t == "True" || t == "1") return *out = true, true;
  if (t == "false" || t == "False" || t == "0") return *out = false, true;
  if (std::optional<double> n = xacro::ParseNumber(t)) return *out = *n != 0, true;
  return false;
}

// Where a name's value was written: the attribute holding it and the level it is read at.
struct Binding {
  const XNode* node = nullptr;
  const XAttr* attr = nullptr;
  std::string text;  // the text to evaluate (an argument, a default, a property value)
  std::size_t level = 0;
};

class Tracer {
 public:
  explicit Tracer(const SourceIndex& index) : index_(index) {
    for (const auto& [name, nodes] : index_.properties) {
      for (int n : nodes) {
        const int macro = xacro::EnclosingMacro(index_, n);
        if (index_.nodes[static_cast<std::size_t>(n)].Attr("value") == nullptr) continue;
        if (macro < 0) {
          global_properties_[name].push_back(n);
        } else {
          macro_properties_[{macro, name}].push_back(n);
        }
      }
    }
  }

  const XNode& Node(int id) const { return index_.nodes[static_cast<std::size_t>(id)]; }

  // Every chain of calls that reaches `node` (bounded).
  std::vector<Chain> ChainsOf(int node) const {
    std::vector<Chain> out;
    Chain chain;
    Extend(xacro::EnclosingMacro(index_, node), &chain, &out, 0);
    return out;
  }

  // The binding of `name` at `level` of `chain`; nullopt when none is known.
  std::optional<Binding> Bind(const std::string& name, const Chain& chain, std::size_t level,
                              int depth = 0) const {
    if (depth > kMaxLookupDepth) return std::nullopt;
    if (level < chain.size()) {
      const XNode& macro = Node(chain[level].macro);
      const XNode& call = Node(chain[level].call);
      auto it = macro_properties_.find({chain[level].macro, name});
      if (it != macro_properties_.end()) {
        const XNode& prop = Node(it->second.front());
        return Binding{&prop, prop.Attr("value"), prop.Attr("value")->value, level};
      }
      for (const Param& p : ParamsOf(macro)) {
        if (p.name != name || p.block) continue;
        if (const XAttr* arg = call.Attr(name)) return Binding{&call, arg, arg->value, level + 1};
        if (!p.default_text) return std::nullopt;
        if (p.default_text->rfind("^", 0) == 0) {
          std::optional<Binding> up = Bind(name, chain, level + 1, depth + 1);
          if (up || p.default_text->size() < 2) return up;
          return Binding{&macro, macro.Attr("params"), p.default_text->substr(2), level + 1};
        }
        return Binding{&macro, macro.Attr("params"), *p.default_text, level + 1};
      }
      return Bind(name, chain, level + 1, depth + 1);  // xacro: the caller's scope is visible
    }
    auto it = global_properties_.find(name);
    if (it == global_properties_.end()) return std::nullopt;
    const XNode& prop = Node(it->second.front());
    return Binding{&prop, prop.Attr("value"), prop.Attr("value")->value, chain.size()};
  }

  std::optional<Value> Evaluate(const std::string& text, const Chain& chain, std::size_t level,
                                int depth = 0) const {
    // A budget of name look-ups per evaluation: properties that each read another twice would
    // otherwise take 2^depth steps.
    if (depth == 0) lookups_left_ = kMaxLookups;
    if (depth > kMaxLookupDepth || lookups_left_ <= 0) return std::nullopt;
    xacro::NameLookup lookup = [&](const std::string& name) -> std::optional<Value> {
      if (name.rfind("$(arg ", 0) == 0) {
        auto arg = index_.args.find(name.substr(6, name.size() - 7));
        if (arg == index_.args.end()) return std::nullopt;
        return EvaluateText(arg->second, [](const std::string&) { return std::nullopt; });
      }
      if (--lookups_left_ < 0) return std::nullopt;
      std::optional<Binding> b = Bind(name, chain, level);
      if (!b) return std::nullopt;
      std::optional<Value> v = Evaluate(b->text, chain, b->level, depth + 1);
      if (v && !v->is_number) {
        if (std::optional<double> n = xacro::ParseNumber(v->text)) {
          v->is_number = true;
          v->number = *n;
        }
      }
      return v;
    };
    return EvaluateText(text, lookup);
  }

  // False when an xacro:if / xacro:unless around the node (at any level of the chain) is
  // known to be off.
  bool Active(int node, const Chain& chain) const {
    for (std::size_t level = 0; level <= chain.size(); ++level) {
      int n = level == 0 ? node : chain[level - 1].call;
      const int stop = level < chain.size() ? chain[level].macro : -1;
      for (n = Node(n).parent; n >= 0 && n != stop; n = Node(n).parent) {
        const XNode& x = Node(n);
        if (x.tag != "xacro:if" && x.tag != "xacro:unless") continue;
        const XAttr* cond = x.Attr("value");
        if (!cond) continue;
        std::optional<Value> v = Evaluate(cond->value, chain, level);
        bool on = true;
        if (v && ParseBool(*v, &on) && on != (x.tag == "xacro:if")) return false;
      }
    }
    return true;
  }

  // The name of the link the node lands in under this chain; nullopt when unknown.
  std::optional<std::string> LinkOf(int node, const Chain& chain) const {
    for (std::size_t level = 0; level <= chain.size(); ++level) {
      int n = level == 0 ? Node(node).parent : chain[level - 1].call;
      const int stop = level < chain.size() ? chain[level].macro : -1;
      for (; n >= 0 && n != stop; n = Node(n).parent) {
        const XNode& x = Node(n);
        if (x.tag == "link") {
          const XAttr* name = x.Attr("name");
          if (!name) return std::nullopt;
          std::optional<Value> v = Evaluate(name->value, chain, level);
          if (!v || v->is_number) return std::nullopt;
          return v->text;
        }
        // A block handed to a macro (<xacro:bumper><inertial>...): the macro's one link.
        const std::string called = xacro::CalledMacro(x.tag);
        if (!called.empty() && level == 0 && n != Node(node).parent) {
          return BlockLink(called, n, chain, level);
        }
        if (!called.empty() && n == Node(node).parent) {
          if (std::optional<std::string> l = BlockLink(called, n, chain, level)) return l;
        }
      }
    }
    return std::nullopt;
  }

  // Is this node an <origin> of an inertial: inside an <inertial>, or a block handed to a macro
  // that inserts it into its <inertial>?
  bool InInertial(int node) const {
    for (int n = Node(node).parent; n >= 0; n = Node(n).parent) {
      const XNode& x = Node(n);
      if (x.tag == "inertial") return true;
      if (x.tag == "link" || x.tag == "xacro:macro" || x.tag == "joint") return false;
      const std::string called = xacro::CalledMacro(x.tag);
      if (!called.empty()) return MacroInsertsIntoInertial(called);
    }
    return false;
  }

  const SourceIndex& index() const { return index_; }

 private:
  void Extend(int macro, Chain* chain, std::vector<Chain>* out, int depth) const {
    if (out->size() >= kMaxChains) return;
    if (macro < 0 || depth >= kMaxChainDepth) {
      out->push_back(*chain);
      return;
    }
    const XAttr* name = Node(macro).Attr("name");
    auto calls = name ? index_.calls.find(name->value) : index_.calls.end();
    if (calls == index_.calls.end()) return;  // a macro nobody calls writes nothing
    for (int call : calls->second) {
      if (std::find_if(chain->begin(), chain->end(),
                       [&](const Level& l) { return l.call == call; }) != chain->end()) {
        continue;  // recursion
      }
      chain->push_back({macro, call});
      Extend(xacro::EnclosingMacro(index_, call), chain, out, depth + 1);
      chain->pop_back();
    }
  }

  std::optional<std::string> BlockLink(const std::string& macro_name, int call, const Chain& chain,
                                       std::size_t level) const {
    auto defs = index_.macros.find(macro_name);
    if (defs == index_.macros.end() || defs->second.size() != 1) return std::nullopt;
    const int def = defs->second.front();
    std::vector<int> links;
    CollectLinks(def, &links);
    if (links.size() != 1) return std::nullopt;
    Chain inner;
    inner.push_back({def, call});
    inner.insert(inner.end(), chain.begin() + static_cast<std::ptrdiff_t>(level), chain.end());
    const XAttr* name = Node(links.front()).Attr("name");
    if (!name) return std::nullopt;
    std::optional<Value> v = Evaluate(name->value, inner, 0);
    if (!v || v->is_number) return std::nullopt;
    return v->text;
  }

  void CollectLinks(int node, std::vector<int>* links) const {
    for (int child : Node(node).children) {
      if (Node(child).tag == "link") {
        links->push_back(child);
      } else {
        CollectLinks(child, links);
      }
    }
  }

  bool MacroInsertsIntoInertial(const std::string& macro_name) const {
    auto defs = index_.macros.find(macro_name);
    if (defs == index_.macros.end()) return false;
    std::function<bool(int, bool)> walk = [&](int n, bool inside) {
      const XNode& x = Node(n);
      if (x.tag == "xacro:insert_block" && inside) return true;
      for (int child : x.children) {
        if (walk(child, inside || x.tag == "inertial")) return true;
      }
      return false;
    };
    for (int def : defs->second) {
      if (walk(def, false)) return true;
    }
    return false;
  }

  const SourceIndex& index_;
  mutable int lookups_left_ = 0;
  std::map<std::string, std::vector<int>> global_properties_;
  std::map<std::pair<int, std::string>, std::vector<int>> macro_properties_;
};

bool SameNumbers(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double scale = std::max(std::fabs(a[i]), std::fabs(b[i]));
    if (!(a[i] == b[i] || std::fabs(a[i] - b[i]) <= 1e-12 * scale)) return false;
  }
  return true;
}

std::vector<double> NumbersOf(const Value& v) {
  if (v.is_number) return {v.number};
  return xacro::ParseNumbers(v.text);
}

bool IsSingleName(const std::string& text, std::string* name) {
  std::string t = text;
  t.erase(0, t.find_first_not_of(' '));
  t.erase(t.find_last_not_of(' ') + 1);
  if (t.size() < 4 || t.rfind("${", 0) != 0 || t.back() != '}') return false;
  std::string inner = t.substr(2, t.size() - 3);
  inner.erase(0, inner.find_first_not_of(' '));
  inner.erase(inner.find_last_not_of(' ') + 1);
  if (inner.empty() || !(std::isalpha(static_cast<unsigned char>(inner[0])) || inner[0] == '_')) {
    return false;
  }
  for (char c : inner) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  *name = inner;
  return true;
}

// The shortest text that reads back as the same double (as Python's repr prints a float).
std::string ShortestText(double value) {
  char buffer[64];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

bool HasExpression(const std::string& text) { return text.find('$') != std::string::npos; }

SourcePlace PlaceAt(const SourceIndex& index, const XNode& node, const XAttr& attr,
                    const std::string& how) {
  SourcePlace place;
  place.file = index.files[static_cast<std::size_t>(node.file)].path;
  place.line = attr.line;
  place.how = how;
  place.text = attr.value;
  place.offset = attr.offset;
  place.length = attr.length;
  const std::string& text = index.files[static_cast<std::size_t>(node.file)].text;
  place.editable = attr.length > 0 && attr.offset + attr.length <= text.size() &&
                   text.compare(attr.offset, attr.length, attr.value) == 0;
  return place;
}

// Where a value that matched was written, following single-name substitutions.
SourcePlace Explain(const Tracer& tracer, int site, const XAttr& attr, const Chain& chain) {
  const SourceIndex& index = tracer.index();
  const XNode& node = tracer.Node(site);
  if (!HasExpression(attr.value)) return PlaceAt(index, node, attr, "literal");
  std::string name;
  std::string text = attr.value;
  const XNode* at_node = &node;
  const XAttr* at_attr = &attr;
  std::size_t level = 0;
  // Follow ${name} → its binding while the text is one name.
  for (int hops = 0; hops < kMaxLookupDepth && IsSingleName(text, &name); ++hops) {
    std::optional<Binding> b = tracer.Bind(name, chain, level);
    if (!b || !b->attr) break;
    at_node = b->node;
    at_attr = b->attr;
    text = b->text;
    level = b->level;
    if (!HasExpression(text)) {
      SourcePlace place = PlaceAt(index, *at_node, *at_attr, "parameter");
      if (at_attr->name == "params") place.editable = false;  // a default inside params="..."
      place.text = text;
      return place;
    }
  }
  // Arithmetic: the call that supplies the inputs is the innermost one at which some input is
  // not just handed on from the caller's own parameters.
  std::vector<std::string> names;
  for (const std::string& e : xacro::ExpressionsOf(text)) {
    for (const std::string& n : xacro::NamesOf(e)) {
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
    }
  }
  SourcePlace place = PlaceAt(index, *at_node, *at_attr, "computed");
  place.editable = false;
  for (const std::string& n : names) {
    std::optional<Value> v = tracer.Evaluate("${" + n + "}", chain, level);
    if (v) place.inputs.push_back(n + "=" + (v->is_number ? ShortestText(v->number) : v->text));
  }
  std::vector<std::string> wanted = names;
  for (std::size_t l = level; l < chain.size() && !wanted.empty(); ++l) {
    std::vector<Param> params = ParamsOf(tracer.Node(chain[l].macro));
    std::vector<std::string> handed_on;
    bool supplies = false;
    bool any_param = false;
    for (const std::string& n : wanted) {
      const bool is_param =
          std::any_of(params.begin(), params.end(), [&](const Param& p) { return p.name == n; });
      if (!is_param) continue;
      any_param = true;
      const XAttr* arg = tracer.Node(chain[l].call).Attr(n);
      std::string inner;
      if (arg && IsSingleName(arg->value, &inner)) {
        handed_on.push_back(inner);
      } else {
        supplies = true;
      }
    }
    if (!any_param) break;
    const XNode& call = tracer.Node(chain[l].call);
    place.file = index.files[static_cast<std::size_t>(call.file)].path;
    place.line = call.line;
    place.offset = place.length = 0;
    if (supplies) break;
    wanted = handed_on;
  }
  return place;
}

bool KeyMatches(const std::string& key, const std::string& element, const std::string& attribute) {
  if (element == "mass") return key == "mass";
  if (key == attribute) return true;
  if (attribute.size() == 3 && attribute[0] == 'i' && key == attribute.substr(1)) return true;
  return false;
}

// Is the YAML key a name the link is made of ("link0" in "fr3_link0")?
bool KeyNamesLink(const std::string& key, const std::string& link) {
  if (key.size() < 2 || key.size() > link.size()) return false;
  for (std::size_t at = link.find(key); at != std::string::npos; at = link.find(key, at + 1)) {
    const bool start = at == 0 || !std::isalnum(static_cast<unsigned char>(link[at - 1]));
    const std::size_t end = at + key.size();
    const bool stop = end == link.size() || !std::isalnum(static_cast<unsigned char>(link[end]));
    if (start && stop) return true;
  }
  return false;
}

struct Candidate {
  SourcePlace place;
  int score = 0;
};

// One <inertial> attribute of the expanded text.
struct ExpandedNumber {
  TracedNumber number;
  std::vector<double> values;
};

std::vector<ExpandedNumber> ReadExpanded(const tinyxml2::XMLDocument& doc) {
  std::vector<ExpandedNumber> out;
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (!robot) return out;
  for (const tinyxml2::XMLElement* link = robot->FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    const char* link_name = link->Attribute("name");
    const tinyxml2::XMLElement* inertial = link->FirstChildElement("inertial");
    if (!link_name || !inertial) continue;
    for (const tinyxml2::XMLElement* e = inertial->FirstChildElement(); e;
         e = e->NextSiblingElement()) {
      const std::string element = e->Name();
      std::vector<std::string> attributes;
      if (element == "mass") attributes = {"value"};
      if (element == "origin") attributes = {"xyz", "rpy"};
      if (element == "inertia") attributes = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
      for (const std::string& a : attributes) {
        const char* text = e->Attribute(a.c_str());
        if (!text) continue;
        ExpandedNumber n;
        n.number.link = link_name;
        n.number.element = element;
        n.number.attribute = a;
        n.number.expanded_value = text;
        n.number.expanded_line = e->GetLineNum();
        n.values = xacro::ParseNumbers(text);
        out.push_back(std::move(n));
      }
    }
  }
  return out;
}

// A place in the sources that writes an inertial attribute, evaluated along one chain.
struct Instance {
  int site = 0;
  const XAttr* attr = nullptr;
  std::size_t chain = 0;
  std::optional<std::string> link;
  std::vector<double> values;
};

}  // namespace

std::string NumberName(const TracedNumber& number) {
  if (number.element == "mass") return "mass";
  return number.element + " " + number.attribute;
}

XacroTrace TraceXacro(std::string_view expanded, const std::string& expanded_name,
                      const XacroTraceOptions& options) {
  XacroTrace trace;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(expanded.data(), expanded.size()) != tinyxml2::XML_SUCCESS) {
    trace.errors.push_back(
        MakeReadError(expanded_name, doc.ErrorLineNum(), "", std::string(doc.ErrorStr())));
    return trace;
  }
  std::vector<ExpandedNumber> numbers = ReadExpanded(doc);
  const SourceIndex index =
      xacro::IndexSources(options.source_roots, options.args, options.exclude_files, expanded);
  trace.errors = index.errors;
  trace.source_files = static_cast<int>(index.files.size());
  const Tracer tracer(index);

  // Every site that writes an inertial attribute, evaluated along each of its chains.
  std::vector<std::vector<Chain>> chains_of(index.nodes.size());
  std::vector<Instance> instances;
  static const std::set<std::string> kInertiaNames = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  for (std::size_t n = 0; n < index.nodes.size(); ++n) {
    const XNode& node = index.nodes[n];
    const bool mass = node.tag == "mass", inertia = node.tag == "inertia",
               origin = node.tag == "origin" && tracer.InInertial(static_cast<int>(n));
    if (!mass && !inertia && !origin) continue;
    for (const XAttr& attr : node.attrs) {
      const bool wanted = (mass && attr.name == "value") ||
                          (inertia && kInertiaNames.count(attr.name)) ||
                          (origin && (attr.name == "xyz" || attr.name == "rpy"));
      if (!wanted) continue;
      if (chains_of[n].empty()) chains_of[n] = tracer.ChainsOf(static_cast<int>(n));
      for (std::size_t c = 0; c < chains_of[n].size(); ++c) {
        const Chain& chain = chains_of[n][c];
        if (!tracer.Active(static_cast<int>(n), chain)) continue;
        Instance instance;
        instance.site = static_cast<int>(n);
        instance.attr = &attr;
        instance.chain = c;
        instance.link = tracer.LinkOf(static_cast<int>(n), chain);
        std::optional<Value> v = tracer.Evaluate(attr.value, chain, 0);
        if (v) instance.values = NumbersOf(*v);
        instances.push_back(std::move(instance));
      }
    }
  }

  // Instances by (element, attribute), so that each number looks only at its own kind.
  std::map<std::pair<std::string, std::string>, std::vector<const Instance*>> by_kind;
  for (const Instance& instance : instances) {
    by_kind[{index.nodes[static_cast<std::size_t>(instance.site)].tag, instance.attr->name}]
        .push_back(&instance);
  }
  const std::vector<const Instance*> no_instances;
  for (ExpandedNumber& expanded_number : numbers) {
    TracedNumber& number = expanded_number.number;
    std::vector<Candidate> candidates;
    auto kind = by_kind.find({number.element, number.attribute});
    for (const Instance* instance_ptr : kind == by_kind.end() ? no_instances : kind->second) {
      const Instance& instance = *instance_ptr;
      if (instance.link && *instance.link != number.link) continue;
      if (!SameNumbers(instance.values, expanded_number.values)) continue;
      Candidate candidate;
      candidate.place = Explain(tracer, instance.site, *instance.attr,
                                chains_of[static_cast<std::size_t>(instance.site)][instance.chain]);
      candidate.score = instance.link ? 10 : 5;
      candidates.push_back(std::move(candidate));
    }
    for (const xacro::YamlScalar& scalar : index.yaml) {
      bool key_ok = false, link_ok = false;
      for (const std::vector<std::string>& path : scalar.paths) {
        if (path.empty() || !KeyMatches(path.back(), number.element, number.attribute)) continue;
        key_ok = true;
        for (std::size_t k = 0; k + 1 < path.size(); ++k)
          link_ok |= KeyNamesLink(path[k], number.link);
      }
      if (!key_ok || !SameNumbers(xacro::ParseNumbers(scalar.text), expanded_number.values))
        continue;
      Candidate candidate;
      candidate.place.file = index.files[static_cast<std::size_t>(scalar.file)].path;
      candidate.place.line = scalar.line;
      candidate.place.how = "yaml";
      candidate.place.text = scalar.text;
      candidate.place.offset = scalar.offset;
      candidate.place.length = scalar.length;
      candidate.place.editable = scalar.editable;
      candidate.score = link_ok ? 9 : 6;
      candidates.push_back(std::move(candidate));
    }
    int best = 0;
    for (const Candidate& c : candidates) best = std::max(best, c.score);
    for (const Candidate& c : candidates) {
      if (c.score != best) continue;
      const bool seen =
          std::any_of(number.places.begin(), number.places.end(), [&](const SourcePlace& p) {
            return p.file == c.place.file && p.line == c.place.line && p.how == c.place.how;
          });
      if (!seen) number.places.push_back(c.place);
    }
    trace.numbers.push_back(std::move(number));
  }
  return trace;
}

}  // namespace massprops
