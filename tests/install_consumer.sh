#!/usr/bin/env bash
# The includes and texfilter::host as a product: install texfilter to a temporary prefix, check what landed
# there, and build and run examples/ (a standalone project) against the installed package only.
#
# usage: install_consumer.sh BUILD_DIR REPO_ROOT
set -euo pipefail
if [[ $# -ne 2 ]]; then
    echo "usage: $0 BUILD_DIR REPO_ROOT" >&2
    exit 2
fi
build=$(realpath "$1")
root=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >/dev/null
for file in bin/texfilter include/texfilter/texfilter.glsl include/texfilter/version.glsl \
    lib/cmake/texfilter/texfilterConfig.cmake lib/cmake/texfilter/texfilterConfigVersion.cmake \
    lib/cmake/texfilter/texfilterShaders.cmake lib/cmake/texfilter/texfilterEmbedSpirv.cmake \
    lib/cmake/texfilter/texfilterTargets.cmake include/texfilter/host.h lib/libtexfilter_host.a \
    share/doc/texfilter/CHANGELOG.md share/doc/texfilter/docs/API.md share/doc/texfilter/docs/images/api/ewa.png; do
    [[ -s $prefix/$file ]] || { echo "install_consumer: $file was not installed" >&2; exit 1; }
done
# Every include of the source tree (subfolders too) and the one C++ header, nothing of the harness or the
# host's own headers.
diff <( (cd "$root/shaders/texfilter" && find . -name '*.glsl'; echo ./host.h) | sort) \
    <(cd "$prefix/include/texfilter" && find . -type f | sort)
"$prefix/bin/texfilter" --help >/dev/null

# Image files from the prefix: bin/texfilter dlopens PREFIX/lib/texfilter/texfilter_oiio.so on the first image
# (host/io/oiio_loader.h). Without it, a .png output is refused before any work, naming the module's path;
# a .pfm output and flag errors never needed it.
if "$prefix/bin/texfilter" info 2>/dev/null | grep -q '^image I/O: OpenImageIO'; then
    module=$(realpath "$prefix")/lib/texfilter/texfilter_oiio.so
    [[ -s $module ]] || { echo "install_consumer: lib/texfilter/texfilter_oiio.so was not installed" >&2; exit 1; }
    render=("$prefix/bin/texfilter" render --scene plane --backend reference --size 32x32 --texture checker --filter trilinear)
    "${render[@]}" -o "$work/installed.png" >/dev/null
    "$prefix/bin/texfilter" diff "$work/installed.png" "$work/installed.png" >/dev/null
    mv "$module" "$module.away"
    status=0
    "${render[@]}" -o "$work/no_module.png" >/dev/null 2>"$work/no_module.txt" || status=$?
    if [[ $status -ne 2 || -e $work/no_module.png ]] || ! grep -qF "$module" "$work/no_module.txt"; then
        echo "install_consumer: without the image I/O module, render -o .png gave exit $status (want 2, no output," \
             "a message naming $module): $(cat "$work/no_module.txt")" >&2
        exit 1
    fi
    "${render[@]}" -o "$work/no_module.pfm" >/dev/null
    mv "$module.away" "$module"
fi

# The package's version check: this minor version is found, another is refused.
mkdir -p "$work/versions"
cat >"$work/versions/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(versions NONE)
find_package(texfilter ${WANT} REQUIRED)
CMAKE
version=$(sed -n 's/^project(texfilter VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
minor=${version%.*}
cmake -S "$work/versions" -B "$work/versions/ok" -DWANT="$minor" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
if cmake -S "$work/versions" -B "$work/versions/no" -DWANT=99.0 -DCMAKE_PREFIX_PATH="$prefix" >/dev/null 2>&1; then
    echo "install_consumer: find_package(texfilter 99.0) succeeded against $version" >&2
    exit 1
fi

# The example, configured and built from the installed package alone (no path into this tree).
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$root/examples" -B "$work/example" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/example" >/dev/null
mkdir -p "$work/out"
# Validation layers on: the example counts their messages and fails on any.
VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation "$work/example/texfilter_example" "$work/out"
for image in fragment.ppm compute.ppm; do
    [[ -s $work/out/$image ]] || { echo "install_consumer: the example wrote no $image" >&2; exit 1; }
done
# A texture2DArray with a separate sampler and a bindless sampler2D[] (nonuniformEXT), compiled by glslc,
# every lookup checked against its layer's or element's colour; validation on as above.
VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation "$work/example/texfilter_resources"
# texfilter::host from the same prefix: SAT box sums against brute force, MIP chain, sRGB decode.
"$work/example/texfilter_host_tables"
echo "install_consumer: installed texfilter $version; the examples built against it, rendered, checked the resource kinds and texfilter::host"
