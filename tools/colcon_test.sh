#!/usr/bin/env bash
# massprops in a ROS 2 workspace (package.xml; docs/install.md; run by tools/test.sh): a scratch
# workspace whose package is this checkout (colcon build --paths), `colcon build` (Debian: colcon,
# python3-colcon-ros, which reads package.xml, and python3-colcon-cmake) without tests or benchmarks (with ccache when present), then the installed
# tool runs from the workspace's install/ folder, and `import massprops` after sourcing
# install/setup.bash. Then the fixture description package tests/colcon/fixture_description,
# built in the same workspace, checks its URDF and xacro files with massprops_add_test()
# (docs/ci.md): `colcon test` runs the checks and `colcon test-result --verbose` must show the one
# bad link's failure at its rule and line, with the clean file and the xacro expansion (given its
# argument) passing. Prints the seconds it took.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ws=${COLCON_TEST_WORKSPACE:-$here/build-colcon}
fail() { echo "colcon_test: FAIL: $*" >&2; exit 1; }
command -v colcon >/dev/null || fail "colcon is not installed (Debian: colcon, python3-colcon-cmake)"
SECONDS=0

fixture=$here/tests/colcon/fixture_description
rm -rf "$ws/install" "$ws/log" "$ws/src" "$ws/build/fixture_description"
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
(cd "$ws" && colcon build --paths "$here" "$fixture" --cmake-args "${cmake_args[@]}") \
  >"$ws/colcon.log" 2>&1 ||
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
echo "colcon_test: massprops built and installed (${SECONDS}s)"

# ---------------------------------------------------------------- colcon test of a description
t=$SECONDS
# tests/colcon/xacro stands in for ROS's xacro (not in Debian): it substitutes $(arg ...) only.
(cd "$ws" && XDG_CACHE_HOME="$ws/cache" PATH="$here/tests/colcon:$PATH" \
   colcon test --paths "$here" "$fixture" --packages-select fixture_description) \
  >"$ws/colcon-test.log" 2>&1 || { tail -40 "$ws/colcon-test.log"; fail "colcon test failed to run"; }
results=$ws/build/fixture_description/test_results/fixture_description
status=0
(cd "$ws" && colcon test-result --test-result-base build/fixture_description --verbose) \
  >"$ws/test-result.txt" 2>&1 || status=$?
cat "$ws/test-result.txt"
[[ $status -eq 1 ]] || fail "colcon test-result exited $status, expected 1 (a failure)"
# The bad link's failing testcase, at the line of its <inertia> (counted here from the file) and
# under the rule for an inertia no body can have (ixx + iyy < izz).
line=$(awk '/<link name="forearm">/ { in_link = 1 } in_link && /<inertia / { print NR; exit }' \
  "$fixture/urdf/arm.urdf")
grep -qx -- "- massprops.arm inertia-not-physical: forearm (urdf/arm.urdf:$line)" \
  "$ws/test-result.txt" || fail "no failing testcase for forearm at urdf/arm.urdf:$line"
grep -qx "build/fixture_description/test_results/fixture_description/urdf.xml: [0-9]* tests\?, 0 errors, 1 failure, 0 skipped" \
  "$ws/test-result.txt" || fail "urdf.xml: not exactly 1 failure"
# The xacro check passed (its argument reached the expander: the default mass 0 would be an
# error), so `colcon test-result` leaves its report out; the clean file's testsuite has no failure.
grep -q "robot.xml" "$ws/test-result.txt" && fail "robot.xml has a failure or an error"
/usr/bin/python3 - "$results" <<'PY' || fail "the JUnit reports do not say what was expected"
import sys
import xml.etree.ElementTree as ET
suites = {s.get("name"): s for f in ("urdf.xml", "robot.xml")
          for s in ET.parse(f"{sys.argv[1]}/{f}").getroot().iter("testsuite")}
clean = suites["urdf/gripper.urdf"]
assert (clean.get("failures"), clean.get("errors")) == ("0", "0"), clean.attrib
assert [c.get("name") for c in clean.iter("testcase")] == ["massprops check"]
xacro = [s for name, s in suites.items() if name.endswith("robot.urdf.xacro>")]
assert len(xacro) == 1 and xacro[0].get("failures") == "0", list(suites)
PY
# ctest ran both, and only 'urdf' failed; the log holds the findings as text.
temporary=$ws/build/fixture_description/Testing/Temporary
failed=$(cat "$temporary"/LastTestsFailed*.log)
[[ $failed =~ ^[0-9]+:urdf$ ]] || fail "ctest's failed tests: '$failed', expected only 'urdf'"
grep -q "urdf/arm.urdf:$line: error: .*\[inertia-not-physical\]" "$temporary"/LastTest*.log ||
  fail "the test log lacks the text finding"
echo "colcon_test: colcon test of the fixture description package ($((SECONDS - t))s)"
echo "colcon_test: passed (${SECONDS}s)"
