#!/usr/bin/env bash
# Installs every Debian package texfilter needs to build, render and test.
# Only what is used: volk (Vulkan loading), nlohmann-json (bench.json) and doctest (tests) are the host's
# libraries; openimageio-tools gives oiiotool (the tests make truncated JPEG/TIFF files with it); clang and
# libclang-rt-14-dev (libFuzzer, ASan, UBSan runtimes) build the fuzz targets (docs/FUZZING.md).
# Idempotent; run as root (or with sudo available) on Debian bookworm.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers
  glslang-tools glslc spirv-tools
  libglm-dev libopenimageio-dev openimageio-tools
  libvulkan-volk-dev nlohmann-json3-dev doctest-dev
  python3 python3-venv
  clang libclang-rt-14-dev
  libglfw3-dev libimgui-dev xvfb xauth x11-apps
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
