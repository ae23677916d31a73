#include "massprops/output/xml_patch.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace massprops {
namespace {

constexpr std::size_t kNpos = std::string_view::npos;

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool EndsName(char c) { return IsSpace(c) || c == '/' || c == '>' || c == '='; }

// An element of the text: its start tag [open_begin, open_end) and end tag [close_begin,
// close_end) (both empty at open_end for a self-closing element).
struct Span {
  std::size_t open_begin = 0, open_end = 0, close_begin = 0, close_end = 0;
  std::string_view name;
};

// Skips a comment, CDATA section, processing instruction or declaration starting at `pos`;
// returns the position after it, or kNpos when `pos` starts none of them.
std::size_t SkipSpecial(std::string_view t, std::size_t pos) {
  auto skip_to = [&](std::string_view end) -> std::size_t {
    const std::size_t e = t.find(end, pos + 2);
    return e == kNpos ? t.size() : e + end.size();
  };
  if (t.compare(pos, 4, "<!--") == 0) return skip_to("-->");
  if (t.compare(pos, 9, "<![CDATA[") == 0) return skip_to("]]>");
  if (t.compare(pos, 2, "<?") == 0) return skip_to("?>");
  if (t.compare(pos, 2, "<!") == 0) return skip_to(">");
  return kNpos;
}

// The end (position after '>') of the tag starting at `pos`, honouring quoted values; kNpos if
// the tag does not end.
std::size_t TagEnd(std::string_view t, std::size_t pos) {
  char quote = 0;
  for (std::size_t i = pos + 1; i < t.size(); ++i) {
    const char c = t[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return i + 1;
    }
  }
  return kNpos;
}

// The element whose start tag begins at `pos` ('<' of a start tag).
std::optional<Span> ElementAt(std::string_view t, std::size_t pos) {
  Span s;
  s.open_begin = pos;
  std::size_t n = pos + 1;
  while (n < t.size() && !EndsName(t[n])) ++n;
  s.name = t.substr(pos + 1, n - pos - 1);
  s.open_end = TagEnd(t, pos);
  if (s.open_end == kNpos || s.name.empty()) return std::nullopt;
  if (t[s.open_end - 2] == '/') {
    s.close_begin = s.close_end = s.open_end;
    return s;
  }
  int depth = 0;
  std::size_t i = s.open_end;
  while (true) {
    i = t.find('<', i);
    if (i == kNpos) return std::nullopt;
    const std::size_t special = SkipSpecial(t, i);
    if (special != kNpos) {
      i = special;
      continue;
    }
    const std::size_t end = TagEnd(t, i);
    if (end == kNpos) return std::nullopt;
    if (t[i + 1] == '/') {
      if (depth == 0) {
        s.close_begin = i;
        s.close_end = end;
        return s;
      }
      --depth;
    } else if (t[end - 2] != '/') {
      ++depth;
    }
    i = end;
  }
}

// The child elements of `parent`, in order.
std::vector<Span> Children(std::string_view t, const Span& parent) {
  std::vector<Span> children;
  std::size_t i = parent.open_end;
  while (i < parent.close_begin) {
    i = t.find('<', i);
    if (i == kNpos || i >= parent.close_begin) break;
    const std::size_t special = SkipSpecial(t, i);
    if (special != kNpos) {
      i = special;
      continue;
    }
    const std::optional<Span> child = ElementAt(t, i);
    if (!child) break;
    children.push_back(*child);
    i = child->close_end;
  }
  return children;
}

std::optional<Span> FirstChild(std::string_view t, const Span& parent, std::string_view name) {
  for (const Span& child : Children(t, parent)) {
    if (child.name == name) return child;
  }
  return std::nullopt;
}

// The value range of attribute `name` in the start tag of `s`.
std::optional<std::pair<std::size_t, std::size_t>> AttributeValue(std::string_view t, const Span& s,
                                                                  std::string_view name) {
  std::size_t i = s.open_begin + 1 + s.name.size();
  const std::size_t end = s.open_end - 1;
  while (i < end) {
    while (i < end && IsSpace(t[i])) ++i;
    if (i >= end || t[i] == '/' || t[i] == '>') break;
    const std::size_t name_begin = i;
    while (i < end && !EndsName(t[i])) ++i;
    const std::string_view attribute = t.substr(name_begin, i - name_begin);
    while (i < end && IsSpace(t[i])) ++i;
    if (i >= end || t[i] != '=') return std::nullopt;
    ++i;
    while (i < end && IsSpace(t[i])) ++i;
    if (i >= end || (t[i] != '"' && t[i] != '\'')) return std::nullopt;
    const char quote = t[i];
    const std::size_t value_begin = ++i;
    while (i < end && t[i] != quote) ++i;
    if (i >= end) return std::nullopt;
    if (attribute == name) return std::make_pair(value_begin, i);
    ++i;
  }
  return std::nullopt;
}

struct Edit {
  std::size_t pos = 0;
  std::size_t length = 0;
  std::string text;
};

class Patcher {
 public:
  Patcher(std::string_view text, Model::Format format, bool included)
      : t_(text), sdf_(format == Model::Format::kSdf), included_(included) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (t_[i] == '\n') line_starts_.push_back(i + 1);
    }
    CollectLinks();
  }

  // The edits of one repair, or an error message.
  std::pair<std::vector<Edit>, std::string> EditsFor(const Repair& r) {
    edits_.clear();
    error_.clear();
    const std::optional<Span> link = FindLink(r.link, r.link_line, included_);
    if (!link) return {{}, error_};
    if (r.inserts_inertial) {
      InsertInertial(*link, r.after);
      return {edits_, error_};
    }
    const std::optional<Span> inertial = FirstChild(t_, *link, "inertial");
    if (!inertial) return {{}, Fail("the link has no <inertial> element")};
    for (const FieldChange& c : r.changes) {
      if (!error_.empty()) break;
      if (c.element == "origin" || c.element == "pose") {
        if (r.inserts_origin) {
          InsertOrigin(*inertial, c.new_values);
          continue;
        }
      }
      std::optional<Span> element = FirstChild(t_, *inertial, c.element);
      if (!element) {
        Fail("<" + c.element + "> not found in the <inertial>");
        break;
      }
      if (c.line > 0 && LineOf(element->open_begin) != c.line) {
        Fail("<" + c.element + "> is at line " + std::to_string(LineOf(element->open_begin)) +
             ", the model says " + std::to_string(c.line));
        break;
      }
      if (sdf_ && c.element == "pose") {
        if (auto rel = AttributeValue(t_, *element, "relative_to")) {
          const std::string_view value = t_.substr(rel->first, rel->second - rel->first);
          if (!value.empty() && value != ShortName(r.link)) {
            Fail("the inertial <pose> is relative_to '" + std::string(value) +
                 "', not the link: its position is not rewritten");
            break;
          }
        }
      }
      if (!sdf_) {
        const auto value = AttributeValue(t_, *element, c.attribute);
        if (!value) {
          Fail("attribute " + c.attribute + " not found on <" + c.element + ">");
          break;
        }
        ReplaceTokens(value->first, value->second, c.first_token, c.new_values);
      } else if (c.attribute.empty()) {
        ReplaceText(*element, c.first_token, c.new_values);
      } else if (std::optional<Span> child = FirstChild(t_, *element, c.attribute)) {
        ReplaceText(*child, c.first_token, c.new_values);
      } else {
        InsertSdfChild(*element, c.attribute, c.new_values);
      }
    }
    return {edits_, error_};
  }

  int LineOf(std::size_t pos) const {
    return static_cast<int>(std::upper_bound(line_starts_.begin(), line_starts_.end(), pos) -
                            line_starts_.begin());
  }

 private:
  std::string Fail(std::string message) {
    if (error_.empty()) error_ = std::move(message);
    return error_;
  }

  static std::string_view ShortName(std::string_view scoped) {
    const std::size_t colons = scoped.rfind("::");
    return colons == kNpos ? scoped : scoped.substr(colons + 2);
  }

  // The <link> element of the repair: found by structure (the element path robot/link, or
  // sdf/[world/]model/[model/...]link with the nested model names as the scope), its name and its
  // line; never inside a comment, CDATA section or another element. In an included file
  // (`included`), the link's scoped name may carry the scopes of the including files in front:
  // "cargo::body" is the element scoped "body" of the included model.
  std::optional<Span> FindLink(const std::string& name, int line, bool included) {
    std::vector<const LinkElement*> named;
    for (const LinkElement& link : links_) {
      const bool same = link.scoped == name;
      const bool suffix =
          included && name.size() > link.scoped.size() + 2 &&
          name.compare(name.size() - link.scoped.size(), link.scoped.size(), link.scoped) == 0 &&
          name.compare(name.size() - link.scoped.size() - 2, 2, "::") == 0;
      if (same || suffix) named.push_back(&link);
    }
    if (named.empty()) {
      Fail("this file has no <link name=\"" + std::string(ShortName(name)) +
           "\"> at the element path " +
           std::string(sdf_ ? "sdf/[world/]model/[model/...]link" : "robot/link") +
           " (an element inside a comment does not count)");
      return std::nullopt;
    }
    std::vector<const LinkElement*> at_line;
    for (const LinkElement* link : named) {
      if (LineOf(link->span.open_begin) == line) at_line.push_back(link);
    }
    if (at_line.size() == 1) return at_line.front()->span;
    if (at_line.empty()) {
      Fail("the <link> element of that name is at line " +
           std::to_string(LineOf(named.front()->span.open_begin)) + ", the model says " +
           std::to_string(line));
    } else {
      Fail("several <link> elements of that name start at line " + std::to_string(line));
    }
    return std::nullopt;
  }

  struct LinkElement {
    std::string scoped;  // nested model names and the link name, joined by "::"
    Span span;
  };

  // Every <link> element of the document by structure (see FindLink).
  void CollectLinks() {
    std::size_t i = 0;
    std::optional<Span> root;
    while ((i = t_.find('<', i)) != kNpos) {
      const std::size_t special = SkipSpecial(t_, i);
      if (special != kNpos) {
        i = special;
        continue;
      }
      root = ElementAt(t_, i);
      break;
    }
    if (!root) return;
    if (!sdf_) {
      if (root->name != "robot") return;
      for (const Span& child : Children(t_, *root)) {
        if (child.name == "link") AddLink(child, "");
      }
      return;
    }
    if (root->name != "sdf") return;
    for (const Span& child : Children(t_, *root)) {
      if (child.name == "model") CollectModel(child, "");
      if (child.name != "world") continue;
      for (const Span& entity : Children(t_, child)) {
        if (entity.name == "model") CollectModel(entity, "");
      }
    }
  }

  // The links of an SDF <model> whose scope (nested model names) is `prefix`. Iterative: a
  // hostile file may nest models very deeply.
  void CollectModel(const Span& top, const std::string& top_prefix) {
    std::vector<std::pair<Span, std::string>> pending = {{top, top_prefix}};
    while (!pending.empty()) {
      const auto [model, prefix] = pending.back();
      pending.pop_back();
      for (const Span& child : Children(t_, model)) {
        if (child.name == "link") AddLink(child, prefix);
        if (child.name != "model") continue;
        const auto value = AttributeValue(t_, child, "name");
        if (!value) continue;
        pending.push_back(
            {child,
             prefix + std::string(t_.substr(value->first, value->second - value->first)) + "::"});
      }
    }
  }

  void AddLink(const Span& link, const std::string& prefix) {
    const auto value = AttributeValue(t_, link, "name");
    if (!value) return;
    links_.push_back(
        {prefix + std::string(t_.substr(value->first, value->second - value->first)), link});
  }

  // Replaces the white-space separated numbers first, first + 1, ... of [begin, end).
  void ReplaceTokens(std::size_t begin, std::size_t end, int first,
                     const std::vector<double>& values) {
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    std::size_t i = begin;
    while (i < end) {
      while (i < end && IsSpace(t_[i])) ++i;
      if (i >= end) break;
      const std::size_t token_begin = i;
      while (i < end && !IsSpace(t_[i])) ++i;
      tokens.push_back({token_begin, i});
    }
    if (tokens.size() < static_cast<std::size_t>(first) + values.size()) {
      Fail("the value at line " + std::to_string(LineOf(begin)) + " has " +
           std::to_string(tokens.size()) + " numbers, fewer than the " +
           std::to_string(first + values.size()) + " expected");
      return;
    }
    for (std::size_t k = 0; k < values.size(); ++k) {
      const auto [b, e] = tokens[first + k];
      edits_.push_back({b, e - b, FormatShortest(values[k])});
    }
  }

  void ReplaceText(const Span& element, int first, const std::vector<double>& values) {
    const std::size_t b = element.open_end, e = element.close_begin;
    if (t_.substr(b, e - b).find('<') != kNpos) {
      Fail("<" + std::string(element.name) + "> at line " +
           std::to_string(LineOf(element.open_begin)) + " holds markup, not just numbers");
      return;
    }
    ReplaceTokens(b, e, first, values);
  }

  std::string Indent(std::size_t pos) const {
    const std::size_t start = line_starts_[LineOf(pos) - 1];
    std::size_t i = start;
    while (i < pos && (t_[i] == ' ' || t_[i] == '\t')) ++i;
    return std::string(t_.substr(start, i - start));
  }

  // Whether only indentation precedes `pos` on its line.
  bool StartsLine(std::size_t pos) const {
    return Indent(pos).size() == pos - line_starts_[LineOf(pos) - 1];
  }

  std::string Newline(std::size_t pos) const {
    const std::size_t nl = t_.find('\n', pos);
    return nl != kNpos && nl > 0 && t_[nl - 1] == '\r' ? "\r\n" : "\n";
  }

  // The indentation of `parent`'s children and one indentation step.
  std::pair<std::string, std::string> ChildIndent(const Span& parent) const {
    const std::string outer = Indent(parent.open_begin);
    const std::vector<Span> children = Children(t_, parent);
    if (!children.empty() && StartsLine(children.front().open_begin) &&
        LineOf(children.front().open_begin) != LineOf(parent.open_begin)) {
      const std::string inner = Indent(children.front().open_begin);
      if (inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0) {
        return {inner, inner.substr(outer.size())};
      }
      return {inner, "  "};
    }
    return {outer + "  ", "  "};
  }

  static std::string Xyz(const Eigen::Vector3d& p) {
    return FormatShortest(p.x()) + " " + FormatShortest(p.y()) + " " + FormatShortest(p.z());
  }

  void InsertInertial(const Span& link, const Inertial& in) {
    // An empty <link .../> is opened up: "/>" becomes ">" + the block + "</link>".
    const bool self_closing = link.close_begin == link.open_end && t_[link.open_end - 2] == '/';
    const auto [ci, u] = ChildIndent(link);
    const std::string nl = Newline(link.open_begin);
    auto n = [](double x) { return FormatShortest(x); };
    std::string block = nl + ci + "<inertial>" + nl;
    if (!sdf_) {
      block += ci + u + "<origin xyz=\"" + Xyz(in.X_BBi.p_AB) + "\" rpy=\"0 0 0\"/>" + nl;
      block += ci + u + "<mass value=\"" + n(in.mass) + "\"/>" + nl;
      block += ci + u + "<inertia ixx=\"" + n(in.ixx) + "\" ixy=\"" + n(in.ixy) + "\" ixz=\"" +
               n(in.ixz) + "\" iyy=\"" + n(in.iyy) + "\" iyz=\"" + n(in.iyz) + "\" izz=\"" +
               n(in.izz) + "\"/>" + nl;
    } else {
      block += ci + u + "<pose>" + Xyz(in.X_BBi.p_AB) + " 0 0 0</pose>" + nl;
      block += ci + u + "<mass>" + n(in.mass) + "</mass>" + nl;
      block += ci + u + "<inertia>" + nl;
      const std::pair<const char*, double> entries[] = {{"ixx", in.ixx}, {"ixy", in.ixy},
                                                        {"ixz", in.ixz}, {"iyy", in.iyy},
                                                        {"iyz", in.iyz}, {"izz", in.izz}};
      for (const auto& [name, value] : entries) {
        block += ci + u + u + "<" + name + ">" + n(value) + "</" + name + ">" + nl;
      }
      block += ci + u + "</inertia>" + nl;
    }
    block += ci + "</inertial>";
    if (self_closing) {
      edits_.push_back(
          {link.open_end - 2, 2, ">" + block + nl + Indent(link.open_begin) + "</link>"});
      return;
    }
    edits_.push_back({link.open_end, 0, block});
  }

  void InsertOrigin(const Span& inertial, const std::vector<double>& xyz) {
    if (inertial.close_begin == inertial.open_end) {
      Fail("the <inertial> element is empty");
      return;
    }
    const auto [ci, u] = ChildIndent(inertial);
    const std::string nl = Newline(inertial.open_begin);
    const Eigen::Vector3d p(xyz[0], xyz[1], xyz[2]);
    const std::string element = sdf_ ? "<pose>" + Xyz(p) + " 0 0 0</pose>"
                                     : "<origin xyz=\"" + Xyz(p) + "\" rpy=\"0 0 0\"/>";
    edits_.push_back({inertial.open_end, 0, nl + ci + element});
  }

  // SDF: an <inertia> child that is absent (its default applies) gets written after the last one.
  void InsertSdfChild(const Span& inertia, const std::string& name,
                      const std::vector<double>& values) {
    const std::vector<Span> children = Children(t_, inertia);
    if (children.empty() || values.size() != 1) {
      Fail("<" + name + "> not found in <inertia>");
      return;
    }
    const Span& last = children.back();
    const std::string nl = Newline(last.open_begin);
    const std::string separator =
        StartsLine(last.open_begin) ? nl + Indent(last.open_begin) : std::string(" ");
    edits_.push_back(
        {last.close_end, 0,
         separator + "<" + name + ">" + FormatShortest(values[0]) + "</" + name + ">"});
  }

  std::string_view t_;
  bool sdf_;
  bool included_;
  std::vector<std::size_t> line_starts_;
  std::vector<LinkElement> links_;
  std::vector<Edit> edits_;
  std::string error_;
};

// MJCF: the repairs are written into a <body>'s <inertial> attributes (mass, pos, diaginertia or
// fullinertia, and an orientation when the repaired tensor is not diagonal in the written one).
// A body without <inertial> (its mass from its geoms) or a compiler setting that changes the
// written numbers (inertiafromgeom="true", boundmass, boundinertia, balanceinertia,
// settotalmass) is refused, naming the element to change.
class MjcfPatcher {
 public:
  explicit MjcfPatcher(std::string_view text) : t_(text) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (t_[i] == '\n') line_starts_.push_back(i + 1);
    }
    Collect();
  }

  std::pair<std::vector<Edit>, std::string> EditsFor(const Repair& r) {
    edits_.clear();
    error_.clear();
    if (!compiler_refusal_.empty()) return {{}, compiler_refusal_};
    std::vector<const Span*> at_line;
    for (const auto& [name, span] : bodies_) {
      if (LineOf(span.open_begin) == r.link_line && (name == r.link || name.empty())) {
        at_line.push_back(&span);
      }
    }
    if (at_line.size() != 1) {
      return {{},
              at_line.empty()
                  ? "this file has no <body name=\"" + r.link + "\"> at line " +
                        std::to_string(r.link_line) +
                        " under mujoco/worldbody (an <include>d file is not patched)"
                  : "several <body> elements start at line " + std::to_string(r.link_line)};
    }
    const std::optional<Span> inertial = FirstChild(t_, *at_line.front(), "inertial");
    if (!inertial || r.inserts_inertial) return {{}, FromGeoms(*at_line.front())};
    const Inertial& a = r.after;
    Replace(*inertial, "mass", {a.mass});
    Replace(*inertial, "pos", {a.X_BBi.p_AB.x(), a.X_BBi.p_AB.y(), a.X_BBi.p_AB.z()});
    Eigen::Matrix3d I_Bi;
    I_Bi << a.ixx, a.ixy, a.ixz, a.ixy, a.iyy, a.iyz, a.ixz, a.iyz, a.izz;
    const Eigen::Matrix3d I_B = a.X_BBi.R_AB * I_Bi * a.X_BBi.R_AB.transpose();
    if (AttributeValue(t_, *inertial,
                       "fullinertia")) {  // read in the body axes (orientation unused)
      Replace(*inertial, "fullinertia",
              {I_B(0, 0), I_B(1, 1), I_B(2, 2), I_B(0, 1), I_B(0, 2), I_B(1, 2)});
      return {edits_, error_};
    }
    const double largest = I_Bi.diagonal().cwiseAbs().maxCoeff();
    const bool diagonal = std::abs(a.ixy) <= 1e-12 * largest &&
                          std::abs(a.ixz) <= 1e-12 * largest && std::abs(a.iyz) <= 1e-12 * largest;
    if (diagonal) {
      Replace(*inertial, "diaginertia", {a.ixx, a.iyy, a.izz});
      return {edits_, error_};
    }
    const char* orientation = WrittenOrientation(*inertial);
    if (orientation == nullptr) {  // no orientation: the body-axes tensor as fullinertia
      Rename(*inertial, "diaginertia", "fullinertia",
             {I_B(0, 0), I_B(1, 1), I_B(2, 2), I_B(0, 1), I_B(0, 2), I_B(1, 2)});
      return {edits_, error_};
    }
    // An orientation is written: the principal axes as quat (w x y z), the moments as diaginertia.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(I_B);
    Eigen::Matrix3d R = eigen.eigenvectors();
    if (R.determinant() < 0) R.col(2) = -R.col(2);
    const Eigen::Quaterniond q(R);
    Rename(*inertial, orientation, "quat", {q.w(), q.x(), q.y(), q.z()});
    const Eigen::Vector3d& d = eigen.eigenvalues();
    Replace(*inertial, "diaginertia", {d.x(), d.y(), d.z()});
    return {edits_, error_};
  }

 private:
  int LineOf(std::size_t pos) const {
    return static_cast<int>(std::upper_bound(line_starts_.begin(), line_starts_.end(), pos) -
                            line_starts_.begin());
  }

  std::string Text(const std::pair<std::size_t, std::size_t>& range) const {
    return std::string(t_.substr(range.first, range.second - range.first));
  }

  const char* WrittenOrientation(const Span& inertial) const {
    for (const char* name : {"quat", "axisangle", "euler", "xyaxes", "zaxis"}) {
      if (AttributeValue(t_, inertial, name)) return name;
    }
    return nullptr;
  }

  // Every <body> under mujoco/worldbody (iteratively: a hostile file may nest deeply), every
  // <default class> under mujoco/default, and the compiler settings that change written numbers.
  void Collect() {
    std::size_t i = 0;
    std::optional<Span> root;
    while ((i = t_.find('<', i)) != kNpos) {
      const std::size_t special = SkipSpecial(t_, i);
      if (special == kNpos) {
        root = ElementAt(t_, i);
        break;
      }
      i = special;
    }
    if (!root || root->name != "mujoco") return;
    std::vector<Span> pending;
    for (const Span& child : Children(t_, *root)) {
      if (child.name == "worldbody" || child.name == "default") pending.push_back(child);
      if (child.name == "compiler") CompilerRefusal(child);
    }
    while (!pending.empty()) {
      const Span parent = pending.back();
      pending.pop_back();
      for (const Span& child : Children(t_, parent)) {
        const auto name = AttributeValue(t_, child, child.name == "default" ? "class" : "name");
        if (child.name == "body") bodies_.push_back({name ? Text(*name) : "", child});
        if (child.name == "default" && name) defaults_.push_back({Text(*name), child});
        if (child.name == "body" || child.name == "default") pending.push_back(child);
      }
    }
  }

  void CompilerRefusal(const Span& compiler) {
    const std::string where = "<compiler> at line " + std::to_string(LineOf(compiler.open_begin));
    if (auto v = AttributeValue(t_, compiler, "inertiafromgeom"); v && Text(*v) == "true") {
      compiler_refusal_ = where + " sets inertiafromgeom=\"true\": MuJoCo ignores every " +
                          "<inertial>, so the geoms' mass or density is what to change";
    }
    for (const char* name : {"boundmass", "boundinertia", "settotalmass", "balanceinertia"}) {
      const auto v = AttributeValue(t_, compiler, name);
      if (!v || !compiler_refusal_.empty() || Text(*v) == "false" || Text(*v) == "0") continue;
      compiler_refusal_ = where + " sets " + name + "=\"" + Text(*v) +
                          "\": the compiled mass properties are not the written ones, so fix " +
                          "does not patch them; remove it or change the <inertial> by hand";
    }
  }

  // The refusal for a body whose mass comes from its geoms, naming the <default> classes (with
  // their lines) that give them a mass or density when there are any.
  std::string FromGeoms(const Span& body) const {
    std::string message =
        "the body has no <inertial>: MuJoCo derives its mass properties from its geoms "
        "(inertiafromgeom); fix does not patch geoms: change their mass or density";
    std::vector<std::string> classes;
    for (const Span& child : Children(t_, body)) {
      if (child.name != "geom") continue;
      if (auto c = AttributeValue(t_, child, "class")) classes.push_back(Text(*c));
    }
    if (auto c = AttributeValue(t_, body, "childclass")) classes.push_back(Text(*c));
    std::string named;
    for (const auto& [name, span] : defaults_) {
      if (std::find(classes.begin(), classes.end(), name) == classes.end()) continue;
      const std::optional<Span> geom = FirstChild(t_, span, "geom");
      if (!geom || named.find("'" + name + "'") != std::string::npos) continue;
      if (!AttributeValue(t_, *geom, "mass") && !AttributeValue(t_, *geom, "density")) continue;
      named += (named.empty() ? "" : ", ") + std::string("<default class='") + name +
               "'> at line " + std::to_string(LineOf(geom->open_begin));
    }
    if (!named.empty()) message += "; their mass or density comes from " + named;
    return message;
  }

  // Rewrites the numbers of attribute `name` that differ from `values` (the others are kept).
  void Replace(const Span& e, const char* name, const std::vector<double>& values) {
    const auto value = AttributeValue(t_, e, name);
    if (!value) {
      if (error_.empty()) error_ = std::string("attribute ") + name + " not found on <inertial>";
      return;
    }
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    for (std::size_t i = value->first; i < value->second;) {
      while (i < value->second && IsSpace(t_[i])) ++i;
      if (i >= value->second) break;
      const std::size_t b = i;
      while (i < value->second && !IsSpace(t_[i])) ++i;
      tokens.push_back({b, i});
    }
    if (tokens.size() != values.size()) {
      if (error_.empty()) {
        error_ = std::string(name) + " at line " + std::to_string(LineOf(value->first)) + " has " +
                 std::to_string(tokens.size()) + " numbers, not " + std::to_string(values.size());
      }
      return;
    }
    for (std::size_t k = 0; k < values.size(); ++k) {
      const std::string old = Text(tokens[k]);
      if (std::strtod(old.c_str(), nullptr) == values[k]) continue;
      edits_.push_back(
          {tokens[k].first, tokens[k].second - tokens[k].first, FormatShortest(values[k])});
    }
  }

  // Replaces attribute `from` (name and value) by `to`="values".
  void Rename(const Span& e, const char* from, const char* to, const std::vector<double>& values) {
    const auto value = AttributeValue(t_, e, from);
    const std::size_t name_begin = value ? t_.rfind(from, value->first) : kNpos;
    if (!value || name_begin == kNpos) {
      if (error_.empty()) error_ = std::string("attribute ") + from + " not found on <inertial>";
      return;
    }
    std::string text = std::string(to) + "=\"";
    for (std::size_t k = 0; k < values.size(); ++k) {
      text += (k ? " " : "") + FormatShortest(values[k]);
    }
    edits_.push_back({name_begin, value->second + 1 - name_begin, text + "\""});
  }

  std::string_view t_;
  std::vector<std::size_t> line_starts_;
  std::vector<std::pair<std::string, Span>> bodies_, defaults_;
  std::string compiler_refusal_;
  std::vector<Edit> edits_;
  std::string error_;
};

// Lines of a text, each with its terminator.
std::vector<std::string_view> SplitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == kNpos ? text.size() : nl + 1;
    lines.push_back(text.substr(start, end - start));
    start = end;
  }
  return lines;
}

enum class Op { kEqual, kDelete, kInsert };
struct Step {
  Op op;
  int a;  // index into before (kEqual, kDelete)
  int b;  // index into after (kEqual, kInsert)
};

// Myers' greedy O(ND) algorithm; keeps the furthest-reaching x of each diagonal for each d (only
// diagonals -d..d, so O(D²) memory) and walks back through them.
std::vector<Step> MyersDiff(const std::vector<std::string_view>& a,
                            const std::vector<std::string_view>& b) {
  const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
  const int max = n + m;
  std::vector<int> v(2 * static_cast<std::size_t>(max) + 3, 0);
  const int offset = max + 1;
  std::vector<std::vector<int>> trace;  // trace[d][k + d] = v[k] after step d
  int final_d = 0;
  for (int d = 0; d <= max; ++d) {
    bool done = false;
    for (int k = -d; k <= d; k += 2) {
      int x = (k == -d || (k != d && v[offset + k - 1] < v[offset + k + 1]))
                  ? v[offset + k + 1]
                  : v[offset + k - 1] + 1;
      int y = x - k;
      while (x < n && y < m && a[x] == b[y]) ++x, ++y;
      v[offset + k] = x;
      if (x >= n && y >= m) done = true;
    }
    trace.emplace_back(v.begin() + offset - d, v.begin() + offset + d + 1);
    if (done) {
      final_d = d;
      break;
    }
  }
  std::vector<Step> steps;
  int x = n, y = m;
  for (int d = final_d; d > 0; --d) {
    const std::vector<int>& prev = trace[d - 1];
    auto at = [&](int k) { return prev[k + d - 1]; };
    const int k = x - y;
    const int prev_k = (k == -d || (k != d && at(k - 1) < at(k + 1))) ? k + 1 : k - 1;
    const int prev_x = at(prev_k);
    const int prev_y = prev_x - prev_k;
    while (x > prev_x && y > prev_y) {
      --x, --y;
      steps.push_back({Op::kEqual, x, y});
    }
    if (x == prev_x) {
      steps.push_back({Op::kInsert, x, prev_y});
    } else {
      steps.push_back({Op::kDelete, prev_x, y});
    }
    x = prev_x;
    y = prev_y;
  }
  while (x > 0 && y > 0) {
    --x, --y;
    steps.push_back({Op::kEqual, x, y});
  }
  std::reverse(steps.begin(), steps.end());
  return steps;
}

}  // namespace

PatchResult PatchModelText(std::string_view original, Model::Format format,
                           const std::vector<Repair>& repairs, const PatchOptions& options) {
  Patcher patcher(original, format, options.included);
  std::optional<MjcfPatcher> mjcf;
  if (format == Model::Format::kMjcf) mjcf.emplace(original);
  PatchResult result;
  std::vector<Edit> edits;
  for (const Repair& r : repairs) {
    auto [repair_edits, error] = mjcf ? mjcf->EditsFor(r) : patcher.EditsFor(r);
    if (!error.empty()) {
      result.errors.push_back({r.link, r.link_line, error});
      continue;
    }
    edits.insert(edits.end(), repair_edits.begin(), repair_edits.end());
    ++result.applied;
  }
  std::stable_sort(edits.begin(), edits.end(),
                   [](const Edit& a, const Edit& b) { return a.pos < b.pos; });
  std::string text;
  text.reserve(original.size() + 256);
  std::size_t pos = 0;
  for (const Edit& e : edits) {
    if (e.pos < pos) continue;  // Overlapping edits cannot come from distinct links.
    text.append(original.substr(pos, e.pos - pos));
    text.append(e.text);
    pos = e.pos + e.length;
  }
  text.append(original.substr(pos));
  result.text = std::move(text);
  return result;
}

LineChanges DiffLines(std::string_view before, std::string_view after) {
  LineChanges changes;
  for (const Step& s : MyersDiff(SplitLines(before), SplitLines(after))) {
    if (s.op == Op::kDelete) changes.removed.push_back(s.a + 1);
    if (s.op == Op::kInsert) changes.added.push_back(s.b + 1);
  }
  return changes;
}

std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name,
                        int context) {
  if (before == after) return "";
  const std::vector<std::string_view> a = SplitLines(before), b = SplitLines(after);
  const std::vector<Step> steps = MyersDiff(a, b);
  std::string out = "--- a/" + name + "\n+++ b/" + name + "\n";
  auto line = [&](char mark, std::string_view text) {
    out += mark;
    out.append(text);
    if (text.empty() || text.back() != '\n') out += "\n\\ No newline at end of file\n";
  };
  const int count = static_cast<int>(steps.size());
  int i = 0;
  while (i < count) {
    while (i < count && steps[i].op == Op::kEqual) ++i;
    if (i >= count) break;
    // A hunk: from `context` equal steps before the first change to `context` after the last,
    // merging changes separated by at most 2·context equal steps.
    const int begin = std::max(0, i - context);
    int end = i;
    while (true) {
      while (end < count && steps[end].op != Op::kEqual) ++end;
      int equal = end;
      while (equal < count && steps[equal].op == Op::kEqual) ++equal;
      if (equal < count && equal - end <= 2 * context) {
        end = equal;
        continue;
      }
      end = std::min(count, end + context);
      break;
    }
    int old_count = 0, new_count = 0;
    for (int s = begin; s < end; ++s) {
      old_count += steps[s].op != Op::kInsert;
      new_count += steps[s].op != Op::kDelete;
    }
    // Start lines: the first line of the hunk, or (for an empty side) the line before it.
    const int old_start = old_count == 0 ? steps[begin].a : steps[begin].a + 1;
    const int new_start = new_count == 0 ? steps[begin].b : steps[begin].b + 1;
    auto range = [](int start, int n) {
      if (n == 1) return std::to_string(start);
      return std::to_string(start) + "," + std::to_string(n);
    };
    out += "@@ -" + range(old_start, old_count) + " +" + range(new_start, new_count) + " @@\n";
    for (int s = begin; s < end; ++s) {
      switch (steps[s].op) {
        case Op::kEqual:
          line(' ', a[steps[s].a]);
          break;
        case Op::kDelete:
          line('-', a[steps[s].a]);
          break;
        case Op::kInsert:
          line('+', b[steps[s].b]);
          break;
      }
    }
    i = end;
  }
  return out;
}

}  // namespace massprops
