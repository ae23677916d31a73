// libFuzzer entry point of the "mjcf" target (see fuzz_targets.h; run with tools/fuzz.sh mjcf).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = massprops::fuzz::FuzzMjcf(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "massprops fuzz (mjcf): %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
