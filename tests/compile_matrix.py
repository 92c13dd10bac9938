#!/usr/bin/env python3
"""Every public function of the includes through the optimisers engines ship with, in every stage it documents.

usage: compile_matrix.py --list
       compile_matrix.py GLSLANG GLSLC SPIRV_VAL INCLUDE_DIR GROUP [--full]
Groups (each its own ctest entry, optimized.GROUP, tests/CMakeLists.txt): one per family (an include and its
calls in GROUPS below; each environment map in four, for time), and `coverage`: every tf_ function and macro the
includes define is called by some group. A group compiles one shader at a time with every call of the family in
it, optimised, and validates the module. What varies from shader to shader:
  stage      frag, comp, rgen, rchit, rmiss (#version 460; the ray-tracing stages with GL_EXT_ray_tracing), less
             where a function documents fewer (the quad macros: fragment; TF_COMPUTE_QUADS and the GPU
             builders: compute);
  arguments  const         every tf_Sampler field and option (probes, shape, alpha, maxAniso, band, boxes, level,
                           kernel, compare op, SAT offset/scale) a literal, with wrap TF_WRAP_REPEAT, _CLAMP
                           or _MIRROR;
             const-wrap    the wrap a literal, lodBias/lodMin/lodMax from a uniform buffer, options literal:
                           tf_Sampler(TF_WRAP_REPEAT, ubo.lodBias, ...), the usual engine call;
             runtime       every one of them from the buffer;
             runtime-wrap  the wrap from the buffer, everything else literal;
             (groups without a tf_Sampler or options: const and runtime);
  compiler   glslc -O (shaderc's performance passes; Debian's shaderc 2023.2 carries SPIRV-Tools 2022.4) and
             glslangValidator -Os, both --target-env vulkan1.2 (glslc -Werror); spirv-val --target-env
             vulkan1.2 then checks the module.
Per compiler, setting i of SETTINGS (glslc: the eight of const and const-wrap with each literal wrap, runtime,
runtime-wrap; glslangValidator: five, each variant and wrap once) goes to stage i (mod 5; the second compiler
two stages on), so every function meets every stage, variant and wrap mode with both compilers without the
product of them all (--full: every setting in every stage, ~4x the time).
A shader that fails is compiled again one call at a time, and the report names the calls that fail alone.
Standard library only. Everything a test shader declares comes after the include.
"""
import os
import re
import subprocess
import sys
import tempfile

import compile_resources  # its Tools: the two compilers' command lines

STAGES = ("frag", "comp", "rgen", "rchit", "rmiss")
COMPILERS = ("glslc", "glslangValidator")

# The names calls use for what the sampler variants set (macros defined before main). Literal values are the
# typical ones (tf_sampler's LOD range, the suggested options); SHAPE is the second shape, the calls name
# TF_ANISO_GPU themselves, so that a literal shape covers both branches.
LITERAL = dict(BIAS="0.0", LODMIN="0.0", LODMAX="1000.0", PROBES="16", SHAPE="TF_ANISO_FELINE", ALPHA="2.0",
               MAXANISO="16.0", BAND="0.25", BOXES="4", LEVEL="1", KERNEL="TF_RECONSTRUCT_CATMULL_ROM",
               OP="TF_COMPARE_LESS_OR_EQUAL", OFFSET="vec4(0.0)", SCALE="vec4(1.0)")
RUNTIME = dict(WRAP="ubo.wrap", BIAS="ubo.lodBias", LODMIN="ubo.lodMin", LODMAX="ubo.lodMax", PROBES="ubo.maxProbes",
               SHAPE="ubo.shape", ALPHA="ubo.alpha", MAXANISO="ubo.maxAniso", BAND="ubo.band", BOXES="ubo.boxes",
               LEVEL="ubo.level", KERNEL="ubo.kernel", OP="ubo.op", OFFSET="ubo.offset", SCALE="ubo.scale")


def sampler_values(variant, wrap):
    """The macro values of VARIANT (one of the settings below) with WRAP the literal wrap mode."""
    if variant == "runtime":
        return dict(RUNTIME)
    values = dict(LITERAL, WRAP=f"TF_WRAP_{wrap}")
    if variant == "const-wrap":
        values.update(BIAS=RUNTIME["BIAS"], LODMIN=RUNTIME["LODMIN"], LODMAX=RUNTIME["LODMAX"])
    elif variant == "runtime-wrap":
        values.update(WRAP=RUNTIME["WRAP"])
    return values


# What a group's shaders pass, in this order: (variant, literal wrap). Every literal wrap mode with every other
# argument literal and with the LOD fields from the buffer (the usual engine call), then everything from the
# buffer, and the wrap alone from it. Groups without a tf_Sampler or options take const and runtime.
SAMPLER_SETTINGS = [("const", "REPEAT"), ("const-wrap", "REPEAT"), ("runtime", None), ("const", "CLAMP"),
                    ("const-wrap", "CLAMP"), ("runtime-wrap", None), ("const", "MIRROR"), ("const-wrap", "MIRROR")]
PLAIN_SETTINGS = [("const", "REPEAT"), ("runtime", None)]
# glslangValidator -Os runs SPIRV-Tools 2023.1 (Debian), which has the block-merge fix: every variant and every
# literal wrap mode once, in five shaders instead of eight, for time.
GLSLANG_SETTINGS = [("const", "REPEAT"), ("const-wrap", "CLAMP"), ("runtime", None), ("runtime-wrap", None),
                    ("const-wrap", "MIRROR")]


# In scope of every call: tex (sampler2D), satLow, satHigh (usampler2D), cube (samplerCube), depth (sampler2D, a
# depth map), uv, dx, dy (vec2), dir, ddx, ddy (vec3: a direction and its change one pixel right / down), xi
# (vec3 in [0, 1)), s (tf_Sampler of the variant), ubo (the uniform buffer), and the macros above. A call is a
# vec4 expression; "frag:" / "comp:" in front limits it to that stage; "do:" makes it a statement.
D2 = "dx, dy, s"
DIR = "dir, ddx, ddy, s"
GROUPS = {
    "common": dict(include="common", calls=[
        "tf_fetch(tex, ivec2(uv * 16.0), LEVEL, WRAP)",
        "vec4(float(tf_wrap(uv.x * 40.0 - 7.0, 16, WRAP)), vec2(tf_level_size(tex, LEVEL)), tf_finite(uv) ? 1.0 : 0.0)",
        "vec4(tf_reduce_uv(uv * 1e6, WRAP), float(tf_sampler(WRAP).wrap), tf_sampler(WRAP).lodMax)",
        "vec4(float(tf_compare(OP, uv.x).op), tf_compare(OP, uv.x).dref, 0.0, 0.0)"]),
    "lod": dict(include="lod", calls=[
        f"vec4(tf_lod(tex, {D2}), tf_lod_unclamped(tex, dx, dy, BIAS), float(tf_mip_level_nearest(tf_lod(tex, {D2}))), 0.0)"]),
    "nearest": dict(include="nearest", calls=[
        "tf_nearest(tex, uv, s)", f"tf_nearest_mip(tex, uv, {D2})", "tf_nearest_level(tex, uv, LEVEL, WRAP)"]),
    "bilinear": dict(include="bilinear", calls=[
        "tf_bilinear(tex, uv, s)", f"tf_bilinear_mip(tex, uv, {D2})", "tf_bilinear_level(tex, uv, LEVEL, WRAP)"]),
    "bicubic": dict(include="bicubic", calls=[
        "tf_bspline(tex, uv, s)", "tf_catmull_rom(tex, uv, s)", "tf_bspline_hw(tex, uv, s)",
        "tf_catmull_rom_hw(tex, uv, s)", "tf_cubic_level(tex, uv, LEVEL, WRAP, KERNEL)",
        "tf_cubic_level_hw(tex, uv, LEVEL, WRAP, KERNEL)",
        "tf_cubic_level(tex, uv, LEVEL, WRAP, TF_RECONSTRUCT_BILINEAR) + tf_cubic_level_hw(tex, uv, LEVEL, WRAP, TF_RECONSTRUCT_BILINEAR)"]),
    "trilinear": dict(include="trilinear", calls=[f"tf_trilinear(tex, uv, {D2})"]),
    "brilinear": dict(include="brilinear", calls=[
        f"tf_brilinear(tex, uv, {D2}, BAND)", "vec4(tf_brilinear_weight(uv.x, BAND))"]),
    "aniso": dict(include="aniso", calls=[
        f"tf_aniso(tex, uv, {D2}, PROBES, TF_ANISO_GPU)", f"tf_aniso(tex, uv, {D2}, PROBES, SHAPE)",
        f"tf_aniso_hw(tex, uv, {D2}, PROBES, TF_ANISO_GPU)", f"tf_aniso_hw(tex, uv, {D2}, PROBES, SHAPE)"]),
    "ewa": dict(include="ewa", calls=[
        f"tf_ewa(tex, uv, {D2}, ALPHA, MAXANISO)", f"tf_ewa_hw(tex, uv, {D2}, ALPHA, MAXANISO)"]),
    "ewa_fast": dict(include="ewa_fast", calls=[f"tf_ewa_fast(tex, uv, {D2})"]),
    "sat": dict(include="sat", calls=[
        f"tf_sat(satLow, satHigh, uv, {D2}, OFFSET, SCALE)",
        f"tf_sat_assembly(satLow, satHigh, uv, {D2}, OFFSET, SCALE, BOXES)"]),
    "stochastic": dict(include="stochastic", calls=[
        "tf_bilinear_stochastic(tex, uv, s, xi)", "tf_bilinear_stochastic_level(tex, uv, LEVEL, WRAP, xi)",
        f"tf_trilinear_stochastic(tex, uv, {D2}, xi)",
        f"tf_aniso_stochastic(tex, uv, {D2}, PROBES, SHAPE, xi)",
        f"tf_ewa_stochastic(tex, uv, {D2}, ALPHA, MAXANISO, xi)", "tf_bilinear_stochastic_hw(tex, uv, s, xi)",
        f"tf_trilinear_stochastic_hw(tex, uv, {D2}, xi)",
        f"tf_aniso_stochastic_hw(tex, uv, {D2}, PROBES, TF_ANISO_GPU, xi)",
        f"tf_ewa_stochastic_hw(tex, uv, {D2}, ALPHA, MAXANISO, xi)"]),
    # Depth maps: the compare op is a sampler argument too (percentage-closer forms, docs/API.md "Resources").
    "shadow": dict(include="texfilter", resources="TF_RESOURCE_SHADOW", calls=[
        "tf_bilinear(depth, uv, tf_compare(OP, uv.x), s)",
        f"tf_trilinear(depth, uv, tf_compare(OP, uv.x), {D2})",
        f"tf_aniso(depth, uv, tf_compare(OP, uv.x), {D2}, PROBES, SHAPE)",
        f"tf_ewa(depth, uv, tf_compare(OP, uv.x), {D2}, ALPHA, MAXANISO)"]),
    "debug": dict(include="debug", calls=[
        "vec4(tf_debug_lod_color(uv.x * 12.0) + tf_debug_anisotropy_color(tf_debug_anisotropy(dx, dy, vec2(64.0))) + tf_debug_heat(uv.y, 8.0), 1.0)",
        "vec4(tf_debug_footprint(uv, dx, dy, vec2(textureSize(tex, 0)), textureQueryLevels(tex), s, TF_DEBUG_ANISO, PROBES, SHAPE, MAXANISO).major, tf_debug_footprint(uv, dx, dy, vec2(64.0), 7, s, TF_DEBUG_EWA, PROBES, SHAPE, MAXANISO).lod, 0.0)",
        "vec4(tf_debug_aniso_probe(uv, dx, dy, vec2(64.0), PROBES, SHAPE, tf_debug_aniso_probe_count(dx, dy, vec2(64.0), PROBES, SHAPE) - 1), 0.0, 0.0)"]),
    "derivatives": dict(include="derivatives", sampler=False, calls=[
        "vec4(tf_ray_differential_gradients(dir, ddx, ddy, 2.0, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)).dUVdx, tf_periodic_gradients(tf_Gradients(dx, dy), tf_Gradients(dy, dx), bvec2(uv.x > 0.5, true)).dUVdy)",
        "vec4(tf_transfer_ray_differentials(dir, 2.0, vec3(0.0, 1.0, 0.0), tf_RayDifferentials(ddx, ddy, ddx, ddy)).dPdx + tf_reflect_ray_differentials(dir, vec3(0.0, 1.0, 0.0), ddx, ddy, tf_RayDifferentials(ddx, ddy, ddx, ddy)).dDdy, 1.0)",
        "vec4(tf_ray_cone_pixel_spread(LITERAL_OR(1.0, ubo.alpha), 1080.0), tf_ray_cone_propagate(tf_RayCone(0.0, uv.x), 3.0).width, tf_ray_cone_reflect(tf_RayCone(uv.y, 0.01), LITERAL_OR(0.5, ubo.band)).spread, 0.0)",
        "vec4(tf_ray_cone_gradients(dir, uv.x, vec3(0.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0)).dUVdx, 0.0, 0.0) + vec4(tf_ray_cone_direction_gradients(dir, ddx, 0.001, uv.y).dDirdx + tf_ray_cone_reflect_direction_gradients(dir, vec3(0.0, 1.0, 0.0), tf_RayCone(uv.x, 0.001), LITERAL_OR(0.5, ubo.band)).dDirdy, 0.0)",
        "frag:vec4(tf_quad_gradients_fine(uv).dUVdx, tf_quad_gradients_coarse(uv).dUVdy) + vec4(tf_quad_gradients_fine_periodic(uv).dUVdx, tf_quad_gradients_coarse_periodic(uv).dUVdy)",
        "comp:vec4(tf_compute_quad_gradients(uv, LITERAL_OR(TF_DERIVATIVES_FINE, ubo.level)).dUVdx, tf_compute_quad_gradients_periodic(uv, TF_DERIVATIVES_COARSE).dUVdy) + vec4(vec2(tf_quad_pixel(ivec2(0), 8)), 0.0, 0.0)"],
        prelude={"comp": "#extension GL_KHR_shader_subgroup_quad : require\n#define TF_COMPUTE_QUADS"}),
    "encode": dict(include="encode", sampler=False, calls=[
        "vec4(float(tf_mip_srgb8(uv.x)), float(tf_mip_unorm8(uv.y)), float(tf_mip_half(dx.x)), 0.0)"]),
    # TF_MAGNIFY's cubics and the counters change what folds away: the families that read level 0 through it.
    "magnify": dict(include="texfilter", calls=[
        f"tf_trilinear(tex, uv, {D2})", f"tf_aniso(tex, uv, {D2}, PROBES, SHAPE)",
        f"tf_aniso_hw(tex, uv, {D2}, PROBES, TF_ANISO_GPU)", f"tf_ewa(tex, uv, {D2}, ALPHA, MAXANISO)",
        f"tf_ewa_hw(tex, uv, {D2}, ALPHA, MAXANISO)"],
        prelude={"*": "uint fetchCount = 0u, hwLookupCount = 0u;\n"
                      "#define TF_COUNT_FETCHES(n) fetchCount += uint(n)\n"
                      "#define TF_COUNT_HW_LOOKUPS(n) hwLookupCount += uint(n)\n"
                      "#define TF_MAGNIFY TF_RECONSTRUCT_CATMULL_ROM"}),
    # The GPU builders: compute only, reading and writing through the user's macros (compile_includes.sh).
    "build_mip": dict(include="build_mip", sampler=False, stages=("comp",), local_size="TF_MIP_GROUP_SIZE", calls=[
        "do:tf_build_mip_pass(LITERAL_OR(0, ubo.level), LITERAL_OR(6, ubo.maxProbes), LITERAL_OR(true, ubo.shape != 0), ivec2(LITERAL_OR(256, ubo.boxes)))",
        "vec4(vec2(tf_mip_level_size(ivec2(uv * 4096.0), LEVEL)), 0.0, 0.0)"],
        prelude={"comp": """layout(set = 1, binding = 0, rgba16f) uniform coherent image2D chain[15];
layout(set = 1, binding = 1, std430) coherent buffer Counter { uint groupsDone; };
#define TF_MIP_LOAD(level, p) imageLoad(chain[level], p)
#define TF_MIP_STORE(level, p, v) imageStore(chain[level], p, v)
#define TF_MIP_COUNTER groupsDone"""}),
    "build_sat": dict(include="build_sat", sampler=False, stages=("comp",), local_size="TF_SAT_GROUP_SIZE", calls=[
        "do:tf_sat_range_pass(ivec2(LITERAL_OR(64, ubo.boxes)))", "do:tf_sat_rows_pass(ivec2(LITERAL_OR(64, ubo.boxes)))",
        "do:tf_sat_columns_pass(ivec2(LITERAL_OR(64, ubo.boxes)))",
        "vec4(float(tf_sat_range_groups(ivec2(uv * 64.0))), tf_sat_unkey(tf_sat_key(uv.x)), tf_sat_offset(range.words).x, tf_sat_scale(range.words).y)"],
        prelude={"comp": """layout(set = 1, binding = 0) uniform sampler2D level0;
layout(set = 1, binding = 1, rgba32ui) uniform uimage2D satTableLow;
layout(set = 1, binding = 2, r32ui) uniform writeonly uimage2D satTableHigh;
layout(set = 1, binding = 3, std430) buffer Range { uint words[9]; } range;
#define TF_SAT_LOAD(p) texelFetch(level0, p, 0)
#define TF_SAT_LOAD_LOW(e) imageLoad(satTableLow, e)
#define TF_SAT_STORE_LOW(e, v) imageStore(satTableLow, e, v)
#define TF_SAT_STORE_HIGH(e, v) imageStore(satTableHigh, e, uvec4(v))
#define TF_SAT_RANGE range.words"""}),
}


# The environment maps (cube.glsl, latlong.glsl): both take the same parameters after the texture (a direction
# and its derivatives). Four groups a map: level 0 and the mip filters, aniso, ewa, the stochastic forms.
def environment_groups(map_name, texture, resources, lookup):
    def group(calls):
        return dict(include=map_name, resources=resources, calls=calls)
    f = lambda name: f"tf_{name}_{map_name}"  # noqa: E731
    return {
        map_name: group([lookup] +
                        [f"{f(n)}({texture}, dir, s)" for n in ("nearest", "bilinear", "bspline", "catmull_rom")] +
                        [f"{f(n)}_hw({texture}, dir, s)" for n in ("bspline", "catmull_rom")] +
                        [f"{f(n)}({texture}, {DIR})" for n in ("nearest_mip", "bilinear_mip", "trilinear")]),
        f"{map_name}_aniso": group([f"{f('aniso')}({texture}, {DIR}, PROBES, SHAPE)",
                                    f"{f('aniso')}_hw({texture}, {DIR}, PROBES, TF_ANISO_GPU)"]),
        f"{map_name}_ewa": group([f"{f('ewa')}({texture}, {DIR}, ALPHA, MAXANISO)",
                                  f"{f('ewa')}_hw({texture}, {DIR}, ALPHA, MAXANISO)"]),
        f"{map_name}_stochastic": group(
            [f"tf_bilinear_stochastic_{map_name}{hw}({texture}, dir, s, xi)" for hw in ("", "_hw")] +
            [f"tf_trilinear_stochastic_{map_name}{hw}({texture}, {DIR}, xi)" for hw in ("", "_hw")] +
            [f"tf_aniso_stochastic_{map_name}({texture}, {DIR}, PROBES, SHAPE, xi)",
             f"tf_aniso_stochastic_{map_name}_hw({texture}, {DIR}, PROBES, TF_ANISO_GPU, xi)"] +
            [f"tf_ewa_stochastic_{map_name}{hw}({texture}, {DIR}, ALPHA, MAXANISO, xi)" for hw in ("", "_hw")]),
    }


GROUPS.update(environment_groups(
    "cube", "cube", "TF_RESOURCE_CUBE",
    "vec4(tf_cube_lookup(dir, ddx, ddy).uv, tf_cube_lookup(dir, ddx, ddy).dUVdx.x, float(tf_cube_lookup(dir, ddx, ddy).face))"))
GROUPS.update(environment_groups(
    "latlong", "tex", "TF_RESOURCE_LATLONG",
    "vec4(tf_latlong_lookup(dir, ddx, ddy).uv, tf_latlong_lookup(dir, ddx, ddy).dUVdy.y, tf_latlong_lookup(dir, ddx, ddy).valid ? 1.0 : 0.0)"))


def settings(group, compiler):
    if not GROUPS[group].get("sampler", True):
        return PLAIN_SETTINGS
    return GLSLANG_SETTINGS if compiler == "glslangValidator" else SAMPLER_SETTINGS


def schedule(group, compiler, full=False):
    """(stage, variant, wrap) of each shader GROUP compiles with COMPILER. Setting i goes to stage i (mod the
    group's stages), shifted by two stages for the second compiler; as many shaders as settings or stages,
    whichever is more, so that every setting and every stage is compiled with each compiler. full: every
    setting in every stage."""
    sets, sts = settings(group, compiler), stages(group)
    if full:
        return [(st, v, w) for st in sts for v, w in sets]
    shift = 2 * COMPILERS.index(compiler)
    return [(sts[(i + shift) % len(sts)],) + sets[i % len(sets)] for i in range(max(len(sets), len(sts)))]


def stages(group):
    return GROUPS[group].get("stages", STAGES)


def calls_in(group, stage):
    """GROUP's calls that STAGE has, without their stage prefix."""
    out = []
    for call in GROUPS[group]["calls"]:
        m = re.match(r"^(frag|comp):(.*)$", call)
        if m and m.group(1) != stage:
            continue
        out.append(m.group(2) if m else call)
    return out


def body(calls):
    lines = []
    for call in calls:
        lines.append(f"    {call[3:]};" if call.startswith("do:") else f"    r += {call};")
    return "\n".join(lines)


STAGE_TEMPLATES = {
    "frag": """layout(location = 0) in vec2 inUV;
layout(location = 1) in vec3 inDir;
layout(location = 0) out vec4 outColor;
void main()
{
    vec2 uv = inUV, dx = dFdxFine(inUV), dy = dFdyFine(inUV);
    vec3 dir = inDir, ddx = dFdxFine(inDir), ddy = dFdyFine(inDir);
    vec3 xi = fract(vec3(inUV * 61.0, inDir.x * 17.0));
@SAMPLER@
    vec4 r = vec4(0.0);
@BODY@
    outColor = r;
}
""",
    "comp": """layout(local_size_x = @LOCAL_SIZE@) in;
struct Lookup { vec2 uv, dUVdx, dUVdy; vec4 dir, dDirdx, dDirdy, xi; };
layout(set = 0, binding = 8, std430) readonly buffer Lookups { Lookup lookups[]; };
layout(set = 0, binding = 9, std430) writeonly buffer Colors { vec4 colors[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    vec2 uv = lookups[i].uv, dx = lookups[i].dUVdx, dy = lookups[i].dUVdy;
    vec3 dir = lookups[i].dir.xyz, ddx = lookups[i].dDirdx.xyz, ddy = lookups[i].dDirdy.xyz, xi = lookups[i].xi.xyz;
@SAMPLER@
    vec4 r = vec4(0.0);
@BODY@
    colors[i] = r;
}
""",
    # Ray generation: the hit shader returns uv and its gradients (ray differentials) in the payload.
    "rgen": """layout(set = 0, binding = 8) uniform accelerationStructureEXT topLevel;
layout(set = 0, binding = 9, rgba32f) uniform writeonly image2D colors;
layout(location = 0) rayPayloadEXT Hit hit;
void main()
{
    ivec2 pixel = ivec2(gl_LaunchIDEXT.xy);
    vec2 ndc = 2.0 * (vec2(pixel) + 0.5) / vec2(gl_LaunchSizeEXT.xy) - 1.0;
    vec3 dir = vec3(ndc, 1.0), ddx = vec3(2.0 / float(gl_LaunchSizeEXT.x), 0.0, 0.0);
    vec3 ddy = vec3(0.0, 2.0 / float(gl_LaunchSizeEXT.y), 0.0);
    hit.dDirdx = ddx;
    hit.dDirdy = ddy;
    traceRayEXT(topLevel, gl_RayFlagsOpaqueEXT, 0xFF, 0, 0, 0, vec3(0.0), 0.0, dir, 1e30, 0);
    vec2 uv = hit.uv, dx = hit.dUVdx, dy = hit.dUVdy;
    vec3 xi = fract(vec3(uv * 61.0, hit.color.x));
@SAMPLER@
    vec4 r = hit.color;
@BODY@
    imageStore(colors, pixel, r);
}
""",
    # Closest hit: uv from the barycentrics, gradients per primitive from a buffer, the ray's direction
    # derivatives from the payload; the result goes back in the payload.
    "rchit": """layout(set = 0, binding = 8, std430) readonly buffer Gradients { vec4 gradients[]; };
layout(location = 0) rayPayloadInEXT Hit hit;
hitAttributeEXT vec2 bary;
void main()
{
    vec2 uv = bary;
    vec4 g = gradients[gl_PrimitiveID];
    vec2 dx = g.xy, dy = g.zw;
    vec3 dir = gl_WorldRayDirectionEXT, ddx = hit.dDirdx, ddy = hit.dDirdy;
    vec3 xi = fract(vec3(bary * 61.0, gl_HitTEXT));
@SAMPLER@
    vec4 r = vec4(0.0);
@BODY@
    hit.uv = uv;
    hit.color = r;
}
""",
    # Miss: the environment in the ray's direction; 2D filters at the direction's lat-long uv.
    "rmiss": """layout(location = 0) rayPayloadInEXT Hit hit;
void main()
{
    vec3 dir = gl_WorldRayDirectionEXT, ddx = hit.dDirdx, ddy = hit.dDirdy;
    vec2 uv = vec2(atan(dir.x, -dir.z), acos(clamp(dir.y / length(dir), -1.0, 1.0))) * vec2(0.5, 1.0) / 3.14159265;
    vec2 dx = ddx.xy, dy = ddy.xy;
    vec3 xi = fract(dir * 17.0);
@SAMPLER@
    vec4 r = vec4(0.0);
@BODY@
    hit.color = r;
}
""",
}

DECLARATIONS = """layout(set = 0, binding = 0) uniform sampler2D tex;
layout(set = 0, binding = 1) uniform usampler2D satLow;
layout(set = 0, binding = 2) uniform usampler2D satHigh;
layout(set = 0, binding = 3) uniform samplerCube cube;
layout(set = 0, binding = 4) uniform sampler2D depth;
layout(set = 0, binding = 5) uniform Options {
    int wrap; float lodBias, lodMin, lodMax;
    int maxProbes, shape; float alpha, maxAniso, band; int boxes, level, kernel, op;
    vec4 offset, scale;
} ubo;
struct Hit { vec4 color; vec2 uv, dUVdx, dUVdy; vec3 dDirdx, dDirdy; };
"""


def shader(group, stage, variant, wrap, calls):
    g = GROUPS[group]
    values = sampler_values(variant, wrap)
    lines = ["#version 460", "#extension GL_GOOGLE_include_directive : require"]
    if stage in ("rgen", "rchit", "rmiss"):
        lines.append("#extension GL_EXT_ray_tracing : require")
    prelude = g.get("prelude", {})
    for key in ("*", stage):
        if key in prelude:
            lines.append(prelude[key])
    # Only the kinds the calls use: the others' functions are never called, so dropped unoptimised, and
    # parsing all nine kinds was most of a small shader's compile time.
    lines.append(f"#define TF_RESOURCES ({g.get('resources', 'TF_RESOURCE_SAMPLER_2D')})")
    lines.append(f'#include "texfilter/{g["include"]}.glsl"')
    lines.append(DECLARATIONS.rstrip())
    for name, value in values.items():
        lines.append(f"#define {name} {value}")
    # LITERAL_OR(literal, run-time): the option's literal in every variant but runtime.
    lines.append("#define LITERAL_OR(a, b) " + ("(b)" if variant == "runtime" else "(a)"))
    sampler = "    tf_Sampler s = tf_Sampler(WRAP, BIAS, LODMIN, LODMAX);" if g.get("sampler", True) else ""
    text = STAGE_TEMPLATES[stage].replace("@SAMPLER@", sampler).replace("@BODY@", body(calls))
    text = text.replace("@LOCAL_SIZE@", g.get("local_size", "64"))
    return "\n".join(lines) + "\n" + text


class Tools(compile_resources.Tools):
    """compile_resources.py's compilers (their command lines), optimising, and spirv-val after them."""

    def __init__(self, glslang, glslc, spirv_val, include_dir, work):
        super().__init__(glslang, glslc, None, include_dir, work)
        self.spirv_val = spirv_val

    def check(self, compiler, source, stage):
        """(ok, log): SOURCE optimised by COMPILER as STAGE, then validated."""
        ok, log, spv = self.compile(compiler, source, stage, optimise=True)
        if not ok:
            return False, log
        v = subprocess.run([self.spirv_val, "--target-env", "vulkan1.2", spv], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        return v.returncode == 0, "" if v.returncode == 0 else f"spirv-val exit {v.returncode}\n{v.stdout}"


def indent(text, prefix="      "):
    return prefix + text.rstrip().replace("\n", "\n" + prefix)


def run_group(tools, group, full=False):
    failures = 0
    for compiler in COMPILERS:
        for stage, variant, wrap in schedule(group, compiler, full):
            calls = calls_in(group, stage)
            label = f"{compiler:16} {stage:5} {variant:12} {wrap or '':6} {group}: {len(calls)} calls"
            source = shader(group, stage, variant, wrap, calls)
            ok, log = tools.check(compiler, source, stage)
            print(f"{'ok  ' if ok else 'FAIL'}  {label}")
            if ok:
                continue
            failures += 1
            print(indent(log))
            # One call at a time: which function fails on its own.
            alone = [c for c in calls
                     if not tools.check(compiler, shader(group, stage, variant, wrap, [c]), stage)[0]]
            for c in alone:
                print(f"      fails alone: {c}")
            if not alone:
                print("      no call fails alone: only together")
            print(indent(source, "      | "))
    return failures == 0


def public_functions(include_dir):
    """Every tf_ function and function-like macro the includes define."""
    names = set()
    folder = os.path.join(include_dir, "texfilter")
    for name in os.listdir(folder):
        if not name.endswith(".glsl"):
            continue
        with open(os.path.join(folder, name)) as f:
            text = f.read()
        names |= set(re.findall(r"^\w+\s+(tf_\w+)\(", text, re.M))
        names |= set(re.findall(r"^#define\s+(tf_\w+)\(", text, re.M))
    return names


def coverage(include_dir):
    called = set()
    for g in GROUPS.values():
        for c in g["calls"]:
            called |= set(re.findall(r"\b(tf_\w+)\s*\(", c))
    missing = sorted(public_functions(include_dir) - called)
    print(f"{'ok  ' if not missing else 'FAIL'}  {len(called)} public functions called; "
          f"{len(missing)} not called by any group{': ' + ', '.join(missing) if missing else ''}")
    return not missing


def main(argv):
    if argv[1:] == ["--list"]:
        print("\n".join(list(GROUPS) + ["coverage"]))
        return 0
    full = "--full" in argv
    argv = [a for a in argv if a != "--full"]
    if len(argv) != 6 or (argv[5] not in GROUPS and argv[5] != "coverage"):
        print(__doc__, file=sys.stderr)
        return 2
    if argv[5] == "coverage":
        return 0 if coverage(argv[4]) else 1
    with tempfile.TemporaryDirectory() as work:
        ok = run_group(Tools(argv[1], argv[2], argv[3], argv[4], work), argv[5], full)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
