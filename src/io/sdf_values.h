#pragma once
// Private to the library: the values of SDF text as libsdformat 12 reads them. Shared by the SDF
// reader (sdf_reader.cc, which reports what it refuses) and SDF merge-fixed (merge_fixed_sdf.cc,
// which rewrites the poses of text the reader has accepted), so that both read a pose alike.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "massprops/model/model.h"

namespace tinyxml2 {
class XMLElement;
}

namespace massprops::internal {

/// The text of `e` without leading and trailing whitespace ("" when e is null or has none).
std::string Text(const tinyxml2::XMLElement* e);

/// The attribute `name` of `e` ("" when e is null or has none).
std::string Attr(const tinyxml2::XMLElement* e, const char* name);

/// The whitespace-separated numbers of `text` (a leading '+' allowed) into *out; false, with the
/// reason in *why, when a word is not a finite double (libsdformat 12 also refuses magnitudes
/// beyond the largest double and subnormal ones) or when there are fewer than `min_count` or more
/// than `max_count` of them.
bool ParseSdfNumbers(const std::string& text, std::size_t min_count, std::size_t max_count,
                     std::vector<double>* out, std::string* why);

/// The value of a <pose>'s (non-empty) text: "x y z roll pitch yaw", the angles in radians or, with
/// `degrees`, in degrees (rotation_format "" or "euler_rpy"); or "x y z qx qy qz qw" with
/// rotation_format "quat_xyzw" (SDF 1.9; the quaternion normalized). nullopt, with the reason in
/// *why, when the text or the format is refused.
std::optional<Pose> ParseSdfPose(const std::string& text, const std::string& rotation_format,
                                 bool degrees, std::string* why);

}  // namespace massprops::internal
