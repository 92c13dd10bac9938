// virtual.comp.glsl — texfilter example: virtual textures, their levels cut into pages scattered through one
// physical texture and found through a page table. TF_SOURCE is an int here, the texture's index; the three
// functions read its sizes from the table and fetch a texel from the page that holds it (the texel comes
// already wrapped into the level by the sampler's wrap mode, so a page lookup never leaves the texture).
// Each virtual texture is one constant colour and the physical texture's other texels another (resources.cpp),
// so each lookup must return its texture's colour: a wrong page or a wrong texture shows.
#version 450
#extension GL_GOOGLE_include_directive : require

#define PAGE 4       // texels a page side
#define MAX_LEVELS 8 // levels a virtual texture may have

layout(set = 0, binding = 0) uniform sampler2D u_physical; // one level; pages at multiples of PAGE

struct VirtualLevel {
    ivec2 size;
    int pagesPerRow;
    int firstEntry; // its pages' entries, row by row, from entries[firstEntry]
};
struct VirtualTexture {
    int levels;
    VirtualLevel level[MAX_LEVELS];
};
layout(set = 0, binding = 1, std430) readonly buffer VirtualTextures { VirtualTexture textures[]; };
layout(set = 0, binding = 2, std430) readonly buffer PageEntries { uint entries[]; }; // page x | page y << 16

ivec2 tf_source_size(int t, int level) { return textures[t].level[level].size; }
int tf_source_levels(int t) { return textures[t].levels; }
vec4 tf_source_fetch(int t, ivec2 texel, int level)
{
    VirtualLevel l = textures[t].level[level];
    ivec2 page = texel / PAGE; // texel >= 0 (wrapped)
    uint entry = entries[l.firstEntry + page.y * l.pagesPerRow + page.x];
    return texelFetch(u_physical, ivec2(entry & 0xffffu, entry >> 16) * PAGE + texel % PAGE, 0);
}

#define TF_SOURCE int
#define TF_RESOURCES 0
#include "texfilter/texfilter.glsl"
#include "probes.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 3, std430) writeonly buffer Results { vec4 results[]; };

void main()
{
    uint i = gl_GlobalInvocationID.x;
    Probe p = probe(i);
    p.s = tf_sampler(TF_WRAP_MIRROR);
    int t = probe_index(i * 7u, pc.count);
    results[2u * i + 0u] = tf_trilinear(t, p.uv, p.dx, p.dy, p.s);
    results[2u * i + 1u] = tf_ewa(t, p.uv, p.dx, p.dy, p.s, 2.0, 8.0);
}
