#!/usr/bin/env bash
# Quick start, command 1: set up, build, and check a model (the bundled example when none is given).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh" -DMASSPROPS_BUILD_TESTS=OFF -DMASSPROPS_BUILD_BENCH=OFF
exec "${BUILD_DIR:-$here/build}/massprops" check "$@"
