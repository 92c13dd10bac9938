#!/usr/bin/env bash
# The CMake package as an engine uses it: texfilter_add_shaders from an installed prefix, in a consumer
# project (tests/shader_package/) configured once with Ninja Multi-Config, then one check a ctest entry.
#
# usage: shader_package.sh BUILD_DIR REPO_ROOT CASE      (shader_package.sh --list names the cases)
#   setup            install to BUILD_DIR/shader_package/prefix, configure the consumer there
#                    (TEXFILTER_SHADER_COMPILER=glslc), build Debug, Release and RelWithDebInfo
#   compilers        call 1 names glslangValidator, call 2 takes the cache's glslc: each module's generator
#                    says which compiled it; spirv-val accepts all
#   configs          per configuration: Debug has OpLine/OpSource (DEBUG_INFO), Release fewer instructions
#                    than RelWithDebInfo (OPTIMIZE: glslc -O, glslangValidator -Os) and no debug info
#   same_name        a/blur.comp.glsl and b/blur.comp.glsl: two modules, two headers, two symbols
#   two_calls        two calls on one target: two custom targets, both calls' modules in TEXFILTER_SPIRV
#   embed_alone      each EMBED header compiles as the only include of a TU; the words equal the .spv
#   rebuild_on_include  editing the caller's include rebuilds the shader that includes it, and only that one
#   bad_arguments    an unknown compiler, and two calls writing one module, stop the configure with a message
#   installed_docs   every relative link and picture of every installed doc resolves inside the prefix
set -euo pipefail
cases=(setup compilers configs same_name two_calls embed_alone rebuild_on_include bad_arguments installed_docs)
if [[ ${1:-} == --list ]]; then
    printf '%s\n' "${cases[@]}"
    exit 0
fi
if [[ $# -ne 3 ]]; then
    echo "usage: $0 BUILD_DIR REPO_ROOT CASE (or --list)" >&2
    exit 2
fi
build=$(realpath "$1")
root=$(realpath "$2")
case_name=$3
work=$build/shader_package
prefix=$work/prefix
consumer=$work/consumer
configs=(Debug Release RelWithDebInfo)

fail() {
    echo "shader_package $case_name: $*" >&2
    exit 1
}
# Instructions of a module (one line each in the disassembly), and how many of them are opcode $2.
instructions() { spirv-dis --no-header "$1" | grep -c 'Op'; }
count_op() { spirv-dis --no-header "$1" | grep -c -E "(^| )$2( |$)" || true; }
module() { echo "$consumer/$1/$2"; } # CONFIG-relative path of a module
blur_dir() { echo "$consumer/texfilter_shaders/consumer/$1"; }
sky_dir() { echo "$consumer/second/$1"; }
need_setup() { [[ -f $work/setup.ok ]] || fail "run the setup case first (ctest fixture shader_package)"; }

case $case_name in
setup)
    rm -rf "$work"
    mkdir -p "$work"
    cmake --install "$build" --prefix "$prefix" >/dev/null
    cp -r "$root/tests/shader_package" "$work/src"
    cmake -S "$work/src" -B "$consumer" -G "Ninja Multi-Config" -DCMAKE_CONFIGURATION_TYPES="Debug;Release;RelWithDebInfo" \
        -DCMAKE_PREFIX_PATH="$prefix" -DTEXFILTER_SHADER_COMPILER=glslc >"$work/configure.log" ||
        { cat "$work/configure.log"; fail "the consumer did not configure"; }
    for config in "${configs[@]}"; do
        cmake --build "$consumer" --config "$config" >"$work/build-$config.log" ||
            { cat "$work/build-$config.log"; fail "the consumer did not build ($config)"; }
    done
    touch "$work/setup.ok"
    echo "shader_package: installed, configured once (Ninja Multi-Config), built ${configs[*]}"
    ;;

compilers)
    need_setup
    grep -q '^TEXFILTER_SHADER_COMPILER:STRING=glslc$' "$consumer/CMakeCache.txt" || fail "the cache option is not glslc"
    for config in "${configs[@]}"; do
        for spv in "$(blur_dir "$config")/a/blur.comp.spv" "$(blur_dir "$config")/b/blur.comp.spv" "$(sky_dir "$config")/sky.frag.spv"; do
            [[ -s $spv ]] || fail "$spv was not built"
            spirv-val --target-env vulkan1.2 "$spv" || fail "spirv-val rejects $spv"
            generator=$(spirv-dis "$spv" | sed -n 's/^; Generator: //p')
            case $spv in
            */sky.frag.spv) want="Google Shaderc over Glslang" ;; # glslc, from TEXFILTER_SHADER_COMPILER
            *) want="Khronos Glslang Reference Front End" ;;      # COMPILER glslangValidator
            esac
            [[ $generator == "$want"* ]] || fail "$spv: generator '$generator', expected '$want'"
        done
    done
    echo "compilers: blur.comp by glslangValidator (COMPILER), sky.frag by glslc (TEXFILTER_SHADER_COMPILER), 3 configs, spirv-val ok"
    ;;

configs)
    need_setup
    for shader in "a/blur.comp" "b/blur.comp" "sky.frag"; do
        case $shader in
        sky.frag) dir=sky_dir ;;
        *) dir=blur_dir ;;
        esac
        debug="$($dir Debug)/$shader.spv" release="$($dir Release)/$shader.spv" plain="$($dir RelWithDebInfo)/$shader.spv"
        lines_debug=$(count_op "$debug" OpLine)
        sources_debug=$(count_op "$debug" OpSource)
        [[ $lines_debug -gt 0 && $sources_debug -gt 0 ]] ||
            fail "$shader Debug: $lines_debug OpLine, $sources_debug OpSource (DEBUG_INFO \$<CONFIG:Debug> gave no -g)"
        for spv in "$plain" "$release"; do
            [[ $(count_op "$spv" OpLine) -eq 0 ]] || fail "$spv has OpLine without DEBUG_INFO"
        done
        n_plain=$(instructions "$plain") n_release=$(instructions "$release") n_debug=$(instructions "$debug")
        [[ $n_release -lt $n_plain ]] ||
            fail "$shader: Release $n_release instructions, RelWithDebInfo $n_plain (OPTIMIZE \$<CONFIG:Release> did not optimise)"
        [[ $(count_op "$release" OpName) -lt $(count_op "$plain" OpName) ]] || fail "$shader: the optimiser kept every OpName"
        echo "configs: $shader: Debug $n_debug instructions ($lines_debug OpLine), RelWithDebInfo $n_plain, Release $n_release"
    done
    ;;

same_name)
    need_setup
    for config in "${configs[@]}"; do
        dir=$(blur_dir "$config")
        [[ -s $dir/a/blur.comp.spv && -s $dir/b/blur.comp.spv ]] || fail "$dir: a/ and b/ modules missing"
        [[ ! -e $dir/blur.comp.spv ]] || fail "$dir/blur.comp.spv: the two blur.comp.glsl share a flat name"
        ! cmp -s "$dir/a/blur.comp.spv" "$dir/b/blur.comp.spv" || fail "$config: a/ and b/ modules are the same file"
        grep -q 'const std::uint32_t a_blur_comp\[\]' "$dir/a/blur_comp.h" || fail "$dir/a/blur_comp.h does not declare a_blur_comp"
        grep -q 'const std::uint32_t b_blur_comp\[\]' "$dir/b/blur_comp.h" || fail "$dir/b/blur_comp.h does not declare b_blur_comp"
    done
    echo "same_name: a/blur.comp.spv, b/blur.comp.spv (different), a/blur_comp.h: a_blur_comp, b/blur_comp.h: b_blur_comp"
    ;;

two_calls)
    need_setup
    targets=$(cmake --build "$consumer" --config Debug -- -t targets all | sed -n 's/^\([A-Za-z0-9_]*texfilter_shaders[A-Za-z0-9_]*\):.*/\1/p' | sort -u)
    [[ $(echo "$targets" | grep -c -x -E 'consumer_texfilter_shaders|consumer_texfilter_shaders_2') -eq 2 ]] ||
        fail "custom targets: $(echo $targets) (expected consumer_texfilter_shaders and consumer_texfilter_shaders_2)"
    for config in "${configs[@]}"; do
        listed=$(sort "$consumer/spirv-$config.txt" | sed '/^$/d')
        expected=$(printf '%s\n' "$(blur_dir "$config")/a/blur.comp.spv" "$(blur_dir "$config")/b/blur.comp.spv" \
            "$(sky_dir "$config")/sky.frag.spv" | sort)
        [[ $listed == "$expected" ]] || fail "TEXFILTER_SPIRV ($config): $listed; expected $expected"
    done
    echo "two_calls: consumer_texfilter_shaders, consumer_texfilter_shaders_2; TEXFILTER_SPIRV lists both calls' 3 modules"
    ;;

embed_alone)
    need_setup
    for config in "${configs[@]}"; do
        # The project's own TU (embed_alone.cpp) built already; the consumer checks magic and difference.
        output=$("$consumer/$config/consumer") || fail "the consumer ($config) failed"
        for shader in "a/blur.comp" "b/blur.comp" "sky.frag"; do
            case $shader in
            sky.frag) dir=$(sky_dir "$config") ;;
            *) dir=$(blur_dir "$config") ;;
            esac
            words=$(( $(stat -c %s "$dir/$shader.spv") / 4 ))
            embedded=$(echo "$output" | sed -n "s|^$shader ||p")
            [[ $embedded == "$words" ]] || fail "$config $shader: $embedded words embedded, the module has $words"
        done
    done
    # Each header alone, strict flags, no project: it must bring <cstdint>.
    for header in "$(blur_dir Release)/a/blur_comp.h" "$(sky_dir Release)/sky_frag.h"; do
        echo "#include \"$header\"" | c++ -std=c++17 -fsyntax-only -Wall -Wextra -Wpedantic -Werror -x c++ - ||
            fail "$header does not compile on its own"
    done
    echo "embed_alone: headers compile alone (c++17, -Wpedantic -Werror); embedded words equal the .spv files in 3 configs"
    ;;

rebuild_on_include)
    need_setup
    tint=$work/src/include/tint.glsl
    sky=$(sky_dir Release)/sky.frag.spv blur=$(blur_dir Release)/a/blur.comp.spv
    before_sky=$(sha1sum <"$sky") before_blur=$(stat -c %y "$blur")
    cp "$tint" "$work/tint.glsl.orig"
    trap 'cp "$work/tint.glsl.orig" "$tint"; cmake --build "$consumer" --config Release >/dev/null' EXIT
    sleep 1 # a coarse-mtime file system must see the edit as newer
    sed -i 's/#define TINT 0.75/#define TINT 0.25/' "$tint"
    log=$(cmake --build "$consumer" --config Release)
    echo "$log" | grep -q 'sky.frag.glsl -> SPIR-V' || fail "editing include/tint.glsl did not rebuild sky.frag.glsl: $log"
    ! echo "$log" | grep -q 'blur.comp.glsl -> SPIR-V' || fail "editing include/tint.glsl rebuilt blur.comp.glsl"
    [[ $(sha1sum <"$sky") != "$before_sky" ]] || fail "sky.frag.spv is unchanged after TINT changed"
    [[ $(stat -c %y "$blur") == "$before_blur" ]] || fail "a/blur.comp.spv was rewritten"
    echo "rebuild_on_include: tint.glsl edited -> sky.frag.spv rebuilt and changed; blur.comp untouched"
    ;;

bad_arguments)
    need_setup
    probe=$work/bad
    rm -rf "$probe"
    mkdir -p "$probe/src"
    echo '#version 450
void main() {}' >"$probe/src/x.frag.glsl"
    expect_error() { # CMAKE_BODY MESSAGE
        printf 'cmake_minimum_required(VERSION 3.22)\nproject(bad NONE)\nfind_package(texfilter REQUIRED)\nadd_custom_target(t)\n%s\n' \
            "$1" >"$probe/src/CMakeLists.txt"
        rm -rf "$probe/build"
        if out=$(cmake -S "$probe/src" -B "$probe/build" -DCMAKE_PREFIX_PATH="$prefix" 2>&1); then
            fail "configure succeeded with: $1"
        fi
        echo "$out" | tr -s '[:space:]' ' ' | grep -q -F "$2" || fail "configure of '$1' failed without saying '$2': $out"
    }
    expect_error 'texfilter_add_shaders(t COMPILER fxc SOURCES x.frag.glsl)' "is 'fxc'; it must be glslangValidator or glslc"
    expect_error 'texfilter_add_shaders(t SOURCES x.frag.glsl)
texfilter_add_shaders(t SOURCES x.frag.glsl)' "x.frag.spv is already written for"
    expect_error 'texfilter_add_shaders(t SOURCES x.frag.glsl x.frag.glsl)' "x.frag.glsl is listed twice"
    expect_error 'texfilter_add_shaders(t SOURCES x.glsl)' "cannot tell the stage of x.glsl"
    echo "bad_arguments: unknown compiler, one module from two calls, a source twice, no stage: each a clear message"
    ;;

installed_docs)
    need_setup
    docs=$prefix/share/doc/texfilter
    [[ -s $docs/docs/API.md ]] || fail "docs/API.md was not installed"
    checked=0 images=0
    while IFS= read -r doc; do
        dir=$(dirname "$doc")
        # Markdown links and pictures ](target) and HTML src="target"; web links and in-page anchors skipped.
        while IFS= read -r target; do
            target=${target%%#*}
            target=${target%% *} # ](file "title")
            [[ -z $target || $target =~ ^[a-z]+: ]] && continue
            checked=$((checked + 1))
            [[ $target == *.png || $target == *.jpg || $target == *.svg ]] && images=$((images + 1))
            [[ -e $dir/$target ]] || fail "${doc#"$prefix"/} links to $target, which is not installed"
        done < <(grep -o -E '\]\([^)]+\)|src="[^"]+"' "$doc" | sed -E 's/^\]\(//; s/\)$//; s/^src="//; s/"$//')
    done < <(find "$docs" -name '*.md')
    [[ $images -gt 0 ]] || fail "no installed doc shows a picture (docs/images/ not installed?)"
    echo "installed_docs: $checked relative links ($images pictures) in $(find "$docs" -name '*.md' | wc -l) installed docs, all resolve"
    ;;

*)
    echo "shader_package.sh: unknown case '$case_name' (--list names them)" >&2
    exit 2
    ;;
esac
