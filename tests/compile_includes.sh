#!/usr/bin/env bash
# Compiles every shaders/texfilter/*.glsl include on its own, the way a user would include it, with
# both glslangValidator and glslc (target Vulkan 1.2, SPIR-V 1.5), in three stages:
#   fragment               #version 450 and 460 (gradients: dFdxFine)
#   compute                #version 460 (gradients: a buffer; 450 in the TF_COMPUTE_QUADS checks below)
#   ray generation (.rgen) #version 460 only: GL_EXT_ray_tracing requires GLSL 4.60 (both compilers refuse
#                          450: "ray tracing shaders require ... version 460 or above"). Gradients come
#                          from the hit shader's ray differentials through the ray payload; no dFdx.
#
# usage: compile_includes.sh GLSLANG GLSLC INCLUDE_DIR [NAME]
#   INCLUDE_DIR is the `shaders` folder: shaders write #include "texfilter/NAME.glsl".
#   NAME: only that include's checks (file name without .glsl), or `options` (the TF_COMPUTE_QUADS and
#   overridden-define shaders); without it, everything. ctest runs one entry per NAME (compile_includes.NAME).
#
# Each test shader includes exactly one file and calls its tf_ functions with a uniform sampler2D (and
# the SAT's two usampler2D), so a missing dependency (an include that relies on another being included
# first) or code that only breaks once instantiated is caught. Everything the shader declares comes
# after the include: an include must not depend on anything the user declares. Further shaders:
#   - each include twice (450 fragment; glslangValidator only: a guard is preprocessing, which both compilers
#     share through glslang): its include guard;
#   - derivatives.glsl with TF_COMPUTE_QUADS and GL_KHR_shader_subgroup_quad (compute, 450 and 460);
#   - texfilter.glsl with every overridable define set before including (TF_COUNT_FETCHES,
#     TF_COUNT_HW_LOOKUPS, TF_EWA_MAX_TEXELS, TF_ANISO_RATIO_SLACK, TF_MAGNIFY; TF_COMPUTE_QUADS in compute), 460,
#     all three stages.
# Each public include's layout is checked too (check_layout): its guard, line 1, relative includes, and its
# header block as a contract (check_header_contract: the labels Use, Options, Needs, Cost, Degenerate input,
# Example in that order, no dates, dB, issue numbers or driver names).
# Prints one line per compile; exits non-zero if any fails.
set -euo pipefail

if [[ $# -ne 3 && $# -ne 4 ]]; then
    echo "usage: $0 GLSLANG GLSLC INCLUDE_DIR [NAME]" >&2
    exit 2
fi
GLSLANG=$1
GLSLC=$2
INCLUDE_DIR=$3
ONLY=${4:-}

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

failures=0
compiles=0

# The expression a test shader evaluates for include NAME (file name without .glsl) in STAGE (frag,
# comp, rgen). It may use tex (sampler2D), satLow, satHigh (usampler2D), uv, dx, dy (vec2 gradients,
# provided by the stage's template) and s (tf_Sampler; declared only where common.glsl was included), and
# must give a vec4. It must not call dFdx & co. itself: compute and ray-tracing stages have none.
# A new include needs a case here: the default branch fails so that nobody forgets to add one.
call_for() {
    local name=$1 stage=$2
    case "$name" in
    version) echo "vec4(float(TF_VERSION_MAJOR), float(TF_VERSION_MINOR), float(TF_VERSION_PATCH), float(TF_VERSION))" ;;
    common) echo "tf_fetch(tex, ivec2(uv * 16.0), 0, s.wrap)" ;;
    lod) echo "vec4(tf_lod(tex, dx, dy, s), float(tf_mip_level_nearest(tf_lod(tex, dx, dy, s))), 0.0, 1.0)" ;;
    nearest) echo "tf_nearest_mip(tex, uv, dx, dy, s) + tf_nearest(tex, uv, s)" ;;
    bilinear) echo "tf_bilinear_mip(tex, uv, dx, dy, s) + tf_bilinear(tex, uv, s) + tf_bilinear_level(tex, uv, 1, s.wrap)" ;;
    trilinear) echo "tf_trilinear(tex, uv, dx, dy, s)" ;;
    bicubic) echo "tf_bspline(tex, uv, s) + tf_catmull_rom(tex, uv, s) + tf_bspline_hw(tex, uv, s) + tf_catmull_rom_hw(tex, uv, s) + tf_cubic_level(tex, uv, 1, s.wrap, TF_RECONSTRUCT_BSPLINE) + tf_cubic_level_hw(tex, uv, 0, s.wrap, TF_RECONSTRUCT_CATMULL_ROM)" ;;
    derivatives)
        local rd="tf_ray_differential_gradients(vec3(uv, 1.0), vec3(0.01, 0.0, 0.0), vec3(0.0, 0.01, 0.0), 2.0, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0))"
        if [[ $stage == frag ]]; then # the quad macros exist only where dFdx does
            echo "vec4($rd.dUVdx, dx) + vec4(tf_quad_gradients_fine(uv).dUVdx, tf_quad_gradients_coarse(uv).dUVdy)"
        else
            echo "vec4($rd.dUVdx, dx)"
        fi
        ;;
    brilinear) echo "tf_brilinear(tex, uv, dx, dy, s, 0.25)" ;;
    aniso) echo "tf_aniso(tex, uv, dx, dy, s, 8, TF_ANISO_GPU) + tf_aniso_hw(tex, uv, dx, dy, s, 8, TF_ANISO_FELINE)" ;;
    ewa) echo "tf_ewa(tex, uv, dx, dy, s, 2.0, 16.0) + tf_ewa_hw(tex, uv, dx, dy, s, 2.0, 16.0)" ;;
    ewa_fast) echo "tf_ewa_fast(tex, uv, dx, dy, s)" ;;
    sat) echo "tf_sat(satLow, satHigh, uv, dx, dy, s, vec4(0.0), vec4(1.0)) + tf_sat_assembly(satLow, satHigh, uv, dx, dy, s, vec4(0.0), vec4(1.0), 4)" ;;
    debug) echo "vec4(tf_debug_lod_color(tf_debug_footprint(uv, dx, dy, vec2(textureSize(tex, 0)), textureQueryLevels(tex), s, TF_DEBUG_ANISO, 16, TF_ANISO_GPU, 16.0).lod) + tf_debug_anisotropy_color(tf_debug_anisotropy(dx, dy, vec2(64.0))) + tf_debug_heat(uv.x, 8.0), 1.0) + vec4(tf_debug_aniso_probe(uv, dx, dy, vec2(64.0), 8, TF_ANISO_FELINE, tf_debug_aniso_probe_count(dx, dy, vec2(64.0), 8, TF_ANISO_FELINE) - 1), 0.0, 0.0)" ;;
    cube) echo "tf_trilinear_cube(cube, vec3(uv, 1.0), vec3(dx, 0.0), vec3(dy, 0.0), s) + tf_aniso_cube(cube, vec3(uv, -1.0), vec3(dx, 0.0), vec3(dy, 0.0), s, 8, TF_ANISO_GPU) + tf_ewa_cube_hw(cube, vec3(1.0, uv), vec3(0.0, dx), vec3(0.0, dy), s, 2.0, 16.0) + tf_nearest_cube(cube, vec3(uv, 0.5), s) + tf_nearest_mip_cube(cube, vec3(0.5, uv), vec3(dx, 0.0), vec3(dy, 0.0), s) + tf_bilinear_mip_cube(cube, vec3(uv.x, 1.0, uv.y), vec3(dx, 0.0), vec3(dy, 0.0), s)" ;;
    latlong) echo "tf_trilinear_latlong(tex, vec3(uv, 1.0), vec3(dx, 0.0), vec3(dy, 0.0), s) + tf_ewa_latlong(tex, vec3(uv, -1.0), vec3(dx, 0.0), vec3(dy, 0.0), s, 2.0, 16.0) + tf_aniso_latlong_hw(tex, vec3(1.0, uv), vec3(0.0, dx), vec3(0.0, dy), s, 8, TF_ANISO_FELINE) + tf_bilinear_latlong(tex, vec3(uv, 0.5), s)" ;;
    encode) echo "vec4(float(tf_mip_srgb8(uv.x)), float(tf_mip_unorm8(uv.y)), float(tf_mip_half(dx.x)), 0.0)" ;;
    texfilter) echo "tf_trilinear(tex, uv, dx, dy, s) + tf_catmull_rom(tex, uv, s) + tf_nearest_mip(tex, uv, dx, dy, s) + tf_brilinear(tex, uv, dx, dy, s, 0.25) + tf_aniso(tex, uv, dx, dy, s, 16, TF_ANISO_GPU) + tf_ewa(tex, uv, dx, dy, s, 2.0, 16.0) + tf_sat(satLow, satHigh, uv, dx, dy, s, vec4(0.0), vec4(1.0)) + vec4(tf_ray_differential_gradients(vec3(uv, 1.0), vec3(0.01, 0.0, 0.0), vec3(0.0, 0.01, 0.0), 2.0, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)).dUVdy, 0.0, 0.0) + tf_ewa_cube(cube, vec3(uv, 1.0), vec3(dx, 0.0), vec3(dy, 0.0), s, 2.0, 16.0) + tf_trilinear_latlong(tex, vec3(uv, 1.0), vec3(dx, 0.0), vec3(dy, 0.0), s)" ;;
    stochastic) echo "tf_bilinear_stochastic(tex, uv, s, vec3(uv, 0.5)) + tf_bilinear_stochastic_level(tex, uv, 1, s.wrap, vec3(0.25)) + tf_trilinear_stochastic(tex, uv, dx, dy, s, vec3(uv, 0.5)) + tf_aniso_stochastic(tex, uv, dx, dy, s, 8, TF_ANISO_FELINE, vec3(0.5)) + tf_ewa_stochastic(tex, uv, dx, dy, s, 2.0, 16.0, vec3(uv, 0.5)) + tf_bilinear_stochastic_hw(tex, uv, s, vec3(0.0)) + tf_trilinear_stochastic_hw(tex, uv, dx, dy, s, vec3(0.5)) + tf_aniso_stochastic_hw(tex, uv, dx, dy, s, 8, TF_ANISO_GPU, vec3(0.5)) + tf_ewa_stochastic_hw(tex, uv, dx, dy, s, 2.0, 16.0, vec3(uv, 0.5))" ;;
    *) return 1 ;;
    esac
}

# write_shader VERSION STAGE NAME CALL INCLUDE_COUNT [PRELUDE] > file
# PRELUDE: lines placed before the include (defines a user may set, extensions). The sampler, textures
# and buffers are declared after the include on purpose: an include must not depend on anything the
# user declares. `s` is declared only where common.glsl was pulled in (version.glsl alone has no
# tf_Sampler); every other include's call uses `s`, so one that lost common.glsl still fails.
write_shader() {
    local version=$1 stage=$2 name=$3 call=$4 count=$5 prelude=${6:-}
    echo "#version $version"
    echo "#extension GL_GOOGLE_include_directive : require"
    if [[ $stage == rgen ]]; then
        echo "#extension GL_EXT_ray_tracing : require"
    fi
    if [[ -n $prelude ]]; then
        echo "$prelude"
    fi
    for ((i = 0; i < count; ++i)); do
        echo "#include \"texfilter/$name.glsl\""
    done
    echo "layout(set = 0, binding = 0) uniform sampler2D tex;"
    echo "layout(set = 0, binding = 3) uniform usampler2D satLow;  // the SAT's two integer words (sat.glsl)"
    echo "layout(set = 0, binding = 4) uniform usampler2D satHigh;"
    echo "layout(set = 0, binding = 5) uniform samplerCube cube;    // cube.glsl"
    case "$stage" in
    frag)
        cat <<EOF
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;
void main()
{
    vec2 dx = dFdxFine(uv), dy = dFdyFine(uv);
#ifdef TF_COMMON_GLSL
    tf_Sampler s = tf_sampler(TF_WRAP_REPEAT);
#endif
    outColor = $call;
}
EOF
        ;;
    comp)
        # Compute shaders have no derivatives: the gradients come from a buffer, as in `texfilter sample`.
        cat <<EOF
layout(local_size_x = 64) in;
struct Lookup { vec2 uv, dUVdx, dUVdy; };
layout(set = 0, binding = 1, std430) readonly buffer Lookups { Lookup lookups[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Colors { vec4 colors[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    vec2 uv = lookups[i].uv, dx = lookups[i].dUVdx, dy = lookups[i].dUVdy;
#ifdef TF_COMMON_GLSL
    tf_Sampler s = tf_sampler(TF_WRAP_CLAMP);
#endif
    colors[i] = $call;
}
EOF
        ;;
    rgen)
        # Ray generation: no quads, no dFdx. The closest-hit shader (not compiled here) returns the hit's
        # uv and its gradients from ray differentials (tf_ray_differential_gradients) in the payload.
        cat <<EOF
layout(set = 0, binding = 1) uniform accelerationStructureEXT topLevel;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D colors;
struct Hit { vec2 uv, dUVdx, dUVdy; };
layout(location = 0) rayPayloadEXT Hit hit;
void main()
{
    ivec2 pixel = ivec2(gl_LaunchIDEXT.xy);
    vec2 ndc = 2.0 * (vec2(pixel) + 0.5) / vec2(gl_LaunchSizeEXT.xy) - 1.0;
    traceRayEXT(topLevel, gl_RayFlagsOpaqueEXT, 0xFF, 0, 0, 0, vec3(0.0), 0.0, normalize(vec3(ndc, 1.0)), 1e30, 0);
    vec2 uv = hit.uv, dx = hit.dUVdx, dy = hit.dUVdy;
#ifdef TF_COMMON_GLSL
    tf_Sampler s = tf_sampler(TF_WRAP_MIRROR);
#endif
    imageStore(colors, pixel, $call);
}
EOF
        ;;
    esac
}

# run_compiler TOOL SHADER: one compiler on one shader, SPIR-V next to it.
run_compiler() {
    local tool=$1 shader=$2
    case "$tool" in
    glslangValidator) "$GLSLANG" -V --target-env vulkan1.2 -I"$INCLUDE_DIR" -o "$shader.glslang.spv" "$shader" ;;
    glslc) "$GLSLC" --target-env=vulkan1.2 -I "$INCLUDE_DIR" -Werror -o "$shader.glslc.spv" "$shader" ;;
    esac
}

# compile LABEL SHADER [TOOLS]: runs the compilers (both unless TOOLS names some), one line each; on
# failure shows the log and the shader.
compile() {
    local label=$1 shader=$2 tools=${3:-glslangValidator glslc} log="$WORK/log" tool
    for tool in $tools; do
        compiles=$((compiles + 1))
        if run_compiler "$tool" "$shader" >"$log" 2>&1; then
            printf 'ok    %-17s %s\n' "$tool" "$label"
        else
            printf 'FAIL  %-17s %s\n' "$tool" "$label"
            sed 's/^/      /' "$log"
            sed 's/^/      | /' "$shader"
            failures=$((failures + 1))
        fi
    done
}

# The guard must be named after the file (TF_NAME_GLSL) so two includes never share a guard; the file
# opens with its header comment ("// texfilter/NAME.glsl — ..."); dependencies are included by a path
# relative to the including file ("common.glsl"), which every compiler resolves whatever -I says.
check_layout() {
    local file=$1 name=$2 guard
    guard="TF_$(echo "$name" | tr '[:lower:]-' '[:upper:]_')_GLSL"
    if grep -q "^#ifndef $guard\$" "$file" && grep -q "^#define $guard\$" "$file"; then
        printf 'ok    %-17s %s\n' "guard" "$name.glsl ($guard)"
    else
        printf 'FAIL  %-17s %s\n' "guard" "$name.glsl: no '#ifndef $guard' / '#define $guard' pair"
        failures=$((failures + 1))
    fi
    if head -n 1 "$file" | grep -q "^// texfilter/$name.glsl "; then
        printf 'ok    %-17s %s\n' "header" "$name.glsl"
    else
        printf 'FAIL  %-17s %s\n' "header" "$name.glsl: line 1 is not '// texfilter/$name.glsl — what it does'"
        failures=$((failures + 1))
    fi
    check_header_contract "$file" "$name"
    if grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]\(texfilter/\|\.\./\|/\)' "$file"; then
        printf 'FAIL  %-17s %s\n' "relative" "$name.glsl: include dependencies by bare name (\"common.glsl\")"
        failures=$((failures + 1))
    else
        printf 'ok    %-17s %s\n' "relative" "$name.glsl"
    fi
}

# The header block (the leading `//` lines) is the include's contract: the labels below, in this order, each
# opening a line ("// Use:"; a file without such a concern writes "none" after the label), and no lab notes
# (dates, dB, issue numbers, driver or GPU names, error figures), which belong in docs/DESIGN.md.
header_labels=("Use:" "Options:" "Needs:" "Cost:" "Degenerate input:" "Example:")
header_banned='20[0-9][0-9]-[0-9][0-9]|\<dB\>|[Ii]ssue [0-9]+|lavapipe|llvmpipe|Mesa|NVIDIA|H100|H200|RMSE|PSNR'
check_header_contract() {
    local file=$1 name=$2 header label line previous=0 problems=()
    header=$(awk '/^\/\// { print; next } { exit }' "$file")
    for label in "${header_labels[@]}"; do
        line=$(grep -n -m 1 "^// $label" <<<"$header" | cut -d: -f1 || true)
        if [[ -z $line ]]; then
            problems+=("no '// $label' line")
        elif ((line < previous)); then
            problems+=("'$label' comes before the label it should follow")
        else
            previous=$line
        fi
    done
    local banned
    banned=$(grep -n -o -E "$header_banned" <<<"$header" | tr '\n' ' ' || true)
    if [[ -n $banned ]]; then
        problems+=("lab notes in the header (docs/DESIGN.md holds them): $banned")
    fi
    if ((${#problems[@]} == 0)); then
        printf 'ok    %-17s %s\n' "contract" "$name.glsl header: ${header_labels[*]}"
    else
        local problem
        for problem in "${problems[@]}"; do
            printf 'FAIL  %-17s %s\n' "contract" "$name.glsl header: $problem"
        done
        failures=$((failures + 1))
    fi
}

# check VERSION STAGE NAME CALL COUNT PRELUDE LABEL [TOOLS]: writes one shader and compiles it (both tools
# unless TOOLS names some).
check() {
    local version=$1 stage=$2 name=$3 call=$4 count=$5 prelude=$6 label=$7 tools=${8:-}
    local shader="$WORK/${name}_${version}_${count}_${compiles}.$stage"
    write_shader "$version" "$stage" "$name" "$call" "$count" "$prelude" >"$shader"
    compile "$version $stage $label" "$shader" $tools
}

shopt -s nullglob
includes=("$INCLUDE_DIR"/texfilter/*.glsl)
internal_includes=("$INCLUDE_DIR"/texfilter/detail/*.glsl)
if [[ ${#includes[@]} -eq 0 || ${#internal_includes[@]} -eq 0 ]]; then
    echo "FAIL: no includes found in $INCLUDE_DIR/texfilter or its detail/" >&2
    exit 1
fi
if [[ $ONLY == detail ]]; then
    includes=("${internal_includes[@]}")
elif [[ -z $ONLY ]]; then
    includes+=("${internal_includes[@]}")
elif [[ $ONLY != options ]]; then
    if [[ ! -f $INCLUDE_DIR/texfilter/$ONLY.glsl ]]; then
        echo "FAIL: no include $INCLUDE_DIR/texfilter/$ONLY.glsl" >&2
        exit 1
    fi
    includes=("$INCLUDE_DIR/texfilter/$ONLY.glsl")
elif [[ $ONLY == options ]]; then
    includes=()
fi

# The internal files (texfilter/detail/: the access layer and each family's per-kind part, re-included once per
# resource kind, so no guard; compile_includes.detail) are not for users: each must open with its header
# comment, say "internal", and refuse to compile when included on its own (outside a family's instantiation).
check_internal() {
    local file=$1 name=detail/$2 shader="$WORK/internal_$2.frag"
    if head -1 "$file" | grep -q "^// texfilter/$name.glsl — internal"; then
        printf 'ok    %-17s %s\n' "header" "$name.glsl (internal)"
    else
        printf 'FAIL  %-17s %s\n' "header" "$name.glsl: line 1 is not '// texfilter/$name.glsl — internal: ...'"
        failures=$((failures + 1))
    fi
    printf '#version 450\n#extension GL_GOOGLE_include_directive : require\n#include "texfilter/%s.glsl"\nvoid main() {}\n' \
        "$name" >"$shader"
    if "$GLSLANG" -V -I"$INCLUDE_DIR" "$shader" -o "$WORK/internal.spv" >/dev/null 2>&1; then
        printf 'FAIL  %-17s %s\n' "alone" "$name.glsl compiled on its own; it must refuse outside an instantiation"
        failures=$((failures + 1))
    else
        printf 'ok    %-17s %s\n' "alone" "$name.glsl refuses to compile on its own"
    fi
}

# The GPU builders (build_mip, build_sat) are compute-only and read and write through macros the user
# defines before including them: each is compiled in a compute shader of its own, as docs/API.md shows,
# at 450 and 460, and included twice; on its own (no macros) it must refuse with its #error.
builder_files=(build_mip build_sat)
builder_prelude() {
    case "$1" in
    build_mip) cat <<'EOF2'
layout(set = 0, binding = 0, rgba16f) uniform coherent image2D chain[15];
layout(set = 0, binding = 1, std430) coherent buffer Counter { uint groupsDone; };
#define TF_MIP_LOAD(level, p) imageLoad(chain[level], p)
#define TF_MIP_STORE(level, p, v) imageStore(chain[level], p, v)
#define TF_MIP_COUNTER groupsDone
EOF2
        ;;
    build_sat) cat <<'EOF2'
layout(set = 0, binding = 0) uniform sampler2D level0;
layout(set = 0, binding = 1, rgba32ui) uniform uimage2D satLow;
layout(set = 0, binding = 2, r32ui) uniform writeonly uimage2D satHigh;
layout(set = 0, binding = 3, std430) buffer Range { uint words[9]; } range;
#define TF_SAT_LOAD(p) texelFetch(level0, p, 0)
#define TF_SAT_LOAD_LOW(e) imageLoad(satLow, e)
#define TF_SAT_STORE_LOW(e, v) imageStore(satLow, e, v)
#define TF_SAT_STORE_HIGH(e, v) imageStore(satHigh, e, uvec4(v))
#define TF_SAT_RANGE range.words
EOF2
        ;;
    esac
}
builder_main() {
    case "$1" in
    build_mip) echo "layout(local_size_x = TF_MIP_GROUP_SIZE) in; void main() { tf_build_mip_pass(0, 6, true, ivec2(256)); }" ;;
    build_sat) echo "layout(local_size_x = TF_SAT_GROUP_SIZE) in; void main() { tf_sat_range_pass(ivec2(64)); tf_sat_rows_pass(ivec2(64)); tf_sat_columns_pass(ivec2(64)); }" ;;
    esac
}
check_builder() {
    local file=$1 name=$2 version count shader
    check_layout "$file" "$name"
    for version in 450 460; do
        for count in 1 2; do
            shader="$WORK/builder_${name}_${version}_${count}.comp"
            {
                echo "#version $version"
                echo "#extension GL_GOOGLE_include_directive : require"
                builder_prelude "$name"
                for ((i = 0; i < count; ++i)); do echo "#include \"texfilter/$name.glsl\""; done
                builder_main "$name"
            } >"$shader"
            if [[ $count == 2 ]]; then
                compile "$version comp $name.glsl included twice" "$shader" glslangValidator
            else
                compile "$version comp $name.glsl" "$shader"
            fi
        done
    done
    shader="$WORK/builder_${name}_alone.comp"
    printf '#version 450\n#extension GL_GOOGLE_include_directive : require\n#include "texfilter/%s.glsl"\nvoid main() {}\n' \
        "$name" >"$shader"
    local out
    out=$("$GLSLANG" -V -S comp -I"$INCLUDE_DIR" "$shader" -o "$WORK/alone.spv" 2>&1 || true)
    if [[ ! -e $WORK/alone.spv && $out == *"define TF_"* ]]; then
        printf 'ok    %-17s %s\n' "alone" "$name.glsl without its macros says which to define"
    else
        printf 'FAIL  %-17s %s\n' "alone" "$name.glsl compiled, or failed without naming its macros, on its own"
        failures=$((failures + 1))
    fi
}

for file in "${includes[@]}"; do
    name=$(basename "$file" .glsl)
    if [[ $file == */texfilter/detail/* ]]; then
        check_internal "$file" "$name"
        continue
    fi
    if [[ " ${builder_files[*]} " == *" $name "* ]]; then
        check_builder "$file" "$name"
        continue
    fi
    if ! call_for "$name" frag >/dev/null; then
        echo "FAIL  $name.glsl: no test call for this include; add a case to call_for() in $0"
        failures=$((failures + 1))
        continue
    fi
    check_layout "$file" "$name"
    for stage in frag comp rgen; do
        call=$(call_for "$name" "$stage")
        if [[ $call == *dFd* || $call == *fwidth* ]]; then
            echo "FAIL  $name.glsl: the $stage call uses implicit derivatives; take dx, dy from the template"
            failures=$((failures + 1))
            continue
        fi
        for version in 450 460; do
            if [[ $stage == rgen && $version == 450 ]]; then
                continue # GL_EXT_ray_tracing needs #version 460 (see the header)
            fi
            if [[ $stage == comp && $version == 450 ]]; then
                continue # both versions are compiled in frag, and compute at 450 in the TF_COMPUTE_QUADS checks
            fi
            check "$version" "$stage" "$name" "$call" 1 "" "$name.glsl"
        done
    done
    # Included twice: without a working guard every function is defined twice.
    check 450 frag "$name" "$(call_for "$name" frag)" 2 "" "$name.glsl included twice" glslangValidator
done

if [[ -n $ONLY && $ONLY != options ]]; then
    echo "$compiles compiles of $ONLY.glsl, $failures failure(s)"
    [[ $failures -eq 0 ]]
    exit
fi

# derivatives.glsl's compute quads: opt-in with TF_COMPUTE_QUADS and the subgroup quad extension.
quads="#extension GL_KHR_shader_subgroup_quad : require
#define TF_COMPUTE_QUADS"
quadCall="vec4(tf_compute_quad_gradients(uv, TF_DERIVATIVES_FINE).dUVdx, tf_compute_quad_gradients(uv, TF_DERIVATIVES_COARSE).dUVdy) + vec4(vec2(tf_quad_pixel(ivec2(0), 8)), dx)"
for version in 450 460; do
    check "$version" comp derivatives "$quadCall" 1 "$quads" "derivatives.glsl with TF_COMPUTE_QUADS"
done

# Every define a user may override, set before the umbrella include (the counters are the user's own).
options="uint fetchCount = 0u, hwLookupCount = 0u;
#define TF_COUNT_FETCHES(n) fetchCount += uint(n)
#define TF_COUNT_HW_LOOKUPS(n) hwLookupCount += uint(n)
#define TF_EWA_MAX_TEXELS 15
#define TF_ANISO_RATIO_SLACK (1.0 / 16.0)
#define TF_MAGNIFY TF_RECONSTRUCT_CATMULL_ROM"
optionsCall="$(call_for texfilter comp) + tf_ewa_hw(tex, uv, dx, dy, s, 2.0, 16.0) + tf_aniso_hw(tex, uv, dx, dy, s, 4, TF_ANISO_GPU) + vec4(float(fetchCount), float(hwLookupCount), 0.0, 0.0)"
check 460 frag texfilter "$optionsCall" 1 "$options" "texfilter.glsl with every option overridden"
check 460 comp texfilter "$optionsCall + vec4(tf_compute_quad_gradients(uv, TF_DERIVATIVES_FINE).dUVdx, 0.0, 0.0)" 1 \
    "$quads
$options" "texfilter.glsl with every option overridden and TF_COMPUTE_QUADS"
check 460 rgen texfilter "$optionsCall" 1 "$options" "texfilter.glsl with every option overridden"

if [[ -n $ONLY ]]; then
    echo "$compiles compiles (options), $failures failure(s)"
else
    echo "$compiles compiles of ${#includes[@]} includes, $failures failure(s)"
fi
[[ $failures -eq 0 ]]
