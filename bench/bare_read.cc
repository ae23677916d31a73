// The physical limit of a mesh pass (bench/mesh_speed.py): reads each file named on the command
// line into memory and sums it as 64-bit words. Prints the CPU seconds this took (user + system,
// getrusage) and the sum (so that the reads cannot be optimised away).
//
//   bare_read FILE...                  each file whole, into one buffer (grown to the largest)
//   bare_read --pieces BYTES FILE...   each file in pieces of BYTES into one buffer of that size,
//                                      as massprops reads meshes (docs/benchmarks.md, section 8)
#include <sys/resource.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
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

std::uint64_t Sum(const char* bytes, std::size_t size) {
  std::uint64_t sum = 0;
  std::size_t k = 0;
  for (; k + 8 <= size; k += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes + k, 8);
    sum += word;
  }
  for (; k < size; ++k) sum += static_cast<unsigned char>(bytes[k]);
  return sum;
}

int main(int argc, char** argv) {
  std::size_t piece = 0;  // 0: whole files
  int first = 1;
  if (argc > 2 && std::strcmp(argv[1], "--pieces") == 0) {
    piece = static_cast<std::size_t>(std::strtoull(argv[2], nullptr, 10));
    first = 3;
    if (piece == 0) {
      std::fprintf(stderr, "bare_read: --pieces needs a size in bytes above 0\n");
      return 2;
    }
  }
  const double start = CpuSeconds();
  std::uint64_t sum = 0;
  std::string bytes(piece, '\0');
  for (int i = first; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary | std::ios::ate);
    if (!in) {
      std::fprintf(stderr, "bare_read: cannot read %s\n", argv[i]);
      return 2;
    }
    const auto size = static_cast<std::size_t>(in.tellg());
    in.seekg(0);
    if (piece == 0) {
      bytes.resize(size);
      in.read(bytes.data(), static_cast<std::streamsize>(size));
      sum += Sum(bytes.data(), size);
      continue;
    }
    for (std::size_t done = 0; done < size;) {
      in.read(bytes.data(), static_cast<std::streamsize>(piece));
      const auto got = static_cast<std::size_t>(in.gcount());
      if (got == 0) break;
      sum += Sum(bytes.data(), got);
      done += got;
    }
  }
  std::printf("%.6f %llu\n", CpuSeconds() - start, static_cast<unsigned long long>(sum));
  return 0;
}
