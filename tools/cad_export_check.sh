#!/usr/bin/env bash
# Checks the raw SolidWorks export that docs/rules.md (cad-default-density) and docs/fix.md (the
# worked example) use: TheRobotStudio/SO-ARM100 at commit 9b30ca26..., folder
# URDF/URDF_SO_5DOF_ARM100_05d.SLDASM. Its files are not in this repository: give the folder of a
# git snapshot (or clone) of that repository.
#
# Usage: tools/cad_export_check.sh GIT_DIR [MASSPROPS]
#   GIT_DIR    a clone or bare snapshot of https://github.com/TheRobotStudio/SO-ARM100
#   MASSPROPS  the tool (default: build/massprops)
# Prints `massprops check`, then the dry run of the fix of docs/fix.md; exit 0 when both ran.
set -euo pipefail
git_dir=${1:?usage: tools/cad_export_check.sh GIT_DIR [MASSPROPS]}
tool=${2:-build/massprops}
commit=9b30ca2623e8fcffe24e02cdf4fbce3816d4a79f
package=URDF/URDF_SO_5DOF_ARM100_05d.SLDASM
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git --git-dir="$git_dir" archive "$commit" "$package" | tar -x -C "$work"
file="$work/$package/urdf/URDF_SO_5DOF_ARM100_05d.SLDASM.urdf"
echo "== massprops check (commit $commit)"
"$tool" check --package-path "$work/URDF" "$file" || true
echo "== massprops fix --dry-run --material LINK=pla for every link"
materials=()
for link in Base Shoulder_Rotation_Pitch Upper_Arm Lower_Arm Wrist_Pitch_Roll Fixed_Gripper \
            Moving_Jaw; do
  materials+=(--material "$link=pla")
done
"$tool" fix --dry-run --package-path "$work/URDF" "${materials[@]}" "$file"
