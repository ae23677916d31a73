#pragma once
// The source tree of a xacro package as the trace reads it: every element of every .xacro /
// .urdf / .gazebo file with the line and byte range of each attribute value, the macros and
// their calls, the properties and args, and every scalar of every .yaml / .yml file with its
// line, byte range and key paths (an aliased node has several). Private to src/io.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "massprops/model/model.h"

namespace massprops::xacro {

struct XAttr {
  std::string name;
  std::string value;       ///< As written (the trace needs no entities in numbers).
  int line = 0;            ///< 1-based line of the value's first character.
  std::size_t offset = 0;  ///< Byte offset of the value (inside the quotes) in the file.
  std::size_t length = 0;  ///< Its length in bytes.
};

struct XNode {
  std::string tag;  ///< "link", "xacro:macro", "xacro:wheel", ...
  int line = 0;
  int file = 0;
  int parent = -1;  ///< -1 for a file's root element.
  std::vector<int> children;
  std::vector<XAttr> attrs;
  const XAttr* Attr(const std::string& name) const;
};

struct YamlScalar {
  int file = 0;
  int line = 0;                        ///< 1-based
  std::size_t offset = 0, length = 0;  ///< Byte range of the text in the file (plain scalars).
  bool editable = false;               ///< The byte range holds exactly `text`.
  std::string text;
  std::vector<std::vector<std::string>> paths;  ///< Every key path that reaches this scalar.
};

struct SourceFile {
  std::string path;  ///< The root as given, joined with the path inside it.
  std::string text;
};

struct SourceIndex {
  std::vector<SourceFile> files;
  std::vector<XNode> nodes;
  std::vector<YamlScalar> yaml;
  std::map<std::string, std::vector<int>> macros;      ///< macro name → its xacro:macro nodes
  std::map<std::string, std::vector<int>> calls;       ///< macro name → nodes that call it
  std::map<std::string, std::vector<int>> properties;  ///< name → xacro:property nodes
  std::map<std::string, std::string> args;             ///< xacro:arg defaults, then overrides
  std::vector<ReadError> errors;                       ///< files that could not be parsed
};

/// Reads every .xacro, .urdf, .gazebo, .yaml and .yml file below each root (hidden folders
/// skipped; at most 20 000 files of at most 16 MB each). `args` overrides xacro:arg defaults.
/// Never throws: unreadable files become errors.
/// Files in `exclude` (the same file by another path too), and files whose bytes are exactly
/// `generated` (the expansion itself, saved below a root), are not read.
SourceIndex IndexSources(const std::vector<std::string>& roots,
                         const std::map<std::string, std::string>& args,
                         const std::vector<std::string>& exclude = {},
                         std::string_view generated = {});

/// The macro a call element calls ("xacro:husarion.wheel" → "wheel"); empty when the element is
/// a xacro directive (macro, property, arg, include, if, unless, insert_block, ...) or not xacro.
std::string CalledMacro(const std::string& tag);

/// The nearest xacro:macro ancestor of a node (or the node itself); -1 at file level.
int EnclosingMacro(const SourceIndex& index, int node);

}  // namespace massprops::xacro
