// Reading an MJCF model: massprops' reader (ReadModelFile: parse, <default> classes, every
// body's mass properties from its <inertial> or its geoms) against MuJoCo 2.2.2's mj_loadXML
// (parse and compile the whole model) on the same files, side by side in one Google Benchmark
// run (issue 36: at least as fast as mj_loadXML). The files are the vendored real models of
// testdata/mjcf/MANIFEST.tsv, or the files given on the command line after the benchmark flags.
// Built only when libmujoco is installed (bench/CMakeLists.txt); docs/benchmarks.md has figures.
//
// Usage: mjcf_load_bench [--benchmark_...] [FILE.xml ...]
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "massprops/io/model_reader.h"

namespace {

const std::string kData = std::string(MASSPROPS_TESTDATA_DIR) + "/mjcf";

std::vector<std::string> ManifestModels() {
  std::vector<std::string> files;
  std::ifstream in(kData + "/MANIFEST.tsv");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::string vendored = line.substr(line.rfind('\t') + 1);
    if (vendored.find("/common/") == std::string::npos) files.push_back(kData + "/" + vendored);
  }
  return files;
}

void ReadWithMassprops(benchmark::State& state, const std::string& path) {
  std::size_t links = 0;
  for (auto _ : state) {
    const massprops::ReadResult read = massprops::ReadModelFile(path);
    if (!read.ok() || read.models.empty()) {
      state.SkipWithError("massprops cannot read it");
      return;
    }
    links = read.models.front().links.size();
    benchmark::DoNotOptimize(read.models.front().links.data());
  }
  state.counters["bodies"] = static_cast<double>(links);
}

void LoadWithMujoco(benchmark::State& state, const std::string& path) {
  char error[1000] = "";
  int bodies = 0;
  for (auto _ : state) {
    mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
    if (m == nullptr) {
      state.SkipWithError(error);
      return;
    }
    bodies = m->nbody;
    mj_deleteModel(m);
  }
  state.counters["bodies"] = bodies;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::vector<std::string> files(argv + 1, argv + argc);
  if (files.empty()) files = ManifestModels();
  for (const std::string& file : files) {
    const std::string name = file.substr(file.rfind('/', file.rfind('/') - 1) + 1);
    benchmark::RegisterBenchmark(("massprops_read/" + name).c_str(), ReadWithMassprops, file)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("mj_loadXML/" + name).c_str(), LoadWithMujoco, file)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
