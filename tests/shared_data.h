#pragma once
// ../shared beside the checkout (MASSPROPS_SHARED_DIR): the real-robot corpus (corpus/), the
// labelled set (labelled/) and the xacro packages (xacro/), which a fresh clone does not have
// (docs/development.md, "The shared corpus"). One policy for every test that reads it, the same as
// tests/shared_data.py's for the Python tests:
//   - ../shared absent: the test is skipped, with kSharedMissing's reason;
//   - ../shared present (as in CI), or MASSPROPS_REQUIRE_SHARED=1: a missing part fails the test.
// tools/test.sh counts the skips by kSharedMissing's words.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace massprops::test_support {

/// The words after "../shared/<part> not found" where it is skipped (the same in
/// tests/shared_data.py).
inline constexpr const char* kSharedMissing =
    " not found: the corpus tests are skipped; docs/development.md says where the corpus comes "
    "from";
/// The words after "../shared/<part> not found in <folder>" where ../shared is required.
inline constexpr const char* kSharedRequired =
    ": where ../shared is present (or MASSPROPS_REQUIRE_SHARED=1) a corpus test fails rather than "
    "skips; docs/development.md says what ../shared holds";

/// The shared folder (MASSPROPS_SHARED_DIR, ../shared beside the checkout by default).
inline std::string SharedDir() { return MASSPROPS_SHARED_DIR; }

/// Whether a missing part of ../shared is a failure rather than a skip: ../shared is there, or
/// MASSPROPS_REQUIRE_SHARED=1.
inline bool SharedRequired() {
  const char* require = std::getenv("MASSPROPS_REQUIRE_SHARED");
  return (require != nullptr && std::string(require) == "1") ||
         std::filesystem::is_directory(SharedDir());
}

/// Empty when ../shared/`part` exists (`part` relative to it: "corpus", "xacro/pmb2", ...);
/// otherwise why the test cannot run, naming the first missing folder or file of `part`.
inline std::string SharedMissing(const std::string& part) {
  std::filesystem::path at = SharedDir();
  std::string missing;
  for (const std::filesystem::path& name : std::filesystem::path(part)) {
    at /= name;
    missing += (missing.empty() ? "" : "/") + name.string();
    if (std::filesystem::exists(at)) continue;
    if (SharedRequired())
      return "../shared/" + missing + " not found in " + SharedDir() + kSharedRequired;
    return "../shared/" + missing + kSharedMissing;
  }
  return "";
}

/// Whether ../shared/`part` exists, for a test whose corpus files add to its testdata ones: when
/// it does not, a failure where ../shared is required (SharedRequired), else a note on stdout.
inline bool SharedPartPresent(const std::string& part) {
  const std::string missing = SharedMissing(part);
  if (missing.empty()) return true;
  if (SharedRequired())
    ADD_FAILURE() << missing;
  else
    std::cout << "note: " << missing << " (the testdata files are tested)\n";
  return false;
}

}  // namespace massprops::test_support

/// Skips the test (or, where ../shared is required, fails it) unless ../shared/`part` exists. In a
/// test's body or SetUp().
#define MASSPROPS_SKIP_WITHOUT_SHARED(part)                                                \
  do {                                                                                     \
    const std::string massprops_missing_ = ::massprops::test_support::SharedMissing(part); \
    if (massprops_missing_.empty()) break;                                                 \
    if (::massprops::test_support::SharedRequired()) FAIL() << massprops_missing_;         \
    GTEST_SKIP() << massprops_missing_;                                                    \
  } while (false)
