// Composition cost on synthetic chains of 1 000 to 1 000 000 links, in memory (no file reading):
// every 10th joint is revolute, the others fixed (welded groups of 10 links); each link has a
// valid inertial with an offset, turned center of mass. BM_WeldedGroupsAndComposites times
// FindWeldedGroups, every group's CalcCompositeInertia and CalcModelCompositeInertia;
// BM_FullReport times ComputeMassReport with one joint value. Each size reports the CPU time per
// link and the minor page faults per link and iteration (getrusage); Google Benchmark's O(N) fit
// is printed too.
//
// What it measured (docs/benchmarks.md, section 2, "Less fresh memory per call": main's build of
// cb995aa and this tree, run alternately on 2 shared cores at a load average of 0.5-0.9): CPU time
// per link at 10^3 / 10^4 / 10^5 links, full report 259 / 262 / 355 ns (before: 268 / 281 / 688:
// at 10^5 the heap, over glibc's trim threshold, was faulted in again on every call, 0.176 faults
// per link, now 0.002), groups + composites 106 / 111 / 233 ns (before 108 / 110 / 274). At 10^6
// one single iteration per repetition right after building the model varies 0.7-1.8 us per link
// for the same binary (first-call page faults); with three calls per repetition
// (--benchmark_min_time=3) the report takes 580-629 ns per link (before 738-741) and groups +
// composites 351-352 ns (before 399-426). The work is linear: callgrind counts 2 269-2 346
// (groups + composites) and 3 695-3 749 (report) instructions per link from 10^3 to 10^6 links;
// what still grows is reading the model from memory (448 bytes per link, 296 per joint: 74 MB at
// 10^5, past the 32 MB L3), 10-15 ns per element and pass, and at 10^6 the fresh pages of the
// report's 320-byte entries. Command:
//   build/bench/composite_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//     --benchmark_filter='BM_(WeldedGroupsAndComposites|FullReport)/(1000|10000|100000)$'
// and for 10^6 links --benchmark_filter='BM_(WeldedGroupsAndComposites|FullReport)/1000000$'
// --benchmark_min_time=3 --benchmark_repetitions=3.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

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

// Minor page faults of this process so far (memory touched for the first time since it was mapped).
long MinorPageFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// The counters every size reports: CPU time per link, and minor page faults per link and
// iteration (`faults_before`: MinorPageFaults() before the timed loop).
void SetPerLinkCounters(benchmark::State& state, long faults_before) {
  const double links = static_cast<double>(state.range(0));
  state.SetComplexityN(state.range(0));
  state.counters["time_per_link"] = benchmark::Counter(
      links, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["faults_per_link"] = static_cast<double>(MinorPageFaults() - faults_before) /
                                      (links * static_cast<double>(state.iterations()));
}

void BM_WeldedGroupsAndComposites(benchmark::State& state) {
  const Model model = MakeChain(static_cast<int>(state.range(0)));
  const long faults_before = MinorPageFaults();
  for (auto _ : state) {
    const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
    double mass = 0;
    for (const WeldedGroup& group : groups) mass += CalcCompositeInertia(model, group).mass;
    mass += CalcModelCompositeInertia(model).inertia.mass;
    benchmark::DoNotOptimize(mass);
  }
  SetPerLinkCounters(state, faults_before);
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
  const long faults_before = MinorPageFaults();
  for (auto _ : state) {
    ModelMassReport report;
    std::string error;
    benchmark::DoNotOptimize(ComputeMassReport(model, options, &report, &error));
  }
  SetPerLinkCounters(state, faults_before);
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
