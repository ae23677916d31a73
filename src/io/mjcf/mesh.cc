// A mesh geom's solid as MuJoCo 2.2.2 computes it (src/user/user_mesh.cc, mjCMesh::Process:
// float vertices scaled, the area-weighted centroid of the faces as the apex of one pyramid per
// face, the mesh re-centered at the pyramids' center of mass, then the products of inertia
// summed over the pyramids; src/user/user_objects.cc, mjCGeom::GetVolume and SetInertia: with
// exactmeshinertia="false", the default, each pyramid volume counts as positive and the geom
// becomes the box with the same principal moments, whose volume then gives the mass), and the
// exact solid (massprops' mesh_inertia.h). The arithmetic repeats MuJoCo's, float where MuJoCo
// computes in float, so that the test against libmujoco can hold it to 1e-9.

#include "io/mjcf/mesh.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <vector>

#include "io/mjcf/mujoco_numbers.h"

namespace massprops {
namespace mjcf {
namespace {

constexpr double kDensity = 1000;  // MuJoCo's default geom density (cancels out).

using Vertex = std::array<float, 3>;

// MuJoCo's _areaNrmCen: the face's area, unit normal and center (the center in float).
double AreaNormalCenter(const Vertex& v1, const Vertex& v2, const Vertex& v3, double* normal,
                        double* center) {
  for (int i = 0; i < 3; ++i) center[i] = (v1[i] + v2[i] + v3[i]) / 3;
  const double b[3] = {v2[0] - v1[0], v2[1] - v1[1], v2[2] - v1[2]};
  const double c[3] = {v3[0] - v1[0], v3[1] - v1[1], v3[2] - v1[2]};
  normal[0] = b[1] * c[2] - b[2] * c[1];
  normal[1] = b[2] * c[0] - b[0] * c[2];
  normal[2] = b[0] * c[1] - b[1] * c[0];
  const double len =
      std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if (len < kMjMinVal) return 0;
  for (int i = 0; i < 3; ++i) normal[i] /= len;
  return len / 2;
}

std::optional<MeshSolid> MujocoSolid(const TriangleMesh& mesh, const Eigen::Vector3d& scale,
                                     bool legacy, std::string* error) {
  std::vector<Vertex> vert(mesh.vertices.size());
  for (std::size_t i = 0; i < vert.size(); ++i) {
    for (int j = 0; j < 3; ++j) {
      float v = static_cast<float>(mesh.vertices[i][j]);
      v = static_cast<float>(v * scale[j]);
      vert[i][j] = v;
    }
  }
  const auto face = [&](std::size_t f, int k) -> const Vertex& {
    return vert[static_cast<std::size_t>(mesh.triangles[f][k])];
  };
  double normal[3], center[3], facecen[3] = {0, 0, 0}, area = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const double a = AreaNormalCenter(face(f, 0), face(f, 1), face(f, 2), normal, center);
    for (int j = 0; j < 3; ++j) facecen[j] += a * center[j];
    area += a;
  }
  if (area < kMjMinVal) {
    *error = "mesh surface area is too small";
    return std::nullopt;
  }
  for (double& c : facecen) c /= area;
  double volume = 0, com[3] = {0, 0, 0};
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const double a = AreaNormalCenter(face(f, 0), face(f, 1), face(f, 2), normal, center);
    const double vec[3] = {center[0] - facecen[0], center[1] - facecen[1], center[2] - facecen[2]};
    double vol = (vec[0] * normal[0] + vec[1] * normal[1] + vec[2] * normal[2]) * a / 3;
    if (legacy) vol = std::fabs(vol);
    volume += vol;
    for (int j = 0; j < 3; ++j) com[j] += vol * (center[j] * 3.0 / 4.0 + facecen[j] / 4.0);
  }
  if (volume < kMjMinVal) {
    *error = "mesh volume is too small";
    return std::nullopt;
  }
  for (double& c : com) c /= volume;
  for (Vertex& v : vert) {
    for (int j = 0; j < 3; ++j) v[j] = static_cast<float>(v[j] - com[j]);
  }
  static const int k[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  double P[6] = {0, 0, 0, 0, 0, 0};
  volume = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Vertex &D = face(f, 0), &E = face(f, 1), &F = face(f, 2);
    const double a = AreaNormalCenter(D, E, F, normal, center);
    double vol = (center[0] * normal[0] + center[1] * normal[1] + center[2] * normal[2]) * a / 3;
    if (legacy) vol = std::fabs(vol);
    volume += vol;
    for (int j = 0; j < 6; ++j) {
      const int p = k[j][0], q = k[j][1];
      const float s = 2 * (D[p] * D[q] + E[p] * E[q] + F[p] * F[q]) + D[p] * E[q] + D[q] * E[p] +
                      D[p] * F[q] + D[q] * F[p] + E[p] * F[q] + E[q] * F[p];
      P[j] += kDensity * vol / 20 * s;
    }
  }
  Eigen::Matrix3d inertia;
  inertia << P[1] + P[2], -P[3], -P[4], -P[3], P[0] + P[2], -P[5], -P[4], -P[5], P[0] + P[1];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
  const Eigen::Vector3d& e = eigen.eigenvalues();  // Ascending.
  if (e[0] <= 0) {
    *error = "eigenvalue of mesh inertia must be positive";
    return std::nullopt;
  }
  if (e[0] + e[1] < e[2]) {
    *error = "eigenvalues of mesh inertia violate A + B >= C";
    return std::nullopt;
  }
  MeshSolid solid;
  solid.p_GoGcm_G = Eigen::Vector3d(com[0], com[1], com[2]);
  solid.pyramid_volume = volume;
  const double mass = volume * kDensity;
  if (!legacy) {
    solid.volume = volume;
    solid.I_GGcm_G_per_density = inertia / kDensity;
    return solid;
  }
  Eigen::Vector3d box;  // Half sizes of the box with these principal moments.
  for (int i = 0; i < 3; ++i) {
    box[i] = std::sqrt(6 * (e.sum() - 2 * e[i]) / mass) / 2;
  }
  solid.volume = 8 * box[0] * box[1] * box[2];
  const Eigen::Vector3d moments(box[1] * box[1] + box[2] * box[2],
                                box[0] * box[0] + box[2] * box[2],
                                box[0] * box[0] + box[1] * box[1]);
  const Eigen::Matrix3d& V = eigen.eigenvectors();
  solid.I_GGcm_G_per_density = V * (solid.volume * moments / 3).asDiagonal() * V.transpose();
  return solid;
}

}  // namespace

std::optional<MeshSolid> CalcMeshSolid(const TriangleMesh& mesh, const Eigen::Vector3d& scale,
                                       MeshMethod method, std::string* error) {
  for (const auto& t : mesh.triangles) {
    for (const std::int32_t index : t) {
      if (index < 0 || static_cast<std::size_t>(index) >= mesh.vertices.size()) {
        *error = "vertex index out of range";
        return std::nullopt;
      }
    }
  }
  if (method != MeshMethod::kExact) {
    return MujocoSolid(mesh, scale, method == MeshMethod::kMujocoLegacy, error);
  }
  TriangleMesh scaled = mesh;
  for (Eigen::Vector3d& v : scaled.vertices) v = v.cwiseProduct(scale);
  MeshMassProperties properties;
  try {
    properties = CalcMeshMassProperties(scaled);
  } catch (const std::exception& e) {
    *error = e.what();
    return std::nullopt;
  }
  if (!(properties.volume > kMjMinVal)) {
    *error = "mesh volume is too small";
    return std::nullopt;
  }
  MeshSolid solid;
  solid.volume = properties.volume;
  solid.pyramid_volume = properties.volume;
  solid.p_GoGcm_G = properties.p_GoGcm_G;
  solid.I_GGcm_G_per_density = properties.I_GGcm_G.CopyToFullMatrix3();  // Density 1.
  return solid;
}

}  // namespace mjcf
}  // namespace massprops
