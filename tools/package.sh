#!/usr/bin/env bash
# Builds the Debian package massprops_VERSION_ARCH.deb into build-deb/ (or $BUILD_DIR) and prints
# its path (docs/install.md): tools/setup.sh installs what is missing (as root) and builds for
# /usr without tests or benchmarks (with ccache when present), then `cpack -G DEB` packs the
# install rules. Extra arguments go to cmake.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$here/build-deb}

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
rm -f "$build_dir"/massprops_*.deb
BUILD_DIR=$build_dir MASSPROPS_SETUP_BUILD_ONLY=${MASSPROPS_SETUP_BUILD_ONLY:-1} \
  "$here/tools/setup.sh" -DCMAKE_INSTALL_PREFIX=/usr -DMASSPROPS_DEBIAN_PACKAGE=ON \
  -DMASSPROPS_BUILD_TESTS=OFF -DMASSPROPS_BUILD_BENCH=OFF "${launcher[@]}" "$@" >&2
(cd "$build_dir" && cpack -G DEB >&2)
ls "$build_dir"/massprops_*.deb
