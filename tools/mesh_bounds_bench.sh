#!/usr/bin/env bash
# The cost of reading the meshes' bounding boxes by default (issue 12): `massprops check` over
# every URDF/SDF of ../shared/corpus (as tools/corpus_summary.py runs it, from the corpus folder)
# by default, with --no-geometry (no mesh read) and with --package-path . (the corpus's own
# example-robot-data meshes resolve), timed by hyperfine. docs/benchmarks.md quotes the output.
#
# One thread (-j 1): on the shared 2-core machine the CPU time is the steadier number.
#
# Usage: tools/mesh_bounds_bench.sh [BUILD_DIR] [RUNS]      (default: build, 30)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
runs=${2:-30}
corpus=$here/../shared/corpus
cd "$corpus"
awk -F'\t' '$2=="urdf"||$2=="sdf"{print $1}' MANIFEST.tsv >"${TMPDIR:-/tmp}/massprops_corpus_files"
list="${TMPDIR:-/tmp}/massprops_corpus_files"
base="xargs -a $list $build/massprops check -j 1 --format json --fail-on error --model-path gazebo_models --model-path sdformat/test/integration/model --model-path gz-sim/test/worlds/models --model-path example-robot-data/robots"
json="${TMPDIR:-/tmp}/massprops_mesh_bounds_bench.json"
hyperfine --runs "$runs" --warmup 2 -N --ignore-failure --export-json "$json" \
  -n "default" "$base" \
  -n "no-geometry" "$base --no-geometry" \
  -n "package-path ." "$base --package-path ." >/dev/null 2>&1
python3 - "$json" "$runs" <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
print(f"| `check -j 1` over the corpus ({sys.argv[2]} runs) | wall min | wall median | "
      "CPU (user + sys) mean |")
print("|---|---:|---:|---:|")
for r in results:
    print(f"| {r['command']} | {r['min']:.3f} s | {r['median']:.3f} s | "
          f"{r['user'] + r['system']:.3f} s |")
PY
