// The URDF reader's light scan (reader.h): the index of index.cc from one pass over the text, with
// no DOM and no copy of the text, so that a URDF is parsed once as XML for its numbers (by
// urdfdom) and only scanned for its lines.
//
// The scan reads the XML that URDF files are written in by tinyxml2 9.0.0's rules (tinyxml2.cpp:
// XMLDocument::Parse and Identify, XMLNode::ParseDeep, XMLElement::ParseAttributes,
// XMLAttribute::ParseDeep, StrPair::ParseText, XMLUtil::IsNameStartChar): elements with
// attributes, comments, text, and <?...?> declarations before anything else. A line is 1 + the
// number of '\n' before the node's '<', as tinyxml2 counts. It gives up, and the tinyxml2 index
// reads the text as before (saying what is wrong when it is not XML), on anything else: a DOCTYPE,
// CDATA, a declaration after another node, `< name`, `</name attr>`, a closing tag that does not
// close the open element, a duplicate attribute, text outside the root, no root or a second one,
// a root other than <robot>, nesting deeper than kMaxDepth, or a value the index reads that
// tinyxml2 would change (an entity, a carriage return). Where it does not give up, tinyxml2 reads
// the same text without error and the index is the same (tests/urdf_index_test.cc compares them).
#include "io/urdf/reader.h"

namespace massprops::internal::urdf_reader {
namespace {

// tinyxml2's XMLUtil::IsNameStartChar and IsNameChar (isalpha and isdigit of the C locale).
bool IsNameStart(char c) {
  const unsigned char u = static_cast<unsigned char>(c);
  return u >= 128 || (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u == ':' || u == '_';
}

bool IsNameChar(char c) { return IsNameStart(c) || (c >= '0' && c <= '9') || c == '.' || c == '-'; }

// A value that tinyxml2 gives back as written: no entity to replace, no line end to normalize.
bool IsPlain(std::string_view value) {
  return value.find_first_of("&\r") == std::string_view::npos;
}

// Well below tinyxml2's limit (TINYXML2_MAX_ELEMENT_DEPTH, 100): URDF nests a few levels.
constexpr std::size_t kMaxDepth = 40;

}  // namespace

// An attribute of the element being scanned (outside the anonymous namespace: a member of
// IndexScanner, which Reader befriends, may not have a type of internal linkage).
struct ScannedAttribute {
  std::string_view name;
  std::string_view value;
};

class IndexScanner {
 public:
  IndexScanner(const std::string& xml, Reader* reader)
      : p_(xml.data()),
        end_(xml.data() + xml.size()),
        counted_(xml.data()),
        reader_(*reader),
        index_(reader->index_) {}

  // The index of the whole text into the reader's; false when the scan gives up.
  bool Scan() {
    SkipSpace();
    if (end_ - p_ >= 3 && p_[0] == '\xEF' && p_[1] == '\xBB' && p_[2] == '\xBF') p_ += 3;
    bool root = false, other_node = false;
    for (;;) {
      SkipSpace();
      if (p_ == end_) return root;
      if (*p_ != '<') return false;
      if (StartsWith("<?")) {
        if (other_node || !SkipPast("?>")) return false;
        continue;
      }
      other_node = true;
      if (StartsWith("<!--")) {
        if (!ReadComment()) return false;
      } else if (root || end_ - p_ < 2 || !IsNameStart(p_[1]) || !ReadRoot()) {
        return false;
      } else {
        root = true;
      }
    }
  }

 private:
  // The root element and all it holds, from its '<'.
  bool ReadRoot() {
    for (;;) {
      const char* at = p_;
      if (end_ - p_ >= 2 && p_[1] == '/') {
        p_ += 2;
        const std::string_view name = ReadName();
        SkipSpace();
        if (name.empty() || p_ == end_ || *p_ != '>' || open_.empty() || open_.back() != name) {
          return false;
        }
        ++p_;
        open_.pop_back();
        End();
      } else if (StartsWith("<!--")) {
        if (!ReadComment()) return false;
      } else if (end_ - p_ >= 2 && IsNameStart(p_[1])) {
        ++p_;
        const std::string_view name = ReadName();
        bool closed = false;
        if (!ReadAttributes(&closed) || open_.size() >= kMaxDepth || !Start(name, at)) {
          return false;
        }
        if (closed) {
          End();
        } else {
          open_.push_back(name);
        }
      } else {
        return false;
      }
      if (open_.empty()) return true;
      // Text up to the next markup: tinyxml2 takes anything but '<'.
      const void* next = std::memchr(p_, '<', static_cast<std::size_t>(end_ - p_));
      if (next == nullptr) return false;
      p_ = static_cast<const char*>(next);
    }
  }

  // After an element's name: its attributes, up to '>' (*closed false) or '/>' (true).
  bool ReadAttributes(bool* closed) {
    attributes_.clear();
    for (;;) {
      SkipSpace();
      if (p_ == end_) return false;
      if (*p_ == '>') {
        ++p_;
        *closed = false;
        return true;
      }
      if (*p_ == '/' && end_ - p_ >= 2 && p_[1] == '>') {
        p_ += 2;
        *closed = true;
        return true;
      }
      const std::string_view name = ReadName();
      if (name.empty()) return false;
      SkipSpace();
      if (p_ == end_ || *p_ != '=') return false;
      ++p_;
      SkipSpace();
      if (p_ == end_ || (*p_ != '"' && *p_ != '\'')) return false;
      const char quote = *p_++;
      const void* close = std::memchr(p_, quote, static_cast<std::size_t>(end_ - p_));
      if (close == nullptr) return false;
      const char* value_end = static_cast<const char*>(close);
      for (const ScannedAttribute& a : attributes_) {
        if (a.name == name) return false;  // tinyxml2: XML_ERROR_PARSING_ATTRIBUTE
      }
      attributes_.push_back({name, std::string_view(p_, static_cast<std::size_t>(value_end - p_))});
      p_ = value_end + 1;
    }
  }

  bool ReadComment() {
    const char* at = p_;
    const std::string_view rest(p_ + 4, static_cast<std::size_t>(end_ - p_ - 4));
    const std::size_t close = rest.find("-->");
    if (close == std::string_view::npos) return false;
    p_ += 4 + close + 3;
    // A comment anywhere inside a link (the link is open_[1]).
    if (in_link_ && open_.size() >= 2) {
      reader_.IndexComment(rest.substr(0, close), Line(at), link_.name, &link_);
    }
    return true;
  }

  // An element starts at `at` with attributes_, inside the open_ elements; as BuildIndex reads
  // the same element from the DOM. False when a value it reads is not plain.
  bool Start(std::string_view name, const char* at) {
    const std::size_t depth = open_.size();
    if (depth == 0) {
      index_.robot_line = Line(at);
      return name == "robot";
    }
    if (depth == 1) {
      in_link_ = name == "link";
      in_joint_ = name == "joint";
      if (in_link_) {
        link_ = IndexedLink();
        link_.line = Line(at);
        return Take("name", &link_.name, &link_.has_name);
      }
      if (in_joint_) {
        joint_ = IndexedJoint();
        joint_.line = Line(at);
        bool has_type = false;
        return Take("name", &joint_.name, &joint_.has_name) &&
               Take("type", &joint_.type, &has_type);
      }
      return true;
    }
    if (in_link_ && depth == 2) {
      if (name == "inertial") {
        in_first_inertial_ = link_.inertial_lines.empty();
        if (in_first_inertial_) std::fill(std::begin(numbers_), std::end(numbers_), Number());
        link_.inertial_lines.push_back(Line(at));
      } else if (name == "visual" || name == "collision") {
        link_.holders.push_back({Line(at), name == "collision"});
      }
    } else if (in_first_inertial_ && depth == 3) {
      return TakeNumbers(name, at);
    } else if (in_joint_ && depth == 2 && name == "axis" && joint_.axis_line == 0) {
      joint_.axis_line = Line(at);
      joint_.axis_has_xyz = Find("xyz") != nullptr;
    }
    return true;
  }

  // The first <origin>, <mass> or <inertia> of a link's first <inertial>: its line and the
  // numbers it holds (kInertialNumbers), checked when the <inertial> ends.
  bool TakeNumbers(std::string_view name, const char* at) {
    int* line = name == "origin"    ? &link_.origin_line
                : name == "mass"    ? &link_.mass_line
                : name == "inertia" ? &link_.inertia_line
                                    : nullptr;
    if (line == nullptr || *line != 0) return true;
    *line = Line(at);
    for (std::size_t k = 0; k < std::size(kInertialNumbers); ++k) {
      if (name != kInertialNumbers[k].element) continue;
      const ScannedAttribute* a = Find(kInertialNumbers[k].attribute);
      if (a == nullptr) continue;
      if (!IsPlain(a->value)) return false;
      numbers_[k] = {true, *line, a->value};
    }
    return true;
  }

  // The element open_.size() deep (its closing tag read, or it closed itself) ends.
  void End() {
    const std::size_t depth = open_.size();
    if (depth == 2 && in_first_inertial_) {
      in_first_inertial_ = false;
      const int link = static_cast<int>(index_.links.size());
      for (std::size_t k = 0; k < std::size(kInertialNumbers); ++k) {
        const Number& n = numbers_[k];
        if (n.present && reader_.IndexUnderflowOf(link, n.line, kInertialNumbers[k], n.text)) break;
      }
    } else if (depth == 1 && in_link_) {
      in_link_ = false;
      index_.first_link.emplace(link_.name, static_cast<int>(index_.links.size()));
      index_.links.push_back(std::move(link_));
    } else if (depth == 1 && in_joint_) {
      in_joint_ = false;
      index_.first_joint.emplace(joint_.name, static_cast<int>(index_.joints.size()));
      index_.joints.push_back(std::move(joint_));
    }
  }

  const ScannedAttribute* Find(std::string_view name) const {
    for (const ScannedAttribute& a : attributes_) {
      if (a.name == name) return &a;
    }
    return nullptr;
  }

  // The attribute `name`, if present, into *out (*present true); false when it is not plain.
  bool Take(std::string_view name, std::string* out, bool* present) const {
    const ScannedAttribute* a = Find(name);
    if (a == nullptr) return true;
    if (!IsPlain(a->value)) return false;
    out->assign(a->value);
    *present = true;
    return true;
  }

  std::string_view ReadName() {
    const char* start = p_;
    if (p_ == end_ || !IsNameStart(*p_)) return {};
    ++p_;
    while (p_ != end_ && IsNameChar(*p_)) ++p_;
    return std::string_view(start, static_cast<std::size_t>(p_ - start));
  }

  void SkipSpace() {
    while (p_ != end_ && IsSpace(*p_)) ++p_;
  }

  bool StartsWith(std::string_view prefix) const {
    return static_cast<std::size_t>(end_ - p_) >= prefix.size() &&
           std::memcmp(p_, prefix.data(), prefix.size()) == 0;
  }

  bool SkipPast(std::string_view close) {
    const std::string_view rest(p_, static_cast<std::size_t>(end_ - p_));
    const std::size_t found = rest.find(close, 2);
    if (found == std::string_view::npos) return false;
    p_ += found + close.size();
    return true;
  }

  // The line of `at`; positions are asked in increasing order, so the text is counted once.
  int Line(const char* at) {
    line_ += static_cast<int>(std::count(counted_, at, '\n'));
    counted_ = at;
    return line_;
  }

  struct Number {
    bool present = false;
    int line = 0;
    std::string_view text;
  };

  const char* p_;
  const char* const end_;
  const char* counted_;
  int line_ = 1;
  Reader& reader_;
  UrdfIndex& index_;
  std::vector<std::string_view> open_;        // the names of the open elements, the root first
  std::vector<ScannedAttribute> attributes_;  // of the element being read
  bool in_link_ = false, in_joint_ = false, in_first_inertial_ = false;
  IndexedLink link_;
  IndexedJoint joint_;
  Number numbers_[std::size(kInertialNumbers)];
};

bool Reader::ScanIndex(const std::string& xml) {
  const std::size_t warnings = result_.warnings.size();
  if (IndexScanner(xml, this).Scan()) return true;
  index_ = UrdfIndex();
  result_.warnings.erase(result_.warnings.begin() + static_cast<std::ptrdiff_t>(warnings),
                         result_.warnings.end());
  return false;
}

}  // namespace massprops::internal::urdf_reader
