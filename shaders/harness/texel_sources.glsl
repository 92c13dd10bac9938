// Harness only: the texel-source kinds (HARNESS_RESOURCE_ATLAS, HARNESS_RESOURCE_VIRTUAL). The texture's
// texels lie in u_texture where the words at HARNESS_BINDING_SOURCE say (config.h's layouts; the host builds
// both in host/core/texel_sources.cpp and reads them back the same way for the CPU reference); the includes
// read them through the TF_SOURCE contract (docs/API.md, "Texel sources"): a type and tf_source_size,
// tf_source_levels and tf_source_fetch, declared before texfilter.glsl is included.
//   atlas:   TF_SOURCE is a struct, the tile (its level-0 origin and size in atlas texels, its levels);
//            level l of the tile is the atlas's level l at origin >> l.
//   virtual: TF_SOURCE is an int, where the texture's words start (the harness binds one texture: 0); a
//            texel is found through its level's page table entry.
#ifndef HARNESS_TEXEL_SOURCES_GLSL
#define HARNESS_TEXEL_SOURCES_GLSL

#include "config.h"

layout(set = 0, binding = HARNESS_BINDING_TEXTURE) uniform sampler2D u_texture;
layout(set = 0, binding = HARNESS_BINDING_SOURCE, std430) readonly buffer HarnessSourceWords
{
    int harnessWords[];
};

#if HARNESS_RESOURCE == HARNESS_RESOURCE_ATLAS

struct HarnessAtlasTile {
    ivec2 origin; // level 0, in atlas texels
    ivec2 size;   // level 0
    int levels;
};
#define TF_SOURCE HarnessAtlasTile

HarnessAtlasTile harness_source()
{
    return HarnessAtlasTile(ivec2(harnessWords[HARNESS_ATLAS_ORIGIN_X], harnessWords[HARNESS_ATLAS_ORIGIN_Y]),
                            ivec2(harnessWords[HARNESS_ATLAS_WIDTH], harnessWords[HARNESS_ATLAS_HEIGHT]),
                            harnessWords[HARNESS_ATLAS_LEVELS]);
}

ivec2 tf_source_size(HarnessAtlasTile tile, int level) { return max(tile.size >> level, ivec2(1)); }
int tf_source_levels(HarnessAtlasTile tile) { return tile.levels; }
vec4 tf_source_fetch(HarnessAtlasTile tile, ivec2 texel, int level)
{
    return texelFetch(u_texture, (tile.origin >> level) + texel, level);
}

// hw-*: the hardware sampler on the atlas at the tile's uv, as an engine samples an atlas without texfilter.
// The sampler's wrap mode applies to the whole atlas, so a footprint at the tile's edge reads its neighbours.
vec4 harness_source_grad(vec2 uv, vec2 dUVdx, vec2 dUVdy)
{
    HarnessAtlasTile tile = harness_source();
    vec2 atlas = vec2(textureSize(u_texture, 0));
    vec2 scale = vec2(tile.size) / atlas;
    return textureGrad(u_texture, vec2(tile.origin) / atlas + uv * scale, dUVdx * scale, dUVdy * scale);
}

#elif HARNESS_RESOURCE == HARNESS_RESOURCE_VIRTUAL

#define TF_SOURCE int

int harness_source() { return 0; }

// Word w of level `level`'s header of the texture whose words start at `id`.
int harness_level_word(int id, int level, int w) { return harnessWords[id + 1 + HARNESS_VIRTUAL_LEVEL_WORDS * level + w]; }

ivec2 tf_source_size(int id, int level)
{
    return ivec2(harness_level_word(id, level, HARNESS_VIRTUAL_WIDTH), harness_level_word(id, level, HARNESS_VIRTUAL_HEIGHT));
}
int tf_source_levels(int id) { return harnessWords[id + HARNESS_VIRTUAL_LEVELS]; }
vec4 tf_source_fetch(int id, ivec2 texel, int level)
{
    ivec2 page = texel / HARNESS_VIRTUAL_PAGE; // texel >= 0: division is floor
    int entry = harnessWords[id + harness_level_word(id, level, HARNESS_VIRTUAL_FIRST_PAGE) +
                             page.y * harness_level_word(id, level, HARNESS_VIRTUAL_PAGES_X) + page.x];
    ivec2 physical = ivec2(entry & 0xffff, entry >> 16) * HARNESS_VIRTUAL_PAGE + texel % HARNESS_VIRTUAL_PAGE;
    return texelFetch(u_texture, physical, 0);
}

vec4 harness_source_grad(vec2 uv, vec2 dUVdx, vec2 dUVdy) { return vec4(0.0); } // hw-*: refused by the host

#endif

#endif
