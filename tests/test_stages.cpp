// Quad derivatives everywhere: the same scene through the fragment pipeline and the compute pipeline
// (2x2 quads from subgroup quad operations) must agree to the last bit, and both must match the CPU
// reference's quads, coarse quads and ray differentials. Runs in-process so that the float32 readbacks
// are compared as they are (an image file would round them). Validation layers on.
#include "support.h"
#include "vulkan/backend.h"
#include "core/procedural.h"
#include "reference/render.h"
#include "scene/scene.h"
#include <cmath>
#include <cstdio>

using namespace tf;

namespace {

// Largest channel difference over pixels, and how many pixels exceed `limit`.
struct Comparison {
    double max_difference = 0;
    int over = 0;
};

Comparison compare(const Image& a, const Image& b, double limit)
{
    Comparison c;
    for (size_t i = 0; i < a.texels.size(); ++i) {
        double d = test::max_channel_diff(glm::dvec4(a.texels[i]), glm::dvec4(b.texels[i]));
        c.max_difference = std::max(c.max_difference, d);
        c.over += d > limit ? 1 : 0;
    }
    return c;
}

// The test device with validation on and the checker uploaded; at the end, no validation message.
struct Stages {
    VulkanContext context = create_context(test::test_context_options());
    MipChain checker = make_procedural("checker", 256);
    GpuTexture texture = upload_texture(context, checker, false);
    SamplerOptions trilinear = [] {
        SamplerOptions o;
        o.filter = Filter::trilinear;
        return o;
    }();
    ~Stages()
    {
        destroy_texture(context, texture);
        destroy_context(context);
        CHECK_EQ(validation_message_count(), 0);
    }
};

} // namespace

TEST_SUITE_BEGIN("gpu");

// 1. Fragment vs compute, every ray-cast scene, quad (fine) and ray-differential gradients: the same float
//    operations in the same order, so the same bits (measured: identical on lavapipe).
TEST_CASE("fragment-vs-compute")
{
    Stages st;
    for (SceneKind kind : all_scenes()) {
        if (kind == SceneKind::mesh || is_environment_scene(kind))
            continue; // mesh is rasterized: it has no compute form (see 3); skybox, reflect: no uv
        SceneParams scene = make_scene(kind, 128, 96, 256);
        for (Gradients g : {Gradients::fine, Gradients::ray}) {
            Image fragment = gpu_render(st.context, st.texture, scene, st.trilinear,
                                        make_render_options(kind, Stage::fragment, g));
            Image compute = gpu_render(st.context, st.texture, scene, st.trilinear,
                                       make_render_options(kind, Stage::compute, g));
            Comparison c = compare(fragment, compute, 0.0);
            std::printf("%-10s %-6s fragment vs compute: max difference %g\n", to_string(kind).c_str(),
                        to_string(g).c_str(), c.max_difference);
            CHECK_EQ(c.max_difference, 0.0);
        }
    }
}

// 2. Each gradient form vs the CPU reference (double; its own quads, coarse quads and central differences
//    for ray differentials). Bound 1e-3: uv reaches ~16 (tunnel, floor), where a float32 ulp is 1e-6 uv =
//    2.5e-4 texel of a 256 texture, times the checker's contrast 0.85, plus the ray cast's own rounding;
//    measured max 2.5e-4 (at 128x96 no pixel sits where float32 and double disagree on a hit or a texel,
//    unlike the 256x256 goldens). Coarse goes through compute: lavapipe's dFdxCoarse is its fine derivative
//    (Vulkan allows that), while the compute quads and the reference take the top-left pixel's pair.
TEST_CASE("gradients-vs-reference")
{
    Stages st;
    for (SceneKind kind : {SceneKind::plane, SceneKind::tunnel, SceneKind::slanted, SceneKind::triangles}) {
        SceneParams scene = make_scene(kind, 128, 96, 256);
        for (Gradients g : {Gradients::fine, Gradients::coarse, Gradients::ray}) {
            RenderOptions render = make_render_options(kind, Stage::compute, g);
            Image gpu = gpu_render(st.context, st.texture, scene, st.trilinear, render);
            Image reference = reference_render(scene, st.checker, st.trilinear, render);
            Comparison c = compare(gpu, reference, 1e-3);
            double percent = 100.0 * c.over / double(gpu.texels.size());
            std::printf("%-10s %-6s compute vs reference: %d pixels (%.3f%%) beyond 1e-3, max %g\n",
                        to_string(kind).c_str(), to_string(g).c_str(), c.over, percent, c.max_difference);
            CHECK_EQ(c.over, 0);
        }
    }
}

// 3. The mesh scene (raster pipeline, perspective-correct uv, helper invocations past triangle edges) vs
//    the reference's ray-cast triangles with helper-style extrapolation. Coverage at shared edges follows
//    the rasterizer's top-left rule there and a float32 edge test here: a few edge pixels. The rasterizer
//    snaps vertices to subPixelPrecisionBits fraction bits of a pixel (Vulkan "Rasterization"; the device's
//    reported precision), which moves each triangle's uv plane by up to 2^-bits pixels: a pixel may show the
//    scene that far from its centre. So each pixel is allowed 1e-3 plus the reference's largest change when the
//    pixel centres move by 2^-bits in x or in y (an NVIDIA H200 differs by up to 1.7e-3 on 7.5 % of the pixels).
Image shifted_reference(SceneParams scene, const MipChain& chain, const SamplerOptions& options,
                        const RenderOptions& render, double dx, double dy)
{
    // The rays are forward + ndc_x right + ndc_y up, ndc_x = 2 px / width - 1, ndc_y = 1 - 2 py / height.
    scene.forward += float(2.0 * dx / scene.kind_size.y) * scene.right - float(2.0 * dy / scene.kind_size.z) * scene.up;
    return reference_render(scene, chain, options, render);
}

TEST_CASE("mesh-raster-vs-reference")
{
    Stages st;
    SceneParams scene = make_scene(SceneKind::mesh, 128, 96, 256);
    RenderOptions render = make_render_options(SceneKind::mesh, Stage::fragment, Gradients::fine);
    const Image gpu = gpu_render(st.context, st.texture, scene, st.trilinear, render);
    const Image reference = reference_render(scene, st.checker, st.trilinear, render);
    const double snap = std::ldexp(1.0, -int(test::test_device_info().sub_pixel_precision_bits));
    std::vector<double> allowance(reference.texels.size(), 1e-3);
    for (const glm::dvec2 shift : {glm::dvec2(snap, 0), glm::dvec2(-snap, 0), glm::dvec2(0, snap), glm::dvec2(0, -snap)}) {
        const Image moved = shifted_reference(scene, st.checker, st.trilinear, render, shift.x, shift.y);
        for (size_t i = 0; i < allowance.size(); ++i)
            allowance[i] = std::max(allowance[i], 1e-3 + test::max_channel_diff(glm::dvec4(moved.texels[i]),
                                                                                 glm::dvec4(reference.texels[i])));
    }
    int over = 0;
    double worst = 0, max_difference = 0;
    for (size_t i = 0; i < gpu.texels.size(); ++i) {
        const double d = test::max_channel_diff(glm::dvec4(gpu.texels[i]), glm::dvec4(reference.texels[i]));
        max_difference = std::max(max_difference, d);
        worst = std::max(worst, d / allowance[i]);
        over += d > allowance[i];
    }
    double percent = 100.0 * over / (128.0 * 96.0);
    std::printf("mesh       fine   raster vs reference: %d pixels (%.3f%%) beyond 1e-3 + a 2^-%u pixel shift's change, "
                "max %g, worst difference/allowance %.3f\n",
                over, percent, test::test_device_info().sub_pixel_precision_bits, max_difference, worst);
    CHECK(percent <= 0.1, test::show(percent));
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("reference");

// 4. Coarse gradients are one pair for the whole quad (the reference's lookups, which the compute render
//    matched in 2), and on the plane they differ from fine ones (else 2 would prove nothing).
TEST_CASE("coarse-gradients-per-quad")
{
    SceneParams scene = make_scene(SceneKind::plane, 64, 64, 256);
    std::vector<PixelLookup> coarse = reference_lookups(scene, Gradients::coarse, false);
    int differing = 0;
    for (int y = 0; y < 64; y += 2)
        for (int x = 0; x < 64; x += 2) {
            const Lookup& a = coarse[size_t(y) * 64 + x].lookup;
            for (int k = 1; k < 4; ++k) {
                const Lookup& b = coarse[size_t(y + k / 2) * 64 + x + k % 2].lookup;
                differing += a.dudx != b.dudx || a.dvdx != b.dvdx || a.dudy != b.dudy || a.dvdy != b.dvdy;
            }
        }
    CHECK_EQ(differing, 0);
    std::vector<PixelLookup> fine = reference_lookups(scene, Gradients::fine, false);
    int changed = 0;
    for (size_t i = 0; i < fine.size(); ++i)
        changed += fine[i].lookup.dudy != coarse[i].lookup.dudy || fine[i].lookup.dvdy != coarse[i].lookup.dvdy;
    CHECK(changed > int(fine.size()) / 4, std::to_string(changed));
}

TEST_SUITE_END();
