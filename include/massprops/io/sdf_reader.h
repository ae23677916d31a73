#pragma once
/// @file
/// Reading SDFormat (SDF 1.4 to 1.11) into massprops Models, with libsdformat 12's pose and frame
/// semantics and the source line of every element. One tinyxml2 pass per file (plus the files that
/// <include> pulls in).

#include <cstddef>
#include <string>
#include <vector>

#include "massprops/model/model.h"

namespace massprops {

/// Files larger than this are refused with a ReadError by default (bounded memory on hostile
/// input; SdfReadOptions::max_file_bytes changes it).
inline constexpr std::size_t kMaxSdfFileBytes = std::size_t{256} << 20;  // 256 MiB

/// Where <include><uri>model://NAME</uri> looks for the folder NAME.
struct SdfReadOptions {
  /// Folders searched first, in order; each may hold a folder NAME with a model.config / model.sdf.
  std::vector<std::string> model_paths;
  /// When true, the colon-separated lists in SDF_PATH, GZ_SIM_RESOURCE_PATH,
  /// IGN_GAZEBO_RESOURCE_PATH and GAZEBO_MODEL_PATH are searched after model_paths (in that order).
  bool use_environment = true;
  /// Includes nested deeper than this (a file that includes a file that includes ...) are a
  /// ReadError naming the include.
  int max_include_depth = 32;
  /// The elements (links, joints, frames, models) that includes bring in, over the whole read,
  /// are bounded by this: beyond it the read stops with a ReadError naming the include (models
  /// that each include the next twice grow exponentially).
  int max_included_elements = 100000;
  /// <inertial auto="true"> (SDF 1.11) links are computed from their collisions; meshes among
  /// them are read (relative to the file holding the link, model:// through model_paths).
  /// When false, such a link gets an inertial-unreadable finding instead.
  bool compute_auto_inertials = true;
  /// The file read, and each file it includes, is refused with a ReadError when larger than this
  /// many bytes (standard input too).
  std::size_t max_file_bytes = kMaxSdfFileBytes;
};

/// Reads the SDF file at `path` ("-": standard input, also bounded by kMaxSdfFileBytes).
/// A <world> gives one Model per top-level <model>; a lone <model>
/// gives one Model. Links of nested models are named "nested::link"; all poses are resolved into
/// the conventions of model.h (Joint::X_PC from the resolved link poses in the model frame,
/// Joint::axis in the child link frame, Inertial::X_BBi in the link frame).
/// An <include> whose URI cannot be resolved (not on the model paths, a Fuel URL, ...) is a
/// ReadFinding "include-unresolved" at the <include> line saying where massprops looked and how
/// to point it elsewhere; the rest of the file is still read, and a joint (or frame) that names
/// one of the missing model's links gets its own include-unresolved finding and is left out. An
/// included file that exists but is unreadable or malformed, a recursive include, and includes
/// beyond max_include_depth / max_included_elements are errors. <include merge="true"> (SDF 1.9)
/// puts the included model's links, joints and frames into the including model, with the proxy
/// frame "_merged__NAME__model__" as libsdformat does. A file with any error yields no model.
/// Elements read from an included file carry that file's path in their SourceLocation.
/// A number of a link's <inertial> that cannot be read (not a number, not finite, out of the
/// range of double, including magnitudes below the smallest normal double such as 1e-400, which
/// libsdformat 12 rejects too) costs only that link: Link::inertial_unreadable is set and a
/// ReadFinding "inertial-unreadable" quotes the text. Any other bad number is a ReadError.
/// Model::root_link is the model's canonical link when no joint (other than one to "world") has
/// it as child, else the first such link.
/// <inertial auto="true"> (SDF 1.11, a file of version >= 1.11) is computed as libsdformat 14
/// does (see auto_inertia.h): the link's Inertial holds the result and a ReadFinding
/// "inertial-auto" (a note) says what was computed from which collisions; when it cannot be
/// computed (no collision, an unsupported shape, a mesh that cannot be read) the link gets an
/// "inertial-unreadable" finding instead.
/// For a joint whose parent is "world", X_PC is the child link's pose in the world: the model's
/// pose (its <pose>, or the <include> override) composed with the link's pose in the model. Never
/// throws for bad input: problems are ReadError values. Cost: linear in the size of the file and of
/// the files it includes.
ReadResult ReadSdfFile(const std::string& path, const SdfReadOptions& options = {});

/// Same as ReadSdfFile, for XML text already in memory; `file_name` is used in SourceLocations
/// and as the base folder of relative include paths.
ReadResult ReadSdfString(const std::string& xml, const std::string& file_name,
                         const SdfReadOptions& options = {});

/// The resolved frames of one Model read from SDF, which model.h does not keep: the pose X_WM of
/// the model frame M in the world W (for a lone model: its own <pose>) and the pose X_MB of each
/// link frame B in M, in the order of Model::links.
struct SdfModelFrames {
  Pose X_WM;
  std::vector<Pose> X_MB;
};

/// ReadSdfString that also returns, when `frames` is not null, one SdfModelFrames per model of
/// the result (same order). Same errors and cost as ReadSdfString.
ReadResult ReadSdfString(const std::string& xml, const std::string& file_name,
                         const SdfReadOptions& options, std::vector<SdfModelFrames>* frames);

/// ReadSdfFile that also returns the frames of each model (see the ReadSdfString overload).
ReadResult ReadSdfFile(const std::string& path, const SdfReadOptions& options,
                       std::vector<SdfModelFrames>* frames);

}  // namespace massprops
