// The values of SDF text (see sdf_values.h).
#include "io/sdf_values.h"

#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

namespace massprops::internal {

std::string Text(const tinyxml2::XMLElement* e) {
  const char* text = e == nullptr ? nullptr : e->GetText();
  if (text == nullptr) return "";
  const std::string_view s(text);
  const char* ws = " \t\r\n";
  const std::size_t b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(ws) - b + 1));
}

std::string Attr(const tinyxml2::XMLElement* e, const char* name) {
  const char* value = e == nullptr ? nullptr : e->Attribute(name);
  return value == nullptr ? "" : value;
}

bool ParseSdfNumbers(const std::string& text, std::size_t min_count, std::size_t max_count,
                     std::vector<double>* out, std::string* why) {
  out->clear();
  const char* p = text.data();
  const char* end = p + text.size();
  while (true) {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
    if (p == end) break;
    const char* tok = p;
    while (p < end && !(*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
    std::string_view token(tok, static_cast<size_t>(p - tok));
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    // Magnitudes beyond the largest double, and below the smallest normal one (1e-400 and
    // subnormals such as 1e-310), are refused: libsdformat 12 (std::stod) rejects both.
    if (r.ec == std::errc::result_out_of_range ||
        (r.ec == std::errc() && std::fpclassify(value) == FP_SUBNORMAL)) {
      *why = "number '" + std::string(token) +
             "' is out of the range of double (beyond 1.8e308 or below 2.2e-308 in "
             "magnitude)";
      return false;
    }
    if (r.ec != std::errc() || r.ptr != digits.data() + digits.size() || digits.empty()) {
      *why = "'" + std::string(token) + "' is not a number";
      return false;
    }
    if (!std::isfinite(value)) {
      *why = "'" + std::string(token) + "' is not a finite number";
      return false;
    }
    out->push_back(value);
    if (out->size() > max_count) break;
  }
  if (out->size() < min_count || out->size() > max_count) {
    *why =
        "expected " +
        (min_count == max_count ? std::to_string(min_count)
                                : std::to_string(min_count) + " to " + std::to_string(max_count)) +
        " numbers, found '" + text + "'";
    return false;
  }
  return true;
}

std::optional<Pose> ParseSdfPose(const std::string& text, const std::string& rotation_format,
                                 bool degrees, std::string* why) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<double> v;
  Pose X;
  if (rotation_format == "quat_xyzw") {
    if (!ParseSdfNumbers(text, 7, 7, &v, why)) return std::nullopt;
    const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
    if (q.norm() == 0) {
      *why = "the quaternion '" + text + "' has zero length";
      return std::nullopt;
    }
    X.R_AB = q.normalized().toRotationMatrix();
  } else {
    if (!rotation_format.empty() && rotation_format != "euler_rpy") {
      *why = "unknown rotation_format '" + rotation_format + "'";
      return std::nullopt;
    }
    if (!ParseSdfNumbers(text, 6, 6, &v, why)) return std::nullopt;
    const double k = degrees ? kPi / 180.0 : 1.0;
    X.R_AB = RotationFromRollPitchYaw(v[3] * k, v[4] * k, v[5] * k);
  }
  X.p_AB = Eigen::Vector3d(v[0], v[1], v[2]);
  return X;
}

}  // namespace massprops::internal
