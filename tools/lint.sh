#!/usr/bin/env bash
# The conventions that CI enforces (docs/development.md, "Size limits" and "Style"), so that the
# code base does not depend on anyone remembering them:
#   1. tools/check_size.py   no file in src/, include/, python/src/ over 900 lines unless
#                            docs/development.md names it with its reason;
#   2. tools/check_layers.py the include directions between the parts (docs/architecture.md);
#   3. clang-tidy            .clang-tidy's checks, readability-function-size among them (no
#                            function over 120 lines), on every source of src/ and python/src/ in
#                            BUILD/compile_commands.json, and on the headers they include.
# Usage: tools/lint.sh [--tidy-only] [--long-only] [BUILD]   (BUILD: a configured build folder,
# default build/; its generated sources, e.g. the embedded page, are left out). --long-only:
# clang-tidy only on the sources where a function could be over the limit, as their text shows
# (tools/long_blocks.py: a block of 100+ lines in the source or in a header of src/ or include/ it
# includes): the size check at a fraction of the cost, as the ctest runs it; without it, every
# source (docs/development.md, "Size limits"). Jobs: MASSPROPS_LINT_JOBS, else nproc. Exit 0 when
# all pass; else 1, each violation named by file and line.
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tidy_only=0
long_only=0
while [[ ${1:-} == --* ]]; do
  case $1 in
    --tidy-only) tidy_only=1 ;;
    --long-only) long_only=1 ;;
    *) echo "lint.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
build=${1:-$here/build}
jobs=${MASSPROPS_LINT_JOBS:-$(nproc)}
status=0

if ((!tidy_only)); then
  python3 "$here/tools/check_size.py" "$here" || status=1
  python3 "$here/tools/check_layers.py" "$here" || status=1
fi

clang_tidy=${CLANG_TIDY:-$(command -v clang-tidy || command -v clang-tidy-14 || true)}
if [[ -z $clang_tidy ]]; then
  echo "lint.sh: clang-tidy not found (apt install clang-tidy)" >&2
  exit 1
fi
if [[ ! -f $build/compile_commands.json ]]; then
  echo "lint.sh: no $build/compile_commands.json: configure the build first (tools/setup.sh)" >&2
  exit 1
fi
# The project's own sources in the compilation database (each once).
mapfile -t sources < <(python3 - "$build/compile_commands.json" "$here" <<'PY'
import json, os, sys
db, root = sys.argv[1], os.path.realpath(sys.argv[2])
seen = set()
for entry in json.load(open(db)):
    path = os.path.realpath(os.path.join(entry["directory"], entry["file"]))
    rel = os.path.relpath(path, root)
    if rel.startswith(("src/", "python/src/")) and rel not in seen:
        seen.add(rel)
        print(path)
PY
)
if ((${#sources[@]} == 0)); then
  echo "lint.sh: no sources of src/ or python/src/ in $build/compile_commands.json" >&2
  exit 1
fi
if ((long_only)); then
  # The sources with a long block, and those that name a header with one (a header that no
  # source names, included only through other headers: every source).
  chosen=$(python3 - "$here" "${sources[@]}" <<'PY'
import os, pathlib, subprocess, sys
root = pathlib.Path(sys.argv[1])
sources = [s for s in sys.argv[2:] if os.path.isfile(s)]  # a stale database may name gone files
headers = [str(p) for d in ("include", "src", "python/src") for p in (root / d).rglob("*.h")]
scan = [root / "tools" / "long_blocks.py"]
long = set(subprocess.run([sys.executable, *scan, *sources, *headers], check=True,
                          capture_output=True, text=True).stdout.split())
chosen = [s for s in sources if s in long]
headers_long = sorted(long - set(sources))
texts = {}
if headers_long:  # each source read once, whatever the number of long headers
    texts = {s: open(s, encoding="utf-8", errors="replace").read() for s in sources}
for h in headers_long:
    name = os.path.basename(h)
    users = [s for s in sources if name in texts[s]]
    chosen += users if users else sources
print("\n".join(dict.fromkeys(chosen)))
PY
  ) || { echo "lint.sh: tools/long_blocks.py failed" >&2; exit 1; }
  mapfile -t sources < <(printf '%s' "$chosen" | sed '/^$/d')
  if ((${#sources[@]} == 0)); then
    echo "lint.sh: no source holds a block of 100 lines or more: no function can be over 120"
    exit $status
  fi
fi
log=$(mktemp)
# Each source as written, without a precompiled header (cmake/precompiled_headers.cmake): clang
# cannot read gcc's, and each source must include what it uses. A copy of the database without
# the header's options when the build has one.
db_dir=$(mktemp -d)
trap 'rm -rf "$log" "$db_dir"' EXIT
python3 - "$build/compile_commands.json" "$db_dir/compile_commands.json" <<'PY'
import json, re, shlex, sys
entries = json.load(open(sys.argv[1]))
pch = re.compile(r" -Winvalid-pch| -include(-pch)? +\S*cmake_pch\.hxx(\.pch|\.gch)?"
                 r"| -Xclang +-include(-pch)? +-Xclang +\S*cmake_pch\.hxx(\.pch|\.gch)?")
for entry in entries:
    if "command" in entry:
        entry["command"] = pch.sub("", entry["command"])
    else:
        entry["arguments"] = shlex.split(pch.sub("", shlex.join(entry["arguments"])))
json.dump(entries, open(sys.argv[2], "w"), indent=1)
PY
start=$SECONDS
printf '%s\n' "${sources[@]}" |
  xargs -P "$jobs" -n 4 "$clang_tidy" -p "$db_dir" --quiet >"$log" 2>&1
tidy_status=$?
# clang-tidy prints each warning of a header once per source that includes it.
grep -E '(warning|error):' "$log" | sort -u
if ((tidy_status != 0)); then
  grep -q -E '(warning|error):' "$log" || cat "$log"
  echo "lint.sh: clang-tidy failed on ${#sources[@]} sources ($((SECONDS - start)) s)"
  status=1
else
  echo "lint.sh: clang-tidy passed on ${#sources[@]} sources ($((SECONDS - start)) s, $jobs jobs)"
  if ((long_only)); then printf '  %s\n' "${sources[@]#"$here"/}"; fi
fi
exit $status
