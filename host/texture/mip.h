#pragma once
// MIP chains built on the host in linear light, following Vulkan's floor rule for sizes.
#include "texture/image.h"

namespace tf {

struct MipChain {
    std::vector<Image> levels; // levels[0] is the full-resolution texture
};

// 1 + floor(log2(max(width, height))): the full chain down to 1x1.
int mip_level_count(int width, int height);

// Next level: size max(1, w >> 1) x max(1, h >> 1). Each destination texel is the box average of the
// source region it covers, [i*W/W', (i+1)*W/W'), weighted by overlap: 2 texels per axis for even sizes,
// 3 (with weights 1/2W'... as overlap lengths) for odd ones, so no source texel is dropped. Separable.
Image downsample(const Image& source);

// Level 0 plus every level down to 1x1.
MipChain build_mip_chain(Image level0);

} // namespace tf
