// The physical limit of a mesh pass (bench/mesh_speed.py): reads each file named on the command
// line into memory and sums it as 64-bit words. Prints the CPU seconds this took (user + system,
// getrusage) and the sum (so that the reads cannot be optimised away).
#include <sys/resource.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace {

double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

int main(int argc, char** argv) {
  const double start = CpuSeconds();
  std::uint64_t sum = 0;
  std::string bytes;
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary | std::ios::ate);
    if (!in) {
      std::fprintf(stderr, "bare_read: cannot read %s\n", argv[i]);
      return 2;
    }
    bytes.resize(static_cast<std::size_t>(in.tellg()));
    in.seekg(0);
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::size_t k = 0;
    for (; k + 8 <= bytes.size(); k += 8) {
      std::uint64_t word;
      std::memcpy(&word, bytes.data() + k, 8);
      sum += word;
    }
    for (; k < bytes.size(); ++k) sum += static_cast<unsigned char>(bytes[k]);
  }
  std::printf("%.6f %llu\n", CpuSeconds() - start, static_cast<unsigned long long>(sum));
  return 0;
}
