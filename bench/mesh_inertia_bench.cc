// Google Benchmark of mesh mass properties on UV spheres of 1e3 to 1e6 triangles (shared
// vertices, as an OBJ file has them): the full CalcMeshMassProperties (topology analysis +
// divergence-theorem integral), the integral alone, the topology alone, and the convex hull
// (qhull). Time per triangle should stay flat (linear time); the hull is n log n.
// Results and the command line: docs/meshes.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "massprops/mesh_inertia.h"

namespace massprops {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A UV sphere of radius 0.1 m with about `triangles` triangles (2·slices·(stacks − 1) with
// stacks = slices/2), centered away from the origin.
TriangleMesh MakeSphere(std::int64_t triangles) {
  const int slices = std::max(8, static_cast<int>(std::lround(std::sqrt(triangles))));
  const int stacks = slices / 2;
  const double r = 0.1;
  const Eigen::Vector3d center(0.3, -0.2, 0.5);
  TriangleMesh mesh;
  mesh.vertices.push_back(center + Eigen::Vector3d(0, 0, r));
  for (int i = 1; i < stacks; ++i) {
    const double theta = kPi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2 * kPi * j / slices;
      mesh.vertices.push_back(center + r * Eigen::Vector3d(std::sin(theta) * std::cos(phi),
                                                           std::sin(theta) * std::sin(phi),
                                                           std::cos(theta)));
    }
  }
  mesh.vertices.push_back(center - Eigen::Vector3d(0, 0, r));
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

void SetCounters(benchmark::State& state, const TriangleMesh& mesh) {
  const auto n = static_cast<double>(mesh.triangles.size());
  state.counters["triangles"] = n;
  state.counters["ns_per_triangle"] = benchmark::Counter(
      n * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_CalcMeshMassProperties(benchmark::State& state) {
  const TriangleMesh mesh = MakeSphere(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(CalcMeshMassProperties(mesh));
  SetCounters(state, mesh);
}

void BM_DivergenceIntegralOnly(benchmark::State& state) {
  const TriangleMesh mesh = MakeSphere(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(CalcClosedMeshMassPropertiesSigned(mesh));
  SetCounters(state, mesh);
}

void BM_TopologyOnly(benchmark::State& state) {
  const TriangleMesh mesh = MakeSphere(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(AnalyzeMeshTopology(mesh));
  SetCounters(state, mesh);
}

void BM_ConvexHull(benchmark::State& state) {
  const TriangleMesh mesh = MakeSphere(state.range(0));
  TriangleMesh hull;
  std::string error;
  for (auto _ : state) benchmark::DoNotOptimize(CalcConvexHull(mesh, &hull, &error));
  SetCounters(state, mesh);
}

BENCHMARK(BM_CalcMeshMassProperties)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DivergenceIntegralOnly)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TopologyOnly)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConvexHull)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace massprops

BENCHMARK_MAIN();
