#pragma once
// The texel-source kinds of `sample --resource` (atlas, virtual): the texture's texels stored somewhere
// else than a texture of their own, and read back through the includes' TF_SOURCE contract (docs/API.md,
// "Texel sources"): a size and a level count for the texture, and a fetch of texel (x, y) of level l, x and y
// already wrapped into [0, size). Built on the host once, the same for both backends: the GPU binds `image`
// and `words` (shaders/harness/texel_sources.glsl reads them), the CPU reference reads the texture back
// through source_fetch, which follows the shader's addressing word for word, and filters that.
//
// atlas: the texture is one tile of a HARNESS_ATLAS_GRID^2 grid of cells of side P (the next power of two
//   >= max(width, height)), in cell (HARNESS_ATLAS_CELL_X, _Y); the other cells hold constant colours of
//   their own and the rest of the texture's cell (a non-square or non-power-of-two tile) another one, so
//   that a read outside the tile shows. The atlas's level l holds the tile's own level l (max(1, w >> l) x
//   max(1, h >> l) by the floor rule) at origin (cell * P) >> l, uploaded as it is, not averaged from the
//   atlas's level 0 (which would mix tiles); a level the tile lacks (the cell is still larger than a texel,
//   or smaller) is the 2x2 average of the atlas level above, as a MIP builder would make it.
// virtual: every level cut into HARNESS_VIRTUAL_PAGE^2 pages (a level's last row and column of pages
//   padded), the pages placed in a deterministic shuffle into one single-level physical texture of
//   ceil(sqrt(pages)) pages a row, unused texels a constant colour; a page table (config.h's layout) maps
//   each level's pages to their places.
//
// Cost: one pass over the texture's levels; the atlas holds HARNESS_ATLAS_GRID^2 P^2 texels at level 0
// (4x a power-of-two square texture), the physical texture about 4/3 of the texture's texels.
#include "core/lookup.h"
#include "core/resource.h"
#include "texture/mip.h"

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace tf {

struct SourceBinding {
    Resource kind = Resource::atlas;
    MipChain image;             // atlas: the atlas, every level; virtual: the physical texture, one level
    std::vector<int32_t> words; // what the shader reads at HARNESS_BINDING_SOURCE (config.h's layout)
};

// The colours of the atlas's other cells (cell index k = y * grid + x), of the texture's cell around the
// tile, and of the physical texture's unused texels.
glm::vec4 atlas_cell_colour(int cell);
glm::vec4 atlas_padding_colour();
glm::vec4 virtual_padding_colour();

// The atlas's or physical texture's size for a width x height texture; check_source_size throws tf::Error
// naming the kind and the sizes when a side would pass `max_side` (a device's maxImageDimension2D), before
// anything is built. make_* check against max_source_side, the host's limit on any texture's side.
constexpr int max_source_side = 16384;
glm::ivec2 source_image_size(Resource kind, int width, int height);
void check_source_size(Resource kind, int width, int height, int max_side);

// The host bytes a width x height texture's source takes beside the texture itself (memory_budget.h's
// add_other): the atlas (every level) or the physical texture and the words; on the CPU reference the
// texture read back through them (read_source); on Vulkan the staging of the image's level 0, and on a CPU
// device (device_in_host_memory) the device's copy of the image as well.
uint64_t source_host_bytes(Resource kind, int width, int height, bool reference, bool device_in_host_memory);

SourceBinding make_atlas(const MipChain& texture);
SourceBinding make_virtual_texture(const MipChain& texture);
SourceBinding make_source_binding(const MipChain& texture, Resource kind); // atlas or virtual

// The contract's three functions as texel_sources.glsl computes them from the words (the virtual texture
// read is id 0, the harness's one texture).
glm::ivec2 source_size(const SourceBinding& b, int level);
int source_levels(const SourceBinding& b);
glm::vec4 source_fetch(const SourceBinding& b, glm::ivec2 texel, int level); // texel in [0, size)

// The texture as the filters see it through the source: every texel of every level by source_fetch.
MipChain read_source(const SourceBinding& b);

// atlas, hw-* filters: the lookup the hardware sampler makes when the shader passes the tile's uv into the
// atlas (what an engine does without texfilter; the sampler's wrap mode then applies to the whole atlas,
// so a footprint that reaches the tile's edge reads the neighbouring cells):
// uv' = (origin + uv * size) / atlas size, gradients times size / atlas size.
Lookup atlas_lookup(const SourceBinding& atlas, const Lookup& lookup);

} // namespace tf
