// Google Benchmark of the core inertia operations (double): shift from the center of mass,
// re-express, the one-step ShiftToThenAwayFromCenterOfMass against two shifts, and
// CouldBePhysicallyValid on inertias near their principal axes (Gershgorin accepts), on rotated
// boxes, and on boundary inertias (rotated thin disks: an eigenvalue solve). Inputs cycle through
// 64 random cases so nothing is constant-folded.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <array>
#include <random>

#include "massprops/core/rotational_inertia.h"
#include "massprops/core/spatial_inertia.h"
#include "massprops/core/unit_inertia.h"

namespace massprops {
namespace {

constexpr int kCases = 64;

struct Inputs {
  std::array<RotationalInertia<double>, kCases> aligned;  // Boxes, nearly principal axes.
  std::array<RotationalInertia<double>, kCases> box;      // Rotated solid boxes.
  std::array<RotationalInertia<double>, kCases> disk;     // Rotated thin disks (boundary).
  std::array<RotationalInertia<double>, kCases> about_p;  // box shifted from its center by p.
  std::array<Matrix3<double>, kCases> rotation;
  std::array<Vector3<double>, kCases> p, q;
};

const Inputs& GetInputs() {
  static const Inputs inputs = [] {
    Inputs in;
    std::mt19937_64 generator(2024);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(0.1, 2.0);
    for (int k = 0; k < kCases; ++k) {
      Eigen::Quaterniond quaternion(normal(generator), normal(generator), normal(generator),
                                    normal(generator));
      quaternion.normalize();
      in.rotation[k] = quaternion.toRotationMatrix();
      const UnitInertia<double> box =
          UnitInertia<double>::SolidBox(uniform(generator), uniform(generator), uniform(generator));
      in.box[k] = box.ReExpress(in.rotation[k]) * 3.0;
      const double small = 0.01 * box(0, 0);
      in.aligned[k] = RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
          box(0, 0), box(1, 1), box(2, 2), small, -small, small, true);
      in.disk[k] = UnitInertia<double>::ThinDisk(uniform(generator), in.rotation[k].col(0)) * 2.0;
      in.p[k] = Vector3<double>(normal(generator), normal(generator), normal(generator));
      in.q[k] = Vector3<double>(normal(generator), normal(generator), normal(generator));
      in.about_p[k] = in.box[k].ShiftFromCenterOfMass(3.0, in.p[k]);
    }
    return in;
  }();
  return inputs;
}

void BM_ShiftFromCenterOfMass(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    RotationalInertia<double> I = in.box[k];
    I.ShiftFromCenterOfMassInPlace(3.0, in.p[k]);
    benchmark::DoNotOptimize(I);
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_ShiftFromCenterOfMass);

void BM_ReExpress(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    RotationalInertia<double> I = in.box[k];
    I.ReExpressInPlace(in.rotation[k]);
    benchmark::DoNotOptimize(I);
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_ReExpress);

void BM_ShiftToThenAwayFromCenterOfMass(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    // From the point P (p_BcmP = p) to the point Q (p_BcmQ = q) in one step.
    RotationalInertia<double> I = in.about_p[k];
    I.ShiftToThenAwayFromCenterOfMassInPlace(3.0, -in.p[k], -in.q[k]);
    benchmark::DoNotOptimize(I);
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_ShiftToThenAwayFromCenterOfMass);

void BM_ShiftToThenFromCenterOfMassAsTwoShifts(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    RotationalInertia<double> I = in.about_p[k];
    I.ShiftToCenterOfMassInPlace(3.0, -in.p[k]);
    I.ShiftFromCenterOfMassInPlace(3.0, in.q[k]);
    benchmark::DoNotOptimize(I);
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_ShiftToThenFromCenterOfMassAsTwoShifts);

void BM_CouldBePhysicallyValidNearlyPrincipal(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.aligned[k].CouldBePhysicallyValid());
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_CouldBePhysicallyValidNearlyPrincipal);

void BM_CouldBePhysicallyValidRotatedBox(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.box[k].CouldBePhysicallyValid());
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_CouldBePhysicallyValidRotatedBox);

void BM_CouldBePhysicallyValidBoundary(benchmark::State& state) {
  const Inputs& in = GetInputs();
  int k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.disk[k].CouldBePhysicallyValid());
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_CouldBePhysicallyValidBoundary);

void BM_SpatialInertiaShift(benchmark::State& state) {
  const Inputs& in = GetInputs();
  std::array<SpatialInertia<double>, kCases> bodies;
  for (int k = 0; k < kCases; ++k) {
    bodies[k] = SpatialInertia<double>::MakeFromCentralInertia(3.0, in.p[k], in.box[k]);
  }
  int k = 0;
  for (auto _ : state) {
    SpatialInertia<double> M = bodies[k];
    M.ShiftInPlace(in.q[k]);
    benchmark::DoNotOptimize(M);
    k = (k + 1) % kCases;
  }
}
BENCHMARK(BM_SpatialInertiaShift);

}  // namespace
}  // namespace massprops

BENCHMARK_MAIN();
