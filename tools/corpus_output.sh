#!/usr/bin/env bash
# Prints everything the massprops tool says about every model file of ../shared/corpus (its
# MANIFEST.tsv): check (text, JSON, SARIF, GitHub; with --geometry; per target), report (text,
# JSON, CSV), fix --dry-run and --diff, merge-fixed and view, each command's exit code included.
# Used to show that a change (a restructuring) leaves the tool's behaviour byte for byte the same:
#
#   tools/corpus_output.sh OLD/massprops > old.txt
#   tools/corpus_output.sh NEW/massprops > new.txt
#   cmp old.txt new.txt && echo identical
#
# or both at once: tools/corpus_output.sh --compare OLD/massprops NEW/massprops (exit 1 and the
# first differences when they differ). The tool is run as `massprops` from the corpus folder
# with relative paths, so that the output names no build folder. The environment's model and
# package paths are cleared; the corpus README's model folders are passed with --model-path.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
corpus=${MASSPROPS_CORPUS_DIR:-$here/../shared/corpus}

if [[ ${1:-} == --compare ]]; then
  [[ $# -eq 3 ]] || { echo "usage: $0 --compare OLD_TOOL NEW_TOOL" >&2; exit 2; }
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
  "$0" "$2" > "$out/old.txt"
  "$0" "$3" > "$out/new.txt"
  if cmp -s "$out/old.txt" "$out/new.txt"; then
    echo "identical: $(wc -l < "$out/new.txt") lines, $(wc -c < "$out/new.txt") bytes," \
         "$(grep -c '^=== ' "$out/new.txt") commands"
    exit 0
  fi
  diff "$out/old.txt" "$out/new.txt" | head -40
  echo "the outputs differ" >&2
  exit 1
fi
[[ $# -eq 1 && -x $1 ]] || { echo "usage: $0 TOOL (the massprops executable)" >&2; exit 2; }
bin=$(mktemp -d)
trap 'rm -rf "$bin"' EXIT
ln -s "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" "$bin/massprops"
export PATH="$bin:$PATH"
unset SDF_PATH GZ_SIM_RESOURCE_PATH IGN_GAZEBO_RESOURCE_PATH GAZEBO_MODEL_PATH ROS_PACKAGE_PATH \
      AMENT_PREFIX_PATH
cd "$corpus"
models=(--model-path=gazebo_models --model-path=sdformat/test/integration/model
        --model-path=gz-sim/test/worlds/models --model-path=example-robot-data/robots)
packages=(--package-path=.)

run() {  # prints the command, its standard output and error, and its exit code
  echo "=== $*"
  local code=0
  "$@" 2>&1 || code=$?
  echo "--- exit $code"
}

mapfile -t files < <(awk -F'\t' 'NR > 1 && ($2 == "urdf" || $2 == "sdf") { print $1 }' MANIFEST.tsv)
for f in "${files[@]}"; do
  run massprops check "${models[@]}" "$f"
  run massprops check --format json "${models[@]}" "$f"
  run massprops check --format sarif "${models[@]}" "$f"
  run massprops check --format github "${models[@]}" "$f"
  run massprops check --geometry "${packages[@]}" "${models[@]}" "$f"
  for target in mujoco drake gazebo; do
    run massprops check --target "$target" "${models[@]}" "$f"
  done
  run massprops report "${models[@]}" "$f"
  run massprops report --format json "${models[@]}" "$f"
  run massprops report --format csv "${models[@]}" "$f"
  run massprops report --target gazebo "${models[@]}" "$f"
  run massprops fix --dry-run "${models[@]}" "$f"
  run massprops fix --diff -o /dev/null "${models[@]}" "$f"
  run massprops fix --dry-run --apply all "${models[@]}" "$f"
  run massprops fix --dry-run --target mujoco "${models[@]}" "$f"
  run massprops merge-fixed -o - "$f"
  # The page embeds three.js (600 kB): its checksum (with a failing exit code) stands for it.
  # Two comments of the page name the source file that fills it, which moved from tools/ to
  # src/tool/ (issue 18): that name is left out.
  echo "=== massprops view -o - $f | sha256sum"
  { massprops view -o - "${models[@]}" "$f" 2>&1 || echo "exit $?"; } |
    sed -E 's#(src/tool|tools)/view_command\.cc#view_command.cc#g' | sha256sum
done
# Folders: the whole corpus in one process, on one core and on two.
run massprops check -j 1 "${models[@]}" .
run massprops check -j 2 --format json "${models[@]}" .
