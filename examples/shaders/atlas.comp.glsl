// atlas.comp.glsl — texfilter example: textures packed as tiles of one atlas, filtered without bleeding.
// TF_SOURCE makes every manual filter read a tile's texels through three functions you write: the tile's
// size and level count, and a fetch of one texel, which the filter hands you already wrapped into the tile
// by the sampler's wrap mode. So repeat, clamp and mirror act on the tile, and no footprint reaches a
// neighbour (the hardware sampler at the tile's uv would blend them: docs/images/api/atlas-bleeding.png).
// The atlas holds each tile's own levels: level l of a tile is at origin >> l in the atlas's level l.
// Every tile is one constant colour (resources.cpp), so each lookup must return its tile's colour.
#version 450
#extension GL_GOOGLE_include_directive : require

layout(set = 0, binding = 0) uniform sampler2D u_atlas; // pc.count x pc.count tiles, power-of-two sides

struct AtlasTile {
    ivec2 origin; // level 0, in atlas texels
    ivec2 size;   // level 0
    int levels;
};

ivec2 tf_source_size(AtlasTile tile, int level) { return max(tile.size >> level, ivec2(1)); }
int tf_source_levels(AtlasTile tile) { return tile.levels; }
vec4 tf_source_fetch(AtlasTile tile, ivec2 texel, int level)
{
    return texelFetch(u_atlas, (tile.origin >> level) + texel, level);
}

#define TF_SOURCE AtlasTile
#define TF_RESOURCES 0 // only the AtlasTile overloads: the shader binds no texture of its own to filter
#include "texfilter/texfilter.glsl"
#include "probes.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 1, std430) writeonly buffer Results { vec4 results[]; };

void main()
{
    uint i = gl_GlobalInvocationID.x;
    Probe p = probe(i);
    p.s = tf_sampler(TF_WRAP_REPEAT); // wraps within the tile
    int grid = pc.count, k = probe_index(i * 5u, grid * grid);
    ivec2 side = textureSize(u_atlas, 0) / grid;
    AtlasTile tile = AtlasTile(ivec2(k % grid, k / grid) * side, side, findMSB(side.x) + 1);
    results[2u * i + 0u] = tf_trilinear(tile, p.uv, p.dx, p.dy, p.s);
    results[2u * i + 1u] = tf_ewa(tile, p.uv, p.dx, p.dy, p.s, 2.0, 8.0);
}
