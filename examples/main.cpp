// main.cpp — texfilter example: a checkerboard ground plane receding to the horizon, rendered once by a
// fragment shader and once by a compute shader that both filter the texture with texfilter's GLSL
// (shaders/). Writes fragment.ppm and compute.ppm, and fails unless the two images agree: the compute
// shader builds the fragment stage's 2x2 quads from subgroup operations, so the math is the same.
//
// Usage: texfilter_example [OUTPUT_DIR [ewa|trilinear]]     (defaults: the current directory, ewa)
//        TEXFILTER_EXAMPLE_DEVICE=SUBSTRING picks the Vulkan device by name.
#include "vulkan_util.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

// SPIR-V from texfilter_add_shaders(... EMBED): `const uint32_t filtered_<stage>[]`.
#include "filtered_comp.h"
#include "filtered_frag.h"
#include "filtered_vert.h"

namespace {

constexpr uint32_t WIDTH = 256, HEIGHT = 256;
constexpr uint32_t TEXTURE_SIZE = 256, CHECKER_SQUARE = 16; // texels; TEXTURE_SIZE a power of two
constexpr uint32_t COMPUTE_TILE = 8;                         // TILE in filtered.comp.glsl
constexpr VkFormat COLOR_FORMAT = VK_FORMAT_R32G32B32A32_SFLOAT; // linear float, like the compute buffer
constexpr float MAX_DIFFERENCE = 2.0f / 255.0f;              // fragment vs compute, sRGB-encoded

// Specialization constant 0 of both pipelines (ground_plane.glsl's FILTER).
constexpr int32_t FILTER_TRILINEAR = 0, FILTER_EWA = 1;

// Level 0 is a checkerboard; every further level is the 2x2 box average of the one before. Averaging is
// done in float, and each level rounded to RGBA8 on its own, so the coarse levels converge to the mean.
std::vector<std::vector<uint8_t>> checkerboard_mip_chain(uint32_t size, uint32_t square)
{
    const float light[4] = {0.85f, 0.80f, 0.70f, 1.0f}, dark[4] = {0.05f, 0.09f, 0.20f, 1.0f}; // linear
    std::vector<float> level(size * size * 4);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x)
            std::memcpy(&level[(y * size + x) * 4], ((x / square + y / square) & 1) ? dark : light, sizeof light);
    std::vector<std::vector<uint8_t>> chain;
    for (uint32_t s = size;; s /= 2) {
        std::vector<uint8_t>& bytes = chain.emplace_back(level.size());
        for (size_t i = 0; i < level.size(); ++i)
            bytes[i] = uint8_t(std::lround(level[i] * 255.0f));
        if (s == 1)
            return chain;
        uint32_t half = s / 2;
        std::vector<float> next(half * half * 4);
        for (uint32_t y = 0; y < half; ++y)
            for (uint32_t x = 0; x < half; ++x)
                for (uint32_t c = 0; c < 4; ++c) {
                    auto at = [&](uint32_t dx, uint32_t dy) { return level[((2 * y + dy) * s + 2 * x + dx) * 4 + c]; };
                    next[(y * half + x) * 4 + c] = 0.25f * (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1));
                }
        level = std::move(next);
    }
}

// Creates the texture and uploads every level through one staging buffer.
Image upload_texture(const Context& context, const std::vector<std::vector<uint8_t>>& levels)
{
    Image texture = create_image(context, VK_FORMAT_R8G8B8A8_UNORM, TEXTURE_SIZE, TEXTURE_SIZE, uint32_t(levels.size()),
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    VkDeviceSize total = 0;
    for (const std::vector<uint8_t>& level : levels)
        total += level.size();
    Buffer staging = create_host_buffer(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t i = 0; i < levels.size(); ++i) {
        std::memcpy(static_cast<uint8_t*>(staging.mapped) + offset, levels[i].data(), levels[i].size());
        uint32_t size = std::max(TEXTURE_SIZE >> i, 1u);
        regions.push_back({.bufferOffset = offset,
                           .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1},
                           .imageExtent = {size, size, 1}});
        offset += levels[i].size();
    }
    submit_and_wait(context, [&](VkCommandBuffer commands) {
        image_barrier(commands, texture.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(commands, staging.buffer, texture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(regions.size()), regions.data());
        image_barrier(commands, texture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    });
    destroy_buffer(context, staging);
    return texture;
}

// Why the compute path cannot run on this device ("" if it can). texfilter/derivatives.glsl lays 2x2 quads
// over subgroups: it needs quad operations in compute, and workgroups made of whole subgroups of 4n lanes.
std::string compute_quads_problem(const Context& context)
{
    const VkPhysicalDeviceSubgroupProperties& s = context.subgroup;
    if (!(s.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) || !(s.supportedOperations & VK_SUBGROUP_FEATURE_QUAD_BIT))
        return "no subgroup quad operations in compute shaders";
    if (s.subgroupSize % 4 != 0 || (COMPUTE_TILE * COMPUTE_TILE) % s.subgroupSize != 0)
        return "subgroups of " + std::to_string(s.subgroupSize) + " lanes do not tile workgroups of " +
               std::to_string(COMPUTE_TILE * COMPUTE_TILE) + " as 2x2 quads";
    if (!context.fullSubgroups)
        return "no computeFullSubgroups";
    return "";
}

VkPipeline create_graphics_pipeline(const Context& context, VkPipelineLayout layout, const VkSpecializationInfo& filter)
{
    VkShaderModule vert = create_shader_module(context, filtered_vert, sizeof filtered_vert);
    VkShaderModule frag = create_shader_module(context, filtered_frag, sizeof filtered_frag);
    VkPipelineShaderStageCreateInfo stages[] = {
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_VERTEX_BIT, .module = vert, .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_FRAGMENT_BIT, .module = frag,
         .pName = "main", .pSpecializationInfo = &filter}};
    VkPipelineVertexInputStateCreateInfo vertexInput{.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                                         .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
    VkViewport viewport{0.0f, 0.0f, float(WIDTH), float(HEIGHT), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {WIDTH, HEIGHT}};
    VkPipelineViewportStateCreateInfo viewportState{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                    .viewportCount = 1, .pViewports = &viewport,
                                                    .scissorCount = 1, .pScissors = &scissor};
    VkPipelineRasterizationStateCreateInfo rasterization{.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                         .polygonMode = VK_POLYGON_MODE_FILL, .cullMode = VK_CULL_MODE_NONE,
                                                         .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE, .lineWidth = 1.0f};
    VkPipelineMultisampleStateCreateInfo multisample{.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                     .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
    VkPipelineColorBlendAttachmentState attachment{.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                                     VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT};
    VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                              .attachmentCount = 1, .pAttachments = &attachment};
    // Dynamic rendering (Vulkan 1.3): the pipeline names its attachment formats instead of a render pass.
    VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                            .colorAttachmentCount = 1, .pColorAttachmentFormats = &COLOR_FORMAT};
    VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                      .pNext = &rendering,
                                      .stageCount = 2,
                                      .pStages = stages,
                                      .pVertexInputState = &vertexInput,
                                      .pInputAssemblyState = &inputAssembly,
                                      .pViewportState = &viewportState,
                                      .pRasterizationState = &rasterization,
                                      .pMultisampleState = &multisample,
                                      .pColorBlendState = &blend,
                                      .layout = layout};
    VkPipeline pipeline;
    VK_CHECK(vkCreateGraphicsPipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    vkDestroyShaderModule(context.device, vert, nullptr);
    vkDestroyShaderModule(context.device, frag, nullptr);
    return pipeline;
}

VkPipeline create_compute_pipeline(const Context& context, VkPipelineLayout layout, const VkSpecializationInfo& filter)
{
    VkShaderModule comp = create_shader_module(context, filtered_comp, sizeof filtered_comp);
    // Full subgroups: otherwise a subgroup could start mid-quad and the quad operations would pair the
    // wrong pixels.
    VkComputePipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
                                     .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                               .flags = VK_PIPELINE_SHADER_STAGE_CREATE_REQUIRE_FULL_SUBGROUPS_BIT,
                                               .stage = VK_SHADER_STAGE_COMPUTE_BIT, .module = comp, .pName = "main",
                                               .pSpecializationInfo = &filter},
                                     .layout = layout};
    VkPipeline pipeline;
    VK_CHECK(vkCreateComputePipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    vkDestroyShaderModule(context.device, comp, nullptr);
    return pipeline;
}

float srgb_encode(float linear)
{
    float c = std::fmin(std::fmax(linear, 0.0f), 1.0f); // also turns NaN into 0
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Writes linear RGBA float pixels as a binary PPM (sRGB-encoded, alpha dropped) and prints a summary line.
void write_image(const char* label, const std::filesystem::path& path, const float* rgba)
{
    std::vector<uint8_t> bytes(WIDTH * HEIGHT * 3);
    double sum[3] = {};
    for (uint32_t i = 0; i < WIDTH * HEIGHT; ++i)
        for (uint32_t c = 0; c < 3; ++c) {
            sum[c] += rgba[i * 4 + c];
            bytes[i * 3 + c] = uint8_t(std::lround(srgb_encode(rgba[i * 4 + c]) * 255.0f));
        }
    std::ofstream file(path, std::ios::binary);
    file << "P6\n" << WIDTH << " " << HEIGHT << "\n255\n";
    file.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!file.flush())
        fail("cannot write " + path.string());
    const double n = WIDTH * HEIGHT;
    std::printf("%s: %s %ux%u, mean linear RGB (%.4f, %.4f, %.4f)\n", label, path.string().c_str(), WIDTH, HEIGHT,
                sum[0] / n, sum[1] / n, sum[2] / n);
}

// Largest difference of any colour channel after sRGB encoding (the scale the eye and the PPMs use).
float max_difference(const float* a, const float* b)
{
    float worst = 0.0f;
    for (uint32_t i = 0; i < WIDTH * HEIGHT * 4; ++i)
        if (i % 4 != 3) {
            float d = std::fabs(srgb_encode(a[i]) - srgb_encode(b[i]));
            worst = std::isnan(d) ? INFINITY : std::fmax(worst, d);
        }
    return worst;
}

} // namespace

int main(int argc, char** argv)
{
    std::string filterName = argc > 2 ? argv[2] : "ewa";
    if (argc > 3 || (argc > 1 && argv[1][0] == '-') || (filterName != "ewa" && filterName != "trilinear")) {
        std::fprintf(stderr, "usage: texfilter_example [OUTPUT_DIR [ewa|trilinear]]\n");
        return 2;
    }
    std::filesystem::path outputDir = argc > 1 ? argv[1] : ".";
    std::error_code error;
    std::filesystem::create_directories(outputDir, error);
    if (error)
        fail("cannot create " + outputDir.string() + ": " + error.message());

    Context context = create_context();
    std::string computeProblem = compute_quads_problem(context);
    std::printf("device: %s, filter: %s\n", context.properties.deviceName, filterName.c_str());

    Image texture = upload_texture(context, checkerboard_mip_chain(TEXTURE_SIZE, CHECKER_SQUARE));
    // texfilter's filters read texels with texelFetch and do the filtering themselves; the sampler's
    // settings matter only to hardware-tap variants such as tf_ewa_hw, which want linear + the same wrap.
    VkSamplerCreateInfo samplerInfo{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                    .magFilter = VK_FILTER_LINEAR, .minFilter = VK_FILTER_LINEAR,
                                    .mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR,
                                    .addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                    .addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                    .addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                    .maxLod = VK_LOD_CLAMP_NONE};
    VkSampler sampler;
    VK_CHECK(vkCreateSampler(context.device, &samplerInfo, nullptr, &sampler));

    // Outputs: the colour attachment (copied to fragmentPixels) and the compute shader's buffer.
    const VkDeviceSize imageBytes = VkDeviceSize(WIDTH) * HEIGHT * 4 * sizeof(float);
    Image color = create_image(context, COLOR_FORMAT, WIDTH, HEIGHT, 1,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    Buffer fragmentPixels = create_host_buffer(context, imageBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    Buffer computePixels = create_host_buffer(context, imageBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    // One descriptor set and pipeline layout serve both pipelines: binding 0 is the texture (both stages),
    // binding 1 the compute output.
    VkDescriptorSetLayoutBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
    VkDescriptorSetLayoutCreateInfo setLayoutInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                                  .bindingCount = 2, .pBindings = bindings};
    VkDescriptorSetLayout setLayout;
    VK_CHECK(vkCreateDescriptorSetLayout(context.device, &setLayoutInfo, nullptr, &setLayout));
    VkDescriptorPoolSize poolSizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
    VkDescriptorPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                        .maxSets = 1, .poolSizeCount = 2, .pPoolSizes = poolSizes};
    VkDescriptorPool pool;
    VK_CHECK(vkCreateDescriptorPool(context.device, &poolInfo, nullptr, &pool));
    VkDescriptorSetAllocateInfo setInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                        .descriptorPool = pool, .descriptorSetCount = 1, .pSetLayouts = &setLayout};
    VkDescriptorSet set;
    VK_CHECK(vkAllocateDescriptorSets(context.device, &setInfo, &set));
    VkDescriptorImageInfo textureDescriptor{sampler, texture.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo bufferDescriptor{computePixels.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet writes[] = {
        {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = set, .dstBinding = 0, .descriptorCount = 1,
         .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, .pImageInfo = &textureDescriptor},
        {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = set, .dstBinding = 1, .descriptorCount = 1,
         .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, .pBufferInfo = &bufferDescriptor}};
    vkUpdateDescriptorSets(context.device, 2, writes, 0, nullptr);

    const VkShaderStageFlags pushStages = VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
    const int32_t imageSize[2] = {int32_t(WIDTH), int32_t(HEIGHT)}; // ground_plane.glsl's params.imageSize
    VkPushConstantRange pushRange{pushStages, 0, sizeof imageSize};
    VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, .setLayoutCount = 1,
                                          .pSetLayouts = &setLayout, .pushConstantRangeCount = 1, .pPushConstantRanges = &pushRange};
    VkPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout(context.device, &layoutInfo, nullptr, &layout));

    const int32_t filter = filterName == "trilinear" ? FILTER_TRILINEAR : FILTER_EWA;
    VkSpecializationMapEntry filterEntry{0, 0, sizeof filter};
    VkSpecializationInfo specialization{1, &filterEntry, sizeof filter, &filter};
    VkPipeline graphics = create_graphics_pipeline(context, layout, specialization);
    VkPipeline compute = computeProblem.empty() ? create_compute_pipeline(context, layout, specialization) : VK_NULL_HANDLE;

    submit_and_wait(context, [&](VkCommandBuffer commands) {
        vkCmdPushConstants(commands, layout, pushStages, 0, sizeof imageSize, imageSize);
        image_barrier(commands, color.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        VkRenderingAttachmentInfo attachment{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                             .imageView = color.view,
                                             .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                             .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                             .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
        VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO, .renderArea = {{0, 0}, {WIDTH, HEIGHT}},
                                  .layerCount = 1, .colorAttachmentCount = 1, .pColorAttachments = &attachment};
        vkCmdBeginRendering(commands, &rendering);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, graphics);
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
        vkCmdDraw(commands, 3, 1, 0, 0); // the full-screen triangle
        vkCmdEndRendering(commands);

        image_barrier(commands, color.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, .imageExtent = {WIDTH, HEIGHT, 1}};
        vkCmdCopyImageToBuffer(commands, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, fragmentPixels.buffer, 1, &region);

        if (compute) {
            vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, compute);
            vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
            vkCmdDispatch(commands, (WIDTH + COMPUTE_TILE - 1) / COMPUTE_TILE, (HEIGHT + COMPUTE_TILE - 1) / COMPUTE_TILE, 1);
        }
        // Make both results visible to the host reads below.
        VkMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                               .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                               .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
    });

    int status = 0;
    const float* fragmentRgba = static_cast<const float*>(fragmentPixels.mapped);
    const float* computeRgba = static_cast<const float*>(computePixels.mapped);
    write_image("fragment", outputDir / "fragment.ppm", fragmentRgba);
    if (compute) {
        write_image("compute", outputDir / "compute.ppm", computeRgba);
        float difference = max_difference(fragmentRgba, computeRgba);
        bool close = difference <= MAX_DIFFERENCE;
        std::printf("fragment vs compute: max abs difference %.6f (%.3f/255, sRGB), limit 2/255: %s\n", difference,
                    difference * 255.0f, close ? "ok" : "FAILED");
        if (!close)
            status = 1;
    } else {
        std::printf("compute: skipped, %s: %s\n", context.properties.deviceName, computeProblem.c_str());
    }

    if (compute)
        vkDestroyPipeline(context.device, compute, nullptr);
    vkDestroyPipeline(context.device, graphics, nullptr);
    vkDestroyPipelineLayout(context.device, layout, nullptr);
    vkDestroyDescriptorPool(context.device, pool, nullptr); // frees the set
    vkDestroyDescriptorSetLayout(context.device, setLayout, nullptr);
    destroy_buffer(context, computePixels);
    destroy_buffer(context, fragmentPixels);
    destroy_image(context, color);
    vkDestroySampler(context.device, sampler, nullptr);
    destroy_image(context, texture);
    destroy_context(context);

    if (int messages = debug_message_count(); messages > 0) {
        std::fprintf(stderr, "texfilter_example: %d Vulkan warning/error message(s), see above\n", messages);
        status = 1;
    }
    return status;
}
