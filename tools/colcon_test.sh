#!/usr/bin/env bash
# massprops in a ROS 2 workspace (package.xml; docs/install.md; run by tools/test.sh): a scratch
# workspace whose package is this checkout (colcon build --paths), `colcon build` (Debian: colcon,
# python3-colcon-ros, which reads package.xml, and python3-colcon-cmake) without tests or benchmarks (with ccache when present), then the installed
# tool runs from the workspace's install/ folder, and `import massprops` after sourcing
# install/setup.bash. Prints the seconds it took.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ws=${COLCON_TEST_WORKSPACE:-$here/build-colcon}
fail() { echo "colcon_test: FAIL: $*" >&2; exit 1; }
command -v colcon >/dev/null || fail "colcon is not installed (Debian: colcon, python3-colcon-cmake)"
SECONDS=0

rm -rf "$ws/install" "$ws/log" "$ws/src"
mkdir -p "$ws"
# The checkout itself is the package (colcon --paths: no discovery below it): its sources are
# compiled from the same paths as build/'s, so that with the same flags (tools/test.sh passes
# -DMASSPROPS_WERROR=ON, as to build/) ccache hits. Extra arguments go to cmake.
cmake_args=(-DCMAKE_BUILD_TYPE=Release -DMASSPROPS_BUILD_TESTS=OFF -DMASSPROPS_BUILD_BENCH=OFF "$@")
if command -v ccache >/dev/null; then
  cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# The build folder stays (build-colcon/build/massprops) so that a second run builds only what
# changed; install/ is made anew each time.
(cd "$ws" && colcon build --paths "$here" --cmake-args "${cmake_args[@]}") >"$ws/colcon.log" 2>&1 ||
  { tail -40 "$ws/colcon.log"; fail "colcon build failed (log: $ws/colcon.log)"; }

# colcon read package.xml (colcon-ros): it records the package's run dependencies, the rosdep
# keys of package.xml's <depend> and <exec_depend> (without colcon-ros it would have taken the
# package for a plain CMake one, with none).
run_deps=$(cat "$ws/install/massprops/share/colcon-core/packages/massprops")
[[ $run_deps == "assimp:eigen:libqhull:python3-numpy:tinyxml2:urdfdom:yaml-cpp" ]] ||
  fail "colcon's run dependencies of massprops: '$run_deps', not those of package.xml"
version=$(sed -n 's/^project(massprops VERSION \([0-9.]*\).*/\1/p' "$here/CMakeLists.txt")
"$ws/install/massprops/bin/massprops" --version | grep -qx "massprops $version" ||
  fail "install/massprops/bin/massprops --version"
status=0
"$ws/install/massprops/bin/massprops" check --quiet "$ws/install/massprops/share/massprops/examples/two_link_arm.urdf" >/dev/null || status=$?
[[ $status -eq 1 ]] || fail "check on the installed example exited $status, expected 1"
# The workspace's environment (what `source install/setup.bash` gives a ROS user) finds the module.
module=$(env -i HOME="$HOME" PATH=/usr/bin:/bin bash -c \
  "source '$ws/install/setup.bash' && python3 -c 'import massprops; print(massprops.__file__)'") ||
  fail "import massprops after sourcing install/setup.bash"
[[ $module == "$ws/install/massprops/"* ]] || fail "imported $module, not the workspace's"
echo "colcon_test: passed (${SECONDS}s)"
