// resources.cpp — texfilter example: the resource kinds engines bind, checked against the CPU.
// shaders/layers.comp.glsl filters a texture array bound as texture2DArray + a separate sampler (one
// explicit layer per lookup, tf_trilinear and tf_ewa_hw); shaders/bindless.comp.glsl a bindless array of
// sampler2D indexed with nonuniformEXT (tf_trilinear and tf_ewa), where the device has descriptor
// indexing. Every layer and every array element is one constant colour, so each lookup must return its
// layer's or element's colour: the program computes which one on the CPU and fails (exit status 1) on a
// mismatch, a wrong layer or element, or any validation message.
//
// Usage: texfilter_resources            TEXFILTER_EXAMPLE_DEVICE=SUBSTRING picks the Vulkan device by name.
#include "vulkan_util.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

// SPIR-V from texfilter_add_shaders(... COMPILER glslc EMBED): `const std::uint32_t layers_comp[]` ...
#include "atlas_comp.h"
#include "bindless_comp.h"
#include "layers_comp.h"
#include "virtual_comp.h"

namespace {

constexpr uint32_t SIZE = 16, LEVELS = 5; // 16x16 with its full MIP chain (tf_ewa needs every level)
constexpr int32_t LAYERS = 4, TEXTURES = 3;
constexpr uint32_t PROBES = 256, WORKGROUP = 64; // local_size_x in the shaders
constexpr uint32_t RESULTS = 2;                   // vec4s a probe writes
constexpr VkFormat FORMAT = VK_FORMAT_R16G16B16A16_SFLOAT; // linear filtering is mandatory for it

struct Rgba {
    float c[4];
};
// Multiples of 1/16 in [0, 1]: exact in half floats, so the texels are what the CPU expects.
Rgba layer_colour(int32_t k) { return {{0.125f * float(k + 1), 1.0f - 0.125f * float(k + 1), 0.0625f * float(k), 1.0f}}; }
Rgba texture_colour(int32_t j) { return {{0.25f + 0.0625f * float(j), 0.5f, 0.75f - 0.0625f * float(j), 0.5f + 0.125f * float(j)}}; }

// The shaders' indices (probes.glsl's probe_index): layers.comp.glsl's layer (before the includes clamp it
// to [0, LAYERS - 1]) and bindless.comp.glsl's element.
int32_t probe_layer(uint32_t i) { return int32_t(i % uint32_t(LAYERS + 2)) - 1; }
int32_t probe_texture(uint32_t i) { return int32_t((i * 7u) % uint32_t(TEXTURES)); }

// A float that half represents exactly (normal or zero) as its bits; anything else is a bug here.
uint16_t to_half(float v)
{
    if (v == 0.0f)
        return 0;
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    int32_t exponent = int32_t((bits >> 23) & 0xff) - 127 + 15;
    if (exponent < 1 || exponent > 30 || (bits & 0x1fff) != 0)
        fail("colour " + std::to_string(v) + " is not exact in half float");
    return uint16_t(((bits >> 16) & 0x8000) | (uint32_t(exponent) << 10) | ((bits >> 13) & 0x3ff));
}

// A square image of side `side` (a power of two), `levels` levels and `layers` layers, texel (x, y) of
// `level` in `layer` = texel(level, layer, x, y).
template <class Texel>
Image upload_image(const Context& context, uint32_t side, uint32_t levels, uint32_t layers, Texel texel)
{
    Image image = create_image(context, FORMAT, side, side, levels, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               layers);
    VkDeviceSize total = 0;
    for (uint32_t level = 0; level < levels; ++level)
        total += VkDeviceSize(side >> level) * (side >> level) * 4 * sizeof(uint16_t) * layers;
    Buffer staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    auto* words = static_cast<uint16_t*>(staging.mapped);
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t level = 0; level < levels; ++level) {
        const uint32_t size = side >> level;
        for (uint32_t layer = 0; layer < layers; ++layer) {
            for (uint32_t t = 0; t < size * size; ++t) {
                const Rgba colour = texel(level, layer, t % size, t / size);
                for (uint32_t c = 0; c < 4; ++c)
                    words[offset / 2 + t * 4 + c] = to_half(colour.c[c]);
            }
            regions.push_back({.bufferOffset = offset,
                               .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, layer, 1},
                               .imageExtent = {size, size, 1}});
            offset += VkDeviceSize(size) * size * 4 * sizeof(uint16_t);
        }
    }
    submit_and_wait(context, [&](VkCommandBuffer commands) {
        image_barrier(commands, image.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(commands, staging.buffer, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(regions.size()), regions.data());
        image_barrier(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT);
    });
    destroy_buffer(context, staging);
    return image;
}

// One image (`colours.size()` layers), every level of layer k filled with colours[k].
Image upload_constant_layers(const Context& context, const std::vector<Rgba>& colours)
{
    return upload_image(context, SIZE, LEVELS, uint32_t(colours.size()),
                        [&](uint32_t, uint32_t layer, uint32_t, uint32_t) { return colours[layer]; });
}

// atlas.comp.glsl's atlas: ATLAS_GRID x ATLAS_GRID tiles of SIZE^2 texels, tile k (row by row) one colour,
// layer_colour(k), on each of its own levels (at origin >> l of the atlas's level l); the atlas's last level,
// smaller than a tile's last, is never read through a tile: it holds tile 0's colour.
constexpr uint32_t ATLAS_GRID = 2;
Image upload_atlas(const Context& context)
{
    const uint32_t side = ATLAS_GRID * SIZE;
    return upload_image(context, side, LEVELS + 1, 1, [](uint32_t level, uint32_t, uint32_t x, uint32_t y) {
        const uint32_t tile = SIZE >> level;
        return layer_colour(tile == 0 ? 0 : int32_t((y / tile) * ATLAS_GRID + x / tile));
    });
}

// virtual.comp.glsl's textures and pages: VIRTUAL_TEXTURES textures of SIZE^2 texels (LEVELS levels), texture
// j all texture_colour(j), cut into PAGE^2 pages that lie scattered in one physical texture of
// PHYSICAL_PAGES^2 pages; the page table as the shader's two buffers declare it (std430).
constexpr uint32_t PAGE = 4, PHYSICAL_PAGES = 8, MAX_LEVELS = 8; // virtual.comp.glsl's PAGE and MAX_LEVELS
constexpr int32_t VIRTUAL_TEXTURES = 2;
const Rgba UNUSED_PAGE = {{1.0f, 0.0f, 1.0f, 1.0f}};
struct VirtualLevel {
    int32_t width, height, pagesPerRow, firstEntry;
};
struct VirtualTexture {
    int32_t levels, pad; // std430: level[] is 8-byte aligned (its struct's largest member, an ivec2)
    VirtualLevel level[MAX_LEVELS];
};
static_assert(sizeof(VirtualTexture) == 136, "virtual.comp.glsl's VirtualTexture in std430");
struct VirtualPages {
    std::vector<VirtualTexture> textures;
    std::vector<uint32_t> entries;  // physical page x | y << 16
    std::vector<int32_t> pageOwner; // the texture whose page lies at physical page n (row by row), or -1
};
VirtualPages make_virtual_pages()
{
    VirtualPages v;
    v.pageOwner.assign(PHYSICAL_PAGES * PHYSICAL_PAGES, -1);
    uint32_t n = 0;
    for (int32_t t = 0; t < VIRTUAL_TEXTURES; ++t) {
        VirtualTexture texture{.levels = int32_t(LEVELS)};
        for (uint32_t l = 0; l < LEVELS; ++l) {
            const uint32_t size = SIZE >> l, pages = (size + PAGE - 1) / PAGE;
            texture.level[l] = {int32_t(size), int32_t(size), int32_t(pages), int32_t(v.entries.size())};
            for (uint32_t p = 0; p < pages * pages; ++p, ++n) {
                const uint32_t slot = (n * 29u + 11u) % (PHYSICAL_PAGES * PHYSICAL_PAGES); // 29 is odd: distinct slots
                v.entries.push_back((slot % PHYSICAL_PAGES) | (slot / PHYSICAL_PAGES) << 16);
                v.pageOwner[slot] = t;
            }
        }
        v.textures.push_back(texture);
    }
    if (n > PHYSICAL_PAGES * PHYSICAL_PAGES)
        fail("virtual textures: " + std::to_string(n) + " pages do not fit the physical texture");
    return v;
}

// One descriptor of a binding: image views and/or samplers (one per array element), or a storage buffer.
struct Resource {
    VkDescriptorType type;
    std::vector<VkDescriptorImageInfo> images; // empty for a buffer
    VkDescriptorBufferInfo buffer{};           // VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
};
uint32_t descriptor_count(const Resource& r) { return r.images.empty() ? 1u : uint32_t(r.images.size()); }

// Runs `code` (PROBES invocations) with `resources` at bindings 0, 1, ... and the results buffer after them,
// push constant `count`; returns the PROBES * RESULTS vec4s it wrote.
std::vector<float> run_probes(const Context& context, const uint32_t* code, size_t bytes, const std::vector<Resource>& resources,
                              int32_t count)
{
    const VkDeviceSize resultBytes = VkDeviceSize(PROBES) * RESULTS * 4 * sizeof(float);
    Buffer results = create_host_buffer(context, resultBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    std::vector<VkDescriptorPoolSize> poolSizes;
    for (const Resource& r : resources) {
        bindings.push_back({uint32_t(bindings.size()), r.type, descriptor_count(r), VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        poolSizes.push_back({r.type, descriptor_count(r)});
    }
    bindings.push_back({uint32_t(bindings.size()), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    poolSizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1});
    VkDescriptorSetLayoutCreateInfo setLayoutInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                                  .bindingCount = uint32_t(bindings.size()), .pBindings = bindings.data()};
    VkDescriptorSetLayout setLayout;
    VK_CHECK(vkCreateDescriptorSetLayout(context.device, &setLayoutInfo, nullptr, &setLayout));
    VkDescriptorPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, .maxSets = 1,
                                        .poolSizeCount = uint32_t(poolSizes.size()), .pPoolSizes = poolSizes.data()};
    VkDescriptorPool pool;
    VK_CHECK(vkCreateDescriptorPool(context.device, &poolInfo, nullptr, &pool));
    VkDescriptorSetAllocateInfo setInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                        .descriptorPool = pool, .descriptorSetCount = 1, .pSetLayouts = &setLayout};
    VkDescriptorSet set;
    VK_CHECK(vkAllocateDescriptorSets(context.device, &setInfo, &set));
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t b = 0; b < resources.size(); ++b)
        writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = set, .dstBinding = b,
                          .descriptorCount = descriptor_count(resources[b]), .descriptorType = resources[b].type,
                          .pImageInfo = resources[b].images.empty() ? nullptr : resources[b].images.data(),
                          .pBufferInfo = resources[b].images.empty() ? &resources[b].buffer : nullptr});
    VkDescriptorBufferInfo resultsInfo{results.buffer, 0, VK_WHOLE_SIZE};
    writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = set, .dstBinding = uint32_t(resources.size()),
                      .descriptorCount = 1, .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, .pBufferInfo = &resultsInfo});
    vkUpdateDescriptorSets(context.device, uint32_t(writes.size()), writes.data(), 0, nullptr);

    VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof count}; // probes.glsl's pc.count
    VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, .setLayoutCount = 1,
                                          .pSetLayouts = &setLayout, .pushConstantRangeCount = 1, .pPushConstantRanges = &pushRange};
    VkPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout(context.device, &layoutInfo, nullptr, &layout));
    VkShaderModule module = create_shader_module(context, code, bytes);
    VkComputePipelineCreateInfo pipelineInfo{.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
                                             .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                                       .stage = VK_SHADER_STAGE_COMPUTE_BIT, .module = module, .pName = "main"},
                                             .layout = layout};
    VkPipeline pipeline;
    VK_CHECK(vkCreateComputePipelines(context.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline));
    vkDestroyShaderModule(context.device, module, nullptr);

    submit_and_wait(context, [&](VkCommandBuffer commands) {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
        vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof count, &count);
        vkCmdDispatch(commands, PROBES / WORKGROUP, 1, 1);
        VkMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER, .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                               .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                             nullptr, 0, nullptr);
    });
    const float* mapped = static_cast<const float*>(results.mapped);
    std::vector<float> values(mapped, mapped + PROBES * RESULTS * 4);

    vkDestroyPipeline(context.device, pipeline, nullptr);
    vkDestroyPipelineLayout(context.device, layout, nullptr);
    vkDestroyDescriptorPool(context.device, pool, nullptr); // frees the set
    vkDestroyDescriptorSetLayout(context.device, setLayout, nullptr);
    destroy_buffer(context, results);
    return values;
}

// Compares result `slot` of every probe with the colour `expected(i)`, relative to its largest channel;
// prints a line and returns whether all are within `bound`.
template <class Expected>
bool check(const char* what, const std::vector<float>& values, uint32_t slot, float bound, Expected expected)
{
    float worst = 0.0f;
    uint32_t firstBad = UINT32_MAX;
    for (uint32_t i = 0; i < PROBES; ++i) {
        const Rgba wanted = expected(i);
        float scale = 0.0f, error = 0.0f;
        for (uint32_t c = 0; c < 4; ++c) {
            scale = std::fmax(scale, std::fabs(wanted.c[c]));
            float d = std::fabs(values[(i * RESULTS + slot) * 4 + c] - wanted.c[c]);
            error = std::isnan(d) ? INFINITY : std::fmax(error, d);
        }
        error /= scale;
        if (error > bound && firstBad == UINT32_MAX)
            firstBad = i;
        worst = std::fmax(worst, error);
    }
    bool ok = firstBad == UINT32_MAX;
    std::printf("%s: %u probes, max relative error %.3g, bound %.3g: %s", what, PROBES, worst, bound, ok ? "ok\n" : "FAILED");
    if (!ok) {
        const float* v = &values[(firstBad * RESULTS + slot) * 4];
        std::printf(" (probe %u: got %.6f %.6f %.6f %.6f)\n", firstBad, v[0], v[1], v[2], v[3]);
    }
    return ok;
}

} // namespace

int main(int argc, char**)
{
    if (argc > 1) {
        std::fprintf(stderr, "usage: texfilter_resources (no arguments)\n");
        return 2;
    }
    Context context = create_context();
    std::printf("device: %s\n", context.properties.deviceName);

    // tf_ewa_hw's taps: linear min/mag, the shaders' wrap (clamp), no LOD clamp (ewa.glsl's "Needs").
    VkSamplerCreateInfo samplerInfo{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                    .magFilter = VK_FILTER_LINEAR, .minFilter = VK_FILTER_LINEAR,
                                    .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                    .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                    .maxLod = VK_LOD_CLAMP_NONE};
    VkSampler sampler;
    VK_CHECK(vkCreateSampler(context.device, &samplerInfo, nullptr, &sampler));

    // Bounds. Manual filters: the result is sum(w_i c) / sum(w_i) (or sum(w_i c) with sum(w_i) = 1) over at
    // most 2 levels x 8x8 texels for footprints <= 2 texels: at most 256 rounded products and sums, so a
    // relative error <= 256 FLT_EPSILON. tf_ewa_hw: each bilinear tap's hardware weights are quantised to
    // subTexelPrecisionBits; four weights off by at most half a step each move a tap of a constant texture
    // by 4 * 2^-(bits+1) of it, and the normalised sum of such taps by no more.
    const float manualBound = 256.0f * FLT_EPSILON;
    const float hwBound = manualBound + 4.0f * std::ldexp(1.0f, -int(context.properties.limits.subTexelPrecisionBits) - 1);
    int status = 0;

    std::vector<Rgba> layerColours;
    for (int32_t k = 0; k < LAYERS; ++k)
        layerColours.push_back(layer_colour(k));
    Image layers = upload_constant_layers(context, layerColours);
    std::vector<float> values =
        run_probes(context, layers_comp, sizeof layers_comp,
                   {{VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, {{VK_NULL_HANDLE, layers.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}}},
                    {VK_DESCRIPTOR_TYPE_SAMPLER, {{sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED}}}},
                   LAYERS);
    auto layerWanted = [](uint32_t i) { return layer_colour(std::clamp(probe_layer(i), 0, LAYERS - 1)); };
    status |= !check("texture2DArray, tf_trilinear(tex, uv, layer, ...)", values, 0, manualBound, layerWanted);
    status |= !check("texture2DArray + sampler, tf_ewa_hw(tex, smp, uv, layer, ...)", values, 1, hwBound, layerWanted);
    destroy_image(context, layers);

    if (context.bindless) {
        std::vector<Image> textures;
        Resource array{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {}};
        for (int32_t j = 0; j < TEXTURES; ++j) {
            textures.push_back(upload_constant_layers(context, {texture_colour(j)}));
            array.images.push_back({sampler, textures.back().view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        }
        values = run_probes(context, bindless_comp, sizeof bindless_comp, {array}, TEXTURES);
        auto textureWanted = [](uint32_t i) { return texture_colour(probe_texture(i)); };
        status |= !check("bindless sampler2D[nonuniformEXT(i)], tf_trilinear", values, 0, manualBound, textureWanted);
        status |= !check("bindless sampler2D[nonuniformEXT(i)], tf_ewa", values, 1, manualBound, textureWanted);
        for (Image& texture : textures)
            destroy_image(context, texture);
    } else {
        // The shader declares a runtime descriptor array indexed non-uniformly: not even creatable without these.
        std::printf("bindless: skipped, %s lacks descriptor indexing:%s\n", context.properties.deviceName,
                    context.bindlessMissing.c_str());
    }

    // Texel sources (TF_SOURCE): an atlas's tiles with repeat wrap inside each tile, and virtual textures
    // through a page table. Manual filters only, so the manual bound.
    Image atlas = upload_atlas(context);
    values = run_probes(context, atlas_comp, sizeof atlas_comp,
                        {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {{sampler, atlas.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}}}},
                        int32_t(ATLAS_GRID));
    auto tileWanted = [](uint32_t i) { return layer_colour(int32_t((i * 5u) % (ATLAS_GRID * ATLAS_GRID))); };
    status |= !check("atlas tile (TF_SOURCE AtlasTile), tf_trilinear, repeat in the tile", values, 0, manualBound, tileWanted);
    status |= !check("atlas tile (TF_SOURCE AtlasTile), tf_ewa, repeat in the tile", values, 1, manualBound, tileWanted);
    destroy_image(context, atlas);

    const VirtualPages pages = make_virtual_pages();
    Image physical = upload_image(context, PHYSICAL_PAGES * PAGE, 1, 1, [&](uint32_t, uint32_t, uint32_t x, uint32_t y) {
        const int32_t owner = pages.pageOwner[(y / PAGE) * PHYSICAL_PAGES + x / PAGE];
        return owner < 0 ? UNUSED_PAGE : texture_colour(owner);
    });
    const VkDeviceSize tableBytes = pages.textures.size() * sizeof(VirtualTexture);
    const VkDeviceSize entryBytes = pages.entries.size() * sizeof(uint32_t);
    Buffer table = create_host_buffer(context, tableBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    Buffer entries = create_host_buffer(context, entryBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memcpy(table.mapped, pages.textures.data(), tableBytes);
    std::memcpy(entries.mapped, pages.entries.data(), entryBytes);
    values = run_probes(context, virtual_comp, sizeof virtual_comp,
                        {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {{sampler, physical.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}}},
                         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {}, {table.buffer, 0, VK_WHOLE_SIZE}},
                         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {}, {entries.buffer, 0, VK_WHOLE_SIZE}}},
                        VIRTUAL_TEXTURES);
    auto virtualWanted = [](uint32_t i) { return texture_colour(int32_t((i * 7u) % uint32_t(VIRTUAL_TEXTURES))); };
    status |= !check("virtual texture (TF_SOURCE int), tf_trilinear, mirror", values, 0, manualBound, virtualWanted);
    status |= !check("virtual texture (TF_SOURCE int), tf_ewa, mirror", values, 1, manualBound, virtualWanted);
    destroy_buffer(context, entries);
    destroy_buffer(context, table);
    destroy_image(context, physical);

    vkDestroySampler(context.device, sampler, nullptr);
    destroy_context(context);
    if (int messages = debug_message_count(); messages > 0) {
        std::fprintf(stderr, "texfilter_resources: %d Vulkan warning/error message(s), see above\n", messages);
        status = 1;
    }
    return status;
}
