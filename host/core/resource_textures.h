#pragma once
// The textures `sample --resource` binds, made from the one texture the command loads, the same on both
// backends: the layers of an array (or the textures of a bindless array), each with DISTINCT content so
// that a lookup on the wrong layer is caught, and the depth field of the shadow kind.
//
// Layer k (k >= 1) is the texture with its colour channels rotated by k and mixed half-way with a colour of
// its own, every level the same way (an affine map per texel, so a level stays the average of the one above:
// a full MIP chain a layer, as an upload needs); layer 0 is the texture itself, so --layer 0 reads what
// --resource combined reads. Alpha is unchanged.
//
// The depth field: each texel's luminance (Rec. 709 weights) clamped to [0, 1], in .r with (0, 0, 1) in
// g, b, a (how Vulkan reads a depth format); its MIP chain is built from level 0 by averaging, like any
// float chain. Cost: one pass over the chain a layer.
#include "core/resource.h"
#include "texture/mip.h"
#include <vector>

namespace tf {

MipChain make_layer(const MipChain& base, int layer);
MipChain make_depth_chain(const MipChain& base);

// The chains the resource holds, in index order: `layers` of them for the layered kinds, the depth
// chain for shadow, `base` itself otherwise.
std::vector<MipChain> make_resource_chains(const MipChain& base, const ResourceOptions& options);

} // namespace tf
