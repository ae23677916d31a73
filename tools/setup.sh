#!/usr/bin/env bash
# Installs the Debian packages massprops needs (only those missing; apt-get needs root),
# then configures and builds into build/ (or $BUILD_DIR), through ccache when it is installed
# (MASSPROPS_NO_CCACHE=1: not). Extra arguments go to cmake.
# MASSPROPS_SETUP_TOOL_ONLY=1 (tools/run.sh): only the packages the `massprops` tool's build needs,
# and only the tool is built (with its mesh module): not the library's .so, the Python module, the
# man page, the tests or the benchmarks (docs/development.md, "Time to the first finding").
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$here/build}

packages=(build-essential cmake libeigen3-dev liburdfdom-dev libtinyxml2-dev libcli11-dev
          nlohmann-json3-dev libtomlplusplus-dev libassimp-dev libqhull-dev libjs-three)
# `massprops identify --html`: Chart.js 3.9, embedded into the tool at build time.
packages+=(libjs-chart.js)
# The xacro trace (src/io/xacro_source.cc): YAML with the line of each scalar.
packages+=(libyaml-cpp-dev)
# Ninja: tools/run.sh builds a new build folder with it (the tool's units beside the library's).
packages+=(ninja-build)
if [[ -z ${MASSPROPS_SETUP_TOOL_ONLY:-} ]]; then
# The Python module (python/).
packages+=(pybind11-dev python3-dev python3-numpy)
# The Debian package (tools/package.sh): the man page is written by help2man, cpack's Depends:
# by dpkg-shlibdeps (dpkg-dev).
packages+=(help2man dpkg-dev)
# ccache: the Release builds of tools/test.sh (build/, the .deb's, the colcon workspace's) compile
# the same sources with the same flags; the first compiles, the others hit the cache
# (docs/development.md, "CI time").
packages+=(ccache)
fi
# MASSPROPS_SETUP_BUILD_ONLY=1 (tools/package.sh, action.yml): only what the build needs.
if [[ -z ${MASSPROPS_SETUP_BUILD_ONLY:-} && -z ${MASSPROPS_SETUP_TOOL_ONLY:-} ]]; then
packages+=(libgtest-dev libgmock-dev libbenchmark-dev libsdformat-dev python3-pytest)
# The rosbag tests write ROS 2 bags with SQLite's C API (tests/rosbag_writer.h); `massprops
# identify` itself loads libsqlite3.so.0 (libsqlite3-0) only when it reads a bag, and builds
# without SQLite (src/io/sqlite_library.h).
packages+=(libsqlite3-dev)
# The MuJoCo differential test (tests/target_profile_mujoco_test.cc): libmujoco 2.2.2.
packages+=(libmujoco-dev)
# The HTML view (`massprops view`): three.js, embedded at build time; its browser test: headless
# Chromium driven by Debian's python3-selenium.
packages+=(libjs-three chromium chromium-driver python3-selenium)
# The libFuzzer targets (tools/fuzz.sh, run by tools/test.sh): clang and its libFuzzer.
packages+=(clang-14 libfuzzer-14-dev)
# The lint (tools/lint.sh, ctest clang_tidy_passes): clang-tidy, whose readability-function-size
# keeps every function within 120 lines (docs/development.md, "Size limits").
packages+=(clang-tidy)
# The language server's real-client test (tests/lsp_neovim_test.py): headless Neovim, an LSP
# client, opens the example with `massprops lsp` attached (docs/editors.md).
packages+=(neovim)
# The packaging tests: lintian judges the .deb (tools/package_test.sh); colcon builds a ROS 2
# workspace holding massprops (tools/colcon_test.sh): colcon-ros reads package.xml, colcon-cmake
# builds, colcon-bash writes install/setup.bash.
packages+=(lintian colcon python3-colcon-cmake python3-colcon-ros python3-colcon-bash)
# `check --format junit` read as GitLab and Jenkins read it (tests/ci_formats_test.py).
packages+=(python3-junitparser)
# urdfdom's check_urdf, timed beside `massprops check` on the same files by
# tools/growth_check.py --curve (docs/benchmarks.md, section 11).
packages+=(liburdfdom-tools)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -eq 0 ]]; then
    echo "setup: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: missing Debian packages: ${missing[*]} (run as root, or install them)" >&2
    exit 1
  fi
fi

launcher=()
if command -v ccache >/dev/null && [[ -z ${MASSPROPS_NO_CCACHE:-} ]]; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} "${launcher[@]}" "$@" \
  >/dev/null
targets=()
[[ -z ${MASSPROPS_SETUP_TOOL_ONLY:-} ]] || targets=(--target massprops-cli)
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"
