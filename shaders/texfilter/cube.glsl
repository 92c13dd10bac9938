// texfilter/cube.glsl — cube-map lookups by direction: nearest, bilinear, trilinear, aniso and EWA, seamless
// across faces (Vulkan cube sampling is always seamless), with the footprint from the direction derivatives
// projected onto the face (docs/ENVIRONMENT.md has the math; host/reference/environment.cpp is its CPU twin).
//
// Use:     vec4 tf_trilinear_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
//          vec4 tf_aniso_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes,
//                             int shape);
//          vec4 tf_ewa_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha,
//                           float maxAniso);
//          also tf_nearest_cube / tf_bilinear_cube (tex, dir, s: level 0), tf_nearest_mip_cube /
//          tf_bilinear_mip_cube (tex, dir, dDirdx, dDirdy, s), tf_bspline_cube / tf_catmull_rom_cube (tex, dir, s:
//          level 0 through bicubic.glsl's cubics, 16 texel reads, seamless as every form), and tf_aniso_cube_hw /
//          tf_ewa_cube_hw / tf_bspline_cube_hw / tf_catmull_rom_cube_hw (the same filters from the hardware's
//          seamless bilinear/trilinear taps: 4 taps for the B-spline, 9 for Catmull-Rom). Stochastic forms
//          (stochastic.glsl, one texel or one tap a lookup chosen by the caller's vec3 xi, appended last):
//          tf_bilinear_stochastic_cube(tex, dir, s, xi), tf_trilinear_stochastic_cube(tex, dir, dDirdx, dDirdy,
//          s, xi), tf_aniso_stochastic_cube(..., maxProbes, shape, xi), tf_ewa_stochastic_cube(..., alpha,
//          maxAniso, xi), each also _hw (a LINEAR sampler: its one tap goes through the seamless filter). TF_MAGNIFY
//          (common.glsl) applies to tf_trilinear_cube, tf_aniso_cube(_hw) and tf_ewa_cube(_hw) as to their 2D
//          families.
//          Every cube kind (TF_RESOURCE_CUBE, TF_RESOURCE_CUBE_ARRAY): samplerCube; textureCube tex, sampler smp;
//          samplerCubeArray and textureCubeArray + sampler with `int layer` right after dir; bindless with
//          TF_NONUNIFORM (common.glsl), e.g. tf_ewa_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer,
//          vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso).
//          tf_CubeLookup tf_cube_lookup(vec3 dir, vec3 dDirdx, vec3 dDirdy): the face, its uv and uv gradients
//          every form filters with (face -1 for a zero or non-finite dir).
// Math:    the face of dir's major axis (ties x, y, z), uv = (sc/|ma| + 1)/2 per the spec's table, gradients by
//          the quotient rule on that face; then the 2D family of the same name on that face (its LOD, probes,
//          ellipse: trilinear.glsl, aniso.glsl, ewa.glsl), every texel past the face's edges read from the cube
//          where the direction through its centre points (the adjacent face's edge texel one texel past an
//          edge; the mean of the three corner texels one texel past a corner). s.wrap is ignored.
//          _hw forms place each tap on the face's plane as the 2D family does and read it at the direction
//          through that point: a tap past an edge is filtered on the face that direction hits, on that face's
//          own grid, so within ~2 texels of an edge the hardware cubics are close to, not equal to, the manual
//          ones (docs/ENVIRONMENT.md, "Hardware taps", has the measured gap).
// Needs:   a cube image with a full MIP chain per face. Manual forms read each texel with textureLod at its
//          centre's direction: the sampler bound (or `smp`) must filter NEAREST (min, mag, mipmapMode) with no
//          LOD bias and no LOD clamp narrower than the levels (textureSize and textureQueryLevels give the
//          rest). _hw forms: a LINEAR sampler (min, mag, mipmapMode LINEAR for aniso, any for ewa), no bias.
// Options: s.lodBias, s.lodMin, s.lodMax, and each family's own (aniso.glsl, ewa.glsl). No defines.
// Cost:    the 2D family's texel reads, each a textureLod (3 at a bilinear corner); _hw: its hardware taps;
//          stochastic forms 1 texel read (3 past a corner) or 1 tap.
// Degenerate input: a zero or non-finite dir gives vec4(0); non-finite derivatives the coarsest level, zero
//          the finest (the 2D rules).
// Example: vec3 d = reflect(viewDir, n);
//          vec4 c = tf_ewa_cube(envNearest, d, dFdxFine(d), dFdyFine(d), tf_sampler(TF_WRAP_CLAMP), 2.0, 16.0);
#ifndef TF_CUBE_GLSL
#define TF_CUBE_GLSL

#include "common.glsl"
#include "nearest.glsl"
#include "trilinear.glsl"
#include "aniso.glsl"
#include "ewa.glsl"
#include "stochastic.glsl"

// A direction lookup as the 2D lookup on one face: face -1 when dir is zero or not finite.
struct tf_CubeLookup {
    int face;
    vec2 uv, dUVdx, dUVdy;
};

tf_CubeLookup tf_cube_lookup(vec3 dir, vec3 dDirdx, vec3 dDirdy)
{
    tf_CubeLookup c = tf_CubeLookup(-1, vec2(0.5), vec2(0.0), vec2(0.0));
    vec3 a = abs(dir);
    if (any(isnan(dir)) || any(isinf(dir)) || max(a.x, max(a.y, a.z)) == 0.0)
        return c;
    c.face = a.x >= a.y && a.x >= a.z ? (dir.x < 0.0 ? 1 : 0) : a.y >= a.z ? (dir.y < 0.0 ? 3 : 2) : (dir.z < 0.0 ? 5 : 4);
    vec3 S, T, M;
    tfi_cube_frame(c.face, S, T, M);
    vec2 sctc = vec2(dot(S, dir), dot(T, dir));
    float m = dot(M, dir);
    c.uv = 0.5 * (sctc / m + 1.0);
    // d(sc/m) = (d(sc)·m − sc·dm) / m²: the direction derivatives projected onto the face.
    c.dUVdx = 0.5 * (vec2(dot(S, dDirdx), dot(T, dDirdx)) * m - sctc * dot(M, dDirdx)) / (m * m);
    c.dUVdy = 0.5 * (vec2(dot(S, dDirdy), dot(T, dDirdy)) * m - sctc * dot(M, dDirdy)) / (m * m);
    return c;
}

// The 2D families' sampler for a face: uv reduction as for clamp (a no-op on a face), the LOD options kept.
tf_Sampler tfi_cube_sampler(tf_Sampler s) { return tf_Sampler(TF_WRAP_CLAMP, s.lodBias, s.lodMin, s.lodMax); }

// BEGIN prototypes (generated: tests/prototypes.py --write; ctest prototypes.current checks it)
// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names.
#if (TF_RESOURCES & TF_RESOURCE_CUBE) != 0
vec4 tf_aniso_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_cube_hw(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_cube_hw(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_stochastic_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_cube_hw(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_cube_hw(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_cube(samplerCube tex, vec3 dir, tf_Sampler s);
vec4 tf_bilinear_cube(textureCube tex, sampler smp, vec3 dir, tf_Sampler s);
vec4 tf_bilinear_mip_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_bilinear_mip_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_bilinear_stochastic_cube(samplerCube tex, vec3 dir, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_cube(textureCube tex, sampler smp, vec3 dir, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_cube_hw(samplerCube tex, vec3 dir, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_cube_hw(textureCube tex, sampler smp, vec3 dir, tf_Sampler s, vec3 xi);
vec4 tf_bspline_cube(samplerCube tex, vec3 dir, tf_Sampler s);
vec4 tf_bspline_cube(textureCube tex, sampler smp, vec3 dir, tf_Sampler s);
vec4 tf_bspline_cube_hw(samplerCube tex, vec3 dir, tf_Sampler s);
vec4 tf_bspline_cube_hw(textureCube tex, sampler smp, vec3 dir, tf_Sampler s);
vec4 tf_catmull_rom_cube(samplerCube tex, vec3 dir, tf_Sampler s);
vec4 tf_catmull_rom_cube(textureCube tex, sampler smp, vec3 dir, tf_Sampler s);
vec4 tf_catmull_rom_cube_hw(samplerCube tex, vec3 dir, tf_Sampler s);
vec4 tf_catmull_rom_cube_hw(textureCube tex, sampler smp, vec3 dir, tf_Sampler s);
vec4 tf_ewa_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_cube_hw(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_cube_hw(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_stochastic_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_cube_hw(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_cube_hw(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_nearest_cube(samplerCube tex, vec3 dir, tf_Sampler s);
vec4 tf_nearest_cube(textureCube tex, sampler smp, vec3 dir, tf_Sampler s);
vec4 tf_nearest_mip_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_nearest_mip_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_stochastic_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_cube(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_cube_hw(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_cube_hw(textureCube tex, sampler smp, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
#endif
#if (TF_RESOURCES & TF_RESOURCE_CUBE_ARRAY) != 0
vec4 tf_aniso_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_cube_hw(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape);
vec4 tf_aniso_stochastic_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_cube_hw(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_aniso_stochastic_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes, int shape, vec3 xi);
vec4 tf_bilinear_cube(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s);
vec4 tf_bilinear_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s);
vec4 tf_bilinear_mip_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_bilinear_mip_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_bilinear_stochastic_cube(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_cube_hw(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bilinear_stochastic_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s, vec3 xi);
vec4 tf_bspline_cube(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s);
vec4 tf_bspline_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s);
vec4 tf_bspline_cube_hw(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s);
vec4 tf_bspline_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s);
vec4 tf_catmull_rom_cube(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s);
vec4 tf_catmull_rom_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s);
vec4 tf_catmull_rom_cube_hw(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s);
vec4 tf_catmull_rom_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s);
vec4 tf_ewa_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_cube_hw(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso);
vec4 tf_ewa_stochastic_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_cube_hw(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_ewa_stochastic_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha, float maxAniso, vec3 xi);
vec4 tf_nearest_cube(samplerCubeArray tex, vec3 dir, int layer, tf_Sampler s);
vec4 tf_nearest_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, tf_Sampler s);
vec4 tf_nearest_mip_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_nearest_mip_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
vec4 tf_trilinear_stochastic_cube(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_cube(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_cube_hw(samplerCubeArray tex, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
vec4 tf_trilinear_stochastic_cube_hw(textureCubeArray tex, sampler smp, vec3 dir, int layer, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, vec3 xi);
#endif
// END prototypes

#define TFI_FAMILY TFI_FAMILY_CUBE
#include "detail/instantiate.glsl"
#undef TFI_FAMILY

#endif
