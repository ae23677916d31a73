#include "massprops/model/model.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace massprops {

std::optional<Eigen::AlignedBox3d> CalcPrimitiveBounds(const Geometry& g) {
  // Half-extent along axis i of B of a shape whose own axes are the columns of R = R_BG: a
  // support-function bound that is attained (box: Σ|R_ij|·s_j/2; cylinder: its axis' extent plus
  // the radius times the row's length without the axis component; ellipsoid: |row i ∘ radii|).
  const Eigen::Matrix3d& R = g.X_BG.R_AB;
  Eigen::Vector3d h;
  for (int i = 0; i < 3; ++i) {
    const double rz = std::abs(R(i, 2));
    const double radial = std::sqrt(std::max(0.0, 1 - rz * rz));
    switch (g.type) {
      case Geometry::Type::kBox:
        h(i) = 0.5 *
               (std::abs(R(i, 0)) * g.size.x() + std::abs(R(i, 1)) * g.size.y() + rz * g.size.z());
        break;
      case Geometry::Type::kCylinder:
        h(i) = rz * 0.5 * g.length + g.radius * radial;
        break;
      case Geometry::Type::kSphere:
        h(i) = g.radius;
        break;
      case Geometry::Type::kCapsule:
        h(i) = rz * 0.5 * g.length + g.radius;
        break;
      case Geometry::Type::kEllipsoid:
        h(i) = std::sqrt(std::pow(R(i, 0) * g.radii.x(), 2) + std::pow(R(i, 1) * g.radii.y(), 2) +
                         std::pow(R(i, 2) * g.radii.z(), 2));
        break;
      default:
        return std::nullopt;
    }
  }
  if (!h.allFinite() || !g.X_BG.p_AB.allFinite()) return std::nullopt;
  return Eigen::AlignedBox3d(g.X_BG.p_AB - h, g.X_BG.p_AB + h);
}

int Model::FindLink(const std::string& link_name) const {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].name == link_name) return static_cast<int>(i);
  }
  return -1;
}

int Model::FindParentJoint(const std::string& child_link) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].child == child_link) return static_cast<int>(i);
  }
  return -1;
}

// The position is printed as compilers do: "file:line:col" when the column is known, "file:line"
// when only the line is, "file" alone when neither is (e.g. a file that cannot be opened).
ReadError MakeReadError(std::string file, int line, std::string element, std::string message) {
  ReadError error;
  error.location.file = std::move(file);
  error.location.line = line;
  error.element = std::move(element);
  error.message = std::move(message);
  return error;
}

std::string ReadError::ToString() const {
  std::string text = location.file.empty() ? std::string("<input>") : location.file;
  if (location.line > 0) {
    text += ':' + std::to_string(location.line);
    if (location.column > 0) text += ':' + std::to_string(location.column);
  }
  text += ": ";
  if (!element.empty()) text += element + ": ";
  text += message;
  return text;
}

Eigen::Matrix3d RotationFromRollPitchYaw(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

const char* ToString(Model::Format format) {
  switch (format) {
    case Model::Format::kSdf:
      return "sdf";
    case Model::Format::kMjcf:
      return "mjcf";
    case Model::Format::kUrdf:
      break;
  }
  return "urdf";
}

}  // namespace massprops
