// Accuracy of the symmetric 3x3 eigen-solvers: massprops' accurate and fast solvers and Eigen's
// SelfAdjointEigenSolver (compute and computeDirect), on the same rotated inertia matrices.
//
// Each input is built in long double as R * diag(moments) * R^T with a random rotation R, then
// rounded to double: that rounded matrix is the input of every solver, and the reference is its
// eigen-decomposition computed in long double (Eigen's QR-based solver, whose error in long double
// is about 1e-19 of the trace, far below the errors measured here).
//
// Prints Markdown tables: per solver and input family, the largest eigenvalue error divided by the
// trace, the largest entry of |V^T V - I| (orthonormality of the axes) and the largest entry of
// |A V - V diag(w)| divided by the trace (residual). Usage: principal_axes_accuracy [samples]

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "../tests/test_shapes.h"
#include "massprops/core/principal_axes.h"

namespace {

using massprops::test_support::RandomRotation;

using massprops::Matrix3;
using massprops::Vector3;
using LongDouble = long double;

struct Family {
  std::string name;
  std::vector<Matrix3<double>> inputs;
};

// R * diag(moments) * R^T, computed in long double, then rounded to double.
Matrix3<double> Rotated(const Vector3<LongDouble>& moments, std::mt19937_64* rng) {
  const Matrix3<LongDouble> R = RandomRotation(rng);
  const Matrix3<LongDouble> A = R * moments.asDiagonal() * R.transpose();
  return A.cast<double>();
}

// Principal moments of a physically valid inertia: from random positive second moments
// (a, b, c) of the mass distribution, the moments are (b + c, a + c, a + b).
Vector3<LongDouble> RandomValidMoments(std::mt19937_64* rng) {
  std::uniform_real_distribution<double> uniform(0.1, 1.0);
  const LongDouble a = uniform(*rng), b = uniform(*rng), c = uniform(*rng);
  return Vector3<LongDouble>(b + c, a + c, a + b);
}

struct Errors {
  double value = 0;       // max |w - w_ref| / trace
  double orthogonal = 0;  // max |V^T V - I|
  double residual = 0;    // max |A V - V diag(w)| / trace
  bool has_vectors = false;
};

struct Solver {
  std::string name;
  bool with_vectors;
  std::function<void(const Matrix3<double>&, Vector3<double>*, Matrix3<double>*)> solve;
};

std::string Format(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1e", x);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  const int samples = argc > 1 ? std::atoi(argv[1]) : 20000;
  std::mt19937_64 rng(20240531);

  std::vector<Family> families;
  {
    Family f{"well-conditioned", {}};
    for (int i = 0; i < samples; ++i) f.inputs.push_back(Rotated(RandomValidMoments(&rng), &rng));
    families.push_back(f);
  }
  for (const LongDouble eps : {1e-4L, 1e-8L, 1e-12L, 1e-16L}) {
    Family f{"thin rod diag(" + Format(static_cast<double>(eps)) + ", 1, 1)", {}};
    for (int i = 0; i < samples; ++i) f.inputs.push_back(Rotated({eps, 1, 1}, &rng));
    families.push_back(f);
  }
  {
    Family f{"near-equal: sphere + 1e-15 perturbation", {}};
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int i = 0; i < samples; ++i) {
      const Vector3<LongDouble> moments(1 + 1e-15L * uniform(rng), 1 + 1e-15L * uniform(rng),
                                        1 + 1e-15L * uniform(rng));
      f.inputs.push_back(Rotated(moments, &rng));
    }
    families.push_back(f);
  }
  {
    // Inertia scales as mass * length^2: masses and lengths each from 1e-9 to 1e9.
    Family f{"scaled: mass, length in 1e-9..1e9", {}};
    const double powers[] = {1e-9, 1e-6, 1e-3, 1, 1e3, 1e6, 1e9};
    for (int i = 0; i < samples; ++i) {
      const LongDouble mass = powers[i % 7];
      const LongDouble length = powers[(i / 7) % 7];
      f.inputs.push_back(Rotated(RandomValidMoments(&rng) * mass * length * length, &rng));
    }
    families.push_back(f);
  }

  using massprops::PrincipalSolver;
  const std::vector<Solver> solvers = {
      {"massprops accurate (values)", false,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>*) {
         *w = massprops::CalcSymmetricEigenvalues(A, PrincipalSolver::kAccurate);
       }},
      {"massprops accurate (vectors)", true,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>* V) {
         std::tie(*w, *V) = massprops::CalcSymmetricEigensystem(A, PrincipalSolver::kAccurate);
       }},
      {"massprops fast (values)", false,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>*) {
         *w = massprops::CalcSymmetricEigenvalues(A, PrincipalSolver::kFast);
       }},
      {"massprops fast (vectors)", true,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>* V) {
         std::tie(*w, *V) = massprops::CalcSymmetricEigensystem(A, PrincipalSolver::kFast);
       }},
      {"Eigen compute (vectors)", true,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>* V) {
         Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver(A);
         *w = solver.eigenvalues();
         *V = solver.eigenvectors();
       }},
      {"Eigen computeDirect (values)", false,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>*) {
         Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver;
         solver.computeDirect(A, Eigen::EigenvaluesOnly);
         *w = solver.eigenvalues();
       }},
      {"Eigen computeDirect (vectors)", true,
       [](const Matrix3<double>& A, Vector3<double>* w, Matrix3<double>* V) {
         Eigen::SelfAdjointEigenSolver<Matrix3<double>> solver;
         solver.computeDirect(A);
         *w = solver.eigenvalues();
         *V = solver.eigenvectors();
       }},
  };

  // errors[family][solver]
  std::vector<std::vector<Errors>> errors(families.size(), std::vector<Errors>(solvers.size()));
  for (size_t f = 0; f < families.size(); ++f) {
    for (const Matrix3<double>& A : families[f].inputs) {
      const Matrix3<LongDouble> A_exact = A.cast<LongDouble>();
      const Vector3<LongDouble> w_ref =
          Eigen::SelfAdjointEigenSolver<Matrix3<LongDouble>>(A_exact, Eigen::EigenvaluesOnly)
              .eigenvalues();
      const LongDouble trace = A_exact.trace();
      for (size_t s = 0; s < solvers.size(); ++s) {
        Vector3<double> w;
        Matrix3<double> V;
        solvers[s].solve(A, &w, &V);
        Errors& e = errors[f][s];
        const LongDouble value_error =
            (w.cast<LongDouble>() - w_ref).cwiseAbs().maxCoeff() / std::abs(trace);
        e.value = std::max(e.value, static_cast<double>(value_error));
        if (solvers[s].with_vectors) {
          e.has_vectors = true;
          const Matrix3<LongDouble> Vl = V.cast<LongDouble>();
          const LongDouble orthogonal =
              (Vl.transpose() * Vl - Matrix3<LongDouble>::Identity()).cwiseAbs().maxCoeff();
          const LongDouble residual =
              (A_exact * Vl - Vl * w.cast<LongDouble>().asDiagonal()).cwiseAbs().maxCoeff() /
              std::abs(trace);
          e.orthogonal = std::max(e.orthogonal, static_cast<double>(orthogonal));
          e.residual = std::max(e.residual, static_cast<double>(residual));
        }
      }
    }
  }

  std::printf("Samples per input family: %d (double; reference: long double, eps = %.2e)\n\n",
              samples, std::numeric_limits<double>::epsilon());
  const char* titles[] = {"Max eigenvalue error / trace", "Max |V^T V - I| (orthonormality)",
                          "Max |A V - V diag(w)| / trace (residual)"};
  for (int table = 0; table < 3; ++table) {
    std::printf("### %s\n\n| input |", titles[table]);
    for (const Solver& s : solvers) {
      if (table == 0 || s.with_vectors) std::printf(" %s |", s.name.c_str());
    }
    std::printf("\n|---|");
    for (const Solver& s : solvers) {
      if (table == 0 || s.with_vectors) std::printf("---|");
    }
    std::printf("\n");
    for (size_t f = 0; f < families.size(); ++f) {
      std::printf("| %s |", families[f].name.c_str());
      for (size_t s = 0; s < solvers.size(); ++s) {
        const Errors& e = errors[f][s];
        if (table == 0) std::printf(" %s |", Format(e.value).c_str());
        if (table == 1 && e.has_vectors) std::printf(" %s |", Format(e.orthogonal).c_str());
        if (table == 2 && e.has_vectors) std::printf(" %s |", Format(e.residual).c_str());
      }
      std::printf("\n");
    }
    std::printf("\n");
  }
  return 0;
}
