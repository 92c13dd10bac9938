#!/usr/bin/env bash
# Creates or updates tools/.venv from tools/requirements.txt (and tools/requirements-nodeps.txt, installed
# with --no-deps: packages wanted for the binaries they carry, e.g. Slang's compiler) and prints the venv's
# python on the last stdout line:  py=$(tools/python_env.sh | tail -1)
# Quiet and fast when already up to date; pip's output goes to stderr so stdout stays parseable.
# Needs Debian's python3-venv (tools/setup.sh installs it) and, to install, PyPI (the network).
# Exit status 3: the venv cannot be made or filled here (no python3/venv, pip install failed: offline,
# say); callers that can do without it (tests/bench_quick.sh) skip their Python part on 3 only.
set -euo pipefail
cd "$(dirname "$0")/.."

venv=tools/.venv
py=$venv/bin/python

# One caller at a time (ctest runs bench_quick and the Slang tests side by side): a second waits for the
# first's install instead of racing it. The lock is on the tools/ folder itself, so no lock file is left.
exec 9<tools
flock 9

# A venv whose interpreter no longer runs (e.g. system python replaced) is rebuilt from scratch.
if [ -e "$venv" ] && ! "$py" -c '' 2>/dev/null; then
  echo "python_env: $venv is broken, recreating" >&2
  rm -rf "$venv"
fi

if [ ! -e "$venv" ]; then
  base=/usr/bin/python3
  [ -x "$base" ] || base=$(command -v python3) || { echo "python_env: python3 not found" >&2; exit 3; }
  echo "python_env: creating $venv" >&2
  if ! "$base" -m venv "$venv" >&2; then
    rm -rf "$venv"  # a half-made venv (no pip) would otherwise look usable next time
    echo "python_env: '$base -m venv' failed; install python3-venv (tools/setup.sh does)" >&2
    exit 3
  fi
fi

# install REQUIREMENTS STAMP [PIP FLAGS...]: pip install -r REQUIREMENTS unless STAMP is newer.
install() {
  local req=$1 stamp=$2
  shift 2
  if [ ! -f "$stamp" ] || [ "$req" -nt "$stamp" ]; then
    echo "python_env: installing $req" >&2
    if ! "$py" -m pip install -q "$@" -r "$req" >&2; then
      echo "python_env: pip could not install $req (no network to PyPI?); the venv stays unfinished" >&2
      exit 3
    fi
    touch "$stamp"  # only after a successful install, so a failed one is retried
  fi
}
install tools/requirements.txt "$venv/.requirements-stamp"
install tools/requirements-nodeps.txt "$venv/.requirements-nodeps-stamp" --no-deps

echo "$PWD/$py"
