#!/usr/bin/env bash
# Compiles every shaders/texfilter/*.glsl include on its own, the way a user would include it, with
# both glslangValidator and glslc, for #version 450 and 460, in a fragment and a compute shader.
#
# usage: compile_includes.sh GLSLANG GLSLC INCLUDE_DIR
#   INCLUDE_DIR is the `shaders` folder: shaders write #include "texfilter/NAME.glsl".
#
# Each test shader includes exactly one file and calls one of its tf_ functions with a uniform
# sampler2D, so a missing dependency (an include that relies on another being included first) or
# code that only breaks once instantiated is caught. A second shader includes the file twice to check
# its include guard. Prints one line per compile; exits non-zero if any fails.
set -euo pipefail

if [[ $# -ne 3 ]]; then
    echo "usage: $0 GLSLANG GLSLC INCLUDE_DIR" >&2
    exit 2
fi
GLSLANG=$1
GLSLC=$2
INCLUDE_DIR=$3

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

failures=0
compiles=0

# The expression a test shader evaluates for include NAME (file name without .glsl). It may use
# tex (sampler2D), uv, dx, dy (vec2 gradients) and s (tf_Sampler), and must give a vec4.
# A new include needs a case here: the default branch fails so that nobody forgets to add one.
call_for() {
    case "$1" in
    common) echo "tf_fetch(tex, ivec2(uv * 16.0), 0, s.wrap)" ;;
    lod) echo "vec4(tf_lod(tex, dx, dy, s), float(tf_mip_level_nearest(tf_lod(tex, dx, dy, s))), 0.0, 1.0)" ;;
    nearest) echo "tf_nearest_mip(tex, uv, dx, dy, s) + tf_nearest(tex, uv, s)" ;;
    bilinear) echo "tf_bilinear_mip(tex, uv, dx, dy, s) + tf_bilinear(tex, uv, s)" ;;
    trilinear) echo "tf_trilinear(tex, uv, dx, dy, s)" ;;
    derivatives) echo "vec4(tf_ray_differential_gradients(vec3(uv, 1.0), vec3(0.01, 0.0, 0.0), vec3(0.0, 0.01, 0.0), 2.0, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)).dUVdx, dx)" ;;
    brilinear) echo "tf_brilinear(tex, uv, dx, dy, s, 0.25)" ;;
    aniso) echo "tf_aniso(tex, uv, dx, dy, s, 8, TF_ANISO_GPU) + tf_aniso_hw(tex, uv, dx, dy, s, 8, TF_ANISO_FELINE)" ;;
    ewa) echo "tf_ewa(tex, uv, dx, dy, s, 2.0, 16.0) + tf_ewa_hw(tex, uv, dx, dy, s, 2.0, 16.0)" ;;
    sat) echo "tf_sat(satLow, satHigh, uv, dx, dy, s, 1.0) + tf_sat_assembly(satLow, satHigh, uv, dx, dy, s, 1.0, 4)" ;;
    texfilter) echo "tf_trilinear(tex, uv, dx, dy, s) + tf_nearest_mip(tex, uv, dx, dy, s) + tf_ewa(tex, uv, dx, dy, s, 2.0, 16.0) + tf_sat(satLow, satHigh, uv, dx, dy, s, 1.0)" ;;
    *) return 1 ;;
    esac
}

# write_shader VERSION STAGE NAME CALL INCLUDE_COUNT > file
# The sampler is declared after the include on purpose: an include must not depend on anything the
# user declares.
write_shader() {
    local version=$1 stage=$2 name=$3 call=$4 count=$5
    echo "#version $version"
    echo "#extension GL_GOOGLE_include_directive : require"
    for ((i = 0; i < count; ++i)); do
        echo "#include \"texfilter/$name.glsl\""
    done
    echo "layout(set = 0, binding = 0) uniform sampler2D tex;"
    echo "layout(set = 0, binding = 3) uniform usampler2D satLow;  // the SAT's two integer words (sat.glsl)"
    echo "layout(set = 0, binding = 4) uniform usampler2D satHigh;"
    if [[ $stage == frag ]]; then
        cat <<EOF
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;
void main()
{
    vec2 dx = dFdxFine(uv), dy = dFdyFine(uv);
    tf_Sampler s = tf_sampler(TF_WRAP_REPEAT);
    outColor = $call;
}
EOF
    else
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
    tf_Sampler s = tf_sampler(TF_WRAP_CLAMP);
    colors[i] = $call;
}
EOF
    fi
}

# run_compiler TOOL SHADER: one compiler on one shader, SPIR-V next to it.
run_compiler() {
    local tool=$1 shader=$2
    case "$tool" in
    glslangValidator) "$GLSLANG" -V --target-env vulkan1.2 -I"$INCLUDE_DIR" -o "$shader.glslang.spv" "$shader" ;;
    glslc) "$GLSLC" --target-env=vulkan1.2 -I "$INCLUDE_DIR" -Werror -o "$shader.glslc.spv" "$shader" ;;
    esac
}

# compile LABEL SHADER: runs both compilers, one line each; on failure shows the log and the shader.
compile() {
    local label=$1 shader=$2 log="$WORK/log" tool
    for tool in glslangValidator glslc; do
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

# The guard must be named after the file (TF_NAME_GLSL) so two includes never share a guard.
check_guard_name() {
    local file=$1 name=$2 guard
    guard="TF_$(echo "$name" | tr '[:lower:]-' '[:upper:]_')_GLSL"
    if grep -q "^#ifndef $guard\$" "$file" && grep -q "^#define $guard\$" "$file"; then
        printf 'ok    %-17s %s\n' "guard" "$name.glsl ($guard)"
    else
        printf 'FAIL  %-17s %s\n' "guard" "$name.glsl: no '#ifndef $guard' / '#define $guard' pair"
        failures=$((failures + 1))
    fi
}

shopt -s nullglob
includes=("$INCLUDE_DIR"/texfilter/*.glsl)
if [[ ${#includes[@]} -eq 0 ]]; then
    echo "FAIL: no includes found in $INCLUDE_DIR/texfilter" >&2
    exit 1
fi

for file in "${includes[@]}"; do
    name=$(basename "$file" .glsl)
    if ! call=$(call_for "$name"); then
        echo "FAIL  $name.glsl: no test call for this include; add a case to call_for() in $0"
        failures=$((failures + 1))
        continue
    fi
    check_guard_name "$file" "$name"
    for version in 450 460; do
        for stage in frag comp; do
            shader="$WORK/${name}_$version.$stage"
            write_shader "$version" "$stage" "$name" "$call" 1 >"$shader"
            compile "$version $stage $name.glsl" "$shader"
        done
    done
    # Included twice: without a working guard every function is defined twice.
    shader="$WORK/${name}_twice.frag"
    write_shader 450 frag "$name" "$call" 2 >"$shader"
    compile "450 frag $name.glsl included twice" "$shader"
done

echo "$compiles compiles of ${#includes[@]} includes, $failures failure(s)"
[[ $failures -eq 0 ]]
