#!/usr/bin/env bash
# Installs the Debian packages (tools/setup.sh), then configures and builds the default preset.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default
