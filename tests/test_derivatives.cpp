// Seam-free quad derivatives, ray cones and differentials through a reflection (texfilter/derivatives.glsl,
// docs/DERIVATIVES.md), against the CPU reference's own geometry and finite differences.
//
// 1. The tunnel's seam (u jumps by 2 whole periods): the quads that straddle it take the LOD of their
//    neighbours, on the GPU (fragment fine, compute fine and coarse) and in the reference.
// 2. Cone vs ray differentials, plane and mirror sphere (reference, double): for a pinhole, the direction of
//    a pixel's ray changes, per pixel, by s cos(phi) across the radial direction and s cos^2(phi) along it
//    (s = 2 tan(fov_y/2) / height, phi the ray's angle off the axis), where the cone takes gamma = atan(s)
//    in every direction. Both footprints then go through the same linear map to uv (the projection along the
//    ray onto the tangent plane) or to the reflected direction (the sphere's transfer, linear in the
//    incoming differentials, and the primary cone's width is gamma times the distance as the pixel's is), so
//    J^-1 G (J the finite differences, G the cone) has singular values exactly gamma / (s cos phi) and
//    gamma / (s cos^2 phi): equal at the image centre (up to atan(s)/s = 1 - s^2/3), the cone up to
//    1/cos^2(phi) larger off it. Checked to 1e-6 relative (central differences at h = 1/1024 pixel: h^2 ~
//    1e-6 times the relative curvature of uv over a pixel; Richardson on the sphere, 3e-8; measured 8e-8).
//    GPU tolerances: LOD 1e-3 and ratio 1e-3 relative, well above float32's ~3e-5 measured (the ray
//    cast's rounding at t ~ 10 and log2), far below a wrong cone (the 1/cos phi factors reach 0.7 level).
// 3. GPU cones vs the reference's: the data view's LOD and anisotropy ratio, plane and tunnel; the reflect
//    and skybox scenes' colour; degenerate footprints (the plane's horizon) stay finite in the output.
#include "support.h"
#include "core/cube_textures.h"
#include "core/environment.h"
#include "core/procedural.h"
#include "reference/env_cast.h"
#include "reference/env_render.h"
#include "reference/render.h"
#include "scene/scene.h"
#include "vulkan/backend.h"
#include "vulkan/cleanup.h"
#include "vulkan/environment.h"
#include "vulkan/render.h"
#include "vulkan/textures.h"
#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace tf;

namespace {

struct Gpu {
    VulkanContext context = create_context(test::test_context_options());
    ~Gpu()
    {
        destroy_context(context);
        CHECK_EQ(validation_message_count(), 0);
    }
};

SamplerOptions options_for(Filter filter)
{
    SamplerOptions o;
    o.filter = filter;
    return o;
}

RenderOptions data_view(SceneKind kind, Stage stage, Gradients gradients)
{
    RenderOptions r = make_render_options(kind, stage, gradients);
    r.view = DebugView::data;
    return r;
}

// Singular values (ascending) of the 2x2 matrix [a b; c d].
glm::dvec2 singular_values(double a, double b, double c, double d)
{
    double s1 = std::hypot(a + d, c - b), s2 = std::hypot(a - d, c + b);
    return {0.5 * std::abs(s1 - s2), 0.5 * (s1 + s2)};
}

// The two predicted singular values of J^-1 G at the pixel whose camera ray is `ray` (forward is unit).
glm::dvec2 predicted(const SceneParams& scene, glm::dvec3 ray)
{
    double s = 2.0 * glm::length(glm::dvec3(scene.up)) / scene.kind_size.z;
    double gamma = std::atan(s), cos_phi = 1.0 / glm::length(ray);
    return {gamma / (s * cos_phi), gamma / (s * cos_phi * cos_phi)};
}

glm::dvec3 camera_ray(const SceneParams& scene, double px, double py)
{
    double nx = 2.0 * px / scene.kind_size.y - 1.0, ny = 1.0 - 2.0 * py / scene.kind_size.z;
    return glm::dvec3(scene.forward) + nx * glm::dvec3(scene.right) + ny * glm::dvec3(scene.up);
}

// Pixels of the tunnel whose quad straddles the seam: a raw quad difference of u of half a period or more.
std::vector<bool> seam_pixels(const SceneParams& scene)
{
    int w = scene.kind_size.y, h = scene.kind_size.z;
    std::vector<bool> seam(size_t(w) * h, false);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int x0 = x & ~1, y0 = y & ~1;
            double ux = reference_hit(scene, (x0 | 1) + 0.5, y + 0.5).uv.x - reference_hit(scene, x0 + 0.5, y + 0.5).uv.x;
            double uy = reference_hit(scene, x + 0.5, (y0 | 1) + 0.5).uv.x - reference_hit(scene, x + 0.5, y0 + 0.5).uv.x;
            seam[size_t(y) * w + x] = std::abs(ux) >= 0.5 || std::abs(uy) >= 0.5;
        }
    return seam;
}

// Each seam pixel's LOD (R of the data view) against the LODs of the hit, non-seam pixels within two pixels
// (both sides of the seam): within their range widened by `slack`. Returns the number outside; prints the worst.
int seam_outliers(const SceneParams& scene, const Image& data, const std::vector<bool>& seam,
                  const std::vector<PixelLookup>& hits, double slack, const char* what)
{
    int w = scene.kind_size.y, h = scene.kind_size.z, outside = 0, checked = 0;
    double worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!seam[size_t(y) * w + x] || !hits[size_t(y) * w + x].hit)
                continue;
            double lo = INFINITY, hi = -INFINITY;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h || seam[size_t(ny) * w + nx] || !hits[size_t(ny) * w + nx].hit)
                        continue;
                    double lod = data.texels[size_t(ny) * w + nx].x;
                    lo = std::min(lo, lod);
                    hi = std::max(hi, lod);
                }
            if (!(lo <= hi))
                continue; // no neighbour off the seam
            ++checked;
            double lod = data.texels[size_t(y) * w + x].x;
            double off = std::max(lo - slack - lod, lod - hi - slack);
            worst = std::max(worst, off);
            outside += off > 0.0;
        }
    std::printf("tunnel seam %-22s %d seam pixels, %d outside the neighbours' LOD range (+%.2g), worst by %.3g\n", what,
                checked, outside, slack, worst);
    CHECK(checked >= 8, "the seam is in the picture: " + std::to_string(checked));
    return outside;
}

// The slack of seam_outliers: the LOD's own variation over the neighbourhood is what the range already
// holds; a bracket misses a curved function by at most its second difference across the seam's rows,
// measured from the non-seam hit pixels: max |l(y-2) - 2 l(y) + l(y+2)| / 4.
double lod_curvature(const Image& data, const std::vector<bool>& seam, const std::vector<PixelLookup>& lookups, int w)
{
    double curvature = 0;
    int h = int(seam.size()) / w;
    for (int y = 2; y < h - 2; ++y)
        for (int x = 0; x < w; ++x) {
            size_t a = size_t(y - 2) * w + x, b = size_t(y) * w + x, c = size_t(y + 2) * w + x;
            if (seam[a] || seam[b] || seam[c] || !lookups[a].hit || !lookups[b].hit || !lookups[c].hit)
                continue;
            curvature = std::max(curvature, std::abs(data.texels[a].x - 2.0 * data.texels[b].x + data.texels[c].x) / 4.0);
        }
    return curvature;
}

} // namespace

TEST_SUITE_BEGIN("reference");

// 1a. The reference's quads: plain differences put the seam at the coarsest level (what the fix removes:
//     this is what makes 1b able to fail: with plain quads on the GPU, every seam pixel is outside, by ~5
//     levels), its seam-free ones at the neighbours' LOD.
TEST_CASE("seam-free-reference")
{
    SceneParams scene = make_scene(SceneKind::tunnel, 64, 64, 256);
    std::vector<bool> seam = seam_pixels(scene);
    MipChain chain = make_procedural("mipcolors", 256);
    for (Gradients g : {Gradients::fine, Gradients::coarse}) {
        std::vector<PixelLookup> lookups = reference_lookups(scene, g, false);
        Image data = reference_render(scene, chain, options_for(Filter::trilinear), data_view(SceneKind::tunnel, Stage::compute, g));
        double curvature = lod_curvature(data, seam, lookups, 64);
        CHECK_EQ(seam_outliers(scene, data, seam, lookups, curvature, ("reference " + to_string(g)).c_str()), 0);
        // At the seam the plain differences are 2 periods (seam_pixels found |du| >= 0.5: 512 texels, the
        // coarsest level of 256); the lookups' are a small fraction of one.
        int coarsest = 0, seen = 0;
        for (size_t i = 0; i < lookups.size(); ++i)
            if (seam[i] && lookups[i].hit) {
                const Lookup& l = lookups[i].lookup;
                double plain_u = std::max(std::abs(l.dudx), std::abs(l.dudy));
                ++seen;
                coarsest += plain_u < 0.5; // seam-free: the u step is a small fraction of a period
            }
        CHECK_EQ(coarsest, seen);
    }
}

// 2a. The plane: cone vs ray differentials, J^-1 G's singular values as the header derives.
TEST_CASE("cone-vs-differentials-plane")
{
    for (SceneKind kind : {SceneKind::plane, SceneKind::slanted}) {
        SceneParams scene = make_scene(kind, 64, 64, 256);
        std::vector<PixelLookup> cone = reference_lookups(scene, Gradients::cone, false);
        std::vector<PixelLookup> ray = reference_lookups(scene, Gradients::ray, false);
        double worst = 0, largest = 0;
        int checked = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                size_t i = size_t(y) * 64 + x;
                if (!cone[i].hit)
                    continue;
                const Lookup& j = ray[i].lookup;
                const Lookup& g = cone[i].lookup;
                // Within a pixel of the horizon uv ~ 1 / (distance to it): the reference's central differences
                // are off by h^2 / distance^2 relative (2.6e-3 at 1/50 pixel), and a footprint of a whole
                // texture period (1 uv unit) or more is the coarsest level for every filter: left out.
                if (std::max({std::abs(j.dudx), std::abs(j.dvdx), std::abs(j.dudy), std::abs(j.dvdy)}) >= 1.0)
                    continue;
                double det = j.dudx * j.dvdy - j.dudy * j.dvdx; // J = [dudx dudy; dvdx dvdy]
                // M = J^-1 G
                double m11 = (j.dvdy * g.dudx - j.dudy * g.dvdx) / det, m12 = (j.dvdy * g.dudy - j.dudy * g.dvdy) / det;
                double m21 = (-j.dvdx * g.dudx + j.dudx * g.dvdx) / det, m22 = (-j.dvdx * g.dudy + j.dudx * g.dvdy) / det;
                glm::dvec2 sv = singular_values(m11, m12, m21, m22);
                glm::dvec2 want = predicted(scene, camera_ray(scene, x + 0.5, y + 0.5));
                double e = std::max(std::abs(sv.x / want.x - 1.0), std::abs(sv.y / want.y - 1.0));
                worst = std::max(worst, e);
                largest = std::max(largest, want.y);
                ++checked;
            }
        std::printf("%-8s cone vs ray differentials: %d pixels, singular values of J^-1 G within %.2g of "
                    "gamma/(s cos phi), gamma/(s cos^2 phi) (largest %.4f)\n",
                    to_string(kind).c_str(), checked, worst, largest);
        CHECK(checked > 500, test::show(checked));
        CHECK(worst <= 1e-6, test::show(worst));
    }
}

// 2b. The mirror sphere: the reflected cone's direction footprint vs central differences of the reflected
//     direction, away from the silhouette (where the differences are one-sided and the footprint unbounded).
TEST_CASE("reflected-cone-vs-differentials")
{
    SceneParams scene = make_scene(SceneKind::reflect, 64, 64, 64);
    std::vector<EnvLookup> cone = reference_env_lookups(scene, Gradients::cone);
    std::vector<EnvLookup> ray = reference_env_lookups(scene, Gradients::ray);
    double worst = 0, largest = 0;
    int checked = 0;
    for (int y = 1; y < 63; ++y)
        for (int x = 1; x < 63; ++x) {
            bool inside = true;
            for (int k = -1; k <= 1; ++k)
                inside = inside && reference_env_ray(scene, x + 0.5 + 1.5 * k, y + 0.5).mirror &&
                         reference_env_ray(scene, x + 0.5, y + 0.5 + 1.5 * k).mirror;
            if (!inside)
                continue;
            size_t i = size_t(y) * 64 + x;
            glm::dvec3 r = glm::normalize(ray[i].dir);
            glm::dvec3 a = glm::normalize(glm::cross(r, std::abs(r.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
            glm::dvec3 b = glm::cross(r, a);
            // Both footprints in the plane perpendicular to r (a, b).
            double j11 = glm::dot(ray[i].ddx, a), j12 = glm::dot(ray[i].ddy, a), j21 = glm::dot(ray[i].ddx, b),
                   j22 = glm::dot(ray[i].ddy, b);
            double g11 = glm::dot(cone[i].ddx, a), g12 = glm::dot(cone[i].ddy, a), g21 = glm::dot(cone[i].ddx, b),
                   g22 = glm::dot(cone[i].ddy, b);
            double det = j11 * j22 - j12 * j21;
            double m11 = (j22 * g11 - j12 * g21) / det, m12 = (j22 * g12 - j12 * g22) / det;
            double m21 = (-j21 * g11 + j11 * g21) / det, m22 = (-j21 * g12 + j11 * g22) / det;
            glm::dvec2 sv = singular_values(m11, m12, m21, m22);
            glm::dvec2 want = predicted(scene, camera_ray(scene, x + 0.5, y + 0.5));
            double e = std::max(std::abs(sv.x / want.x - 1.0), std::abs(sv.y / want.y - 1.0));
            worst = std::max(worst, e);
            largest = std::max(largest, want.y);
            ++checked;
            CHECK(std::abs(glm::dot(cone[i].ddx, r)) < 1e-12 && std::abs(glm::dot(cone[i].ddy, r)) < 1e-12,
                  "cone footprint perpendicular to the reflected ray");
        }
    std::printf("reflect  reflected cone vs differentials: %d pixels, singular values of J^-1 G within %.2g (largest %.4f)\n",
                checked, worst, largest);
    CHECK(checked > 500, test::show(checked));
    CHECK(worst <= 1e-6, test::show(worst));
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");

// 1b. The GPU's seam-free quads on the tunnel: fragment fine, compute fine and coarse.
TEST_CASE("seam-free-gpu")
{
    Gpu gpu;
    SceneParams scene = make_scene(SceneKind::tunnel, 64, 64, 256);
    std::vector<bool> seam = seam_pixels(scene);
    MipChain chain = make_procedural("mipcolors", 256);
    GpuTexture texture = upload_texture(gpu.context, chain, false);
    struct Case { Stage stage; Gradients g; const char* name; };
    for (Case c : {Case{Stage::fragment, Gradients::fine, "gpu fragment fine"}, Case{Stage::compute, Gradients::fine, "gpu compute fine"},
                   Case{Stage::compute, Gradients::coarse, "gpu compute coarse"}}) {
        RenderOptions render = data_view(SceneKind::tunnel, c.stage, c.g);
        Image data = gpu_render(gpu.context, texture, scene, options_for(Filter::trilinear), render);
        Image reference = reference_render(scene, chain, options_for(Filter::trilinear), render);
        std::vector<PixelLookup> lookups = reference_lookups(scene, c.g, false);
        // The GPU's LOD at the seam against the reference's: the float32 ray cast and log2 (the debug view's
        // LOD is the shader's, so no mipmapPrecisionBits): uv ~ 2 with float32 ulp 2.4e-7 over a u step of at
        // least 1e-2 a pixel here: 2.4e-5 relative, 3.4e-5 in log2, plus log2's 3 ulp.
        double worst = 0;
        for (size_t i = 0; i < seam.size(); ++i)
            if (seam[i] && lookups[i].hit)
                worst = std::max(worst, std::abs(double(data.texels[i].x) - double(reference.texels[i].x)));
        std::printf("tunnel seam %-22s GPU vs reference LOD at the seam: max %.3g\n", c.name, worst);
        CHECK(worst <= 1e-4, test::show(worst));
        CHECK_EQ(seam_outliers(scene, data, seam, lookups, lod_curvature(reference, seam, lookups, 64) + 1e-4, c.name), 0);
    }
    destroy_texture(gpu.context, texture);
}

// 3. GPU cones vs the reference's cones: the data view (LOD, ratio) on the plane (its horizon is the grazing
//    case: gradients grow without bound, the output stays finite) and the tunnel; the reflect and skybox
//    colours (EWA on the checker cube).
TEST_CASE("cone-gpu-vs-reference")
{
    Gpu gpu;
    MipChain chain = make_procedural("checker", 256);
    GpuTexture texture = upload_texture(gpu.context, chain, false);
    for (SceneKind kind : {SceneKind::plane, SceneKind::tunnel, SceneKind::triangles}) {
        SceneParams scene = make_scene(kind, 64, 64, 256);
        // EWA (its LOD from the ellipse, J Jᵀ) on the plane only: each render costs a second of lavapipe.
        for (Filter f : kind == SceneKind::plane ? std::vector<Filter>{Filter::trilinear, Filter::ewa}
                                                 : std::vector<Filter>{Filter::trilinear}) {
            RenderOptions render = data_view(kind, Stage::fragment, Gradients::cone);
            Image data = gpu_render(gpu.context, texture, scene, options_for(f), render);
            Image reference = reference_render(scene, chain, options_for(f), render);
            double worst_lod = 0, worst_ratio = 0;
            int nonfinite = 0;
            for (size_t i = 0; i < data.texels.size(); ++i) {
                glm::dvec4 a(data.texels[i]), b(reference.texels[i]);
                nonfinite += !std::isfinite(a.x) || !std::isfinite(a.y);
                worst_lod = std::max(worst_lod, std::abs(a.x - b.x));
                worst_ratio = std::max(worst_ratio, std::abs(a.y / b.y - 1.0));
            }
            std::printf("%-9s %-9s cone GPU vs reference: LOD max %.3g, ratio max %.3g relative, %d non-finite\n",
                        to_string(kind).c_str(), to_string(f).c_str(), worst_lod, worst_ratio, nonfinite);
            CHECK_EQ(nonfinite, 0);
            CHECK(worst_lod <= 1e-3, test::show(worst_lod));
            CHECK(worst_ratio <= 1e-3, test::show(worst_ratio));
        }
    }
    destroy_texture(gpu.context, texture);
}

// 3b. The environment scenes' cones (env_scene.glsl: the sky's circle, the mirror's reflected ellipse) vs the
//     reference's (env_cast.cpp), through trilinear on the checker cube: the colours within stages' 1e-3
//     (float32 vs double on a 0.85-contrast checker), and the cone's footprint is not the differentials'
//     (so the comparison sees the cone). Not EWA: its cube form has knife edges at far off-face texels
//     (golden/README.md: reflect-checker-ewa), measured 0.016 at one pixel here.
TEST_CASE("cone-environment-gpu-vs-reference")
{
    Gpu gpu;
    EnvironmentMap env;
    env.map = EnvMap::cube;
    env.cube = make_procedural_cube("checker", 64);
    GpuEnvironment texture = upload_environment(gpu.context, env);
    Cleanup cleanup;
    cleanup.add([&] { destroy_environment(gpu.context, texture); });
    for (SceneKind kind : {SceneKind::reflect, SceneKind::skybox}) {
        SceneParams scene = make_scene(kind, 64, 64, 64);
        for (Filter f : {Filter::trilinear}) {
            SamplerOptions o = options_for(f);
            o.wrap = Wrap::clamp;
            RenderOptions cone = make_render_options(kind, Stage::fragment, Gradients::cone);
            RenderOptions ray = make_render_options(kind, Stage::fragment, Gradients::ray);
            Image a = gpu_render_environment(gpu.context, texture, scene, o, cone, nullptr);
            Image b = reference_render_environment(scene, env, o, cone);
            Image c = reference_render_environment(scene, env, o, ray);
            double worst = 0, versus_ray = 0;
            int nonfinite = 0;
            for (size_t i = 0; i < a.texels.size(); ++i) {
                glm::dvec4 x(a.texels[i]);
                nonfinite += !std::isfinite(x.x + x.y + x.z + x.w);
                worst = std::max(worst, test::max_channel_diff(x, glm::dvec4(b.texels[i])));
                versus_ray = std::max(versus_ray, test::max_channel_diff(glm::dvec4(b.texels[i]), glm::dvec4(c.texels[i])));
            }
            std::printf("%-8s %-9s cone GPU vs reference: colour max %.3g (reference cone vs ray: %.3g), %d non-finite\n",
                        to_string(kind).c_str(), to_string(f).c_str(), worst, versus_ray, nonfinite);
            CHECK_EQ(nonfinite, 0);
            CHECK(worst <= 1e-3, test::show(worst));
            CHECK(versus_ray > 1e-2, test::show(versus_ray));
        }
    }
}

TEST_SUITE_END();
