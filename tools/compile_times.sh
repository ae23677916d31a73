#!/usr/bin/env bash
# The CPU time (user + sys) of each compiled unit, for docs/development.md, "Compile time".
#   1. as the compiler launcher, ccache off, e.g. from a fresh clone:
#        CMAKE_CXX_COMPILER_LAUNCHER=$PWD/tools/compile_times.sh MASSPROPS_COMPILE_TIMES=/tmp/t.log \
#        MASSPROPS_NO_CCACHE=1 bash tools/run.sh
#      (cmake reads CMAKE_CXX_COMPILER_LAUNCHER from the environment at a tree's first configure):
#      each compile appends "user sys source" to $MASSPROPS_COMPILE_TIMES;
#   2. tools/compile_times.sh --sum LOG [N]: the number of units, their total CPU seconds and the N
#      heaviest (default 15).
set -euo pipefail
if [[ ${1:-} == --sum ]]; then
  sort -k1,1 -g -r <(awk '{printf "%.2f %s\n", $1 + $2, $3}' "$2") |
    awk -v n="${3:-15}" '{t += $1; if (NR <= n) top = top sprintf("%8.2f  %s\n", $1, $2)}
                         END {printf "%d units, %.1f CPU-s\n%s", NR, t, top}'
  exit 0
fi
source=""
previous=""
for argument in "$@"; do
  [[ $previous == -c ]] && source=$argument
  previous=$argument
done
exec /usr/bin/time -a -o "${MASSPROPS_COMPILE_TIMES:?the log file}" -f "%U %S $source" "$@"
