#pragma once
// Private to the MJCF reader: the mass properties MuJoCo 2.2.2's compiler gives a mesh geom
// (mjCMesh::Process and mjCGeom::GetVolume/SetInertia in src/user/), and the exact ones.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "massprops/mesh/mesh_inertia.h"

namespace massprops {
namespace mjcf {

/// A mesh geom's volume, center and central inertia per unit density, in the mesh's file frame
/// scaled by the <mesh scale> (the geom frame G as the MJCF writes its pos and orientation).
struct MeshSolid {
  double volume = 0;
  Eigen::Vector3d p_GoGcm_G = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_GGcm_G_per_density = Eigen::Matrix3d::Zero();
  /// How MuJoCo's pyramid volume differs from this one (legacy only: |pyramid volume| - volume,
  /// the equivalent box's volume being used instead).
  double pyramid_volume = 0;
};

/// How a mesh geom's mass properties are computed.
enum class MeshMethod {
  kExact,         ///< massprops' exact solid (mesh_inertia.h): the physically exact value.
  kMujoco,        ///< MuJoCo 2.2 with exactmeshinertia="true": signed pyramids, float vertices.
  kMujocoLegacy,  ///< MuJoCo 2.2's default: |pyramid| volumes, then the equivalent inertia box.
};

/// The solid of `mesh` (vertices already in the file's units) scaled by `scale`, as `method`
/// says. nullopt and *error (MuJoCo's words) when MuJoCo would refuse the mesh: surface area or
/// volume below mjMINVAL, a non-positive principal moment, or moments that break the triangle
/// inequality. Cost: linear in the triangles (kExact may add a convex hull, mesh_inertia.h).
std::optional<MeshSolid> CalcMeshSolid(const TriangleMesh& mesh, const Eigen::Vector3d& scale,
                                       MeshMethod method, std::string* error);

}  // namespace mjcf
}  // namespace massprops
