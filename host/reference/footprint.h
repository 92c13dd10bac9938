#pragma once
// The footprint of one pixel's lookup, from the CPU reference in double: what the viewer draws over the
// image under the cursor (the ellipse and aniso's probes) and what the debug views show (LOD, anisotropy;
// shaders/texfilter/debug.glsl is the GPU half, written separately, docs/API.md "debug.glsl").
//
// LOD: the level the filter samples at. aniso: its probes' LOD (log2(Pmax/N) or Feline's); ewa: its level
// rule; every other filter (hw-aniso too: its footprint is implementation-defined): Vulkan's isotropic
// lambda = log2(rho) + bias; all clamped to [lod_min, lod_max] and the levels, as the filters clamp.
// Anisotropy: sigma1/sigma2 of J = [duv/dx duv/dy] in level-0 texels (the pixel's own, before any clamp); 1
// for zero or non-finite gradients, +inf for a footprint of zero area with a non-zero axis.
// Ellipse: half-axes (vectors, uv units) of what the filter integrates, after its clamps: ewa the pixel's
// pre-image J·(disk of radius 1/2) with the minor axis grown to major/max_aniso; aniso the probes' line
// (half the axis they span, at least the level's half texel) by half the level's texel 2^lod across it;
// the others a circle of half the level's texel. Cost: four ray casts and the filter's footprint math.
//
// Example: PixelFootprint f = pixel_footprint(scene, chain, options, render, {x, y});
//          if (f.hit) draw_ellipse(f.uv, f.major, f.minor), draw_points(f.probes);
#include "core/filter.h"
#include "core/lookup.h"
#include "scene/scene.h"
#include "texture/mip.h"
#include <glm/glm.hpp>
#include <vector>

namespace tf {

struct PixelFootprint {
    bool hit = false;
    glm::dvec2 uv{0.0}, duv_dx{0.0}, duv_dy{0.0}; // the lookup the GPU makes there (the reference's quads)
    double lod = 0.0;
    double anisotropy = 1.0;
    glm::dvec2 major{0.0}, minor{0.0}; // ellipse half-axes in uv
    std::vector<glm::dvec2> probes;    // aniso: probe centres in uv; empty for the other filters
};

// Pixel (x, y) of the scene as reference_render sees it (the same quad derivatives; a miss: hit false, the
// rest the unbounded surface's). Throws tf::Error for a pixel outside the image or an empty chain.
PixelFootprint pixel_footprint(const SceneParams& scene, const MipChain& chain, const SamplerOptions& options,
                               const RenderOptions& render, glm::ivec2 pixel);

// The same for one lookup (hit true).
PixelFootprint lookup_footprint(const MipChain& chain, const SamplerOptions& options, const Lookup& lookup);

// sigma1/sigma2 of the lookup's J in level-0 texels (the rules above).
double footprint_anisotropy(const MipChain& chain, const Lookup& lookup);

} // namespace tf
