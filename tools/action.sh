#!/usr/bin/env bash
# The steps of the GitHub Action (action.yml at the repository root; docs/ci.md), as one script
# so that it runs the same outside GitHub (tools/action_test.sh). Inputs come in the environment,
# as action.yml passes them:
#   INPUT_PATHS         files or folders to check, separated by white space (default: .)
#   INPUT_FAIL_ON       error | warning | note (default: error)
#   INPUT_PACKAGE_PATH  folders where package://NAME/... is found, separated by white space
#   INPUT_SARIF         true: also write massprops.sarif (for code scanning); default false
#   INPUT_DEB           URL or path of a massprops .deb to install
#   INPUT_VERSION       else: the .deb of this release of ACTION_REPOSITORY (e.g. 0.1.0)
#   (neither)           else: build the .deb from ACTION_PATH (the action's checkout)
#   MASSPROPS_ACTION_ROOT  (tests only) unpack the .deb into this folder instead of installing it
# Runs `massprops check --format github` (annotations on the pull request) and exits with its
# exit code: 0 clean, 1 findings at or above INPUT_FAIL_ON, 2 an unreadable file or bad input.
# Writes sarif-file=PATH to $GITHUB_OUTPUT when INPUT_SARIF is true.
set -euo pipefail
set -f  # the inputs are split on white space, never expanded as globs
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
action_path=${ACTION_PATH:-$here}

as_root() {
  if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi
}

# ---------------------------------------------------------------- the .deb
deb=${INPUT_DEB:-}
if [[ -z $deb && -n ${INPUT_VERSION:-} ]]; then
  version=${INPUT_VERSION#v}
  deb="https://github.com/${ACTION_REPOSITORY:?ACTION_REPOSITORY is not set}/releases/download/v$version/massprops_${version}_amd64.deb"
fi
workdir=$(mktemp -d)
trap 'rm -rf "$workdir"' EXIT
if [[ -z $deb ]]; then
  echo "::group::Build massprops from source ($action_path)"
  deb=$(bash "$action_path/tools/package.sh")
  echo "::endgroup::"
elif [[ $deb =~ ^https?:// ]]; then
  if ! command -v curl >/dev/null; then
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      curl ca-certificates >/dev/null
  fi
  curl -fsSL --retry 3 -o "$workdir/massprops.deb" "$deb"
  deb=$workdir/massprops.deb
elif [[ ! -f $deb ]]; then
  echo "massprops action: no such .deb: $deb" >&2
  exit 2
fi

if [[ -n ${MASSPROPS_ACTION_ROOT:-} ]]; then
  dpkg -x "$deb" "$MASSPROPS_ACTION_ROOT"
  export PATH="$MASSPROPS_ACTION_ROOT/usr/bin:$PATH"
else
  echo "::group::Install $(dpkg-deb -f "$deb" Package Version | paste -sd ' ')"
  cp "$deb" "$workdir/install.deb"  # apt-get wants a path with a slash
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "$workdir/install.deb"
  echo "::endgroup::"
fi
massprops --version

# ---------------------------------------------------------------- the check
read -r -d '' -a paths <<<"${INPUT_PATHS:-.}" || true
((${#paths[@]} > 0)) || paths=(.)  # blank: the repository (with no FILE, check takes its example)
args=(--fail-on "${INPUT_FAIL_ON:-error}")
read -r -d '' -a package_paths <<<"${INPUT_PACKAGE_PATH:-}" || true
for p in "${package_paths[@]}"; do args+=(--package-path "$p"); done

status=0
massprops check --format github "${args[@]}" -- "${paths[@]}" || status=$?
if [[ ${INPUT_SARIF:-false} == true ]]; then
  sarif=${GITHUB_WORKSPACE:-$PWD}/massprops.sarif
  # Exit code 1 (findings) is what SARIF is for; 2 still writes the readable files' findings.
  massprops check --format sarif "${args[@]}" -- "${paths[@]}" >"$sarif" || true
  echo "sarif-file=$sarif" >>"${GITHUB_OUTPUT:-/dev/null}"
fi
exit "$status"
