// The interface between the C++ host and the harness shaders: every id, constant, binding, layout offset
// and record size both sides use, written once here. Plain #defines so that one file serves GLSL and C++;
// host/scene/shader_interface.h checks the C++ types against it (static_assert), and filter_select.glsl
// checks the ids that must equal the texfilter includes' own (#error). Harness names, not the product's
// TF_ prefix: none of this is texfilter's API.
#ifndef HARNESS_CONFIG_H
#define HARNESS_CONFIG_H

// Filter ids: the values of tf::Filter (host/core/filter.h).
#define HARNESS_FILTER_NEAREST 0
#define HARNESS_FILTER_BILINEAR 1
#define HARNESS_FILTER_TRILINEAR 2
#define HARNESS_FILTER_NEAREST_MIP 3
#define HARNESS_FILTER_BILINEAR_MIP 4
#define HARNESS_FILTER_HW_NEAREST 5
#define HARNESS_FILTER_HW_BILINEAR 6
#define HARNESS_FILTER_HW_TRILINEAR 7
#define HARNESS_FILTER_HW_ANISO 8
#define HARNESS_FILTER_BRILINEAR 9
#define HARNESS_FILTER_ANISO 10
#define HARNESS_FILTER_EWA 11
#define HARNESS_FILTER_SAT 12
#define HARNESS_FILTER_SAT_ASSEMBLY 13
#define HARNESS_FILTER_GROUND_TRUTH 14 // render only: supersampled integral of the level-0 texture
#define HARNESS_FILTER_NONE 15         // render only: no texture (the benchmark's baseline)
#define HARNESS_FILTER_BSPLINE 16      // level 0, cubic B-spline (bicubic.glsl; --taps manual|hardware)
#define HARNESS_FILTER_CATMULL_ROM 17  // level 0, Catmull-Rom
#define HARNESS_FILTER_EWA_FAST 18     // at most 9 hardware trilinear lookups (ewa_fast.glsl)

// Sampler options passed straight to the includes: tf::Wrap, tf::AnisoShape, tf::Taps. They must equal
// the includes' TF_WRAP_*, TF_ANISO_*, TF_TAPS_* (filter_select.glsl stops the build if not).
#define HARNESS_WRAP_REPEAT 0
#define HARNESS_WRAP_CLAMP 1
#define HARNESS_WRAP_MIRROR 2
#define HARNESS_ANISO_GPU 0
#define HARNESS_ANISO_FELINE 1
#define HARNESS_TAPS_MANUAL 0
#define HARNESS_TAPS_HARDWARE 1
// trilinear, aniso, ewa: level 0's reconstruction (tf::Reconstruction, --magnify; the includes' TF_MAGNIFY,
// a specialization constant here: HARNESS_SPEC_MAGNIFY), equal to TF_RECONSTRUCT_*.
#define HARNESS_RECONSTRUCT_BILINEAR 0
#define HARNESS_RECONSTRUCT_BSPLINE 1
#define HARNESS_RECONSTRUCT_CATMULL_ROM 2

// Ground truth's pixel filters (tf::PixelFilter) and its stratified grid's largest side.
#define HARNESS_PIXEL_FILTER_BOX 0
#define HARNESS_PIXEL_FILTER_GAUSSIAN 1
#define HARNESS_GROUND_TRUTH_SIGMA 0.5 // Gaussian pixel filter: standard deviation in pixels
#define HARNESS_MAX_TRUTH_SIDE 64      // samples a pixel = side^2, at most 4096
// Ground truth's integrand (tf::AnalyticKind; --truth): level 0's texels reconstructed bilinearly (none, --truth
// texels), or a procedural texture's analytic definition (host/core/analytic_texture.h, analytic_texture.glsl).
#define HARNESS_ANALYTIC_NONE 0
#define HARNESS_ANALYTIC_CHECKER 1
#define HARNESS_ANALYTIC_ZONEPLATE 2
#define HARNESS_ANALYTIC_GRID 3

// Scene kinds: a textured plane or quad (plane, zoom, minify, slanted) and a cylinder (tunnel).
#define HARNESS_SCENE_PLANE 0
#define HARNESS_SCENE_CYLINDER 1
#define HARNESS_SCENE_TRIANGLES 2 // ray-cast triangle list (triangles, and the mesh scene's CPU twin)
#define HARNESS_SCENE_SKYBOX 3    // environment: the camera ray is the lookup direction (env_scene.glsl)
#define HARNESS_SCENE_REFLECT 4   // environment: a mirror sphere (p0: centre, radius), reflected directions
#define HARNESS_MAX_TRIANGLES 16
#define HARNESS_EDGE_SLACK 1e-5 // triangles: barycentric slack at edges (watertight ray casts; see scene.glsl)

// How the harness gets uv gradients (render; tf::Gradients): quads of fine or coarse differences, or ray
// differentials.
#define HARNESS_GRADIENTS_FINE 0
#define HARNESS_GRADIENTS_COARSE 1
#define HARNESS_GRADIENTS_RAY 2
#define HARNESS_GRADIENTS_CONE 3 // ray cones (texfilter/derivatives.glsl): ray-cast 2D scenes, skybox, reflect

// What a render shows (tf::DebugView; texfilter/debug.glsl draws the debug views): the filtered colour,
// the LOD as the mipcolors palette, the footprint's anisotropy ratio, texel fetches + hardware lookups as a
// heat map (0 .. HARNESS_VIEW_FETCHES_MAX), or the numbers themselves (R LOD, G ratio, B fetches, A 1).
#define HARNESS_VIEW_COLOR 0
#define HARNESS_VIEW_LOD 1
#define HARNESS_VIEW_ANISOTROPY 2
#define HARNESS_VIEW_FETCHES 3
#define HARNESS_VIEW_DATA 4
#define HARNESS_VIEW_FETCHES_MAX 128.0 // the heat map's top: 16 aniso probes of 8 fetches

#define HARNESS_RENDER_TILE 8 // compute render: 8x8 pixels a workgroup of 64 invocations, as 2x2 quads

// Descriptor set 0.
#define HARNESS_BINDING_TEXTURE 0 // combined image sampler: the MIP chain. texelFetch ignores the sampler;
                                  // hardware taps and hw-* filters use it (trilinear with the wrap mode, or
                                  // the hw-* state)
#define HARNESS_BINDING_SCENE 1   // uniform buffer: the scene block (render)
#define HARNESS_BINDING_LOOKUPS 1 // storage buffer: HARNESS_LOOKUP_FLOATS floats a lookup (sample)
#define HARNESS_BINDING_RESULTS 2 // storage buffer: vec4 a lookup (sample), vec4 a pixel (compute render)
#define HARNESS_BINDING_STATS 3   // storage buffer: HARNESS_STATS_UINTS a lookup (sample)
#define HARNESS_BINDING_SAT_LOW 4  // usampler2D RGBA32UI: summed-area table, low 32 bits per channel
#define HARNESS_BINDING_SAT_HIGH 5 // usampler2D R32UI: bits 32..39 of the four channels, one byte each
#define HARNESS_BINDING_SAMPLER 6  // sampler (separate kinds) or samplerShadow (shadow): for the hardware taps
#define HARNESS_BINDING_TEXTURE_NEAREST 7 // environment renders, cube: the cube again with a NEAREST sampler
                                          // (the manual cube filters read texels through it)

// Environment renders (render_env.frag.glsl, env_select.glsl): which map a variant binds at
// HARNESS_BINDING_TEXTURE (-DHARNESS_ENV=ID): samplerCube (linear: hardware taps, or the hw-* state), or a
// lat-long sampler2D (repeat in u, clamp in v).
#define HARNESS_ENV_CUBE 1
#define HARNESS_ENV_LATLONG 2

// How the harness binds the texture (a -D define per SPIR-V variant; filter_select.glsl, api: access.glsl):
#define HARNESS_RESOURCE_COMBINED 0       // sampler2D u_texture (and usampler2D SAT tables)
#define HARNESS_RESOURCE_SEPARATE 1       // texture2D u_image + sampler u_sampler (utexture2D SAT tables)
#define HARNESS_RESOURCE_ARRAY 2          // sampler2DArray u_texture, layer pc.layer (usampler2DArray tables)
#define HARNESS_RESOURCE_SEPARATE_ARRAY 3 // texture2DArray u_image + sampler u_sampler (utexture2DArray tables)
#define HARNESS_RESOURCE_BINDLESS 4       // sampler2D u_textures[HARNESS_BINDLESS_COUNT], index non-uniform
#define HARNESS_RESOURCE_UINT 5           // usampler2D u_texture (integer data, manual filters only)
#define HARNESS_RESOURCE_SINT 6           // isampler2D u_texture
#define HARNESS_RESOURCE_SHADOW 7         // texture2D u_image (depth) + samplerShadow u_sampler: manual
                                          // filters compare with tf_compare(pc.compareOp, pc.dref), hw with
                                          // the sampler's compareOp
#define HARNESS_RESOURCE_ATLAS 8          // the texture as one tile of an atlas (sampler2D u_texture, levels
                                          // per tile), read through TF_SOURCE (texel_sources.glsl)
#define HARNESS_RESOURCE_VIRTUAL 9        // the texture's levels in pages of a one-level physical texture
                                          // (sampler2D u_texture), found through a page table (TF_SOURCE)
#define HARNESS_BINDLESS_COUNT 4 // bindless: lookup i reads u_textures[(pc.layer + i) % HARNESS_BINDLESS_COUNT]

// The texel-source kinds (atlas, virtual; host/core/texel_sources.h, shaders/harness/texel_sources.glsl):
// the ints at HARNESS_BINDING_SOURCE that say where the texture's texels lie in u_texture.
#define HARNESS_BINDING_SOURCE 8 // storage buffer: int words[] (readonly)
// atlas: the tile's level-0 origin and size in atlas texels and its level count; level l of the tile is the
// atlas's level l at origin >> l, max(1, size >> l) texels (the floor rule).
#define HARNESS_ATLAS_ORIGIN_X 0
#define HARNESS_ATLAS_ORIGIN_Y 1
#define HARNESS_ATLAS_WIDTH 2
#define HARNESS_ATLAS_HEIGHT 3
#define HARNESS_ATLAS_LEVELS 4
#define HARNESS_ATLAS_WORDS 5
#define HARNESS_ATLAS_GRID 2      // the atlas: HARNESS_ATLAS_GRID^2 cells of side P = the next power of two
#define HARNESS_ATLAS_CELL_X 1    // >= the texture's sides; the texture in this cell, the others constant
#define HARNESS_ATLAS_CELL_Y 1
// virtual: a texture's words start at its id (TF_SOURCE is an int): its level count, then for each level
// its width, height, pages a row and where its first page entry is, counted from the texture's first word
// (words[id + first + py * pages a row + px] is page (px, py) of the level); a page entry is the
// page's place in the physical texture, in pages: x | y << 16. Page p of a level is its texels
// [p.x * PAGE, (p.x + 1) * PAGE) x [p.y * PAGE, ...); the pages lie shuffled in the physical texture.
#define HARNESS_VIRTUAL_PAGE 8          // texels a page side
#define HARNESS_VIRTUAL_LEVELS 0
#define HARNESS_VIRTUAL_LEVEL_WORDS 4   // a level's words, from word 1 on
#define HARNESS_VIRTUAL_WIDTH 0
#define HARNESS_VIRTUAL_HEIGHT 1
#define HARNESS_VIRTUAL_PAGES_X 2
#define HARNESS_VIRTUAL_FIRST_PAGE 3

// sample's records: a lookup is u, v, du/dx, dv/dx, du/dy, dv/dy (floats), its result a vec4, its stats
// texel fetches and hardware lookups (uints).
#define HARNESS_LOOKUP_FLOATS 6
#define HARNESS_RESULT_FLOATS 4
#define HARNESS_STATS_UINTS 2

// The push constants every pass shares (std430 offsets in bytes; tf::PushConstants).
#define HARNESS_PUSH_WRAP_MODE 0
#define HARNESS_PUSH_LOD_BIAS 4
#define HARNESS_PUSH_LOD_MIN 8
#define HARNESS_PUSH_LOD_MAX 12
#define HARNESS_PUSH_COUNT 16
#define HARNESS_PUSH_BAND 20
#define HARNESS_PUSH_PROBES 24
#define HARNESS_PUSH_ANISO_SHAPE 28
#define HARNESS_PUSH_TAPS 32
#define HARNESS_PUSH_ALPHA 36
#define HARNESS_PUSH_MAX_ANISO 40
#define HARNESS_PUSH_BOXES 44
#define HARNESS_PUSH_FREE_48 48       // free (the gradients are HARNESS_SPEC_GRADIENTS)
#define HARNESS_PUSH_TRUTH_SIDE 52
#define HARNESS_PUSH_PIXEL_FILTER 56
#define HARNESS_PUSH_FREE_60 60    // free (the debug view is HARNESS_SPEC_VIEW)
#define HARNESS_PUSH_SAT_OFFSET 64 // vec4: 16-byte aligned
#define HARNESS_PUSH_SAT_SCALE 80
#define HARNESS_PUSH_TRUTH_FIRST 96  // ground-truth: the first sample of the range a frame takes (viewer)
#define HARNESS_PUSH_TRUTH_COUNT 100 // ground-truth: samples in the range; 0 = every sample from the first on
#define HARNESS_PUSH_GRADIENT_SCALE 104 // render: uv gradients times this (the viewer's previews; else 1)
#define HARNESS_PUSH_LAYER 108       // sample: the array layer read (array kinds), the first bindless index
#define HARNESS_PUSH_COMPARE_OP 112  // sample, shadow kind: VkCompareOp of the manual filters' comparison
#define HARNESS_PUSH_DREF 116        // sample, shadow kind: the reference depth
#define HARNESS_PUSH_TRUTH_ANALYTIC 120 // ground-truth: HARNESS_ANALYTIC_* (--truth analytic), NONE for the texels
#define HARNESS_PUSH_STOCHASTIC 124  // --stochastic: frame * 4 + HARNESS_NOISE_* (stochastic_noise.glsl); 0 off
#define HARNESS_PUSH_SIZE 128        // padded to a multiple of 16, the block's alignment (vec4 members); 128 is
                                     // Vulkan's least maxPushConstantsSize: nothing more fits

// The scene's uniform block (std140 offsets in bytes; tf::SceneParams): ten vec4s of parameters, then
// three corners a triangle of positions, then of uvs (vec4 arrays: 16-byte stride in std140).
#define HARNESS_SCENE_PARAMS_SIZE 160
#define HARNESS_SCENE_POSITIONS HARNESS_SCENE_PARAMS_SIZE
#define HARNESS_SCENE_UVS (HARNESS_SCENE_POSITIONS + 3 * HARNESS_MAX_TRIANGLES * 16)
#define HARNESS_SCENE_SIZE (HARNESS_SCENE_UVS + 3 * HARNESS_MAX_TRIANGLES * 16)

#define HARNESS_SAMPLE_LOCAL_SIZE 64
// sample: filters whose lookups each get a whole subgroup, every 2x2 quad of it differencing to the lookup's
// gradients (the hw-* filters, through textureGrad; see sample.comp.glsl); every other filter runs one
// invocation a lookup.
#define HARNESS_SAMPLE_IN_QUADS(filter) ((filter) >= HARNESS_FILTER_HW_NEAREST && (filter) <= HARNESS_FILTER_HW_ANISO)

#define HARNESS_SPEC_FILTER 0 // specialization constant id of the filter (HARNESS_FILTER_*)
#define HARNESS_SPEC_MAGNIFY 1 // specialization constant id of level 0's reconstruction (HARNESS_RECONSTRUCT_*)
#define HARNESS_SPEC_STOCHASTIC 2 // specialization constant id: 1 = the stochastic forms (stochastic.glsl), 0 = not
#define HARNESS_SPEC_VIEW 3 // specialization constant id of render's debug view (HARNESS_VIEW_*)
#define HARNESS_SPEC_GRADIENTS 4 // specialization constant id of render's gradients (HARNESS_GRADIENTS_*)
#define HARNESS_SPEC_LOOKUPS 5 // specialization constant id of render's lookups a pixel (bench --lookups-per-pixel)
#define HARNESS_SPEC_SCENE 6 // specialization constant id of render's scene kind (HARNESS_SCENE_*; -1: the scene block's)

// --stochastic: the random numbers of the one-texel forms (tf::Noise; shaders/harness/stochastic_noise.glsl,
// host/core/stochastic_noise.h): white (an integer hash) or blue (a Cranley-Patterson rotated R3 sequence).
#define HARNESS_NOISE_WHITE 1
#define HARNESS_NOISE_BLUE 2
#define HARNESS_MAX_ACCUMULATE 4096 // --accumulate N: 1..this frames averaged

// GPU builds (build_mip.comp.glsl, build_sat.comp.glsl): their own descriptor sets and push constants.
#define HARNESS_MIP_MAX_LEVELS 15  // 16384 a side: 1 + log2(16384) levels, one storage view each
#define HARNESS_BUILD_BINDING_LEVELS 0  // build_mip: image2D[HARNESS_MIP_MAX_LEVELS] rgba32f, coherent
#define HARNESS_BUILD_BINDING_COUNTER 1 // build_mip: buffer { uint }, the tail's group counter
#define HARNESS_BUILD_BINDING_CODES 2   // pack_level: uimage2D[HARNESS_MIP_MAX_LEVELS], integer views of the format's levels
#define HARNESS_BUILD_BINDING_LEVEL0 0  // build_sat: image2D rgba32f, level 0 (readonly)
#define HARNESS_BUILD_BINDING_SAT_LOW 1 // build_sat: uimage2D rgba32ui
#define HARNESS_BUILD_BINDING_SAT_HIGH 2 // build_sat: uimage2D r32ui
#define HARNESS_BUILD_BINDING_RANGE 3   // build_sat: buffer { uint words[9] }
#define HARNESS_BUILD_PUSH_SIZE 32      // ivec2 size0, int sourceLevel (build_mip) or pass (build_sat), int levels, int tail
#define HARNESS_SAT_PASS_RANGE 0
#define HARNESS_SAT_PASS_ROWS 1
#define HARNESS_SAT_PASS_COLUMNS 2
#define HARNESS_ENCODING_FLOAT32 0 // pack_level: a stored channel's encoding (core/texture_format.h)
#define HARNESS_ENCODING_FLOAT16 1
#define HARNESS_ENCODING_UNORM8 2
#define HARNESS_ENCODING_SRGB8 3

#endif
