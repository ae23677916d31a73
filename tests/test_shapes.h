#pragma once
// Inputs shared by the tests and the benchmarks: uniformly random rotations and a UV sphere mesh.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <random>

#include "massprops/core/eigen_types.h"
#include "massprops/mesh/mesh_inertia.h"

namespace massprops::test_support {

/// A uniformly distributed random rotation: a normalized Gaussian quaternion (Shoemake /
/// Marsaglia), built in long double and rounded to T.
template <typename T = long double>
Matrix3<T> RandomRotation(std::mt19937_64* generator) {
  std::normal_distribution<double> normal;
  Eigen::Quaternion<long double> q(normal(*generator), normal(*generator), normal(*generator),
                                   normal(*generator));
  q.normalize();
  return q.toRotationMatrix().template cast<T>();
}

/// A UV sphere of radius r about `center`: `slices` longitudes and slices/2 stacks, vertices on
/// the sphere, shared between triangles (2·slices·(stacks − 1) triangles), wound outward.
inline TriangleMesh MakeUvSphere(double r, int slices,
                                 const Eigen::Vector3d& center = Eigen::Vector3d::Zero()) {
  constexpr double kPi = 3.14159265358979323846;
  const int stacks = slices / 2;
  TriangleMesh mesh;
  mesh.vertices.push_back(center + Eigen::Vector3d(0, 0, r));  // North pole: 0.
  for (int i = 1; i < stacks; ++i) {
    const double theta = kPi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2 * kPi * j / slices;
      mesh.vertices.push_back(center + r * Eigen::Vector3d(std::sin(theta) * std::cos(phi),
                                                           std::sin(theta) * std::sin(phi),
                                                           std::cos(theta)));
    }
  }
  mesh.vertices.push_back(center - Eigen::Vector3d(0, 0, r));  // South pole.
  const auto south = static_cast<std::int32_t>(mesh.vertices.size() - 1);
  auto ring = [&](int i, int j) { return 1 + (i - 1) * slices + (j % slices); };
  for (int j = 0; j < slices; ++j) mesh.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  for (int j = 0; j < slices; ++j) {
    mesh.triangles.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
  }
  return mesh;
}

}  // namespace massprops::test_support
