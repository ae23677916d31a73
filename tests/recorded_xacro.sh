#!/bin/sh
# A stand-in for ROS's `xacro` in the tests (CI has no ROS): it does NOT expand anything. Given a
# top-level .xacro file inside one of the packages of ../shared/xacro/, it prints that package's
# recorded expansion (expanded.urdf, made with ROS's xacro, see ../shared/xacro/README.md), found
# as the nearest folder upward that holds an expanded.urdf. Further arguments (NAME:=VALUE) are
# ignored: the recorded expansion was made with the arguments of the package's SOURCE.md.
set -eu
dir=$(cd "$(dirname "$1")" && pwd)
while [ "$dir" != "/" ]; do
  if [ -f "$dir/expanded.urdf" ]; then
    exec cat "$dir/expanded.urdf"
  fi
  dir=$(dirname "$dir")
done
echo "recorded_xacro.sh: no expanded.urdf above $1" >&2
exit 1
