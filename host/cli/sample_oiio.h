#pragma once
// `texfilter sample --backend oiio`: the lookups answered by OpenImageIO's TextureSystem (io/oiio_texture.h),
// the project's peer, on the same texture's level 0.
#include "core/filter.h"
#include "flags/args.h"

namespace tf {

// --oiio-interp's flag, for sample's list.
FlagSpec oiio_interp_flag();
// Refuses --oiio-interp without --backend oiio (tf::Error naming it).
void check_oiio_interp_unused(const Args& args);
// The whole command once --backend oiio is known and the sampler flags are read: refuses, before any work,
// a --filter other than trilinear or aniso and every flag OIIO does not read (naming it), and a build without
// the peer; then loads the texture's level 0, runs the lookups and writes -o. Returns the exit status.
int run_sample_oiio(const Args& args, const SamplerOptions& options);

} // namespace tf
