#!/usr/bin/env bash
# Quick start, command 1: set up, build, and check a model (the bundled example when none is given).
# Only what the tool needs is installed and built (tools/setup.sh, MASSPROPS_SETUP_TOOL_ONLY): the
# `massprops` executable and its mesh module; tools/test.sh installs and builds everything.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# A unity build (MASSPROPS_UNITY: the units compiled 8 to a batch): half the compile time of one
# unit at a time; with Ninja in a new build folder, so that the tool's units compile beside the
# library's last ones instead of after them (docs/development.md, "Time to the first finding").
generator=()
[[ -f ${BUILD_DIR:-$here/build}/CMakeCache.txt ]] || generator=(-G Ninja)
MASSPROPS_SETUP_TOOL_ONLY=1 "$here/tools/setup.sh" "${generator[@]}" -DMASSPROPS_BUILD_TESTS=OFF \
  -DMASSPROPS_BUILD_BENCH=OFF -DMASSPROPS_UNITY=ON
exec "${BUILD_DIR:-$here/build}/massprops" check "$@"
