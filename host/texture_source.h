#pragma once
// Where a texture comes from: a procedural name (checker, zoneplate, ...) or an image file.
#include "image_io.h"
#include "mip.h"
#include <string>

namespace tf {

struct TextureSource {
    std::string name_or_path;        // a procedural name wins over a file of the same name (use ./name)
    int procedural_size = 256;       // --texture-size, procedural textures only
    ColorSpace color = ColorSpace::automatic; // files only: --linear forces data/linear
};

// The largest texture side accepted from a file before any device is asked (Vulkan guarantees 4096;
// desktop GPUs and lavapipe allow 16384). Bigger files are rejected with a clear message.
constexpr int max_texture_dimension = 16384;

MipChain load_texture(const TextureSource& source);

} // namespace tf
