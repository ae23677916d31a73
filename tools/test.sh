#!/usr/bin/env bash
# Quick start, command 2: set up and run every test, twice:
#   1. build/        Release, warnings are errors, with the lint (tools/lint.sh: sizes, layers,
#                    clang-tidy); then the Debian package (tools/package_test.sh) and a ROS 2
#                    workspace (tools/colcon_test.sh), their objects from ccache;
#   2. build-asan/   clang-14 at -O1 under AddressSanitizer + UndefinedBehaviorSanitizer: the
#                    tests, then each libFuzzer target of tests/fuzz for 45 s (inertia 15 s;
#                    tools/fuzz.sh), as many at once as there are cores. MASSPROPS_FUZZ_SECONDS:
#                    the time per target.
# Set MASSPROPS_SKIP_SANITIZERS=1 to run only the first (no sanitizer build, no fuzzing).
# The tests that read ../shared (the corpus beside the checkout) skip without it and fail where it
# is present but incomplete (tests/shared_data.py); the last line says how many were skipped.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc)

# The wall time of each phase, printed as the last line (also when a phase fails), so that a CI
# log's tail says where its time went (docs/development.md, "CI time").
phases=()
phase_start=$SECONDS
phase_done() {
  phases+=("$1 $((SECONDS - phase_start)) s")
  phase_start=$SECONDS
}
print_phases() {
  local IFS=,
  echo "tools/test.sh: wall time by phase: ${phases[*]:-none}; total $SECONDS s"
}

# The Release builds (build/, the .deb's, the colcon workspace's) compile the same sources with the
# same flags: through ccache (tools/setup.sh installs it), the first compiles them and the others
# hit. A cache of the checkout's own unless CCACHE_DIR names one (docs/development.md, "CI time").
export CCACHE_DIR=${CCACHE_DIR:-$here/build-ccache}
# The benchmarks named too: tools/run.sh configures the same build/ without them. No precompiled
# header for the library and the tool in the Release trees (MASSPROPS_PCH, its path differs in each
# tree): the .deb's and colcon's compile commands equal build/'s, and they hit.
# Nor a unity build (tools/run.sh configures build/ with one): unit by unit, as the others compile.
release_args=(-DMASSPROPS_WERROR=ON -DMASSPROPS_PCH=OFF -DMASSPROPS_UNITY=OFF)
BUILD_DIR="$here/build" "$here/tools/setup.sh" "${release_args[@]}" -DMASSPROPS_BUILD_TESTS=ON \
  -DMASSPROPS_BUILD_BENCH=ON
phase_done "Release build"

# One clang-14 tree for both sanitizer passes: the tests under ASan + UBSan, and the libFuzzer
# targets (MASSPROPS_FUZZ=ON instruments everything for coverage too; only the fuzz targets link
# libFuzzer's main), at -O1 with line tables only (enough for symbolized reports): the library is
# compiled once for both (docs/development.md, "CI time"). It builds in the background while the
# Release pass runs its tests and packaging, which leave a core idle much of the time.
asan=$here/build-asan
asan_pid=
if [[ -z ${MASSPROPS_SKIP_SANITIZERS:-} ]]; then
  if [[ -f $asan/CMakeCache.txt ]] && ! grep -q '^MASSPROPS_FUZZ:BOOL=ON' "$asan/CMakeCache.txt"
  then
    rm -rf "$asan"  # an older tree of gcc's (before the two passes shared one)
  fi
  mkdir -p "$asan"
  # In a process group of its own (setsid), so that a failure of the Release pass stops it whole.
  CC=clang-14 CXX=clang++-14 BUILD_DIR="$asan" BUILD_TYPE=Debug setsid "$here/tools/setup.sh" \
    -DMASSPROPS_WERROR=ON -DMASSPROPS_BUILD_BENCH=OFF -DMASSPROPS_FUZZ=ON -DMASSPROPS_UNITY=ON \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" >"$asan/build.log" 2>&1 &
  asan_pid=$!
fi
trap 'print_phases; [[ -z $asan_pid ]] || kill -- -"$asan_pid" 2>/dev/null || true' EXIT

# Each ctest pass writes its results as JUnit, whose skipped tests are counted at the end.
junit=("$here/build/Testing/test-sh.xml")
shared_skips() {
  local count passes=Release
  count=$(python3 "$here/tests/shared_data.py" --count "${junit[@]}")
  ((${#junit[@]} == 1)) || passes="Release and sanitizer passes"
  if ((count > 0)); then
    echo "tools/test.sh: $count tests skipped ($passes): ../shared/corpus not found" \
         "(docs/development.md says where the corpus comes from)"
  else
    echo "tools/test.sh: 0 tests skipped for a missing corpus ($passes)"
  fi
}

(cd "$here/build" && ctest --output-on-failure -j "$jobs" --output-junit "${junit[0]}")
phase_done "Release ctest"

# As users install it (docs/install.md): the .deb built, judged by lintian and run from its files
# only, with the GitHub Action's script on it; a ROS 2 workspace built by colcon.
bash "$here/tools/package_test.sh" "${release_args[@]}"
bash "$here/tools/colcon_test.sh" "${release_args[@]}"
phase_done ".deb + colcon"

if [[ -n ${MASSPROPS_SKIP_SANITIZERS:-} ]]; then
  shared_skips
  exit 0
fi

if ! wait "$asan_pid"; then
  asan_pid=
  tail -60 "$asan/build.log"
  echo "tools/test.sh: the sanitizer build failed (log: build-asan/build.log)" >&2
  exit 1
fi
asan_pid=
phase_done "sanitizer build (after the Release pass)"
junit+=("$asan/Testing/test-sh.xml")
(cd "$asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
   LSAN_OPTIONS=suppressions="$here/tools/lsan.supp" \
   ctest --output-on-failure -j "$jobs" -LE 'lint|sdformat|sweep' --output-junit "${junit[1]}")
phase_done "sanitizer ctest"
# Left out here, run in the Release pass: the lint; the comparisons with libsdformat (label
# sdformat), whose time goes to libsdformat's own allocations through ASan's allocator (61-80 s
# each; the same corpus goes through our readers here in corpus_sdf_test and the CLI tests); and
# the sweeps of the CLI over every labelled or corpus file for a figure or a message form (label
# sweep, 95 and 164 s here), whose code paths corpus_fix_test, the CLI tests and the fuzzers take.

# A short fuzz run, $jobs targets at a time: any crash, sanitizer report or broken invariant fails
# the run (the input is left in build-asan/artifacts/TARGET/; keep it in
# testdata/fuzz/regressions/TARGET/). Every target runs even when an earlier one fails, so that
# one failure hides no other; the failed targets are named at the end.
export FUZZ_BUILD_DIR=$asan MASSPROPS_FUZZ_PREBUILT=1
failed=()
declare -A running=()
finish_one() {
  local pid
  wait -n -p pid "${!running[@]}" || failed+=("${running[$pid]}")
  unset "running[$pid]"
}
for target in urdf sdf mjcf fix inertia; do
  ((${#running[@]} < jobs)) || finish_one
  # A fixed seed: the same start on every CI run, so that a run fails only for a real change.
  # 45 s for each reader's and fix's target, 15 s for the inertia target (a small input space,
  # whose coverage stops growing within seconds): two rounds of two and the inertia alone.
  seconds=${MASSPROPS_FUZZ_SECONDS:-45}
  [[ $target != inertia ]] || seconds=${MASSPROPS_FUZZ_SECONDS:-15}
  "$here/tools/fuzz.sh" "$target" "$seconds" -seed=1 &
  running[$!]=$target
done
while ((${#running[@]} > 0)); do finish_one; done
phase_done "fuzz"
if ((${#failed[@]} > 0)); then
  echo "tools/test.sh: fuzz target(s) failed: ${failed[*]} (inputs in build-asan/artifacts/)" >&2
  exit 1
fi
shared_skips
