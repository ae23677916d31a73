// The joint-torque regressor's cost per sample against the recursive Newton–Euler algorithm's,
// on a 7-joint arm: the KUKA iiwa 14 of ../shared/corpus (drake-models, URDF), read once. Each
// iteration computes one sample from a pool of 1 024 random states (q, q̇, q̈ uniform in ±2 rad,
// ±2 rad/s, ±6 rad/s²), so the numbers are per sample:
//   BM_InverseDynamics     τ by CalcInverseDynamics (friction terms of the tree, all zero);
//   BM_TorqueRegressor     Y (7 × 98: 70 inertial, 21 friction and 7 armature columns) written into
//   a
//                          preallocated matrix, as a stacked regressor is filled.
// What it measured is in docs/benchmarks.md (section 12), with the command.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "massprops/dynamics/inverse_dynamics.h"
#include "massprops/dynamics/torque_regressor.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

const char kArm[] =
    MASSPROPS_CORPUS_DIR "/drake-models/iiwa_description/urdf/iiwa14_no_collision.urdf";

struct Samples {
  KinematicTree tree;
  std::vector<Eigen::VectorXd> q, dq, ddq;
};

const Samples* LoadSamples(benchmark::State& state) {
  static const Samples* samples = [] {
    const ReadResult read = ReadModelFile(kArm);
    if (!read.ok() || read.models.empty()) return static_cast<Samples*>(nullptr);
    KinematicTreeResult made = MakeKinematicTree(read.models[0]);
    if (!made.tree) return static_cast<Samples*>(nullptr);
    auto* s = new Samples{*made.tree, {}, {}, {}};
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> any(-2, 2);
    const int n = s->tree.size();
    for (int k = 0; k < 1024; ++k) {
      Eigen::VectorXd q(n), dq(n), ddq(n);
      for (int i = 0; i < n; ++i) {
        q(i) = any(rng);
        dq(i) = any(rng);
        ddq(i) = 3 * any(rng);
      }
      s->q.push_back(q);
      s->dq.push_back(dq);
      s->ddq.push_back(ddq);
    }
    return s;
  }();
  if (samples == nullptr) state.SkipWithError(("cannot read " + std::string(kArm)).c_str());
  return samples;
}

void BM_InverseDynamics(benchmark::State& state) {
  const Samples* s = LoadSamples(state);
  if (s == nullptr) return;
  std::size_t k = 0;
  for (auto _ : state) {
    Eigen::VectorXd tau = CalcInverseDynamics(s->tree, s->q[k], s->dq[k], s->ddq[k]);
    benchmark::DoNotOptimize(tau.data());
    k = (k + 1) % s->q.size();
  }
  state.counters["joints"] = s->tree.size();
}
BENCHMARK(BM_InverseDynamics);

void BM_TorqueRegressor(benchmark::State& state) {
  const Samples* s = LoadSamples(state);
  if (s == nullptr) return;
  const RegressorOptions options{true, true};
  Eigen::MatrixXd Y(s->tree.size(), CountRegressorColumns(s->tree, options));
  std::size_t k = 0;
  for (auto _ : state) {
    CalcTorqueRegressor(s->tree, s->q[k], s->dq[k], s->ddq[k], options, Y);
    benchmark::DoNotOptimize(Y.data());
    k = (k + 1) % s->q.size();
  }
  state.counters["columns"] = static_cast<double>(Y.cols());
}
BENCHMARK(BM_TorqueRegressor);

}  // namespace
}  // namespace massprops

BENCHMARK_MAIN();
