// Loads SDF files with libsdformat 12 (sdf::Root::Load) and prints, per file, the links it holds
// and the seconds Load took: the peer of `massprops check` in tools/sdf_bench.sh (which measures
// both with /usr/bin/time on the same files). Built only when libsdformat 12 is installed.
//
// Usage: sdformat_load FILE...

#include <chrono>
#include <cstdio>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/Root.hh>
#include <sdf/World.hh>

int main(int argc, char** argv) {
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    const auto start = std::chrono::steady_clock::now();
    sdf::Root root;
    const sdf::Errors errors = root.Load(argv[i]);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t links = 0;
    if (root.Model() != nullptr) links += root.Model()->LinkCount();
    for (std::uint64_t w = 0; w < root.WorldCount(); ++w) {
      for (std::uint64_t m = 0; m < root.WorldByIndex(w)->ModelCount(); ++m) {
        links += root.WorldByIndex(w)->ModelByIndex(m)->LinkCount();
      }
    }
    std::printf("%s: %zu links, %zu errors, Load %.3f s\n", argv[i], links, errors.size(), seconds);
    if (!errors.empty()) status = 1;
  }
  return status;
}
