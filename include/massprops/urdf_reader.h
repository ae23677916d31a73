#pragma once
/// @file
/// Reading URDF into a massprops Model in one tinyxml2 pass that reproduces urdfdom 3's model
/// (links, joints, inertials, geometries, root link) and records the line of every element.
/// urdfdom itself is kept as the test oracle (tests/corpus_urdf_test.cc).
///
/// Where urdfdom 3.0 only logs a problem and goes on with a partly filled model (a link whose
/// <inertial>, <visual> or <collision> cannot be parsed is kept with zeros or without its
/// geometries), this reader reports an error instead: a number is never silently replaced by 0.
/// It is also stricter on the tree: a link that is the child of two joints, or links that form a
/// kinematic loop, are errors. It is more lenient in one place: <capsule radius length> geometry,
/// unknown to urdfdom 3, is read as Geometry::Type::kCapsule. Joint axes are stored as unit
/// vectors (urdfdom keeps them as written); a missing <axis>, or one without xyz (a warning), is
/// (1, 0, 0) as the URDF specification says; a zero axis is kept, with a warning.

#include <cstddef>
#include <string>
#include <string_view>

#include "massprops/model.h"

namespace massprops {

/// URDF files (or standard input) larger than this are refused with a ReadError, so that hostile
/// input cannot exhaust memory. Reading a file of n bytes takes about 4 to 6 times n of memory
/// at peak (the text, tinyxml2's copy and its DOM).
inline constexpr std::size_t kMaxUrdfFileBytes = std::size_t{256} << 20;  // 256 MiB

/// Reads the URDF file at `path`; "-" reads standard input to its end (locations then name the
/// file "<stdin>"). Yields exactly one Model when the file has no errors, none otherwise.
/// Never throws for bad input (missing file, directory, too large, malformed XML, bad numbers,
/// bad tree): each problem is a ReadError naming the file, line and element.
/// Cost: linear in the file size.
ReadResult ReadUrdfFile(const std::string& path);

/// Same as ReadUrdfFile for URDF text already in memory; `file_name` is used in SourceLocations.
ReadResult ReadUrdfString(const std::string& xml, const std::string& file_name);

/// Outcome of ParseUrdfNumber.
enum class UrdfNumberStatus {
  kOk,          ///< A finite number (values below the smallest subnormal round to ±0).
  kNotANumber,  ///< Empty, trailing characters, "1,5", "abc", hexadecimal, ...
  kNotFinite,   ///< "nan", "inf", "infinity" in any case, with or without sign.
  kOutOfRange,  ///< Overflows a double ("1e400").
};

/// Parses one number with the grammar urdfdom 3 accepts (urdf::strToDouble: C++ stream
/// extraction in the classic locale that must consume the whole text): optional leading white
/// space, optional sign, decimal digits with an optional point and exponent, nothing after it.
/// Locale-independent; correctly rounded. Writes *value only on kOk.
UrdfNumberStatus ParseUrdfNumber(std::string_view text, double* value);

}  // namespace massprops
