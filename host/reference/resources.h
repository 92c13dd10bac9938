#pragma once
// The CPU reference for `sample --resource`: each lookup filtered on the texture the harness gives it
// (core/resource.h's texture_index: an array's clamped layer, a bindless array's (first + i) % count),
// and percentage-closer filtering for the shadow kind: the depth chain's texels compared with dref on
// every level BEFORE filtering (Vulkan: a texel passes, 1, when `dref OP D`, else 0), then the ordinary
// reference filter over those 0/1 texels. The result is the lit fraction in all four channels, as the
// includes' tf_compare forms return it. Independent of the GLSL (double, from the spec's formulas).
#include "core/resource.h"
#include "core/texel_sources.h"
#include "reference/reference.h"
#include <vector>

namespace tf {

// Every texel of every level of `depth` (D in .r) replaced by vec4(compare_depth(op, dref, D)).
MipChain compare_chain(const MipChain& depth, CompareOp op, double dref);

// chains: core/resource_textures.h's make_resource_chains for `resource`. dref is read as the float the
// shader sees.
std::vector<glm::dvec4> reference_sample_resource(const std::vector<MipChain>& chains,
                                                  const std::vector<Lookup>& lookups, const SamplerOptions& options,
                                                  const ResourceOptions& resource);

// The texel-source kinds (atlas, virtual; core/texel_sources.h): the texture read back through the source's
// addressing (read_source: every texel by source_fetch, as the shader's tf_source_fetch finds it), then the
// ordinary reference on it. The hw-* filters on the atlas read the atlas itself at the tile's uv
// (atlas_lookup), with the sampler's wrap mode over the whole atlas: they bleed, as the hardware does.
std::vector<glm::dvec4> reference_sample_source(const SourceBinding& source, const std::vector<Lookup>& lookups,
                                                const SamplerOptions& options);

} // namespace tf
