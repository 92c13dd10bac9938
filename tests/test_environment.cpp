// The environment filters on the device (shaders/texfilter/cube.glsl, latlong.glsl) through the harness's
// environment renders (vulkan/environment.h), against the math (docs/ENVIRONMENT.md) and its CPU reference
// (reference/environment.h). The reference's own facts (face table, edge and corner rules, seamlessness,
// constants) are tests/test_environment_reference.cpp; the goldens (golden/manifest.txt, skybox-*, reflect-*)
// compare whole images. Small maps (16..64 texels a face), 64x64 renders: each case a few seconds on lavapipe.
//
// Float bounds. A GPU lookup direction is the reference's up to the float ray cast: measured per pixel with
// the `none` filter, which returns normalize(dir)/2 + 1/2, so δd = |gpu - ref| of the unit direction. A face
// coordinate s = (sc/|ma| + 1)/2 moves by at most |∂s/∂d̂|·δd <= (1 + sqrt(2))/2·sqrt(3)·δd (|ma| >= 1/sqrt(3)
// for a unit direction; |∂(sc/ma)| <= (1 + |sc/ma|)/|ma|), i.e. by N·2.1·δd texels on an N-texel face.
#include "core/cube_textures.h"
#include "core/environment.h"
#include "core/procedural.h"
#include "reference/env_cast.h"
#include "reference/env_render.h"
#include "reference/environment.h"
#include "reference/stochastic.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "device_lod.h"
#include "support.h"
#include "texture/mip.h"
#include "vulkan/environment.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

using namespace tf;

namespace {

// One context and its environment pipelines for the whole process (each filter compiled once), destroyed
// when the run ends (test::at_end_of_run), not at static destruction.
struct Device {
    VulkanContext context;
    std::unique_ptr<EnvironmentPipelineCache> pipelines = std::make_unique<EnvironmentPipelineCache>();
    Device() : context(create_context(test::test_context_options())) {}
    ~Device()
    {
        pipelines.reset();
        destroy_context(context);
    }
};

Device& device()
{
    static Device* const d = [] {
        Device* made = new Device;
        test::at_end_of_run([made] { delete made; });
        return made;
    }();
    return *d;
}

Image render_gpu(const EnvironmentMap& env, const SceneParams& scene, const SamplerOptions& options,
                 Gradients gradients = Gradients::fine)
{
    const VulkanContext& context = device().context;
    GpuEnvironment gpu = upload_environment(context, env);
    Cleanup cleanup;
    cleanup.add([&] { destroy_environment(context, gpu); });
    RenderOptions render;
    render.gradients = gradients;
    return gpu_render_environment(context, gpu, scene, options, render, device().pipelines.get());
}

Image render_reference(const EnvironmentMap& env, const SceneParams& scene, const SamplerOptions& options,
                       Gradients gradients = Gradients::fine)
{
    RenderOptions render;
    render.gradients = gradients;
    return reference_render_environment(scene, env, options, render);
}

SamplerOptions with_filter(Filter filter)
{
    SamplerOptions o;
    o.filter = filter;
    o.wrap = Wrap::clamp;
    return o;
}

EnvironmentMap cube_env(const std::string& name, int size)
{
    EnvironmentMap env;
    env.map = EnvMap::cube;
    env.cube = make_procedural_cube(name, size);
    return env;
}

EnvironmentMap constant_env(EnvMap map, glm::vec4 value)
{
    EnvironmentMap env;
    env.map = map;
    if (map == EnvMap::cube) {
        std::array<Image, cube_face_count> faces;
        for (Image& f : faces)
            f = make_image(16, 16, value);
        env.cube = build_cube_map(std::move(faces));
    } else {
        env.latlong = build_mip_chain(make_image(32, 16, value));
    }
    return env;
}

// The cube of `n` whose every face is mipcolors (each level one colour): what the device's LOD is read from.
EnvironmentMap mipcolors_cube(int n)
{
    EnvironmentMap env;
    env.map = EnvMap::cube;
    for (MipChain& face : env.cube.faces)
        face = make_procedural("mipcolors", n);
    return env;
}

// Per pixel, |gpu direction - reference direction| of the unit directions (see the top of the file).
std::vector<double> direction_error(const EnvironmentMap& env, const SceneParams& scene)
{
    const Image gpu = render_gpu(env, scene, with_filter(Filter::none));
    const int width = scene.kind_size.y;
    std::vector<double> out(gpu.texels.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const glm::dvec3 ref = glm::normalize(reference_env_direction(scene, double(i % width) + 0.5, double(i / width) + 0.5));
        const glm::dvec3 got = 2.0 * glm::dvec3(gpu.texels[i]) - 1.0;
        out[i] = glm::length(got - ref);
    }
    return out;
}

// cube-hash with n-texel faces, and the 4n x 2n lat-long map resampled from it.
std::vector<EnvironmentMap> hash_maps(int n)
{
    std::vector<EnvironmentMap> maps = {cube_env("cube-hash", n)};
    EnvironmentMap latlong;
    latlong.map = EnvMap::latlong;
    latlong.latlong = build_mip_chain(latlong_from_cube(maps[0].cube, 4 * n));
    maps.push_back(latlong);
    return maps;
}

double largest_texel(const CubeMap& cube)
{
    double m = 0;
    for (const MipChain& f : cube.faces)
        for (const glm::vec4& t : f.levels[0].texels)
            m = std::max({m, double(t.r), double(t.g), double(t.b), double(t.a)});
    return m;
}

} // namespace

TEST_SUITE_BEGIN("gpu");

// A constant map gives its constant for every filter, on every pixel of both scenes and both maps: the weights
// of every family sum to one (float: EWA divides by its total weight, K <= 2·95² terms, each rounding once).
TEST_CASE("constant")
{
    const glm::vec4 value(0.25f, 0.5f, 0.75f, 1.0f);
    // nearest-mip and bilinear-mip are trilinear's two halves (the same LOD and level reads).
    const std::vector<Filter> filters = {Filter::nearest, Filter::bilinear, Filter::trilinear, Filter::aniso,
                                         Filter::ewa, Filter::bspline, Filter::catmull_rom, Filter::hw_trilinear,
                                         Filter::ground_truth};
    for (EnvMap map : {EnvMap::cube, EnvMap::latlong}) {
        const EnvironmentMap env = constant_env(map, value);
        for (SceneKind kind : {SceneKind::reflect}) // the sky behind and the mirror: both kinds of pixel
            for (Filter filter : filters) {
                // Lat-long: the families with their own weights (the others are the 2D code on a sampler2D).
                const bool taps_forms = filter == Filter::aniso || filter == Filter::ewa || filter == Filter::bspline ||
                                        filter == Filter::catmull_rom;
                if (map == EnvMap::latlong && filter != Filter::trilinear && !taps_forms)
                    continue;
                for (Taps taps : {Taps::manual, Taps::hardware}) {
                    if (taps == Taps::hardware && !taps_forms)
                        continue;
                    SamplerOptions o = with_filter(filter);
                    o.taps = taps;
                    o.truth_side = 2;
                    test::limit_failure_lines(4);
                    const Image image = render_gpu(env, make_scene(kind, 32, 32, 16), o);
                    const double eps = 2.0 * 95 * 95 * 2 * std::ldexp(1.0, -24);
                    for (const glm::vec4& t : image.texels)
                        CHECK(test::near(glm::dvec4(t), glm::dvec4(value), eps),
                              to_string(map) + " " + to_string(kind) + " " + to_string(filter) + " taps " +
                                  std::to_string(int(taps)) + ": " + test::show(glm::dvec4(t)));
                }
            }
    }
}

// Every texel of every face its own colour (cube-hash): nearest on the device reads the texel the reference
// reads, wherever the pixel's face coordinate is not within the float bound of a texel boundary, in both
// scenes: a face uploaded to the wrong layer or flipped or rotated against the spec's face table, or an
// off-by-one edge rule, changes the colour. (The includes read every texel through the direction of its
// centre, so their own face frame cancels out; what this pins is the data and the device's addressing.)
TEST_CASE("faces-and-orientation")
{
    const int n = 32;
    const EnvironmentMap env = cube_env("cube-hash", n);
    for (SceneKind kind : {SceneKind::skybox, SceneKind::reflect}) {
        const SceneParams scene = make_scene(kind, 64, 64, n);
        const std::vector<double> dir_error = direction_error(env, scene);
        const Image gpu = render_gpu(env, scene, with_filter(Filter::nearest));
        const Image ref = render_reference(env, scene, with_filter(Filter::nearest));
        int compared = 0, faces_seen = 0;
        std::array<bool, cube_face_count> seen{};
        test::limit_failure_lines(8);
        for (size_t i = 0; i < gpu.texels.size(); ++i) {
            const double px = double(i % 64) + 0.5, py = double(i / 64) + 0.5;
            EnvLookup l;
            l.dir = reference_env_direction(scene, px, py);
            int face = 0;
            const Lookup uv = cube_face_lookup(l, face);
            const double slack = 2.1 * n * dir_error[i] + 1e-6;
            auto clear = [&](double x) { return std::abs(x * n - std::round(x * n)) > slack; };
            if (!clear(uv.u) || !clear(uv.v))
                continue;
            ++compared;
            seen[size_t(face)] = true;
            CHECK(glm::dvec4(gpu.texels[i]) == glm::dvec4(ref.texels[i]),
                  to_string(kind) + " pixel " + std::to_string(i) + " face " + std::to_string(face) + ": gpu " +
                      test::show(glm::dvec4(gpu.texels[i])) + " reference " + test::show(glm::dvec4(ref.texels[i])));
        }
        for (bool s : seen)
            faces_seen += s;
        CHECK(compared > 64 * 64 * 9 / 10, std::to_string(compared) + " pixels compared");
        CHECK(faces_seen >= 3, to_string(kind) + ": " + std::to_string(faces_seen) + " faces seen");
    }
}

// Bilinear at level 0 across the seams: every tap that falls off a face reads the neighbour's texel (and the
// corner's mean of three). On cube-hash a wrong neighbour is off by the hash's contrast (~0.5); the device may
// differ from the reference only through the direction's float error: the weights move by N·2.1·δd, each
// texel contrast at most the largest texel value, plus a float rounding of the blend.
TEST_CASE("seamless-bilinear")
{
    const int n = 16;
    const EnvironmentMap env = cube_env("cube-hash", n);
    const double contrast = largest_texel(env.cube);
    for (SceneKind kind : {SceneKind::skybox, SceneKind::reflect}) {
        const SceneParams scene = make_scene(kind, 64, 64, n);
        const std::vector<double> dir_error = direction_error(env, scene);
        const Image gpu = render_gpu(env, scene, with_filter(Filter::bilinear));
        const Image ref = render_reference(env, scene, with_filter(Filter::bilinear));
        test::limit_failure_lines(8);
        for (size_t i = 0; i < gpu.texels.size(); ++i) {
            const double tol = 2.0 * 2.1 * n * dir_error[i] * contrast + 8 * std::ldexp(1.0, -24) * contrast;
            CHECK(test::max_channel_diff(glm::dvec4(gpu.texels[i]), glm::dvec4(ref.texels[i])) <= tol,
                  to_string(kind) + " pixel " + std::to_string(i) + ": gpu " + test::show(glm::dvec4(gpu.texels[i])) +
                      " reference " + test::show(glm::dvec4(ref.texels[i])) + " tolerance " + test::show(tol));
        }
    }
}

// Manual cube trilinear against the device's own seamless cube trilinear (textureGrad on the samplerCube), on
// every pixel of both scenes, across the edges and the corner the skybox looks into. The device may round
// what Vulkan lets it round, with this device's precision bits: each bilinear weight to subTexelPrecisionBits
// (one step on each axis, times the texels' contrast on that level), the LOD to mipmapPrecisionBits and the
// level blend to as many (two steps, times the difference of the two levels' values: lod_error), plus the
// direction's float error as above. cube-smooth keeps contrasts small, so a wrong texel or LOD is not hidden.
// The corner texel's weight is the one thing left to the device (the spec recommends the mean of three; lavapipe
// does it): a device that does otherwise fails here near the corner, as it should be reported.
// The LOD is the device's own: Vulkan lets it approximate the scale factor (device_lod.h), so its lambda is read
// per pixel from the same scene on a mipcolors cube, checked against Vulkan's bounds on the face's derivatives,
// and the manual filter (exact lambda) may differ by what the blend changes between the two lambdas.
TEST_CASE("manual-vs-hardware-trilinear")
{
    const int n = 32;
    const EnvironmentMap env = cube_env("cube-smooth", n);
    const DeviceInfo& info = test::test_device_info();
    const double step = std::ldexp(1.0, -int(info.sub_texel_precision_bits));
    const double lod_error = 2.0 * std::ldexp(1.0, -int(info.mipmap_precision_bits));
    // The largest difference between neighbouring texels (also across face edges) on any level: the contrast.
    double texel_contrast = 0;
    for (int level = 0; level < int(env.cube.faces[0].levels.size()); ++level) {
        const int size = env.cube.faces[0].levels[size_t(level)].width;
        for (int f = 0; f < cube_face_count; ++f)
            for (int j = -1; j <= size; ++j)
                for (int i = -1; i <= size; ++i) {
                    const glm::dvec4 t = cube_texel(env.cube, f, level, i, j);
                    texel_contrast = std::max({texel_contrast, test::max_channel_diff(t, cube_texel(env.cube, f, level, i + 1, j)),
                                               test::max_channel_diff(t, cube_texel(env.cube, f, level, i, j + 1))});
                }
    }
    for (SceneKind kind : {SceneKind::skybox, SceneKind::reflect}) {
        const SceneParams scene = make_scene(kind, 64, 64, n);
        const std::vector<double> dir_error = direction_error(env, scene);
        const Image manual = render_gpu(env, scene, with_filter(Filter::trilinear));
        const Image hardware = render_gpu(env, scene, with_filter(Filter::hw_trilinear));
        const std::vector<EnvLookup> lookups = reference_env_lookups(scene, Gradients::fine);
        // lambda per pixel: the device's (hw-trilinear on the mipcolors cube) and the exact one (the reference's).
        const EnvironmentMap colors = mipcolors_cube(n);
        const Image device_colors = render_gpu(colors, scene, with_filter(Filter::hw_trilinear));
        const MipChain& chain = colors.cube.faces[0];
        const double top = double(chain.levels.size() - 1);
        std::vector<double> device_lod(lookups.size()), exact_lod(lookups.size());
        int outside = 0, unblended = 0;
        double below = 0, above = 0;
        for (size_t i = 0; i < lookups.size(); ++i) {
            double residual = 0, exact_residual = 0;
            device_lod[i] = test::mipcolors_lod(chain, glm::dvec4(device_colors.texels[i]), residual);
            exact_lod[i] = test::mipcolors_lod(
                chain, reference_cube_sample(colors.cube, with_filter(Filter::trilinear), lookups[i]), exact_residual);
            int face = 0;
            const test::LodRange range = test::spec_lod_range(cube_face_lookup(lookups[i], face), n, n);
            unblended += residual > 1e-3;
            outside += device_lod[i] < std::clamp(range.lo, 0.0, top) - lod_error ||
                       device_lod[i] > std::clamp(range.hi, 0.0, top) + lod_error;
            below = std::min(below, device_lod[i] - exact_lod[i]);
            above = std::max(above, device_lod[i] - exact_lod[i]);
        }
        MESSAGE(to_string(kind) << ": device LOD " << below << ".." << above << " levels from the exact one, " << outside
                                << " pixels outside Vulkan's bounds, " << unblended << " no blend of two levels");
        CHECK(outside == 0 && unblended == 0, to_string(kind) + ": " + std::to_string(outside) +
                                                  " pixels' LOD outside Vulkan's scale-factor bounds, " +
                                                  std::to_string(unblended) + " no blend of two mipcolors levels");
        test::limit_failure_lines(8);
        double worst = 0;
        int near_edge = 0, near_corner = 0; // pixels within one level-0 texel of a face edge / of a corner
        for (const EnvLookup& lookup : lookups) {
            int face = 0;
            const Lookup l = cube_face_lookup(lookup, face);
            const double dx = std::min(l.u, 1.0 - l.u) * n, dy = std::min(l.v, 1.0 - l.v) * n;
            near_edge += std::min(dx, dy) < 1.0;
            near_corner += std::max(dx, dy) < 1.0;
        }
        CHECK(near_edge > 0 && (kind != SceneKind::skybox || near_corner > 0),
              to_string(kind) + ": " + std::to_string(near_edge) + " pixels within a texel of an edge, " +
                  std::to_string(near_corner) + " of a corner");
        for (size_t i = 0; i < manual.texels.size(); ++i) {
            // What a blend weight can move: the largest difference of two neighbouring levels' values at the
            // lookup (every pair, not only the reference LOD's: the device's LOD may sit in the next pair).
            SamplerOptions level = with_filter(Filter::bilinear_mip);
            double level_gap = 0;
            for (int k = 0; k + 1 < int(env.cube.faces[0].levels.size()); ++k) {
                level.lod_min = level.lod_max = float(k);
                SamplerOptions next = level;
                next.lod_min = next.lod_max = float(k + 1);
                level_gap = std::max(level_gap, test::max_channel_diff(reference_cube_sample(env.cube, level, lookups[i]),
                                                                        reference_cube_sample(env.cube, next, lookups[i])));
            }
            const double lod_gap = std::abs(device_lod[i] - exact_lod[i]) + lod_error;
            const double tol = 2.0 * step * texel_contrast + lod_gap * level_gap + 2.0 * 2.1 * n * dir_error[i] * texel_contrast +
                               1e-6;
            const double diff = test::max_channel_diff(glm::dvec4(manual.texels[i]), glm::dvec4(hardware.texels[i]));
            worst = std::max(worst, diff / tol);
            CHECK(diff <= tol, to_string(kind) + " pixel " + std::to_string(i) + ": manual " +
                                   test::show(glm::dvec4(manual.texels[i])) + " hardware " +
                                   test::show(glm::dvec4(hardware.texels[i])) + " tolerance " + test::show(tol));
        }
        MESSAGE(to_string(kind) << ": worst |manual - hardware| / tolerance " << worst);
    }
}

// EWA on the mirror sphere against the ground truth through the same reflection (Gaussian pixel, 64 samples a
// pixel): closer than trilinear, whose isotropic footprint blurs the curved, anisotropic ones (the family
// that models the Gaussian pixel must beat the one that does not, as it does on every 2D scene).
TEST_CASE("ewa-reflect-vs-truth")
{
    const EnvironmentMap env = cube_env("checker", 64);
    const SceneParams scene = make_scene(SceneKind::reflect, 64, 64, 64);
    SamplerOptions truth = with_filter(Filter::ground_truth);
    truth.pixel_filter = PixelFilter::gaussian;
    truth.truth_side = 8;
    const Image ideal = render_gpu(env, scene, truth);
    auto rmse = [&](const Image& image) {
        double sum = 0;
        for (size_t i = 0; i < image.texels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                sum += std::pow(double(image.texels[i][c]) - double(ideal.texels[i][c]), 2.0);
        return std::sqrt(sum / (3.0 * double(image.texels.size())));
    };
    const double ewa = rmse(render_gpu(env, scene, with_filter(Filter::ewa)));
    const double trilinear = rmse(render_gpu(env, scene, with_filter(Filter::trilinear)));
    MESSAGE("reflect, Gaussian truth: ewa rmse " << ewa << ", trilinear " << trilinear);
    CHECK(ewa < trilinear, "ewa " + test::show(ewa) + " trilinear " + test::show(trilinear));
}

// The lat-long map on the device across its seam (u = 0/1, the camera turned to look along +z) and towards the
// +y pole, against the reference, bilinear and trilinear: the float bound as above with the mapping's own
// Jacobian (|∂u/∂d̂| = 1/(2πρ), |∂v/∂d̂| = 1/(πρ), ρ = sqrt(d.x² + d.z²) of the unit direction) in texels,
// plus the precision Vulkan requires of atan (4096 ULP), which both angles come from. A texel read from the
// wrong side of the seam or the pole is off by the hash's contrast (~0.5), 10-100x that bound.
TEST_CASE("latlong-seam-and-pole")
{
    EnvironmentMap env;
    env.map = EnvMap::latlong;
    env.latlong = build_mip_chain(latlong_from_cube(make_procedural_cube("cube-hash", 16), 64));
    const double contrast = 1.0;
    bool seam = false, pole = false;
    for (double yaw : {-48.0, 48.0})
        for (double pitch : {0.0, 55.0}) {
            SceneParams scene = make_scene(SceneKind::skybox, 64, 64, 64);
            Camera turn = camera_of(scene);
            turn.yaw = yaw;
            turn.pitch = pitch;
            scene = with_camera(scene, turn);
            const std::vector<double> dir_error = direction_error(env, scene);
            double umin = 1, umax = 0, rho_min = 1;
            for (int i = 0; i < 64 * 64; ++i) {
                EnvLookup l;
                l.dir = reference_env_direction(scene, double(i % 64) + 0.5, double(i / 64) + 0.5);
                const Lookup uv = latlong_lookup(l);
                umin = std::min(umin, uv.u);
                umax = std::max(umax, uv.u);
                rho_min = std::min(rho_min, std::hypot(l.dir.x, l.dir.z) / glm::length(l.dir));
            }
            seam = seam || (umin < 0.05 && umax > 0.95);
            pole = pole || rho_min < 0.2;
            for (Filter filter : {Filter::bilinear, Filter::trilinear}) {
                const Image gpu = render_gpu(env, scene, with_filter(filter));
                const Image ref = render_reference(env, scene, with_filter(filter));
                test::limit_failure_lines(8);
                for (size_t i = 0; i < gpu.texels.size(); ++i) {
                    const glm::dvec3 d = glm::normalize(reference_env_direction(scene, double(i % 64) + 0.5, double(i / 64) + 0.5));
                    const double rho = std::max(std::hypot(d.x, d.z), 1e-3);
                    // The angles themselves: Vulkan gives atan 4096 ULP (of a result <= π: ulp 2^-22).
                    const double atan_error = 4096.0 * std::ldexp(1.0, -22);
                    const double texels = (64.0 / (2.0 * M_PI) + 32.0 / M_PI) * (dir_error[i] / rho + atan_error);
                    const double tol = (filter == Filter::trilinear ? 4.0 : 2.0) * texels * contrast + 1e-5;
                    CHECK(test::max_channel_diff(glm::dvec4(gpu.texels[i]), glm::dvec4(ref.texels[i])) <= tol,
                          to_string(filter) + " yaw " + test::show(yaw) + " pitch " + test::show(pitch) + " pixel " +
                              std::to_string(i) + ": gpu " + test::show(glm::dvec4(gpu.texels[i])) + " reference " +
                              test::show(glm::dvec4(ref.texels[i])));
                }
            }
        }
    CHECK(seam, "no view crossed the u = 0/1 seam");
    CHECK(pole, "no view came near the +y pole");
}

// The cubics on the maps, bspline and catmull-rom (level 0, 16 texel reads, past a face's edge or a pole by the
// map's rule on the device and in the reference alike), on every pixel of both scenes and both maps. The bound
// is the reference's own spread when the pixel's direction moves by its float error (direction_error) along each
// axis, plus 16 reads' float rounding: that covers the reconstruction's slope and, near a cube edge, the device
// choosing the other face of a float tie (a cubic on a face's extended plane is continuous across the edge only
// to ~1e-4 of the contrast here: the off-face texels do not lie on the neighbour's grid). It can fail: a texel
// read from the wrong face or across the pole is off by the contrast, far beyond the spread. On the lat-long map
// the device's atan error is added (as in latlong-seam-and-pole). One more term on the cube: a texel k >= 2 past both edges of a corner, diagonally (|di| = |dj|), is read through a direction that
// lies exactly between the two side faces, so float and double may take it from either: its weight |w_i w_j|
// times the contrast (tie_weight).
// |k(d)| of the kernel at the four taps i0-1..i0+2 for fraction t (bicubic.glsl's math).
std::array<double, 4> cubic_weights(double t, Filter filter)
{
    auto k = [&](double d) {
        d = std::abs(d);
        if (filter == Filter::bspline)
            return d < 1 ? (4 - 6 * d * d + 3 * d * d * d) / 6 : d < 2 ? (2 - d) * (2 - d) * (2 - d) / 6 : 0.0;
        return d < 1 ? 1.5 * d * d * d - 2.5 * d * d + 1 : d < 2 ? -0.5 * d * d * d + 2.5 * d * d - 4 * d + 2 : 0.0;
    };
    return {std::abs(k(1 + t)), std::abs(k(t)), std::abs(k(1 - t)), std::abs(k(2 - t))};
}

// The summed |weight| of the cubic's taps that sit diagonally k >= 2 texels past a corner of the lookup's face.
double tie_weight(const glm::dvec3& dir, int n, Filter filter)
{
    EnvLookup l;
    l.dir = dir;
    int face = 0;
    const Lookup uv = cube_face_lookup(l, face);
    const double x = uv.u * n - 0.5, y = uv.v * n - 0.5;
    const double ix = std::floor(x), iy = std::floor(y);
    const std::array<double, 4> wx = cubic_weights(x - ix, filter), wy = cubic_weights(y - iy, filter);
    auto past = [&](long long i) { return i < 0 ? -i : i >= n ? i - n + 1 : 0; }; // texels past an edge
    double sum = 0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
            const long long px = past((long long)ix - 1 + a), py = past((long long)iy - 1 + b);
            if (px >= 2 && px == py)
                sum += wx[size_t(a)] * wy[size_t(b)];
        }
    return sum;
}
// The hardware-tap forms (--taps hardware: 4 bilinear taps for the B-spline, 9 for Catmull-Rom, each through
// the cube's seamless sampler or the lat-long one, which the reference models tap by tap) add the device's
// sub-texel rounding: each tap's two blend fractions move by up to 2^-subTexelPrecisionBits, so a tap by at
// most 2 steps times the contrast, times the taps' summed |weight| = (sum |k|)² over the axes (tap_weight_sum).
// They have no float tie past a corner: a tap there lies on the edge of two faces, where seamless bilinear
// reads the same texels from either side.
// --magnify: trilinear with level 0's cubic is that cubic wherever λ <= 0, as everywhere in the skybox here
// (~0.25-0.5 texel a pixel), bit for bit on the device and in the reference. ewa --taps hardware with it is the
// mean of that cubic's taps at four points of the footprint (ewa.glsl), held to the cubic's tolerance.
double tap_weight_sum(const glm::dvec3& dir, const EnvironmentMap& env, int n, Filter filter)
{
    EnvLookup l;
    l.dir = dir;
    int face = 0;
    const Lookup uv = env.map == EnvMap::cube ? cube_face_lookup(l, face) : latlong_lookup(l);
    const double w = env.map == EnvMap::cube ? n : 4.0 * n, h = env.map == EnvMap::cube ? n : 2.0 * n;
    const double x = uv.u * w - 0.5, y = uv.v * h - 0.5;
    double sx = 0, sy = 0;
    for (double k : cubic_weights(x - std::floor(x), filter)) sx += k;
    for (double k : cubic_weights(y - std::floor(y), filter)) sy += k;
    return sx * sy;
}

TEST_CASE("cubic-magnification")
{
    const int n = 16;
    const std::vector<EnvironmentMap> maps = hash_maps(n);
    const double contrast = largest_texel(maps[0].cube);
    const double step = std::ldexp(1.0, -int(test::test_device_info().sub_texel_precision_bits));
    for (const EnvironmentMap& env : maps)
        for (SceneKind kind : {SceneKind::skybox, SceneKind::reflect}) {
            const SceneParams scene = make_scene(kind, 64, 64, n);
            const std::vector<double> dir_error = direction_error(env, scene);
            std::vector<double> ewa_tolerance(dir_error.size(), 0.0);
            for (Filter filter : {Filter::bspline, Filter::catmull_rom})
            for (Taps taps : {Taps::manual, Taps::hardware}) {
                SamplerOptions o = with_filter(filter);
                o.taps = taps;
                const bool hardware = taps == Taps::hardware;
                const Image gpu = render_gpu(env, scene, o);
                auto reference_with = [&](const glm::dvec3& dir, const SamplerOptions& options) {
                    EnvLookup l;
                    l.dir = dir;
                    return env.map == EnvMap::cube ? reference_cube_sample(env.cube, options, l)
                                                   : reference_latlong_sample(env.latlong, options, l);
                };
                auto reference_at = [&](const glm::dvec3& dir) { return reference_with(dir, o); };
                SamplerOptions manual = o;
                manual.taps = Taps::manual;
                test::limit_failure_lines(8);
                double worst = 0;
                int off_manual = 0; // hardware taps: pixels where the manual form's reference would fail
                for (size_t i = 0; i < gpu.texels.size(); ++i) {
                    const glm::dvec3 d = glm::normalize(reference_env_direction(scene, double(i % 64) + 0.5, double(i / 64) + 0.5));
                    const glm::dvec4 ref = reference_at(d);
                    double spread = 0;
                    for (int axis = 0; axis < 3; ++axis)
                        for (double sign : {-1.0, 1.0}) {
                            glm::dvec3 moved = d;
                            moved[axis] += sign * 2.0 * dir_error[i];
                            spread = std::max(spread, test::max_channel_diff(reference_at(moved), ref));
                        }
                    const double ties = env.map == EnvMap::cube && !hardware ? tie_weight(d, n, filter) * contrast : 0.0;
                    const double rounding = hardware ? 2.0 * step * contrast * tap_weight_sum(d, env, n, filter) : 0.0;
                    // lat-long: the device's atan itself (Vulkan: 4096 ULP of a result <= π), in texels of the
                    // 4n x 2n map, times the steepest slope (B-spline 1, Catmull-Rom 1.5 a texel) on two axes.
                    const double angles = env.map == EnvMap::latlong
                                              ? 2.0 * (filter == Filter::bspline ? 1.0 : 1.5) *
                                                    (4.0 * n / (2.0 * M_PI) + 2.0 * n / M_PI) * 4096.0 *
                                                    std::ldexp(1.0, -22) * contrast
                                              : 0.0;
                    const double tol = spread + ties + rounding + angles + 32 * std::ldexp(1.0, -24) * contrast;
                    // ewa's magnification below reads this cubic's taps at four points near d: the same terms
                    // with the largest summed |weight| of Catmull-Rom's taps, 1.25² (at fraction 1/2).
                    if (filter == Filter::catmull_rom && hardware)
                        ewa_tolerance[i] = tol - rounding + 2.0 * step * contrast * 1.5625;
                    const double e = test::max_channel_diff(glm::dvec4(gpu.texels[i]), ref);
                    worst = std::max(worst, e / tol);
                    if (hardware)
                        off_manual += test::max_channel_diff(glm::dvec4(gpu.texels[i]), reference_with(d, manual)) > tol;
                    CHECK(e <= tol, to_string(env.map) + " " + to_string(kind) + " " + to_string(filter) + " taps " +
                                        to_string(taps) + " pixel " +
                                        std::to_string(i) + ": gpu " + test::show(glm::dvec4(gpu.texels[i])) +
                                        " reference " + test::show(ref) + " tolerance " + test::show(tol));
                }
                std::printf("%s %s %s taps %s: worst error / tolerance %.3f\n", to_string(env.map).c_str(),
                            to_string(kind).c_str(), to_string(filter).c_str(), to_string(taps).c_str(), worst);
                // The skybox looks into a corner, where re-projected taps part from the texel sum by far more
                // than the rounding: the reference's tap model is what the device is held to, not the manual sum.
                if (hardware && env.map == EnvMap::cube && kind == SceneKind::skybox)
                    CHECK(off_manual > 0, to_string(filter) + " taps hardware: within tolerance of the manual form "
                                                              "everywhere (the check could not tell the models apart)");
            }
            if (kind != SceneKind::skybox)
                continue;
            SamplerOptions magnified = with_filter(Filter::trilinear);
            magnified.magnify = Reconstruction::catmull_rom;
            const Image cubic_gpu = render_gpu(env, scene, with_filter(Filter::catmull_rom));
            const Image magnified_gpu = render_gpu(env, scene, magnified);
            CHECK(cubic_gpu.texels == magnified_gpu.texels,
                  to_string(env.map) + ": trilinear --magnify catmull-rom differs from catmull-rom where λ <= 0 (device)");
            CHECK(render_reference(env, scene, with_filter(Filter::catmull_rom)).texels ==
                      render_reference(env, scene, magnified).texels,
                  to_string(env.map) + ": trilinear --magnify catmull-rom differs from catmull-rom where λ <= 0 (reference)");
            CHECK(cubic_gpu.texels != render_gpu(env, scene, with_filter(Filter::trilinear)).texels,
                  to_string(env.map) + ": trilinear without --magnify equals the cubic (the check could not fail)");
            SamplerOptions cubic_hw = with_filter(Filter::catmull_rom), ewa_hw = with_filter(Filter::ewa);
            cubic_hw.taps = ewa_hw.taps = Taps::hardware;
            ewa_hw.magnify = Reconstruction::catmull_rom;
            // ewa --taps hardware --magnify catmull-rom where λ <= 0 (the whole skybox): the mean of the cubic's
            // taps at four points spread over the pixel's footprint (ewa.glsl), on the device as in the reference.
            const Image ewa_gpu = render_gpu(env, scene, ewa_hw), ewa_ref = render_reference(env, scene, ewa_hw);
            const Image cubic_ref = render_reference(env, scene, cubic_hw);
            double worst_ewa = 0, spread_effect = 0;
            for (size_t i = 0; i < ewa_gpu.texels.size(); ++i) {
                const double e = test::max_channel_diff(glm::dvec4(ewa_gpu.texels[i]), glm::dvec4(ewa_ref.texels[i]));
                worst_ewa = std::max(worst_ewa, e / ewa_tolerance[i]);
                spread_effect = std::max(spread_effect, test::max_channel_diff(glm::dvec4(cubic_ref.texels[i]),
                                                                               glm::dvec4(ewa_ref.texels[i])));
            }
            std::printf("%s skybox ewa taps hardware --magnify catmull-rom: worst error / tolerance %.3f; "
                        "largest change from the cubic alone %.3f\n",
                        to_string(env.map).c_str(), worst_ewa, spread_effect);
            CHECK(worst_ewa <= 1.0, test::show(worst_ewa));
            // On the hash (every texel its own colour) a spread of a quarter texel or more moves some pixel off
            // the cubic at the centre by over 5% of the contrast (measured 10-15%): the check saw the spread.
            CHECK(spread_effect > 0.05 * contrast, test::show(spread_effect));
        }
}

// --stochastic on the maps (the 2D estimators of stochastic.glsl on the face or the lat-long uv, every texel and
// tap read by the map's rule). Reference: the estimator's expectation is the deterministic filter (bilinear,
// trilinear, aniso; aniso --taps hardware too) to double rounding, on every pixel of both scenes and both maps,
// edges, corners, seam and pole included; on a constant map every family (ewa too) gives the constant with no
// variance (the probabilities sum to 1). Device: the mean of 4 frames equals the reference's mean of the same
// frames wherever the picks agree. A pick flips only where xi lies within the float error of a weight boundary
// (~1e-6 of the pixels), so at most 1 % of the pixels may differ by more than: manual, the float rounding of a
// mean of texel copies (1e-5); hardware taps, the sub-texel rounding (2 steps a tap), the level blend
// (mipmapPrecisionBits, aniso's trilinear taps), and the taps' move under the direction's float error (as in
// seamless-bilinear). The check sees the noise: most pixels' 4-frame mean differs from the deterministic filter.
TEST_CASE("stochastic")
{
    const int n = 16;
    const std::vector<EnvironmentMap> maps = hash_maps(n);
    const double contrast = largest_texel(maps[0].cube);
    const DeviceInfo& info = test::test_device_info();
    const double step = std::ldexp(1.0, -int(info.sub_texel_precision_bits));
    const double blend = 2.0 * std::ldexp(1.0, -int(info.mipmap_precision_bits));
    struct Case {
        Filter filter;
        Taps taps;
    };
    const Case cases[] = {{Filter::bilinear, Taps::manual}, {Filter::trilinear, Taps::manual},
                          {Filter::trilinear, Taps::hardware}, {Filter::aniso, Taps::manual},
                          {Filter::aniso, Taps::hardware}, {Filter::ewa, Taps::manual}};
    for (const EnvironmentMap& env : maps)
        for (SceneKind kind : {SceneKind::skybox, SceneKind::reflect}) {
            const SceneParams scene = make_scene(kind, 64, 64, n);
            const std::vector<EnvLookup> lookups = reference_env_lookups(scene, Gradients::fine);
            const std::vector<double> dir_error = direction_error(env, scene);
            EnvironmentMap flat = constant_env(env.map, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
            for (const Case& c : cases) {
                SamplerOptions o = with_filter(c.filter);
                o.taps = c.taps;
                o.stochastic = true;
                o.accumulate = 4;
                const bool tap_trilinear = c.filter == Filter::trilinear && c.taps == Taps::hardware;
                const std::string what = to_string(env.map) + " " + to_string(kind) + " " + to_string(c.filter) +
                                         (c.taps == Taps::hardware ? " taps" : "");
                SamplerOptions deterministic = o;
                deterministic.stochastic = false;
                deterministic.accumulate = 1;
                auto moments = [&](const EnvironmentMap& m, const EnvLookup& l) {
                    return m.map == EnvMap::cube ? reference_cube_stochastic_moments(m.cube, o, l)
                                                 : reference_latlong_stochastic_moments(m.latlong, o, l);
                };
                double expectation = 0, constant = 0;
                for (const EnvLookup& l : lookups) {
                    // ewa's expectation is its weighted mean, not its fit (stochastic.glsl); trilinear's taps on a
                    // lat-long map clamp at a pole, where the manual filter reads across it.
                    if (c.filter != Filter::ewa && !(tap_trilinear && env.map == EnvMap::latlong))
                        expectation = std::max(expectation, test::max_channel_diff(
                                                                moments(env, l).mean,
                                                                reference_environment_sample(env, deterministic, l)));
                    const StochasticMoments m = moments(flat, l);
                    constant = std::max({constant, test::max_channel_diff(m.mean, glm::dvec4(0.25, 0.5, 0.75, 1.0)),
                                         test::max_channel_diff(m.variance, glm::dvec4(0.0))});
                }
                CHECK(expectation <= 1e-12, what + ": |E[one texel] - deterministic| " + test::show(expectation));
                CHECK(constant <= 1e-12, what + ": constant map, |E - constant| or variance " + test::show(constant));

                const Image gpu = render_gpu(env, scene, o);
                const Image ref = render_reference(env, scene, o);
                const Image fixed = render_reference(env, scene, deterministic);
                int differ = 0, noisy = 0;
                for (size_t i = 0; i < gpu.texels.size(); ++i) {
                    const double moved = 2.0 * 2.1 * n * dir_error[i] * contrast;
                    const double tol = c.taps == Taps::hardware
                                           ? 2.0 * step * contrast + (c.filter == Filter::aniso ? blend * contrast : 0.0) +
                                                 moved + 1e-5
                                           : 1e-5;
                    differ += test::max_channel_diff(glm::dvec4(gpu.texels[i]), glm::dvec4(ref.texels[i])) > tol;
                    noisy += test::max_channel_diff(glm::dvec4(ref.texels[i]), glm::dvec4(fixed.texels[i])) > 1e-3;
                }
                const double share = double(differ) / double(gpu.texels.size());
                std::printf("%s: device vs reference, 4 frames: %d pixels differ (%.4f %%); %d of %zu noisy\n",
                            what.c_str(), differ, 100.0 * share, noisy, gpu.texels.size());
                CHECK(share <= 0.01, what + ": " + std::to_string(differ) + " pixels differ from the reference's picks");
                // Trilinear's taps choose only a level: none to choose where the skybox magnifies (λ <= 0 everywhere),
                // on the mirror where frac(λ) > 0.
                const double least = !tap_trilinear ? 0.5 : kind == SceneKind::reflect ? 0.1 : 0.0;
                CHECK(noisy >= least * double(gpu.texels.size()),
                      what + ": only " + std::to_string(noisy) + " pixels noisy (the check could not see a wrong pick)");
            }
        }
}

// What the environment scenes refuse, before any work.
TEST_CASE("refusals")
{
    const EnvironmentMap env = constant_env(EnvMap::cube, glm::vec4(1.0f));
    const SceneParams scene = make_scene(SceneKind::skybox, 8, 8, 16);
    CHECK_THROWS_WITH(render_gpu(env, scene, with_filter(Filter::sat)), "no environment-map form");
    CHECK_THROWS_WITH(render_gpu(env, scene, with_filter(Filter::brilinear)), "no environment-map form");
    CHECK_THROWS_WITH(render_reference(env, scene, with_filter(Filter::sat_assembly)), "no environment-map form");
    SamplerOptions stochastic = with_filter(Filter::nearest); // as in 2D: bilinear, trilinear, aniso, ewa only
    stochastic.stochastic = true;
    CHECK_THROWS_WITH(render_gpu(env, scene, stochastic), "--stochastic applies to bilinear, trilinear, aniso and ewa");
    stochastic.filter = Filter::ewa; // the block taps have no CPU reference, on the maps as in 2D
    stochastic.taps = Taps::hardware;
    CHECK_THROWS_WITH(render_reference(env, scene, stochastic), "has no CPU reference");
}

TEST_SUITE_END();
