// Composition cost on synthetic chains of 1 000 to 1 000 000 links (in memory, no file reading):
// every 10th joint is revolute, the others fixed (welded groups of 10 links); each link has a
// valid inertial with an offset, turned center of mass. Google Benchmark fits the times to
// O(N) and prints the fit (BigO) and its relative error (RMS); the per-link time of each size is
// in docs/benchmarks.md, before and after the fix of issue #17 (a report that grew 55x for 10x
// links). Command:
//   build/bench/composite_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/model/model.h"

namespace massprops {
namespace {

Model MakeChain(int n) {
  Model model;
  model.name = "chain";
  model.links.resize(n);
  for (int i = 0; i < n; ++i) {
    Link& link = model.links[i];
    link.name = "link" + std::to_string(i);
    Inertial inertial;
    inertial.mass = 1.0 + 0.001 * (i % 7);
    inertial.X_BBi.p_AB = Eigen::Vector3d(0.05, 0.01 * (i % 3), 0.02);
    inertial.X_BBi.R_AB =
        Eigen::AngleAxisd(0.1 * (i % 5), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    inertial.ixx = 0.01;
    inertial.iyy = 0.02;
    inertial.izz = 0.025;
    link.inertial = inertial;
  }
  model.root_link = model.links[0].name;
  for (int i = 1; i < n; ++i) {
    Joint joint;
    joint.name = "joint" + std::to_string(i);
    joint.type = i % 10 == 0 ? Joint::Type::kRevolute : Joint::Type::kFixed;
    joint.type_name = i % 10 == 0 ? "revolute" : "fixed";
    joint.parent = model.links[i - 1].name;
    joint.child = model.links[i].name;
    joint.X_PC.p_AB = Eigen::Vector3d(0.1, 0, 0);
    joint.X_PC.R_AB = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitY()).toRotationMatrix();
    joint.axis = Eigen::Vector3d::UnitZ();
    model.joints.push_back(joint);
  }
  return model;
}

void BM_WeldedGroupsAndComposites(benchmark::State& state) {
  const Model model = MakeChain(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
    double mass = 0;
    for (const WeldedGroup& group : groups) mass += CalcCompositeInertia(model, group).mass;
    mass += CalcModelCompositeInertia(model).inertia.mass;
    benchmark::DoNotOptimize(mass);
  }
  state.SetComplexityN(state.range(0));
  state.counters["time_per_link"] = benchmark::Counter(
      static_cast<double>(state.range(0)),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_WeldedGroupsAndComposites)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

void BM_FullReport(benchmark::State& state) {
  const Model model = MakeChain(static_cast<int>(state.range(0)));
  MassReportOptions options;
  options.joint_values["joint10"] = 0.5;
  for (auto _ : state) {
    ModelMassReport report;
    std::string error;
    benchmark::DoNotOptimize(ComputeMassReport(model, options, &report, &error));
  }
  state.SetComplexityN(state.range(0));
  state.counters["time_per_link"] = benchmark::Counter(
      static_cast<double>(state.range(0)),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FullReport)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

// --only one link near the root: the cost is the name index (hashing), not the composition.
void BM_OnlyOneLink(benchmark::State& state) {
  const Model model = MakeChain(static_cast<int>(state.range(0)));
  MassReportOptions options;
  options.only = {"link3"};
  for (auto _ : state) {
    ModelMassReport report;
    std::string error;
    benchmark::DoNotOptimize(ComputeMassReport(model, options, &report, &error));
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_OnlyOneLink)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace massprops

BENCHMARK_MAIN();
