#!/usr/bin/env bash
# Runs Slang's compiler, slangc, from tools/.venv (slangtorch's wheel, pinned in tools/requirements-nodeps.txt;
# tools/python_env.sh installs it on first use):  tools/slangc.sh -allow-glsl -target spirv -O0 ...
# `tools/slangc.sh --path` prints slangc's path instead (its shared libraries are in the same folder: run it
# with LD_LIBRARY_PATH there, as this script does).
# Exit status 3: the venv cannot be made here (python_env.sh's message says why); callers may skip on 3 only.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

status=0
py=$("$root/tools/python_env.sh" | tail -1) || status=$?
[[ $status -eq 0 ]] || exit "$status"
# The package's folder, found without importing it (its __init__ imports torch, which is not installed).
package=$("$py" -c 'import importlib.util, os; print(os.path.dirname(importlib.util.find_spec("slangtorch").origin))')
bin=$package/bin
[[ -x $bin/slangc ]] || { echo "slangc.sh: $bin/slangc missing (slangtorch's wheel changed?)" >&2; exit 1; }
if [[ ${1-} == --path ]]; then
    echo "$bin/slangc"
    exit 0
fi
LD_LIBRARY_PATH=$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} exec "$bin/slangc" "$@"
