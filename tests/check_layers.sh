#!/usr/bin/env bash
# The host's layers hold (host/CMakeLists.txt): each folder includes only the layers below it, and the CPU
# reference and the installed texture library reach no Vulkan and no OpenImageIO, neither through
# CMake's link graph nor through an undefined symbol in their archives; no layer, and not the texfilter
# executable, links OpenImageIO (only the image I/O module does, loaded on the first image file).
# usage: check_layers.sh BUILD_DIR SOURCE_DIR
set -u
build=$1 source=$2
layers_file=$build/layers.txt
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The layers each one may include, itself included. harness/ is shaders/harness/config.h.
declare -A allowed=(
  [texture]="texture"
  [core]="core texture harness"
  [scene]="scene core texture harness"
  [reference]="reference scene core texture harness"
  [io]="io core texture"
  [vulkan]="vulkan scene core texture harness"
  [bench]="bench vulkan reference io scene core texture harness"
  [flags]="flags vulkan io scene core texture"
  [view]="view flags bench vulkan reference io scene core texture harness"
  [cli]="cli view flags bench vulkan reference io scene core texture harness"
)
# Layers that must stay free of the GPU and of OpenImageIO. The io layer reaches OIIO only through the image
# I/O module, host/io/oiio_module.cpp (texfilter_oiio.so, dlopen'ed on first use): the one file that includes it.
no_vulkan="texture core scene reference io"
no_oiio="texture core scene reference io vulkan"
oiio_module=host/io/oiio_module.cpp

[[ -f $layers_file ]] || { echo "FAIL: $layers_file missing (configure the build first)"; exit 1; }

# 1. Includes, file by file.
for layer in "${!allowed[@]}"; do
  [[ -d $source/host/$layer ]] || { fail "host/$layer/ missing"; continue; }
  for file in "$source"/host/"$layer"/*.{h,cpp}; do
    [[ -f $file ]] || continue
    while IFS= read -r include; do
      [[ $include == */* ]] || continue # the generated SPIR-V headers (vulkan) and system headers
      top=${include%%/*}
      [[ " ${allowed[$layer]} " == *" $top "* ]] || fail "${file#"$source"/}: includes \"$include\" (layer $layer may include: ${allowed[$layer]})"
    done < <(sed -n 's/^#include "\(.*\)".*/\1/p' "$file")
    if [[ " $no_vulkan " == *" $layer "* ]] && grep -Eq '^#include <(vulkan/|volk)' "$file"; then
      fail "${file#"$source"/}: includes Vulkan (layer $layer must not)"
    fi
    if [[ " $no_oiio " == *" $layer "* && ${file#"$source"/} != "$oiio_module" ]] &&
       grep -Eq '^#include <OpenImageIO/' "$file"; then
      fail "${file#"$source"/}: includes OpenImageIO (layer $layer must not)"
    fi
  done
done

# 2. The link graph: every library a layer reaches through CMake, directly or through another layer.
declare -A links archive
while IFS='|' read -r layer path libs; do
  archive[$layer]=$path
  links[$layer]=${libs//;/ }
done < "$layers_file"
reach() { # reach LAYER: every link library below it, once each
  local -A seen=()
  local queue=("$1") item lib
  while ((${#queue[@]})); do
    item=${queue[0]}; queue=("${queue[@]:1}")
    for lib in ${links[$item]-}; do
      [[ -n ${seen[$lib]-} ]] && continue
      seen[$lib]=1
      [[ $lib == texfilter_* ]] && queue+=("${lib#texfilter_}")
    done
  done
  echo "${!seen[@]}"
}
for layer in $no_vulkan; do
  for lib in $(reach "$layer"); do
    [[ $lib == *Vulkan* || $lib == *volk* || $lib == texfilter_vulkan ]] && fail "layer $layer links $lib"
  done
done
for layer in $no_oiio; do
  for lib in $(reach "$layer"); do
    [[ $lib == *OIIO* || $lib == *OpenImageIO* || $lib == texfilter_io ]] && fail "layer $layer links $lib"
  done
done

# 3. The archives: no undefined Vulkan or OpenImageIO symbol (what a header-only back door would leave).
for layer in $no_vulkan; do
  [[ -f ${archive[$layer]-} ]] || { fail "layer $layer: no archive ${archive[$layer]-} (build first)"; continue; }
  if nm -u "${archive[$layer]}" | grep -Eq '\b(vk[A-Z]|volk)'; then
    fail "layer $layer: its archive needs Vulkan symbols: $(nm -u "${archive[$layer]}" | grep -Eo '\b(vk[A-Z]|volk)[A-Za-z0-9_]*' | sort -u | head -3 | tr '\n' ' ')"
  fi
done
for layer in $no_oiio; do
  [[ -f ${archive[$layer]-} ]] || continue
  nm -u "${archive[$layer]}" | grep -q 'OpenImageIO' && fail "layer $layer: its archive needs OpenImageIO symbols"
done

# 4. The executable: OpenImageIO's ~260 libraries are the module's, never loaded at start-up.
if [[ -f $build/texfilter ]] && readelf -d "$build/texfilter" | grep -q 'NEEDED.*OpenImageIO'; then
  fail "texfilter links OpenImageIO directly (it belongs in texfilter_oiio.so, host/io/oiio_loader.h)"
fi

checked=$(for layer in "${!allowed[@]}"; do ls "$source"/host/"$layer"/*.{h,cpp} 2>/dev/null; done | wc -l)
if ((failures)); then
  echo "FAILED: $failures layer violations"
  exit 1
fi
echo "all passed: $checked files in ${#allowed[@]} layers; reference and texture reach no Vulkan, no OpenImageIO;" \
     "only $oiio_module includes OpenImageIO"
