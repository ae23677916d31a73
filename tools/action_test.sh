#!/usr/bin/env bash
# tools/action_test.sh DEB: runs the GitHub Action's script (tools/action.sh, the one step of
# action.yml) as GitHub would, with the inputs in the environment, on the bundled example and on a
# clean model, unpacking DEB into a scratch folder instead of installing it (run by
# tools/package_test.sh). Checks the annotations, the exit codes and the SARIF output.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deb=$(realpath "${1:?usage: tools/action_test.sh path/to/massprops.deb}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "action_test: FAIL: $*" >&2; exit 1; }

# Runs the action in the checkout (GitHub's working directory) with the inputs given as
# NAME=VALUE arguments; its output goes to $work/out.txt, its exit code to $status.
run_action() {
  rm -rf "$work/root" "$work/github_output" "$work/massprops.sarif"
  status=0
  (cd "$here" && env -u INPUT_PATHS -u INPUT_FAIL_ON -u INPUT_PACKAGE_PATH -u INPUT_SARIF \
     -u INPUT_VERSION INPUT_DEB="$deb" MASSPROPS_ACTION_ROOT="$work/root" \
     GITHUB_OUTPUT="$work/github_output" GITHUB_WORKSPACE="$work" ACTION_PATH="$here" "$@" \
     bash tools/action.sh) >"$work/out.txt" 2>&1 || status=$?
}

# The bundled example (README): one error, two warnings. fail-on error: exit 1; an annotation per
# finding in GitHub's workflow-command form (::error file=...,line=...::), line 73 for forearm.
run_action INPUT_PATHS="examples/two_link_arm.urdf" INPUT_SARIF=true
[[ $status -eq 1 ]] || { cat "$work/out.txt"; fail "exit $status on the example, expected 1"; }
grep -q "^massprops 0\." "$work/out.txt" || fail "no massprops --version line"
grep -q "^::error file=examples/two_link_arm.urdf,line=73.*inertia-not-physical" "$work/out.txt" ||
  { cat "$work/out.txt"; fail "no error annotation at line 73"; }
[[ $(grep -c "^::warning file=examples/two_link_arm.urdf" "$work/out.txt") -eq 2 ]] ||
  fail "expected 2 warning annotations"
grep -qx "sarif-file=$work/massprops.sarif" "$work/github_output" || fail "no sarif-file output"
python3 - "$work/massprops.sarif" <<'PY' || fail "SARIF"
import json, sys
sarif = json.load(open(sys.argv[1]))
assert sarif["version"] == "2.1.0", sarif["version"]
rules = sorted(r["ruleId"] for r in sarif["runs"][0]["results"])
assert rules == ["inertia-not-physical", "inertial-missing", "massless-link-with-mass-outboard",
                 "units-suspect"], rules
PY

# fail-on warning with several paths (white space, a folder): still 1; no SARIF when not asked.
run_action INPUT_PATHS="examples
  testdata/check/clean.urdf" INPUT_FAIL_ON=warning
[[ $status -eq 1 ]] || fail "exit $status with two paths, expected 1"
[[ ! -e $work/massprops.sarif && ! -s $work/github_output ]] || fail "SARIF written unasked"

# A clean model: exit 0, no annotation.
run_action INPUT_PATHS="testdata/check/clean.urdf" INPUT_FAIL_ON=note
[[ $status -eq 0 ]] || { cat "$work/out.txt"; fail "exit $status on a clean model, expected 0"; }
! grep -q "^::" "$work/out.txt" || fail "annotations on a clean model"

# A file that does not exist: exit 2.
run_action INPUT_PATHS="no/such/robot.urdf"
[[ $status -eq 2 ]] || fail "exit $status on a missing file, expected 2"
echo "action_test: passed"
