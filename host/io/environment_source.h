#pragma once
// The environment map an environment scene (skybox, reflect) reads, from --texture and --env
// (docs/ENVIRONMENT.md): a cube map made procedurally or cut from a horizontal-cross image, or a lat-long map
// from a 2:1 image (or the procedural cube resampled, so that both maps show the same environment).
#include "core/environment.h"
#include "io/texture_source.h"

namespace tf {

// Checks the size against the memory budget (and the device's limits in `use`) before anything is made,
// then loads. Environment maps are RGBA32F and built on the host: another --format or --build gpu throws
// tf::Error naming the flag, as does a file that is not the layout --env asks for.
EnvironmentMap load_environment(const TextureSource& source, const TextureUse& use = {});

} // namespace tf
