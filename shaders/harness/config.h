// Shared by the C++ host and the harness shaders (GLSL): binding numbers, filter and scene ids.
// Plain #defines so that one file serves both languages. The ids match tf::Filter, tf::Wrap.
#ifndef TF_HARNESS_CONFIG_H
#define TF_HARNESS_CONFIG_H

// Filter ids, in tf::Filter order.
#define TF_FILTER_NEAREST 0
#define TF_FILTER_BILINEAR 1
#define TF_FILTER_TRILINEAR 2
#define TF_FILTER_NEAREST_MIP 3
#define TF_FILTER_BILINEAR_MIP 4
#define TF_FILTER_HW_NEAREST 5
#define TF_FILTER_HW_BILINEAR 6
#define TF_FILTER_HW_TRILINEAR 7
#define TF_FILTER_HW_ANISO 8
#define TF_FILTER_BRILINEAR 9
#define TF_FILTER_ANISO 10
#define TF_FILTER_EWA 11
#define TF_FILTER_SAT 12
#define TF_FILTER_SAT_ASSEMBLY 13
#define TF_FILTER_GROUND_TRUTH 14 // render only: supersampled integral of the level-0 texture
#define TF_FILTER_NONE 15         // render only: no texture (the benchmark's baseline)

// Ground truth's pixel filters (tf::PixelFilter) and its stratified grid's largest side.
#define TF_PIXEL_FILTER_BOX 0
#define TF_PIXEL_FILTER_GAUSSIAN 1
#define TF_GROUND_TRUTH_SIGMA 0.5 // Gaussian pixel filter: standard deviation in pixels
#define TF_MAX_TRUTH_SIDE 64

// Scene kinds: a textured plane or quad (plane, zoom, minify, slanted) and a cylinder (tunnel).
#define TF_SCENE_PLANE 0
#define TF_SCENE_CYLINDER 1
#define TF_SCENE_TRIANGLES 2 // ray-cast triangle list (triangles, and the mesh scene's CPU twin)
#define TF_MAX_TRIANGLES 16
#define TF_EDGE_SLACK 1e-5 // triangles: barycentric slack at edges (watertight ray casts; see scene.glsl)

// How the harness gets uv gradients (render): quads of fine or coarse differences, or ray differentials.
#define TF_GRADIENTS_FINE 0
#define TF_GRADIENTS_COARSE 1
#define TF_GRADIENTS_RAY 2

#define TF_RENDER_TILE 8 // compute render: 8x8 pixels a workgroup of 64 invocations, as 2x2 quads

// Descriptor set 0.
#define TF_BINDING_TEXTURE 0 // combined image sampler: the MIP chain. texelFetch ignores the sampler; hardware
                             // taps and hw-* filters use it (trilinear with the wrap mode, or the hw-* state)
#define TF_BINDING_SCENE 1   // uniform buffer: tf_SceneParams (render)
#define TF_BINDING_LOOKUPS 1 // storage buffer: 6 floats a lookup (sample)
#define TF_BINDING_RESULTS 2 // storage buffer: vec4 a lookup (sample), vec4 a pixel (compute render)
#define TF_BINDING_STATS 3   // storage buffer: uvec2 a lookup, texel fetches and hardware lookups (sample)
#define TF_BINDING_SAT_LOW 4  // usampler2D RGBA32UI: summed-area table, low 32 bits per channel
#define TF_BINDING_SAT_HIGH 5 // usampler2D R32UI: bits 32..39 of the four channels, one byte each

#define TF_SAMPLE_LOCAL_SIZE 64
// sample: filters whose lookups each get a whole subgroup, every 2x2 quad of it differencing to the lookup's
// gradients (the hw-* filters, through textureGrad; see sample.comp.glsl); every other filter runs one
// invocation a lookup.
#define TF_SAMPLE_IN_QUADS(filter) ((filter) >= TF_FILTER_HW_NEAREST && (filter) <= TF_FILTER_HW_ANISO)

#define TF_SPEC_FILTER 0 // specialization constant id of the filter (TF_FILTER_*)

#endif
