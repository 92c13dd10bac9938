// texfilter/cube.glsl — cube-map lookups by direction: nearest, bilinear, bicubic, trilinear, aniso, EWA and
// the stochastic forms, seamless across faces (as Vulkan cube sampling), with the footprint from the direction
// derivatives projected onto the face (docs/ENVIRONMENT.md; host/reference/environment.cpp is its CPU twin).
//
// Use:     vec4 tf_trilinear_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s);
//          vec4 tf_aniso_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, int maxProbes,
//                             int shape);
//          vec4 tf_ewa_cube(samplerCube tex, vec3 dir, vec3 dDirdx, vec3 dDirdy, tf_Sampler s, float alpha,
//                           float maxAniso);
//          and the 2D families' other forms with the 2D name + _cube and (tex, dir[, dDirdx, dDirdy], s, the
//          2D extras): tf_nearest_cube, tf_bilinear_cube, tf_bspline_cube, tf_catmull_rom_cube (level 0),
//          tf_nearest_mip_cube, tf_bilinear_mip_cube; _hw forms (tf_aniso_cube_hw, tf_ewa_cube_hw,
//          tf_bspline_cube_hw, tf_catmull_rom_cube_hw); stochastic forms with the caller's vec3 xi last
//          (tf_bilinear_stochastic_cube, tf_trilinear_stochastic_cube, tf_aniso_stochastic_cube,
//          tf_ewa_stochastic_cube, each also _hw). tf_CubeLookup tf_cube_lookup(vec3 dir, vec3 dDirdx,
//          vec3 dDirdy): the face (−1 for a zero or non-finite dir), its uv and uv gradients.
//          Every cube kind has the same overloads: textureCube + sampler smp; samplerCubeArray and
//          textureCubeArray + sampler with `int layer` after dir. No TF_SOURCE form. The prototype list below.
// Math:    the face of dir's major axis (ties x, y, z), uv = (sc/|ma| + 1)/2 per the spec's table, gradients by
//          the quotient rule; then the 2D family of the same name on that face, every texel past the face's
//          edges read from the cube where the direction through its centre points (the adjacent face's edge
//          texel past an edge; the mean of the three corner texels past a corner). _hw taps past an edge are
//          filtered on the face their direction hits, on that face's grid: near an edge the hardware cubics
//          are close to, not equal to, the manual ones (docs/ENVIRONMENT.md, "Hardware taps").
// Options: s.lodBias, s.lodMin, s.lodMax and each family's own (aniso.glsl, ewa.glsl); s.wrap is ignored.
//          TF_MAGNIFY (common.glsl) applies to tf_trilinear_cube, tf_aniso_cube(_hw), tf_ewa_cube(_hw).
// Needs:   a cube image with a full MIP chain. Manual forms read each texel with textureLod at its centre's
//          direction: the sampler (bound, or `smp`) must be NEAREST (min, mag, mipmapMode) with no LOD bias and
//          no LOD clamp narrower than the levels. _hw forms: a LINEAR sampler (min, mag; mipmapMode LINEAR for
//          aniso, any for ewa), no bias.
// Cost:    the 2D family's texel reads, each a textureLod (3 at a texel past a corner); _hw: its hardware
//          lookups; stochastic forms 1 texel read (3 past a corner) or 1 lookup.
// Degenerate input: a zero or non-finite dir gives vec4(0); non-finite derivatives the coarsest level, zero
//          derivatives the finest (the 2D rules).
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
