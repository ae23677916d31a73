// Google Benchmark of mesh mass properties on UV spheres of 1e3 to 1e6 triangles (shared
// vertices, as an OBJ file has them): the full CalcMeshMassProperties (topology analysis +
// divergence-theorem integral), the integral alone, the topology alone, and the convex hull
// (qhull). Time per triangle should stay flat (linear time); the hull is n log n.
// Results and the command line: docs/meshes.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "../tests/test_shapes.h"
#include "massprops/mesh/mesh_inertia.h"

namespace massprops {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A UV sphere of radius 0.1 m with about `triangles` triangles (2·slices·(stacks − 1) with
// stacks = slices/2), centered away from the origin.
TriangleMesh MakeSphere(std::int64_t triangles) {
  const int slices = std::max(8, static_cast<int>(std::lround(std::sqrt(triangles))));
  return test_support::MakeUvSphere(0.1, slices, Eigen::Vector3d(0.3, -0.2, 0.5));
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
