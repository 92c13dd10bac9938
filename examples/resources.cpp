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
#include "bindless_comp.h"
#include "layers_comp.h"

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

// One image (`colours.size()` layers), every level of layer k filled with colours[k].
Image upload_constant_layers(const Context& context, const std::vector<Rgba>& colours)
{
    const uint32_t layers = uint32_t(colours.size());
    Image image = create_image(context, FORMAT, SIZE, SIZE, LEVELS, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               layers);
    VkDeviceSize total = 0;
    for (uint32_t level = 0; level < LEVELS; ++level)
        total += VkDeviceSize(SIZE >> level) * (SIZE >> level) * 4 * sizeof(uint16_t) * layers;
    Buffer staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    auto* words = static_cast<uint16_t*>(staging.mapped);
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t level = 0; level < LEVELS; ++level) {
        const uint32_t size = SIZE >> level;
        for (uint32_t layer = 0; layer < layers; ++layer) {
            for (uint32_t t = 0; t < size * size; ++t)
                for (uint32_t c = 0; c < 4; ++c)
                    words[offset / 2 + t * 4 + c] = to_half(colours[layer].c[c]);
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

// One descriptor of a binding: an image view and/or a sampler, or (view and sampler null) the results buffer.
struct Resource {
    VkDescriptorType type;
    std::vector<VkDescriptorImageInfo> images; // one per array element; empty for the buffer
};

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
        bindings.push_back({uint32_t(bindings.size()), r.type, uint32_t(r.images.size()), VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        poolSizes.push_back({r.type, uint32_t(r.images.size())});
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
                          .descriptorCount = uint32_t(resources[b].images.size()), .descriptorType = resources[b].type,
                          .pImageInfo = resources[b].images.data()});
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

    vkDestroySampler(context.device, sampler, nullptr);
    destroy_context(context);
    if (int messages = debug_message_count(); messages > 0) {
        std::fprintf(stderr, "texfilter_resources: %d Vulkan warning/error message(s), see above\n", messages);
        status = 1;
    }
    return status;
}
