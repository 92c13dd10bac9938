#pragma once
// Where a texture comes from: a procedural name (checker, zoneplate, ...) or an image file.
#include "io/image_io.h"
#include "core/memory_budget.h"
#include "core/texture_build.h"
#include "core/texture_format.h"
#include "core/lookup.h"
#include "texture/mip.h"
#include <cstdint>
#include <string>

namespace tf {

struct TextureSource {
    std::string name_or_path;        // a procedural name wins over a file of the same name (use ./name)
    int procedural_size = 256;       // --texture-size, procedural textures only
    ColorSpace color = ColorSpace::automatic; // files only: --linear forces data/linear
    uint64_t memory_budget = 0;      // --memory-budget in bytes; 0: default_memory_budget()
    // --format: what the upload stores; load_texture rounds every level to it (quantise_chain), so the
    // CPU reference reads the texels the device does.
    TextureFormat format = TextureFormat::rgba32f;
    // --build: cpu builds the MIP chain (and SAT) on the host and uploads every level; gpu uploads level 0 and
    // the device builds the rest (core/texture_build.h).
    TextureBuild build = TextureBuild::cpu;
    // --texture-frame: the frame of the "dynamic" procedural texture (tf::dynamic_texture; 0 = make_procedural's);
    // any other texture must leave it 0 (load_texture and check_texture refuse it).
    int texture_frame = 0;
    // --env: what an environment scene (skybox, reflect) makes of the texture: a cube map or a lat-long map
    // (io/environment_source.h). The 2D scenes ignore it.
    EnvMap env = EnvMap::cube;
};

// A --texture is a procedural name (the 2D ones, or the environment scenes' cube-only ones) or an image file.
bool is_procedural_texture(const std::string& name);
// "cube-labels, cube-hash, ..., mipcolors or dynamic": every procedural name, for messages.
std::string procedural_texture_names();
// A procedural name, or a file this process can open: else tf::Error "unknown texture 'NAME': not a procedural
// texture (...) and no such file", or the system's reason ("PATH: Permission denied"). Commands call it as
// they read their flags, before any device is opened; check_texture calls it again when the texture loads
// (the viewer's script names files that a screenshot may write first).
void check_texture_name(const std::string& name_or_path);

// The animated procedural texture: the only one with frames (--texture-frame), rebuilt every frame on the
// device by the viewer with --build gpu (vulkan/gpu_build.h).
bool is_dynamic_texture(const TextureSource& source);
constexpr int max_texture_frame = 1000000;

// What the texture will be used for, which decides how much memory loading it takes.
struct TextureUse {
    bool sat = false;                      // a summed-area table is built (sat, sat-assembly): at most 4096 a side
    const DeviceLimits* device = nullptr;  // uploaded to this Vulkan device (and a staging copy on the host)
    bool streamed = false;                 // with a device: level 0 decoded into staging (read_level0), no MipChain
    // load_texture gives level 0 alone, as decoded, not rounded to the format (--build gpu: the upload rounds
    // it, and the device builds the other levels from the unrounded texels, as build_mip_chain does).
    bool level0_only = false;
    // What the command holds beside the texture while it lives (render_output_bytes, the lookups): checked
    // against the memory budget with the texture, in one message that names it.
    uint64_t other_bytes = 0;
    std::string other_what;
};

// The largest texture side accepted from a file before any device is asked (Vulkan guarantees 4096;
// desktop GPUs and lavapipe allow 16384). Bigger files are rejected with a clear message.
constexpr int max_texture_dimension = 16384;

// Checks the size (the file's header, or the procedural side) against the limits of `use` and the memory
// budget before anything is decoded or allocated, then loads and builds the MIP chain, every level rounded
// to source.format. Throws tf::Error naming the texture.
MipChain load_texture(const TextureSource& source, const TextureUse& use = {});

// The checks of load_texture alone: the texture's level-0 size, nothing decoded.
struct TextureSize {
    int width = 0, height = 0;
};
TextureSize check_texture(const TextureSource& source, const TextureUse& use = {});

// Image files: level 0 is all there is to load (the rest of the chain is built from it), so it can be decoded
// straight into memory of the caller's, such as a device's staging buffer. Procedural textures (mipcolors
// gives each level its own colour) come whole from load_texture.
bool streams_level0(const TextureSource& source);

// Decodes the file's level 0 (linear RGBA, as load_texture) into size.width x size.height texels, the size
// check_texture gave. Throws tf::Error as load_texture; for a procedural source, says to use load_texture.
void read_level0(const TextureSource& source, TextureSize size, glm::vec4* texels);

} // namespace tf
