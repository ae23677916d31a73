#pragma once
/// @file
/// The xacro trace: for each number of each <inertial> of an expanded URDF (mass, origin xyz and
/// rpy, the six inertia entries), where in the xacro package it was written. docs/xacro.md says
/// how it works and what it cannot trace.

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "massprops/model/model.h"
#include "massprops/model/source_place.h"

namespace massprops {

/// One inertial number of the expanded URDF and where it was written.
struct TracedNumber {
  std::string link;
  std::string element;         ///< "mass", "origin" or "inertia".
  std::string attribute;       ///< "value", "xyz", "rpy", "ixx", ... "izz".
  std::string expanded_value;  ///< The attribute's text in the expanded URDF.
  int expanded_line = 0;
  /// Empty: not traced. One: traced. Several: each writes the number and none is closer to the
  /// link than the others (see docs/xacro.md).
  std::vector<SourcePlace> places;
};

struct XacroTraceOptions {
  /// Folders holding the package and the packages it uses (searched recursively for .xacro,
  /// .urdf, .gazebo, .yaml, .yml).
  std::vector<std::string> source_roots;
  /// xacro arguments given to the expansion (NAME → VALUE); others take their defaults.
  std::map<std::string, std::string> args;
  /// Files below the roots that are not sources (the expansion itself, when it was saved there).
  std::vector<std::string> exclude_files;
};

struct XacroTrace {
  std::vector<TracedNumber> numbers;  ///< In the order of the expanded text.
  std::vector<ReadError> errors;      ///< Source files that could not be read (traced without).
  int source_files = 0;               ///< Files read.
};

/// Traces every inertial number of `expanded` (the text of an expanded URDF; `expanded_name`
/// names it in the result; a source file with exactly its bytes is not read as a source). Never
/// throws; an expanded text that is not XML gives no numbers and
/// one error.
XacroTrace TraceXacro(std::string_view expanded, const std::string& expanded_name,
                      const XacroTraceOptions& options);

/// "mass", "origin xyz", "inertia ixx": how a number is named in messages.
std::string NumberName(const TracedNumber& number);

}  // namespace massprops
