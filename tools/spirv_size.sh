#!/usr/bin/env bash
# SPIR-V code size of each public filter function: it must not grow.
#
# One small compute shader per function (sampler2D kind, the form users call today), compiled with
# `glslc -O --target-env=vulkan1.2`, disassembled with spirv-dis. The count:
#   instructions = the lines of spirv-dis output from each OpFunction to its OpFunctionEnd, both
#                  included, summed over the module's functions (after -O everything is inlined into
#                  main, so this is main's body: OpLabel, OpVariable, OpPhi, OpBranch... each count 1).
#                  Declarations (types, constants, decorations, debug names) are not counted.
#   net          = instructions minus those of the same shader with the call replaced by a plain
#                  vec4 of its inputs (the template's own loads and store): the function's share.
# Two calls a function (both counted, both checked):
#   run-time  every argument that is not a texture or a coordinate comes from a push constant (wrap,
#             LOD bias/range, probe count, shape, alpha, band, boxes, SAT offset/scale): no branch is
#             folded away, so this is the whole function, as a caller with run-time choices gets it;
#   constant  the typical call: tf_sampler(TF_WRAP_REPEAT) and literal options (16 probes, TF_ANISO_GPU,
#             alpha 2, maxAniso 16, band 0.25, 4 boxes, SAT offset 0 / scale 1): what is left after folding.
#
# usage: spirv_size.sh GLSLC SPIRV_DIS INCLUDE_DIR                      # prints the table
#        spirv_size.sh GLSLC SPIRV_DIS INCLUDE_DIR --write BASELINE     # writes the baseline (TSV)
#        spirv_size.sh GLSLC SPIRV_DIS INCLUDE_DIR --check FUNCTION BASELINE
#                     # exit 1 when FUNCTION's count is above its baseline row (the ctest entry)
#        spirv_size.sh --list                                           # the function names
# INCLUDE_DIR is the `shaders` folder (shaders write #include "texfilter/NAME.glsl").
set -euo pipefail

FUNCTIONS=(tf_nearest tf_bilinear tf_nearest_mip tf_bilinear_mip tf_trilinear tf_brilinear tf_aniso
    tf_aniso_hw tf_ewa tf_ewa_hw tf_ewa_fast tf_sat tf_sat_assembly)

if [[ ${1:-} == --list ]]; then
    printf '%s\n' "${FUNCTIONS[@]}"
    exit 0
fi
if [[ $# -lt 3 ]]; then
    echo "usage: $0 GLSLC SPIRV_DIS INCLUDE_DIR [--write BASELINE | --check FUNCTION BASELINE]" >&2
    exit 2
fi
GLSLC=$1
SPIRV_DIS=$2
INCLUDE_DIR=$3
shift 3

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# call_for FUNCTION VARIANT: the call; tex (sampler2D), satLow/satHigh (usampler2D), uv, dx, dy, s and
# pc.* are in scope. VARIANT runtime reads the options from pc, constant passes literals.
call_for() {
    local band=pc.band probes=pc.maxProbes shape=pc.shape alpha=pc.alpha maxAniso=pc.maxAniso
    local offset=pc.offset scale=pc.scale boxes=pc.boxes
    if [[ ${2:-runtime} == constant ]]; then
        band=0.25 probes=16 shape=TF_ANISO_GPU alpha=2.0 maxAniso=16.0 offset="vec4(0.0)" scale="vec4(1.0)" boxes=4
    fi
    case "$1" in
    tf_nearest | tf_bilinear) echo "$1(tex, uv, s)" ;;
    tf_nearest_mip | tf_bilinear_mip | tf_trilinear | tf_ewa_fast) echo "$1(tex, uv, dx, dy, s)" ;;
    tf_brilinear) echo "tf_brilinear(tex, uv, dx, dy, s, $band)" ;;
    tf_aniso | tf_aniso_hw) echo "$1(tex, uv, dx, dy, s, $probes, $shape)" ;;
    tf_ewa | tf_ewa_hw) echo "$1(tex, uv, dx, dy, s, $alpha, $maxAniso)" ;;
    tf_sat) echo "tf_sat(satLow, satHigh, uv, dx, dy, s, $offset, $scale)" ;;
    tf_sat_assembly) echo "tf_sat_assembly(satLow, satHigh, uv, dx, dy, s, $offset, $scale, $boxes)" ;;
    empty) echo "vec4(uv + dx, dy)" ;;
    *) return 1 ;;
    esac
}

# The sampler of VARIANT.
sampler_for() {
    if [[ $1 == constant ]]; then
        echo "tf_sampler(TF_WRAP_REPEAT)"
    else
        echo "tf_Sampler(pc.wrap, pc.lodBias, pc.lodMin, pc.lodMax)"
    fi
}

# write_shader CALL SAMPLER
write_shader() {
    cat <<EOF
#version 460
#extension GL_GOOGLE_include_directive : require
#include "texfilter/texfilter.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D tex;
layout(set = 0, binding = 3) uniform usampler2D satLow;
layout(set = 0, binding = 4) uniform usampler2D satHigh;
struct Lookup { vec2 uv, dUVdx, dUVdy; };
layout(set = 0, binding = 1, std430) readonly buffer Lookups { Lookup lookups[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Colors { vec4 colors[]; };
layout(push_constant) uniform Options {
    vec4 offset, scale;
    int wrap; float lodBias, lodMin, lodMax;
    int maxProbes, shape, boxes; float alpha, maxAniso, band;
} pc;
void main()
{
    uint i = gl_GlobalInvocationID.x;
    vec2 uv = lookups[i].uv, dx = lookups[i].dUVdx, dy = lookups[i].dUVdy;
    tf_Sampler s = $2;
    colors[i] = $1;
}
EOF
}

# count FUNCTION VARIANT: prints the instruction count of its shader (see the header).
count() {
    local shader="$WORK/$1.$2.comp"
    write_shader "$(call_for "$1" "$2")" "$(sampler_for "$2")" >"$shader"
    if ! "$GLSLC" -O --target-env=vulkan1.2 -I "$INCLUDE_DIR" -o "$shader.spv" "$shader" 2>"$WORK/log"; then
        echo "FAIL: glslc -O could not compile the $1 shader ($2 options):" >&2
        sed 's/^/      /' "$WORK/log" >&2
        return 1
    fi
    "$SPIRV_DIS" --no-color --no-header "$shader.spv" |
        awk '/ OpFunction / || /^ *OpFunction / { inside = 1 } inside { n++ } /OpFunctionEnd/ { inside = 0 } END { print n + 0 }'
}

glslc_version() { "$GLSLC" --version | head -n 3 | paste -sd, - | sed "s/,/, /g"; }

mode=${1:-table}
case "$mode" in
table | --write)
    empty=$(count empty runtime)
    rows=()
    for f in "${FUNCTIONS[@]}"; do
        n=$(count "$f" runtime)
        c=$(count "$f" constant)
        rows+=("$f"$'\t'"$n"$'\t'"$((n - empty))"$'\t'"$c")
    done
    if [[ $mode == --write ]]; then
        [[ $# -eq 2 ]] || { echo "usage: $0 ... --write BASELINE" >&2; exit 2; }
        {
            echo "# SPIR-V instructions per public filter function (tools/spirv_size.sh: glslc -O, function bodies)."
            echo "# recorded $(date -u +%Y-%m-%d) with $(glslc_version), $("$SPIRV_DIS" --version | head -n 1)"
            echo "# empty template: $empty instructions"
            printf 'function\tinstructions\tnet\tconstant\tglslc\n'
            for row in "${rows[@]}"; do printf '%s\t%s\n' "$row" "$(glslc_version)"; done
        } >"$2"
        echo "wrote $2"
    fi
    printf '%-18s %12s %6s %9s\n' function instructions net constant
    for row in "${rows[@]}"; do
        IFS=$'\t' read -r f n net c <<<"$row"
        printf '%-18s %12s %6s %9s\n' "$f" "$n" "$net" "$c"
    done
    echo "(glslc -O, $(glslc_version); run-time options; net = instructions - $empty of the empty template;"
    echo " constant = instructions of the call with constant options, tf_sampler(TF_WRAP_REPEAT))"
    ;;
--check)
    [[ $# -eq 3 ]] || { echo "usage: $0 ... --check FUNCTION BASELINE" >&2; exit 2; }
    f=$2 baseline=$3
    call_for "$f" >/dev/null || { echo "FAIL: unknown function '$f' (see --list)" >&2; exit 2; }
    row=$(awk -F'\t' -v f="$f" '$1 == f { print; exit }' "$baseline")
    if [[ -z $row ]]; then
        echo "FAIL: $f has no row in $baseline; run $0 GLSLC SPIRV_DIS INCLUDE_DIR --write $baseline"
        exit 1
    fi
    IFS=$'\t' read -r _ limit _ limitConstant version <<<"$row"
    n=$(count "$f" runtime)
    c=$(count "$f" constant)
    echo "$f: $n SPIR-V instructions with run-time options (baseline $limit), $c with constant options (baseline $limitConstant)"
    if [[ $version != "$(glslc_version)" ]]; then
        echo "note: the baseline was recorded with $version, this is $(glslc_version): a change may be the compiler's"
    fi
    status=0
    if ((n > limit)); then
        echo "FAIL: $f (run-time options) grew by $((n - limit)) instructions over its baseline ($baseline)"
        status=1
    fi
    if ((c > limitConstant)); then
        echo "FAIL: $f (constant options) grew by $((c - limitConstant)) instructions over its baseline ($baseline)"
        status=1
    fi
    if ((status == 0 && (n < limit || c < limitConstant))); then
        echo "ok: below the baseline (lower it with --write when the gain is meant to stay)"
    fi
    exit $status
    ;;
*)
    echo "unknown mode '$mode'" >&2
    exit 2
    ;;
esac
