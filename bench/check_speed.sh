#!/usr/bin/env bash
# Wall time of `massprops check`, as docs/benchmarks.md sections 3 and 4 publish it. The tools to
# compare are run interleaved: ROUNDS rounds of one `hyperfine -N -i` over all of them (a changing
# load then hits every tool alike), and the minimum and median are taken over all runs of each.
#
#   bench/check_speed.sh startup TOOL...   `TOOL check -q examples/two_link_arm.urdf` for each
#                                          TOOL, then `check_urdf examples/two_link_arm.urdf`
#                                          (liburdfdom-tools), from the source tree
#   bench/check_speed.sh jobs TOOL...      `TOOL check -q -j N --format json` over the 298 URDF and
#                                          SDF files of ../shared/corpus/MANIFEST.tsv (model paths
#                                          of tools/corpus_summary.py), N = 1, 2, 4, from the corpus
#
# ROUNDS (default 8 for startup, 4 for jobs) and RUNS (40 / 5) set the counts. Prints `uptime`
# before and after (the machine is shared), then one line per command: runs, minimum and median
# wall time, mean user and system CPU time, and for jobs the files per second at the median.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
corpus=${MASSPROPS_CORPUS_DIR:-$here/../shared/corpus}
mode=${1:-}
shift || true
[[ ($mode == startup || $mode == jobs) && $# -ge 1 ]] ||
  { echo "usage: $0 startup|jobs TOOL..." >&2; exit 2; }
tools=()
for tool in "$@"; do tools+=("$(cd "$(dirname "$tool")" && pwd)/$(basename "$tool")"); done

cmds=()
if [[ $mode == startup ]]; then
  cd "$here"
  rounds=${ROUNDS:-8} runs=${RUNS:-40} files=1
  for tool in "${tools[@]}"; do cmds+=("$tool check -q examples/two_link_arm.urdf"); done
  cmds+=("check_urdf examples/two_link_arm.urdf")
else
  cd "$corpus"
  rounds=${ROUNDS:-4} runs=${RUNS:-5}
  mapfile -t models < <(awk -F'\t' 'NR > 1 && ($2 == "urdf" || $2 == "sdf") {print $1}' MANIFEST.tsv)
  files=${#models[@]}
  paths="--model-path gazebo_models --model-path sdformat/test/integration/model"
  paths+=" --model-path gz-sim/test/worlds/models --model-path example-robot-data/robots"
  for jobs in 1 2 4; do
    for tool in "${tools[@]}"; do
      cmds+=("$tool check -q -j $jobs --format json $paths ${models[*]}")
    done
  done
fi

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
uptime
for round in $(seq "$rounds"); do
  hyperfine -N -i --warmup 5 --runs "$runs" --export-json "$out/$round.json" "${cmds[@]}" \
    > /dev/null 2>&1
done
uptime
python3 - "$out" "$files" <<'EOF'
import glob, json, statistics, sys
runs = {}
for path in sorted(glob.glob(sys.argv[1] + "/*.json")):
    for r in json.load(open(path))["results"]:
        entry = runs.setdefault(r["command"], {"t": [], "user": [], "sys": []})
        entry["t"] += r["times"]
        entry["user"].append(r["user"])
        entry["sys"].append(r["system"])
files = int(sys.argv[2])
for command, e in runs.items():
    name = command.split(" --format")[0]
    median = statistics.median(e["t"])
    line = (f"{name}: {len(e['t'])} runs, min {min(e['t']) * 1e3:.3f} ms, median {median * 1e3:.3f} ms,"
            f" user {statistics.mean(e['user']) * 1e3:.2f} ms, system {statistics.mean(e['sys']) * 1e3:.2f} ms")
    if files > 1:
        line += f", {files / median:.0f} files/s"
    print(line)
EOF
