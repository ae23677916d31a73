// `Identify` (massprops/analysis/identify.h) on a 7-joint arm with 20 000 samples, the speed bar
// of issue 51 (under a second on one core): the KUKA iiwa 14 of ../shared/corpus (drake-models,
// URDF). The recording, made once before timing: 20 000 samples at 100 Hz of a sum of three
// sinusoids per joint (as tests/identify_test.cc's), torques by the RNEA of a "true" arm whose
// masses are 10% above the file's, plus Gaussian noise σ = 0.05 N·m (seeded). Per iteration:
//   BM_Identify20000           the whole fit: regressor stacked, QR of [W τ], identifiability,
//                              least squares, the log-Cholesky Levenberg–Marquardt fit, the
//                              held-out RMS (validation 0.3: 14 000 samples fitted);
//   BM_StackRegressor20000     the stacked regressor of the 20 000 samples alone (its share).
// The regressor's cost per sample against the RNEA's is bench/dynamics_bench.cc. The figures and
// the command are in docs/identify.md ("Speed").
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>

#include "massprops/analysis/identify.h"
#include "massprops/dynamics/inverse_dynamics.h"
#include "massprops/dynamics/torque_regressor.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

const char kIiwa[] =
    MASSPROPS_CORPUS_DIR "/drake-models/iiwa_description/urdf/iiwa14_no_collision.urdf";
constexpr int kSamples = 20000;

struct Recording {
  KinematicTree tree;  // the file's values: the prior
  OrderedTrajectory data;
};

const Recording* LoadRecording(benchmark::State& state) {
  static const Recording* recording = []() -> Recording* {
    const ReadResult read = ReadModelFile(kIiwa);
    if (!read.ok() || read.models.empty()) return nullptr;
    KinematicTreeResult made = MakeKinematicTree(read.models[0]);
    if (!made.tree) return nullptr;
    auto* r = new Recording{*made.tree, {}};
    KinematicTree truth = r->tree;
    for (MovingBody& b : truth.bodies) b.pi_BBo_B *= 1.1;  // 10% heavier, same shape
    const int n = truth.size();
    OrderedTrajectory& d = r->data;
    d.q.setZero(kSamples, n);
    d.dq.setZero(kSamples, n);
    d.ddq.setZero(kSamples, n);
    d.tau.resize(kSamples, n);
    std::mt19937 rng(51);
    std::normal_distribution<double> noise(0, 0.05);
    for (int k = 0; k < kSamples; ++k) {
      const double t = 0.01 * k;
      for (int j = 0; j < n; ++j) {
        for (int h = 1; h <= 3; ++h) {
          const double w = 2 * M_PI * 0.2 * h, phase = 0.7 * j + 1.3 * h * j + 0.4 * h;
          const double a = 0.9 / h;
          d.q(k, j) += a * std::sin(w * t + phase);
          d.dq(k, j) += a * w * std::cos(w * t + phase);
          d.ddq(k, j) -= a * w * w * std::sin(w * t + phase);
        }
      }
      const Eigen::VectorXd tau = CalcInverseDynamics(
          truth, d.q.row(k).transpose(), d.dq.row(k).transpose(), d.ddq.row(k).transpose());
      for (int j = 0; j < n; ++j) d.tau(k, j) = tau(j) + noise(rng);
    }
    return r;
  }();
  if (recording == nullptr) state.SkipWithError(("cannot read " + std::string(kIiwa)).c_str());
  return recording;
}

void BM_Identify20000(benchmark::State& state) {
  const Recording* r = LoadRecording(state);
  if (r == nullptr) return;
  IdentifyResult result;
  for (auto _ : state) {
    result = Identify(r->tree, r->data);
    benchmark::DoNotOptimize(result.identified.data());
  }
  state.counters["samples"] = kSamples;
  state.counters["parameters"] = static_cast<double>(result.column_names.size());
  state.counters["rank"] = result.identifiability.rank;
  state.counters["iterations"] = result.solver_iterations;
  double worst = 0;  // held-out RMS over the noise: 1 when the fit explains all but the noise
  for (Eigen::Index j = 0; j < result.rms_identified.size(); ++j)
    worst = std::max(worst, result.rms_identified[j] / 0.05);
  state.counters["rms_over_noise"] = worst;
}
BENCHMARK(BM_Identify20000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_StackRegressor20000(benchmark::State& state) {
  const Recording* r = LoadRecording(state);
  if (r == nullptr) return;
  for (auto _ : state) {
    Eigen::MatrixXd W = StackTorqueRegressor(r->tree, r->data.q, r->data.dq, r->data.ddq);
    benchmark::DoNotOptimize(W.data());
  }
}
BENCHMARK(BM_StackRegressor20000)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace massprops

BENCHMARK_MAIN();
