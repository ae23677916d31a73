#!/usr/bin/env bash
# The cost of finding package:// meshes in the description's repository (issue 29), section 8 of
# docs/benchmarks.md. Needs hyperfine (Debian package `hyperfine`).
#
#   tools/crawl_bench.sh [BUILD_DIR/massprops] [CORPUS_DIR]
#
# 1. A generated repository of 10 000 folders (.git at its top; 100 folders of 99 subfolders,
#    a package.xml in the last one) and a description 3 folders down: `check` of a URDF whose
#    mesh is in that last package (the whole tree is crawled), of one whose package exists
#    nowhere (the whole tree, then the ancestors), against --no-geometry (no mesh looked up).
# 2. The corpus (no .git, no package.xml: each description's folder is crawled, and
#    package://example-robot-data/ is found as an ancestor folder): one process over every model
#    file (-j 1), and one file (finger_edu.urdf), each against --no-geometry.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
tool="$(realpath "${1:-$here/../build/massprops}")"
corpus="$(realpath "${2:-$here/../../shared/corpus}")"
command -v hyperfine > /dev/null || { echo "hyperfine is needed (apt-get install hyperfine)"; exit 2; }

tree="$(mktemp -d)"
trap 'rm -rf "$tree"' EXIT
mkdir -p "$tree/.git"
for i in $(seq -w 0 99); do
  for j in $(seq -w 1 99); do echo "$tree/d$i/s$j"; done
done | xargs mkdir -p
echo "folders: $(find "$tree" -mindepth 1 -type d -not -path '*/.git*' | wc -l)"
printf '<package format="3"><name>last_pkg</name></package>\n' > "$tree/d99/s99/package.xml"
cp "$here/../testdata/mesh/box_ascii.stl" "$tree/d99/s99/m.stl"
mkdir -p "$tree/d00/s01/urdf"
link() {
  printf '<robot name="r"><link name="b"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial><visual><geometry><mesh filename="%s"/></geometry></visual></link></robot>\n' "$1"
}
link "package://last_pkg/m.stl" > "$tree/d00/s01/urdf/found.urdf"
link "package://no_such_pkg/m.stl" > "$tree/d00/s01/urdf/missing.urdf"
"$tool" check --format json "$tree/d00/s01/urdf/found.urdf" | grep -c '"found_by": "repository-package"'

hyperfine -N --warmup 3 --runs 20 --style basic \
  -n "10 000 folders, --no-geometry" "$tool check -q --no-geometry $tree/d00/s01/urdf/found.urdf" \
  -n "10 000 folders, package found last" "$tool check -q $tree/d00/s01/urdf/found.urdf" \
  -n "10 000 folders, package nowhere" "$tool check -q $tree/d00/s01/urdf/missing.urdf"

mapfile -t files < <(awk -F'\t' 'NR > 1 && ($2 == "urdf" || $2 == "sdf") {print $1}' "$corpus/MANIFEST.tsv")
cd "$corpus"
finger=example-robot-data/robots/finger_edu_description/robots/finger_edu.urdf
hyperfine -N --warmup 2 --runs 10 -i --style basic \
  -n "corpus, ${#files[@]} files, --no-geometry" "$tool check -q -j 1 --no-geometry ${files[*]}" \
  -n "corpus, ${#files[@]} files" "$tool check -q -j 1 ${files[*]}" \
  -n "finger_edu.urdf, --no-geometry" "$tool check -q --no-geometry $finger" \
  -n "finger_edu.urdf" "$tool check -q $finger"
