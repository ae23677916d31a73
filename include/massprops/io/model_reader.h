#pragma once
/// @file
/// One entry point for every model file: reads a path (or "-" for standard input), tells URDF
/// from SDF by the root element of its content (not by its extension) and hands the text to the
/// URDF or SDF reader.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "massprops/io/mjcf_reader.h"
#include "massprops/io/sdf_reader.h"
#include "massprops/model/model.h"

namespace massprops {

/// Inputs larger than this are refused (the readers' own limits are the same: 256 MiB).
inline constexpr std::size_t kMaxModelFileBytes = std::size_t{256} << 20;

struct ReadOptions {
  SdfReadOptions sdf;  ///< Where SDF <include>s are looked up.
  MjcfReadOptions mjcf;  ///< How MJCF mesh geoms are integrated.
  /// Inputs larger than this many bytes are refused with a ReadError.
  std::size_t max_file_bytes = kMaxModelFileBytes;
};

/// The format of a model text judged by its first element: <robot> is URDF, <sdf> is SDF,
/// <mujoco> is MJCF.
/// Skips a byte order mark, white space, the XML declaration, processing instructions, comments
/// and a DOCTYPE. nullopt when the first element is something else or there is none.
/// Cost: proportional to the text before the first element.
std::optional<Model::Format> DetectModelFormat(std::string_view xml);

/// Reads a whole file ("-": standard input) into *contents. Returns nullopt on success, or the
/// error: the file does not exist or cannot be read, is a directory, or is larger than
/// `max_bytes` (then nothing larger than max_bytes + 64 KiB is ever held in memory).
/// The error's file is `path`, or "<stdin>" for "-".
std::optional<ReadError> ReadInputFile(const std::string& path, std::size_t max_bytes,
                                       std::string* contents);

/// Reads the model file at `path` ("-" = standard input), detects its format with
/// DetectModelFormat and returns what ReadUrdfString, ReadSdfString or ReadMjcfString returns. A
/// text that is none of them is a ReadError. Never throws for bad input.
ReadResult ReadModelFile(const std::string& path, const ReadOptions& options = {});

/// Same as ReadModelFile for text already in memory; `file_name` names it in SourceLocations
/// (and is the base of relative SDF include paths).
ReadResult ReadModelString(const std::string& xml, const std::string& file_name,
                           const ReadOptions& options = {});

}  // namespace massprops
