// Speed of the symmetric 3x3 eigen-solvers: massprops' accurate and fast solvers, called as free
// functions on a matrix and through the class users call (RotationalInertia::
// CalcPrincipalMomentsOfInertia / CalcPrincipalMomentsAndAxesOfInertia, BM_Class*), beside Eigen's
// SelfAdjointEigenSolver::compute and ::computeDirect, on the same pre-generated inputs (double),
// in one run. Numbers and the command that produced them: docs/benchmarks.md.
//   build/bench/principal_axes_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only
//   (docs/benchmarks.md also runs it under callgrind to count instructions).
//
// Argument 0: 1024 well-conditioned rotated inertias; argument 1: 1024 rotated thin rods
// diag(eps, 1, 1) with eps cycling through 1e-4, 1e-8, 1e-12, 1e-16. Each benchmark iteration
// solves one matrix (cycling through the array), so the reported time is per matrix.

#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "massprops/core/principal_axes.h"
#include "massprops/core/rotational_inertia.h"

namespace {

using massprops::Matrix3;
using massprops::PrincipalSolver;
using massprops::Vector3;

constexpr int kCount = 1024;  // A power of two: the index wraps with a mask.

std::vector<Matrix3<double>> MakeInputs(int family) {
  std::mt19937_64 rng(family == 0 ? 7 : 11);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.1, 1.0);
  const double rod_eps[] = {1e-4, 1e-8, 1e-12, 1e-16};
  std::vector<Matrix3<double>> inputs;
  for (int i = 0; i < kCount; ++i) {
    Vector3<double> moments;
    if (family == 0) {
      // Principal moments (b + c, a + c, a + b) from positive second moments a, b, c.
      const double a = uniform(rng), b = uniform(rng), c = uniform(rng);
      moments = Vector3<double>(b + c, a + c, a + b);
    } else {
      moments = Vector3<double>(rod_eps[i % 4], 1, 1);
    }
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    const Matrix3<double> R = q.toRotationMatrix();
    inputs.push_back(R * moments.asDiagonal() * R.transpose());
  }
  return inputs;
}

const std::vector<Matrix3<double>>& Inputs(int family) {
  static const std::vector<Matrix3<double>> well = MakeInputs(0);
  static const std::vector<Matrix3<double>> rods = MakeInputs(1);
  return family == 0 ? well : rods;
}

// The same inputs as RotationalInertia values (entries of the lower triangle, unchecked).
std::vector<massprops::RotationalInertia<double>> MakeInertias(int family) {
  std::vector<massprops::RotationalInertia<double>> inertias;
  for (const Matrix3<double>& A : Inputs(family)) {
    inertias.push_back(massprops::RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
        A(0, 0), A(1, 1), A(2, 2), A(1, 0), A(2, 0), A(2, 1), true));
  }
  return inertias;
}

const std::vector<massprops::RotationalInertia<double>>& Inertias(int family) {
  static const std::vector<massprops::RotationalInertia<double>> well = MakeInertias(0);
  static const std::vector<massprops::RotationalInertia<double>> rods = MakeInertias(1);
  return family == 0 ? well : rods;
}

template <typename Solve>
void RunClass(benchmark::State& state, Solve solve) {
  const std::vector<massprops::RotationalInertia<double>>& inputs =
      Inertias(static_cast<int>(state.range(0)));
  int i = 0;
  for (auto _ : state) {
    solve(inputs[i]);
    i = (i + 1) & (kCount - 1);
  }
  state.SetLabel(state.range(0) == 0 ? "well-conditioned" : "thin rods");
}

template <typename Solve>
void Run(benchmark::State& state, Solve solve) {
  const std::vector<Matrix3<double>>& inputs = Inputs(static_cast<int>(state.range(0)));
  int i = 0;
  for (auto _ : state) {
    solve(inputs[i]);
    i = (i + 1) & (kCount - 1);
  }
  state.SetLabel(state.range(0) == 0 ? "well-conditioned" : "thin rods");
}

void BM_AccurateValues(benchmark::State& state) {
  Run(state, [](const Matrix3<double>& A) {
    benchmark::DoNotOptimize(massprops::CalcSymmetricEigenvalues(A, PrincipalSolver::kAccurate));
  });
}

void BM_AccurateVectors(benchmark::State& state) {
  Run(state, [](const Matrix3<double>& A) {
    benchmark::DoNotOptimize(massprops::CalcSymmetricEigensystem(A, PrincipalSolver::kAccurate));
  });
}

void BM_FastValues(benchmark::State& state) {
  Run(state, [](const Matrix3<double>& A) {
    benchmark::DoNotOptimize(massprops::CalcSymmetricEigenvalues(A, PrincipalSolver::kFast));
  });
}

void BM_FastVectors(benchmark::State& state) {
  Run(state, [](const Matrix3<double>& A) {
    benchmark::DoNotOptimize(massprops::CalcSymmetricEigensystem(A, PrincipalSolver::kFast));
  });
}

void BM_ClassAccurateValues(benchmark::State& state) {
  RunClass(state, [](const massprops::RotationalInertia<double>& I) {
    benchmark::DoNotOptimize(I.CalcPrincipalMomentsOfInertia(PrincipalSolver::kAccurate));
  });
}

void BM_ClassFastValues(benchmark::State& state) {
  RunClass(state, [](const massprops::RotationalInertia<double>& I) {
    benchmark::DoNotOptimize(I.CalcPrincipalMomentsOfInertia(PrincipalSolver::kFast));
  });
}

void BM_ClassAxes(benchmark::State& state) {
  RunClass(state, [](const massprops::RotationalInertia<double>& I) {
    benchmark::DoNotOptimize(I.CalcPrincipalMomentsAndAxesOfInertia());
  });
}

void BM_EigenComputeValues(benchmark::State& state) {
  Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver;
  Run(state, [&solver](const Matrix3<double>& A) {
    solver.compute(A, Eigen::EigenvaluesOnly);
    benchmark::DoNotOptimize(solver.eigenvalues());
  });
}

void BM_EigenComputeVectors(benchmark::State& state) {
  Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver;
  Run(state, [&solver](const Matrix3<double>& A) {
    solver.compute(A);
    benchmark::DoNotOptimize(solver.eigenvectors());
  });
}

void BM_EigenComputeDirectValues(benchmark::State& state) {
  Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver;
  Run(state, [&solver](const Matrix3<double>& A) {
    solver.computeDirect(A, Eigen::EigenvaluesOnly);
    benchmark::DoNotOptimize(solver.eigenvalues());
  });
}

void BM_EigenComputeDirectVectors(benchmark::State& state) {
  Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver;
  Run(state, [&solver](const Matrix3<double>& A) {
    solver.computeDirect(A);
    benchmark::DoNotOptimize(solver.eigenvectors());
  });
}

BENCHMARK(BM_AccurateValues)->Arg(0)->Arg(1);
BENCHMARK(BM_AccurateVectors)->Arg(0)->Arg(1);
BENCHMARK(BM_FastValues)->Arg(0)->Arg(1);
BENCHMARK(BM_FastVectors)->Arg(0)->Arg(1);
BENCHMARK(BM_ClassAccurateValues)->Arg(0)->Arg(1);
BENCHMARK(BM_ClassFastValues)->Arg(0)->Arg(1);
BENCHMARK(BM_ClassAxes)->Arg(0)->Arg(1);
BENCHMARK(BM_EigenComputeValues)->Arg(0)->Arg(1);
BENCHMARK(BM_EigenComputeVectors)->Arg(0)->Arg(1);
BENCHMARK(BM_EigenComputeDirectValues)->Arg(0)->Arg(1);
BENCHMARK(BM_EigenComputeDirectVectors)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
