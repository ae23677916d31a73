#pragma once
/// @file
/// The bodies of the libFuzzer targets (tests/fuzz/*_fuzzer.cc), shared with the normal test
/// suite (tests/fuzz_regression_test.cc), which runs every seed and every input a fuzzer ever
/// found through them. Each returns "" when the input passed, else what went wrong (the fuzzers
/// abort on it; the regression test fails). An exception escaping a reader, a check or the fix
/// planner is not caught here: libFuzzer reports it as a crash, GoogleTest as a failure.

#include <cstddef>
#include <cstdint>
#include <string>

namespace massprops::fuzz {

/// URDF text → ReadUrdfString → ReaderFindings + CheckModel (every rule enabled) + the fix planner.
std::string FuzzUrdf(const std::uint8_t* data, std::size_t size);

/// SDF text (includes are not looked up) → ReadSdfString → every check, as FuzzUrdf; then
/// merge-fixed, whose result (when it merges) must read again with the merged links gone.
std::string FuzzSdf(const std::uint8_t* data, std::size_t size);

/// MJCF text (includes refused: max_include_depth 0) → ReadMjcfString, with the exact and the
/// MuJoCo mesh methods → every check, as FuzzUrdf. A model read must have one link per <body>
/// plus the world, and every joint's parent and child among them.
std::string FuzzMjcf(const std::uint8_t* data, std::size_t size);

/// Model text (URDF or SDF, detected by content) → checks → PlanRepairs → PatchModelText. The
/// patched text must read again when the input read, and a second fix of it must change nothing.
std::string FuzzFix(const std::uint8_t* data, std::size_t size);

/// Six doubles (the input's first 48 bytes; more bytes give a mass and a shift vector) →
/// RotationalInertia → principal moments, validity, shifts. No NaN from finite input, moments
/// ascending, summing to the trace and bounded by the Frobenius norm (within round-off), a valid
/// inertia shifted away from its center of mass stays valid.
std::string FuzzInertia(const std::uint8_t* data, std::size_t size);

/// The target by name ("urdf", "sdf", "mjcf", "fix", "inertia"), or nullptr.
using FuzzFunction = std::string (*)(const std::uint8_t*, std::size_t);
FuzzFunction FindFuzzTarget(const std::string& name);

}  // namespace massprops::fuzz
