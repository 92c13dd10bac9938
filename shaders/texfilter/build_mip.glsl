// texfilter/build_mip.glsl — the MIP chain every texfilter filter reads, built on the GPU by a compute
// shader you dispatch: the same levels as tf::build_mip_chain (texture/mip.h), within float rounding.
//
// Use:     define, before the include, how a level's texel is read and written, then call one function a
//          dispatch (docs/API.md "build_mip.glsl" has the whole shader):
//              #define TF_MIP_LOAD(level, p)      imageLoad(chain[level], p)   // vec4, level's texel p
//              #define TF_MIP_STORE(level, p, v)  imageStore(chain[level], p, v)
//              #define TF_MIP_COUNTER             counter.value  // coherent buffer uint, 0 before the first
//                                                                // dispatch; the last group resets it to 0
//              #include "texfilter/build_mip.glsl"
//              layout(local_size_x = TF_MIP_GROUP_SIZE) in;
//              void tf_build_mip_pass(int sourceLevel, int passLevels, bool tail, ivec2 size0);
//          One dispatch a pass of tf::plan_mip_build (texfilter/host.h): groups = pass.groups_x x
//          pass.groups_y, the pass's fields as push constants, a compute -> compute barrier (shader writes ->
//          shader reads) between passes. Also: ivec2 tf_mip_level_size(ivec2 size0, int level).
// Math:    size_l = max(1, size_0 >> l). Below an even (or 1-texel) side, texel i averages source texels 2i
//          and 2i+1 (or takes i); below an odd side 2d+1, texels 2i, 2i+1, 2i+2 at weights (d−i, d, i+1)/(2d+1)
//          (each source texel's overlap with the destination's box). Separable, rows first, in float: within
//          12.5·2^-23·Σ w·|x| of tf::downsample's double sums, plus 16·2^-126 where denormals are flushed.
// Options: TF_MIP_TAIL_TEXELS (default 16384, i.e. 128 x 128): the largest level the last group finishes
//          alone; host and shader must agree (tf::mip_build_tail_texels).
// Needs:   a compute shader with local size TF_MIP_GROUP_SIZE; one storage view a level (image2D chain[N],
//          rgba32f or rgba16f), `coherent` (the tail's group reads what other groups wrote in the same
//          dispatch); TF_MIP_COUNTER a coherent buffer member; a 16 KB shared tile (every Vulkan device). Level 0
//          in linear light: decode sRGB first; store 8-bit, sRGB and half levels through encode.glsl.
// Cost:    every level read once and written once (the tile's levels from shared memory): memory bound,
//          ~1.33x level 0's bytes read and written. A 2^k texture up to 8192² is one dispatch; odd levels take
//          one dispatch each until a level fits the tail.
// Degenerate input: none checked: a NaN or ±Inf texel spreads into every texel of the levels below it that
//          averages it (as tf::build_mip_chain's do). Without TF_MIP_LOAD the include stops with an #error.
// Example: tf_build_mip_pass(pc.sourceLevel, pc.levels, pc.tail != 0, pc.size0); // in main()
#ifndef TF_BUILD_MIP_GLSL
#define TF_BUILD_MIP_GLSL

// Passes. A pass reads its source level through TF_MIP_LOAD and writes `passLevels` levels below it (1..6).
// A group makes a 32 x 32 tile of the first, keeps it in shared memory and halves it for the next ones
// (32 -> 16 -> ... -> 1), so every level of a pass after its first must come from an even or 1-texel side
// on both axes (no texel of another tile needed). With `tail`, the group that finishes last (counted
// through TF_MIP_COUNTER, as single-pass downsamplers hand over their last levels) then builds every
// remaining level alone, reading and writing the images, any parity; the planner adds the tail once the
// pass's last level has at most TF_MIP_TAIL_TEXELS texels.
// sRGB, 8-bit and half-float textures: storage images of sRGB formats are not writable on most devices,
// and a store's float -> unorm or -> half conversion may round to either neighbour. Build the chain in
// linear light in an RGBA32F image, then store each level's codes (tf_mip_srgb8, tf_mip_unorm8,
// tf_mip_half: the host's rounding, exactly) through an integer view (R8G8B8A8_UINT, R16G16B16A16_UINT,
// ...) of the target image created with VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT. vkCmdBlitImage from the
// RGBA32F chain also converts, with the device's own rounding (docs/DESIGN.md has a measured case).

#include "encode.glsl"

#ifndef TF_MIP_LOAD
#error "texfilter/build_mip.glsl: define TF_MIP_LOAD(level, p) (and TF_MIP_STORE, TF_MIP_COUNTER) before including it"
#endif
#ifndef TF_MIP_TAIL_TEXELS
#define TF_MIP_TAIL_TEXELS 16384
#endif
#define TF_MIP_GROUP_SIZE 256
#define TF_MIP_TILE 32

// Vulkan's floor rule.
ivec2 tf_mip_level_size(ivec2 size0, int level)
{
    return max(ivec2(1), size0 >> level);
}

// One axis: the source texels (first index, count 1..3) and weights of destination texel i when a side of
// `src` texels becomes `dst` (the floor rule: dst = max(1, src >> 1)).
void tfi_mip_axis(int i, int src, int dst, out int first, out int count, out vec3 w)
{
    if (src == 1) {
        first = i; count = 1; w = vec3(1.0, 0.0, 0.0);
    } else if ((src & 1) == 0) {
        first = 2 * i; count = 2; w = vec3(0.5, 0.5, 0.0);
    } else { // src = 2d + 1: each source texel's overlap with [i, i+1)·(2d+1)/d, over (2d+1)/d
        float n = float(src);
        first = 2 * i; count = 3;
        w = vec3(float(dst - i) / n, float(dst) / n, float(i + 1) / n);
    }
}

// Destination texel q of `level` from level − 1 (size srcSize), read through TF_MIP_LOAD.
vec4 tfi_mip_texel(int level, ivec2 srcSize, ivec2 dstSize, ivec2 q)
{
    if (((srcSize.x | srcSize.y) & 1) == 0) { // the common case, unrolled: 2 x 2 texels at 1/2 a side
        const ivec2 s = 2 * q;
        const vec4 top = 0.5 * TF_MIP_LOAD(level - 1, s) + 0.5 * TF_MIP_LOAD(level - 1, s + ivec2(1, 0));
        const vec4 bottom = 0.5 * TF_MIP_LOAD(level - 1, s + ivec2(0, 1)) + 0.5 * TF_MIP_LOAD(level - 1, s + ivec2(1, 1));
        return 0.5 * top + 0.5 * bottom;
    }
    int fx, nx, fy, ny;
    vec3 wx, wy;
    tfi_mip_axis(q.x, srcSize.x, dstSize.x, fx, nx, wx);
    tfi_mip_axis(q.y, srcSize.y, dstSize.y, fy, ny, wy);
    vec4 sum = vec4(0.0);
    for (int b = 0; b < ny; ++b) {
        vec4 row = vec4(0.0);
        for (int a = 0; a < nx; ++a)
            row += wx[a] * TF_MIP_LOAD(level - 1, ivec2(fx + a, fy + b));
        sum += wy[b] * row;
    }
    return sum;
}

shared vec4 tfi_mip_tile[TF_MIP_TILE * TF_MIP_TILE]; // 16 KB: the group's tile of its current level
shared bool tfi_mip_last;

// Builds every level below `sourceLevel` up to sourceLevel + passLevels (1..6) of this group's tile, then with
// `tail` and if this group is the last to finish, every level after those. size0: level 0's size.
void tf_build_mip_pass(int sourceLevel, int passLevels, bool tail, ivec2 size0)
{
    const uint lid = gl_LocalInvocationIndex;
    const ivec2 group = ivec2(gl_WorkGroupID.xy);
    // The pass's first level: a 32 x 32 tile, four texels an invocation, any source parity.
    {
        const int level = sourceLevel + 1;
        const ivec2 srcSize = tf_mip_level_size(size0, sourceLevel), dstSize = tf_mip_level_size(size0, level);
        for (uint k = 0u; k < 4u; ++k) {
            const uint t = lid + k * uint(TF_MIP_GROUP_SIZE);
            const ivec2 q = group * TF_MIP_TILE + ivec2(t % uint(TF_MIP_TILE), t / uint(TF_MIP_TILE));
            vec4 v = vec4(0.0);
            if (all(lessThan(q, dstSize))) {
                v = tfi_mip_texel(level, srcSize, dstSize, q);
                TF_MIP_STORE(level, q, v);
            }
            tfi_mip_tile[t] = v;
        }
    }
    // The pass's other levels from the tile: side 16, 8, ..., each from a halving (or 1-texel) source.
    for (int l = 2; l <= passLevels; ++l) {
        const int level = sourceLevel + l;
        const int side = TF_MIP_TILE >> (l - 1), srcSide = side * 2;
        const ivec2 srcSize = tf_mip_level_size(size0, level - 1), dstSize = tf_mip_level_size(size0, level);
        const ivec2 srcOrigin = group * srcSide, origin = group * side;
        barrier(); // the tile of level − 1 is whole
        vec4 v = vec4(0.0);
        const ivec2 p = ivec2(int(lid) % side, int(lid) / side);
        const ivec2 q = origin + p;
        const bool inside = int(lid) < side * side && all(lessThan(q, dstSize));
        if (inside) {
            int fx, nx, fy, ny;
            vec3 wx, wy;
            tfi_mip_axis(q.x, srcSize.x, dstSize.x, fx, nx, wx);
            tfi_mip_axis(q.y, srcSize.y, dstSize.y, fy, ny, wy);
            vec4 sum = vec4(0.0);
            for (int b = 0; b < ny; ++b) {
                vec4 row = vec4(0.0);
                for (int a = 0; a < nx; ++a) {
                    const ivec2 s = ivec2(fx + a, fy + b) - srcOrigin;
                    row += wx[a] * tfi_mip_tile[s.y * srcSide + s.x];
                }
                sum += wy[b] * row;
            }
            v = sum;
            TF_MIP_STORE(level, q, v);
        }
        barrier(); // every read of level − 1's tile is done
        if (int(lid) < side * side)
            tfi_mip_tile[p.y * side + p.x] = v;
    }
    const int last = sourceLevel + passLevels;
    const int finalLevel = int(findMSB(uint(max(size0.x, size0.y))));
    if (!tail || last >= finalLevel)
        return;
    // Hand the rest to the group that finishes last: its stores are ordered before its count, and every
    // other group's before theirs, so the last one sees every texel of level `last`.
    memoryBarrier();
    barrier();
    if (lid == 0u) {
        const uint groups = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
        tfi_mip_last = atomicAdd(TF_MIP_COUNTER, 1u) == groups - 1u;
    }
    barrier();
    if (!tfi_mip_last)
        return;
    memoryBarrier();
    for (int level = last + 1; level <= finalLevel; ++level) {
        const ivec2 srcSize = tf_mip_level_size(size0, level - 1), dstSize = tf_mip_level_size(size0, level);
        const uint texels = uint(dstSize.x * dstSize.y);
        for (uint t = lid; t < texels; t += uint(TF_MIP_GROUP_SIZE)) {
            const ivec2 q = ivec2(t % uint(dstSize.x), t / uint(dstSize.x));
            TF_MIP_STORE(level, q, tfi_mip_texel(level, srcSize, dstSize, q));
        }
        memoryBarrier(); // level's stores visible to the group's reads of the next level
        barrier();
    }
    if (lid == 0u)
        TF_MIP_COUNTER = 0u; // ready for the next dispatch
}

#endif // TF_BUILD_MIP_GLSL
