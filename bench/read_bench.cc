// Reading speed on synthetic serial chains of 10 to 100 000 links, side by side:
//   Urdfdom   urdf::parseURDF alone (urdfdom 3, TinyXML 1 underneath): the reference;
//   Tinyxml2  tinyxml2::XMLDocument::Parse alone: the floor for any tinyxml2-based reader;
//   Massprops massprops::ReadUrdfString: parse + model + line numbers + all checks urdfdom makes;
//   MasspropsFile  massprops::ReadUrdfFile on the same text written to a temporary file.
// The text is MakeChainUrdf(n), byte-identical to `tools/gen_chain.py n OUT`.
//   ReadAndCheck   ReadUrdfString + CheckModel: what `massprops check` costs per file.
// Results and commands: README.md, section "Benchmarks".

#include <benchmark/benchmark.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "massprops/checks.h"
#include "massprops/urdf_reader.h"

namespace {

// Same text as tools/gen_chain.py (URDF).
std::string MakeChainUrdf(int n) {
  std::string out = "<?xml version=\"1.0\"?>\n<robot name=\"chain\">\n";
  out.reserve(static_cast<std::size_t>(n) * 600 + 64);
  for (int k = 0; k < n; ++k) {
    const std::string name = "link" + std::to_string(k);
    out += "  <link name=\"" + name + "\">\n";
    out += "    <inertial>\n";
    out += "      <origin xyz=\"0 0 0.05\" rpy=\"0 0 0\"/>\n";
    out += "      <mass value=\"1.5\"/>\n";
    out +=
        "      <inertia ixx=\"0.00145\" ixy=\"0\" ixz=\"0\" iyy=\"0.00145\" iyz=\"0\" "
        "izz=\"0.0004\"/>\n";
    out += "    </inertial>\n";
    out += "    <collision>\n";
    out += "      <origin xyz=\"0 0 0.05\" rpy=\"0 0 0\"/>\n";
    out += "      <geometry><box size=\"0.04 0.04 0.1\"/></geometry>\n";
    out += "    </collision>\n";
    out += "  </link>\n";
    if (k > 0) {
      out += "  <joint name=\"joint" + std::to_string(k) + "\" type=\"revolute\">\n";
      out += "    <origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/>\n";
      out += "    <parent link=\"link" + std::to_string(k - 1) + "\"/>\n";
      out += "    <child link=\"" + name + "\"/>\n";
      out += "    <axis xyz=\"0 1 0\"/>\n";
      out += "    <limit lower=\"-1.57\" upper=\"1.57\" effort=\"10\" velocity=\"1\"/>\n";
      out += "  </joint>\n";
    }
  }
  out += "</robot>\n";
  return out;
}

const std::string& Chain(int n) {
  static std::map<int, std::string> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, MakeChainUrdf(n)).first;
  return it->second;
}

const std::string& ChainFile(int n) {
  static std::map<int, std::string> paths;
  auto it = paths.find(n);
  if (it == paths.end()) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("massprops_read_bench_" + std::to_string(n) + ".urdf");
    std::ofstream(path, std::ios::binary) << Chain(n);
    it = paths.emplace(n, path.string()).first;
  }
  return it->second;
}

void Report(benchmark::State& state, int n) {
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(Chain(n).size()));
  state.counters["links/s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["MB"] = static_cast<double>(Chain(n).size()) / 1e6;
}

void BM_Urdfdom(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& xml = Chain(n);
  for (auto _ : state) {
    urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
    if (!model || model->links_.size() != static_cast<std::size_t>(n)) {
      state.SkipWithError("urdfdom failed");
    }
    benchmark::DoNotOptimize(model.get());
  }
  Report(state, n);
}

void BM_Tinyxml2(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& xml = Chain(n);
  for (auto _ : state) {
    tinyxml2::XMLDocument doc;
    doc.Parse(xml.data(), xml.size());
    if (doc.Error()) state.SkipWithError("tinyxml2 failed");
    benchmark::DoNotOptimize(doc.RootElement());
  }
  Report(state, n);
}

void BM_Massprops(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& xml = Chain(n);
  for (auto _ : state) {
    massprops::ReadResult result = massprops::ReadUrdfString(xml, "chain.urdf");
    if (!result.ok() || result.models[0].links.size() != static_cast<std::size_t>(n)) {
      state.SkipWithError("massprops failed");
    }
    benchmark::DoNotOptimize(result.models.data());
  }
  Report(state, n);
}

void BM_MasspropsFile(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& path = ChainFile(n);
  for (auto _ : state) {
    massprops::ReadResult result = massprops::ReadUrdfFile(path);
    if (!result.ok()) state.SkipWithError("massprops failed");
    benchmark::DoNotOptimize(result.models.data());
  }
  Report(state, n);
}

// What `massprops check` does per file: read, then every rule (welded groups, composites,
// principal moments). Issue 4's budget: at most 1.3x urdfdom's parse alone (BM_Urdfdom).
void BM_ReadAndCheck(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& xml = Chain(n);
  for (auto _ : state) {
    massprops::ReadResult result = massprops::ReadUrdfString(xml, "chain.urdf");
    if (!result.ok()) state.SkipWithError("massprops failed");
    const std::vector<massprops::Finding> findings = massprops::CheckModel(result.models[0]);
    benchmark::DoNotOptimize(findings.data());
  }
  Report(state, n);
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10, 100, 1000, 10000, 100000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_Urdfdom)->Apply(Sizes);
BENCHMARK(BM_Tinyxml2)->Apply(Sizes);
BENCHMARK(BM_Massprops)->Apply(Sizes);
BENCHMARK(BM_MasspropsFile)->Apply(Sizes);
BENCHMARK(BM_ReadAndCheck)->Apply(Sizes);

}  // namespace

BENCHMARK_MAIN();
