// Reading URDF, side by side on the same text: synthetic serial chains (MakeChainUrdf(n), byte-
// identical to `tools/gen_chain.py n OUT`) of 1 000, 10 000 and 100 000 links.
//   Urdfdom         urdf::parseURDF alone (urdfdom 3, TinyXML 1 underneath): the reference.
//   MasspropsRead   massprops::ReadUrdfString: urdfdom + the tinyxml2 line index + the Model.
//   CheckEndToEnd   what `massprops check FILE` does per file, in process: ReadModelFile on the
//                   file, ReaderFindings, CheckModel, the text report. Budget (issue 13): at most
//                   1.3 times Urdfdom.
// Peak memory needs one process per measurement:
//   read_bench --once urdfdom FILE      runs urdf::parseURDF once on FILE and prints the peak
//                                       resident set (KiB) of the process;
//   read_bench --once massprops FILE    the same for massprops::ReadUrdfString;
// tools/read_bench.py runs these and `massprops check FILE` (budget: at most 2 times urdfdom's
// peak) and prints the table of docs/urdf.md.

#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <urdf_parser/urdf_parser.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/urdf_reader.h"
#include "massprops/output/reporters.h"

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

void BM_MasspropsRead(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& xml = Chain(n);
  for (auto _ : state) {
    massprops::ReadResult result = massprops::ReadUrdfString(xml, "chain.urdf");
    if (!result.ok() || result.models.at(0).links.size() != static_cast<std::size_t>(n)) {
      state.SkipWithError("massprops failed");
    }
    benchmark::DoNotOptimize(result.models.data());
  }
  Report(state, n);
}

// What src/tool/main.cc does for `massprops check FILE` (text format).
void BM_CheckEndToEnd(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& path = ChainFile(n);
  for (auto _ : state) {
    const massprops::ReadResult read = massprops::ReadModelFile(path);
    if (!read.ok()) state.SkipWithError("massprops failed");
    massprops::FileResult file;
    file.path = path;
    file.format = "urdf";
    file.errors = read.errors;
    file.findings = massprops::ReaderFindings(read, massprops::CheckOptions{});
    for (const massprops::Model& model : read.models) {
      file.models.push_back(model.name);
      std::vector<massprops::Finding> findings = massprops::CheckModel(model);
      file.findings.insert(file.findings.end(), findings.begin(), findings.end());
    }
    std::ostringstream out;
    massprops::WriteReport(out, massprops::ReportFormat::kText, {file}, {});
    benchmark::DoNotOptimize(out.str().data());
  }
  Report(state, n);
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n : {1000, 10000, 100000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_Urdfdom)->Apply(Sizes);
BENCHMARK(BM_MasspropsRead)->Apply(Sizes);
BENCHMARK(BM_CheckEndToEnd)->Apply(Sizes);

// `read_bench --once urdfdom|massprops FILE`: one read, then the process's peak resident set.
int RunOnce(const std::string& what, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    return 2;
  }
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t links = 0;
  if (what == "urdfdom") {
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
    links = model ? model->links_.size() : 0;
  } else if (what == "massprops") {
    const massprops::ReadResult result = massprops::ReadUrdfString(xml, path);
    links = result.models.empty() ? 0 : result.models[0].links.size();
  } else {
    std::fprintf(stderr, "unknown reader %s (urdfdom or massprops)\n", what.c_str());
    return 2;
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("%s links=%zu peak_kib=%ld\n", what.c_str(), links, usage.ru_maxrss);
  return links > 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--once") == 0) return RunOnce(argv[2], argv[3]);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
