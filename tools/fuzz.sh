#!/usr/bin/env bash
# Runs one libFuzzer target of tests/fuzz for SECONDS seconds under ASan + UBSan:
#   tools/fuzz.sh urdf|sdf|mjcf|fix|inertia SECONDS [extra libFuzzer flags...]
# Builds build-fuzz/ (or $FUZZ_BUILD_DIR) with clang++-14 (or $FUZZ_CXX) the first time. Seeds:
# testdata/fuzz/<target>/ (fix: the urdf and sdf seeds); the growing corpus is kept in
# build-fuzz/corpus/<target>/. A crash, leak, sanitizer report, timeout or broken invariant stops
# the run with exit 1 and leaves the input in build-fuzz/artifacts/<target>/: copy it into
# testdata/fuzz/regressions/<target>/ (the normal test suite then runs it for ever:
# tests/fuzz_regression_test.cc). Prints one summary line: executions, coverage (cov, ft).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
target=${1:?usage: tools/fuzz.sh urdf|sdf|mjcf|fix|inertia SECONDS [libFuzzer flags...]}
seconds=${2:?usage: tools/fuzz.sh urdf|sdf|mjcf|fix|inertia SECONDS [libFuzzer flags...]}
shift 2
case $target in urdf | sdf | mjcf | fix | inertia) ;; *)
  echo "fuzz.sh: unknown target '$target' (urdf, sdf, mjcf, fix, inertia)" >&2
  exit 2
  ;;
esac
build=${FUZZ_BUILD_DIR:-$here/build-fuzz}
cxx=${FUZZ_CXX:-clang++-14}
cc=${FUZZ_CC:-${cxx/clang++/clang}}

if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=$cc CXX=$cxx cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
    -DMASSPROPS_FUZZ=ON -DMASSPROPS_BUILD_TESTS=OFF -DMASSPROPS_BUILD_BENCH=OFF \
    -DMASSPROPS_WERROR=ON >/dev/null
fi
# MASSPROPS_FUZZ_PREBUILT=1 (tools/test.sh, which runs targets side by side): the targets are
# built already; no two builds at once in one tree.
if [[ -z ${MASSPROPS_FUZZ_PREBUILT:-} ]]; then
  cmake --build "$build" -j "$(nproc)" --target "massprops_fuzz_$target" >/dev/null
fi

corpus=$build/corpus/$target
artifacts=$build/artifacts/$target
mkdir -p "$corpus" "$artifacts"
seeds=("$here/testdata/fuzz/$target")
flags=(-max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -max_len=65536
       -print_final_stats=1 -artifact_prefix="$artifacts/")
if [[ $target == fix ]]; then seeds=("$here/testdata/fuzz/urdf" "$here/testdata/fuzz/sdf"); fi
if [[ $target != inertia ]]; then flags+=(-dict="$here/testdata/fuzz/model.dict"); fi
# Inputs kept from earlier findings (git keeps no empty folder, so the folder may be absent).
if [[ -d $here/testdata/fuzz/regressions/$target ]]; then
  seeds+=("$here/testdata/fuzz/regressions/$target")
fi

log=$build/fuzz-$target.log
status=0
# Leak detection off: a leak is not a wrong answer, and the readers' caches live until exit.
ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$build/tests/fuzz/massprops_fuzz_$target" "${flags[@]}" "$@" "$corpus" "${seeds[@]}" >"$log" 2>&1 ||
  status=$?
execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
cov=$(grep -o 'cov: [0-9]*' <<<"$last" | grep -o '[0-9]*' || true)
ft=$(grep -o 'ft: [0-9]*' <<<"$last" | grep -o '[0-9]*' || true)
found=$(find "$artifacts" -type f | wc -l)
echo "fuzz $target: ${seconds}s, executions ${execs:-?}, cov ${cov:-?}, ft ${ft:-?}," \
  "corpus $(find "$corpus" -type f | wc -l) files, artifacts $found (log: $log)"
if ((status != 0)); then
  echo "fuzz $target: FAILED (exit $status); the input is in $artifacts/:" >&2
  grep -E 'ERROR|massprops fuzz|SUMMARY|Test unit written' "$log" | head -20 >&2 || true
  exit 1
fi
