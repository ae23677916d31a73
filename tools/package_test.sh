#!/usr/bin/env bash
# Tests the Debian package as a user gets it (docs/install.md; run by tools/test.sh):
#   1. tools/package.sh builds it (into build-deb/); dpkg-deb -I shows its fields; lintian (when
#      installed) finds no error in it;
#   2. unpacked with dpkg -x into a scratch root, and run from that root's files only: the tool
#      (--version; check on the installed example: exit 1 and its three findings; a mesh read
#      through the installed mesh module), the man page (every subcommand), `import massprops`
#      from the installed Python module, and tests/package/'s find_package(massprops) consumer;
#   3. the GitHub Action's script on the bundled example with this .deb (tools/action_test.sh).
# Prints the seconds each part took. Installs nothing system-wide. Arguments go to tools/package.sh
# (tools/test.sh builds the package with -DMASSPROPS_WERROR=ON).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "package_test: FAIL: $*" >&2; exit 1; }
SECONDS=0

# ---------------------------------------------------------------- 1. build and judge the .deb
deb=$(bash "$here/tools/package.sh" "$@")
[[ -f $deb ]] || fail "tools/package.sh printed no .deb ($deb)"
version=$(sed -n 's/^project(massprops VERSION \([0-9.]*\).*/\1/p' "$here/CMakeLists.txt")
[[ $(basename "$deb") == "massprops_${version}_$(dpkg --print-architecture).deb" ]] ||
  fail "unexpected file name $(basename "$deb")"
dpkg-deb -I "$deb"
depends=$(dpkg-deb -f "$deb" Depends)
# What the binaries link, as Debian names it (dpkg-shlibdeps): each must be in Depends.
for package in libtinyxml2 liburdfdom-model libconsole-bridge libassimp libqhull-r libyaml-cpp libstdc++6 \
               libc6; do
  [[ $depends == *"$package"* ]] || fail "Depends lacks $package: $depends"
done
echo "package_test: built $(basename "$deb") in ${SECONDS}s"
t=$SECONDS
if command -v lintian >/dev/null; then
  # --fail-on error: warnings are listed (docs/install.md says which and why), errors fail.
  lintian --fail-on error --no-tag-display-limit "$deb" || fail "lintian reports an error"
  echo "package_test: lintian: no error ($((SECONDS - t))s)"
else
  echo "package_test: lintian not installed: not run"
fi

# ---------------------------------------------------------------- 2. the installed files
t=$SECONDS
root=$work/root
dpkg -x "$deb" "$root"
libdir=$root/usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)
tool=$root/usr/bin/massprops
# A clean environment: nothing from the build tree or the checkout can be found.
clean_env=(env -i HOME="$work" PATH=/usr/bin:/bin LANG=C.UTF-8)

"${clean_env[@]}" "$tool" --version | grep -qx "massprops $version" || fail "massprops --version"
if ldd "$tool" "$libdir"/libmassprops.so.* "$libdir"/massprops/libmassprops_meshlibs.so | grep "not found"; then
  fail "a library of the package is missing"
fi
# The installed example: exit 1 by design, with its three findings (README, quick start).
example=$root/usr/share/massprops/examples/two_link_arm.urdf
status=0
(cd "$work" && "${clean_env[@]}" "$tool" check "$example") >"$work/check.txt" || status=$?
[[ $status -eq 1 ]] || fail "check on the example exited $status, expected 1"
grep -q "link 'forearm'.*\[inertia-not-physical\]" "$work/check.txt" || fail "no inertia-not-physical"
grep -q "checked 1 file: 1 error, 2 warnings, 1 note" "$work/check.txt" || fail "summary line"
# A mesh read by the installed module (<lib>/massprops/libmassprops_meshlibs.so, found from the
# installed tool): the box mesh of 0.1 x 0.2 x 0.3 m, scaled 3x along x, is a 0.3 x 0.2 x 0.3 box.
printf '%s\n' '<robot name="m"><link name="box">' \
  '<inertial><mass value="2"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>' \
  "<collision><geometry><mesh filename=\"$here/testdata/mesh/box_ascii.stl\" scale=\"3 1 1\"/></geometry></collision>" \
  '</link></robot>' >"$work/mesh.urdf"
"${clean_env[@]}" "$tool" report --geometry --format json "$work/mesh.urdf" >"$work/mesh.json" ||
  fail "report --geometry through the installed mesh module"
python3 - "$work/mesh.json" <<'PY' || fail "the mesh's inertia"
import json, sys
# A solid box a x b x c = 0.3 x 0.2 x 0.3 m (corner at the origin) of mass 2 kg: center of mass
# (a/2, b/2, c/2), Ixx = m(b^2 + c^2)/12, Iyy = m(a^2 + c^2)/12, Izz = m(a^2 + b^2)/12 (textbook);
# the STL holds floats, hence the relative 1e-6.
geometry = json.load(open(sys.argv[1]))["models"][0]["links"][0]["geometry"]
expected_com = [0.15, 0.1, 0.15]
expected_moments = [2 * 0.13 / 12, 2 * 0.18 / 12, 2 * 0.13 / 12]
moments = [geometry["inertia_about_com"][i][i] for i in range(3)]
for got, want in zip(geometry["com"] + moments, expected_com + expected_moments):
    assert abs(got - want) <= 1e-6 * abs(want), (got, want)
PY
echo "package_test: the tool from the installed files ($((SECONDS - t))s)"

t=$SECONDS
man=$root/usr/share/man/man1/massprops.1.gz
[[ -f $man ]] || fail "no man page"
MANWIDTH=1000 man -l "$man" 2>/dev/null | col -b >"$work/man.txt"
commands=$("$tool" --help | sed -n '/^Subcommands:/,/^$/s/^  \([a-z-]*\).*/\1/p')
[[ -n $commands ]] || fail "no subcommand in massprops --help"
for command in $commands; do
  grep -q "^ *massprops $command\$" "$work/man.txt" || fail "man page: no section massprops $command"
  for option in $("$tool" "$command" --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
    grep -q -- "$option" "$work/man.txt" || fail "man page: massprops $command: no $option"
  done
done
echo "package_test: man page shows $(echo $commands | wc -w) subcommands and their options" \
     "($((SECONDS - t))s)"

t=$SECONDS
python_dir=$root/usr/lib/python3/dist-packages
[[ -d $python_dir/massprops ]] || fail "no Python module in /usr/lib/python3/dist-packages"
module=$("${clean_env[@]}" PYTHONPATH="$python_dir" LD_LIBRARY_PATH="$libdir" python3 -c \
  'import massprops; print(massprops.__file__); print(len(massprops.check("'"$example"'")))') ||
  fail "import massprops"
[[ $(head -1 <<<"$module") == "$python_dir/massprops/__init__.py" ]] || fail "imported $module"
[[ $(tail -1 <<<"$module") == 4 ]] || fail "massprops.check found $(tail -1 <<<"$module"), not 4"
echo "package_test: import massprops ($((SECONDS - t))s)"

t=$SECONDS
consumer=$work/consumer
"${clean_env[@]}" cmake -S "$here/tests/package" -B "$consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$root/usr" >/dev/null
grep -q "^massprops_DIR:PATH=$libdir/cmake/massprops\$" "$consumer/CMakeCache.txt" ||
  fail "find_package found $(grep '^massprops_DIR' "$consumer/CMakeCache.txt")"
"${clean_env[@]}" cmake --build "$consumer" >/dev/null
# ldd's whole output first: `ldd | grep -q` under pipefail fails at random when grep stops reading
# before ldd has written its last line (SIGPIPE; CI's run of 2029638 failed so, on a loaded machine).
linked=$(ldd "$consumer/consumer")
grep -q "libmassprops.so.* => $libdir/" <<<"$linked" || fail "consumer links elsewhere: $linked"
"$consumer/consumer"
echo "package_test: find_package(massprops) consumer ($((SECONDS - t))s)"

# ---------------------------------------------------------------- 3. the GitHub Action's script
t=$SECONDS
bash "$here/tools/action_test.sh" "$deb"
echo "package_test: action ($((SECONDS - t))s)"
echo "package_test: all passed (${SECONDS}s)"
