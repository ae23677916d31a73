// SDFormat 1.11 auto inertials (see auto_inertia.h). Behaviour learned from the SDFormat 1.11
// specification and libsdformat 14's Link::ResolveAutoInertials / Collision::CalculateInertial
// (github.com/gazebosim/sdformat, src/Link.cc and src/Collision.cc); the code is ours.

#include "massprops/io/auto_inertia.h"

#include <cmath>
#include <sstream>

namespace massprops {
namespace {

std::string Num(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

std::string DescribeShape(const Geometry& g) {
  switch (g.type) {
    case Geometry::Type::kBox:
      return "box " + Num(g.size.x()) + " × " + Num(g.size.y()) + " × " + Num(g.size.z()) + " m";
    case Geometry::Type::kCylinder:
      return "cylinder r " + Num(g.radius) + " m, length " + Num(g.length) + " m";
    case Geometry::Type::kSphere:
      return "sphere r " + Num(g.radius) + " m";
    case Geometry::Type::kCapsule:
      return "capsule r " + Num(g.radius) + " m, length " + Num(g.length) + " m";
    case Geometry::Type::kEllipsoid:
      return "ellipsoid radii " + Num(g.radii.x()) + " " + Num(g.radii.y()) + " " +
             Num(g.radii.z()) + " m";
    case Geometry::Type::kMesh:
      return "mesh '" + g.uri + "'";
    case Geometry::Type::kOther:
      break;
  }
  return "an unsupported geometry";
}

}  // namespace

std::optional<AutoInertiaResult> CalcAutoInertial(
    const std::vector<AutoInertiaCollision>& collisions, std::optional<double> mass,
    const MeshResolveOptions& mesh_options, std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<AutoInertiaResult> {
    if (error) *error = why;
    return std::nullopt;
  };
  if (collisions.empty()) {
    return fail("auto=\"true\" but the link has no <collision> to compute it from");
  }
  struct Part {
    double mass = 0;
    Eigen::Vector3d p_BoPcm_B;
    Eigen::Matrix3d I_PPcm_B;
  };
  std::vector<Part> parts;
  double total = 0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  std::string list;
  for (const AutoInertiaCollision& c : collisions) {
    const std::string who = "collision '" + c.name + "'";
    if (!(c.density > 0) || !std::isfinite(c.density)) {
      return fail(who + ": the density " + Num(c.density) + " kg/m³ is not positive and finite");
    }
    std::string why;
    const std::optional<GeometryMassProperties> unit =
        CalcGeometryMassProperties(c.geometry, mesh_options, &why);
    if (!unit) return fail(who + ": " + why);
    Part part;
    part.mass = c.density * unit->volume;  // Unit density: volume = mass.
    part.p_BoPcm_B = unit->p_BoGcm_B;
    part.I_PPcm_B = c.density * unit->I_GGcm_B.CopyToFullMatrix3();
    total += part.mass;
    first_moment += part.mass * part.p_BoPcm_B;
    parts.push_back(part);
    if (!list.empty()) list += ", ";
    list += "'" + c.name + "' " + DescribeShape(c.geometry) + " at " + Num(c.density) + " kg/m³ (" +
            c.density_source + ")";
  }
  if (!(total > 0) || !std::isfinite(total)) {
    return fail("the collisions give a total mass of " + Num(total) + " kg");
  }
  // The composite about its center of mass: each part's central inertia shifted away from its
  // own center to the common one (parallel-axis theorem; only positive semi-definite terms).
  const Eigen::Vector3d p_BoBcm_B = first_moment / total;
  Eigen::Matrix3d I_BBcm_B = Eigen::Matrix3d::Zero();
  for (const Part& part : parts) {
    const Eigen::Vector3d d = part.p_BoPcm_B - p_BoBcm_B;
    I_BBcm_B += part.I_PPcm_B +
                part.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  double result_mass = total;
  std::string scaled;
  if (mass) {
    if (!(*mass >= 0) || !std::isfinite(*mass)) {
      return fail("the <mass> " + Num(*mass) + " beside auto=\"true\" is negative or not finite");
    }
    // libsdformat 14: the unit-mass inertia of the sum times the given mass.
    I_BBcm_B = I_BBcm_B / total * *mass;
    result_mass = *mass;
    scaled = ", scaled from " + Num(total) + " kg to the <mass> " + Num(*mass) + " kg";
  }
  AutoInertiaResult result;
  Inertial& in = result.inertial;
  in.mass = result_mass;
  in.X_BBi.p_AB = p_BoBcm_B;
  in.ixx = I_BBcm_B(0, 0);
  in.iyy = I_BBcm_B(1, 1);
  in.izz = I_BBcm_B(2, 2);
  in.ixy = I_BBcm_B(0, 1);
  in.ixz = I_BBcm_B(0, 2);
  in.iyz = I_BBcm_B(1, 2);
  std::ostringstream summary;
  summary << Num(result_mass) << " kg" << scaled << " from " << collisions.size() << " collision"
          << (collisions.size() == 1 ? "" : "s") << ": " << list << "; center of mass ("
          << Num(p_BoBcm_B.x()) << ", " << Num(p_BoBcm_B.y()) << ", " << Num(p_BoBcm_B.z())
          << ") m, inertia ixx " << Num(in.ixx) << ", iyy " << Num(in.iyy) << ", izz "
          << Num(in.izz) << ", ixy " << Num(in.ixy) << ", ixz " << Num(in.ixz) << ", iyz "
          << Num(in.iyz) << " kg·m²";
  result.summary = summary.str();
  return result;
}

}  // namespace massprops
