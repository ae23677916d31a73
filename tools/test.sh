#!/usr/bin/env bash
# Quick start, command 2: set up and run every test, twice:
#   1. build/        Release, warnings are errors, with the lint (tools/lint.sh: sizes, layers,
#                    clang-tidy); then the Debian package (tools/package_test.sh) and a ROS 2
#                    workspace (tools/colcon_test.sh), their objects from ccache;
#   2. build-asan/   Debug under AddressSanitizer + UndefinedBehaviorSanitizer.
#   3. build-fuzz/   each libFuzzer target of tests/fuzz for 60 s under ASan + UBSan (clang-14;
#                    tools/fuzz.sh). Set MASSPROPS_FUZZ_SECONDS to change the time per target.
# Set MASSPROPS_SKIP_SANITIZERS=1 to run only the first (no sanitizer build, no fuzzing).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc)

# The Release builds (build/, the .deb's, the colcon workspace's) compile the same sources with the
# same flags: through ccache (tools/setup.sh installs it), the first compiles them and the others
# hit. A cache of the checkout's own unless CCACHE_DIR names one (docs/development.md, "CI time").
export CCACHE_DIR=${CCACHE_DIR:-$here/build-ccache}
BUILD_DIR="$here/build" "$here/tools/setup.sh" -DMASSPROPS_WERROR=ON -DMASSPROPS_BUILD_TESTS=ON
(cd "$here/build" && ctest --output-on-failure -j "$jobs")

# As users install it (docs/install.md): the .deb built, judged by lintian and run from its files
# only, with the GitHub Action's script on it; a ROS 2 workspace built by colcon.
bash "$here/tools/package_test.sh" -DMASSPROPS_WERROR=ON
bash "$here/tools/colcon_test.sh" -DMASSPROPS_WERROR=ON

if [[ -z ${MASSPROPS_SKIP_SANITIZERS:-} ]]; then
  BUILD_DIR="$here/build-asan" BUILD_TYPE=Debug "$here/tools/setup.sh" -DMASSPROPS_WERROR=ON \
    -DMASSPROPS_BUILD_BENCH=OFF -DMASSPROPS_SANITIZE=address,undefined
  (cd "$here/build-asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     LSAN_OPTIONS=suppressions="$here/tools/lsan.supp" \
     ctest --output-on-failure -j "$jobs" -LE lint)  # the lint ran in the Release pass
fi

if [[ -z ${MASSPROPS_SKIP_SANITIZERS:-} ]]; then
  # A short fuzz run: any crash, sanitizer report or broken invariant fails the run (the input is
  # left in build-fuzz/artifacts/TARGET/; keep it in testdata/fuzz/regressions/TARGET/). Every
  # target runs even when an earlier one fails, so that one failure hides no other; the failed
  # targets are named at the end.
  failed=()
  for target in urdf sdf mjcf fix inertia; do
    # A fixed seed: the same inputs on every CI run, so that a run fails only for a real change.
    if ! "$here/tools/fuzz.sh" "$target" "${MASSPROPS_FUZZ_SECONDS:-60}" -seed=1; then
      failed+=("$target")
    fi
  done
  if ((${#failed[@]} > 0)); then
    echo "tools/test.sh: fuzz target(s) failed: ${failed[*]} (inputs in build-fuzz/artifacts/)" >&2
    exit 1
  fi
fi
