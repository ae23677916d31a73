#pragma once
/// @file
/// Where a number of a generated description was written: the place in the sources (a .xacro,
/// .urdf or .yaml line) that the xacro trace (massprops/io/xacro_trace.h) found for it.

#include <cstddef>
#include <string>
#include <vector>

#include "massprops/model/model.h"

namespace massprops {

/// One number's source. `how` is one of:
/// - "literal": written verbatim inside an <inertial> element (or a block handed to a macro);
/// - "yaml": a YAML value read with xacro.load_yaml;
/// - "parameter": a macro call argument or an xacro:property value, substituted unchanged;
/// - "computed": the result of arithmetic; `line` is the macro call that supplies the inputs
///   (`inputs` names them, "mass=0.17"), or the expression's own line when no call does.
struct SourcePlace {
  std::string file;  ///< The source root as given, joined with the file's path inside it.
  int line = 0;      ///< 1-based.
  std::string how;
  std::string text;  ///< What is written there ("0.0090", "${(1/2) * mass * radius*radius}").
  std::vector<std::string> inputs;  ///< computed: "name=value" of each input.
  /// literal, yaml, parameter: the byte range of `text` in the file (what a fix would replace).
  std::size_t offset = 0, length = 0;
  bool editable = false;  ///< The byte range holds exactly `text`.
};

/// A finding's source: the number it points at and where that was written.
struct FindingSource {
  std::string number;  ///< "mass", "origin xyz", "inertia ixx", ...
  /// Where it was written: one place, or several when the trace could not choose between them
  /// (each writes the same number and none is closer to the link); the first is shown first.
  std::vector<SourcePlace> places;
  SourceLocation generated;  ///< The line of the expanded description.
};

}  // namespace massprops
