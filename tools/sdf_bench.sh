#!/usr/bin/env bash
# Read + check of generated SDF chains (tools/gen_chain.py --sdf) with `massprops check`, against
# libsdformat 12's sdf::Root::Load (bench/sdformat_load) on the same files: wall time and peak
# resident memory of each process, measured by /usr/bin/time. docs/sdf.md quotes the output.
#
# Usage: tools/sdf_bench.sh [BUILD_DIR] [N...]     (default: build, 100 1000 10000)
# libsdformat runs under a 6 GiB address-space limit (ulimit -v) and a 300 s timeout; a run that
# exceeds them is reported as such.
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$here/build}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(100 1000 10000)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

measure() {  # measure LABEL CMD... -> "LABEL: T s, M MB"
  local label=$1
  shift
  /usr/bin/time -f '%e %U %S %M' "$@" >"$tmp/out" 2>"$tmp/err"
  local seconds user system kib
  read -r seconds user system kib <<<"$(tail -1 "$tmp/err")"
  if [[ ! $seconds =~ ^[0-9.]+$ ]] || grep -q "non-zero status\|terminated" "$tmp/err"; then
    printf '  %-18s failed (%s s): %s\n' "$label" "$seconds" \
      "$(grep -v '^[0-9.]* [0-9.]* [0-9.]* [0-9]*$' "$tmp/err" | tail -2 | tr '\n' ' ' | cut -c1-160)"
    return
  fi
  printf '  %-18s wall %8.2f s  cpu %8.2f s  peak %6d MB\n' "$label" "$seconds" \
    "$(awk -v u="$user" -v s="$system" 'BEGIN{print u + s}')" "$((kib / 1024))"
}

echo "SDF chains: read + check (massprops) vs sdf::Root::Load (libsdformat 12); $(nproc) cores"
for n in "${sizes[@]}"; do
  file="$tmp/chain_$n.sdf"
  python3 "$here/tools/gen_chain.py" "$n" "$file" --sdf
  echo "$n links ($(($(stat -c %s "$file") / 1024)) KiB):"
  measure "massprops check" "$build/massprops" check "$file"
  if [[ -x $build/bench/sdformat_load ]]; then
    measure "libsdformat Load" bash -c "ulimit -v 6291456; exec timeout 300 '$build/bench/sdformat_load' '$file'"
  fi
done
