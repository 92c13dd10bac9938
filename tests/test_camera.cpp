// The movable camera (host/scene/camera.h) and `texfilter render --camera/--frame`: the scene's own camera
// is an exact identity, the text form reads back to the bit, fly/turn/orbit do what they say, a moved camera
// renders on the GPU within the golden tests' own thresholds of the CPU reference (ray-cast and mesh), and the
// CLI's flags give the in-process render bit for bit. Validation layers on.
#include "support.h"
#include "cli/golden.h"
#include "core/diff.h"
#include "io/image_io.h"
#include "io/pfm.h"
#include "io/texture_source.h"
#include "reference/render.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "texture/image.h"
#include "vulkan/backend.h"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

using namespace tf;

namespace {

bool same_bits(const SceneParams& a, const SceneParams& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_bits(const Camera& a, const Camera& b)
{
    double x[5] = {a.position.x, a.position.y, a.position.z, a.yaw, a.pitch};
    double y[5] = {b.position.x, b.position.y, b.position.z, b.yaw, b.pitch};
    return std::memcmp(x, y, sizeof x) == 0;
}

glm::dvec3 d3(glm::vec4 v) { return glm::dvec3(v); }

// Where a world point appears: its ndc through the scene's camera (the mesh vertex shader's projection).
glm::dvec2 ndc_of(const SceneParams& scene, glm::dvec3 point)
{
    glm::dvec3 c = point - d3(scene.origin), r = d3(scene.right), u = d3(scene.up);
    double z = glm::dot(c, d3(scene.forward));
    return {glm::dot(c, r) / (glm::dot(r, r) * z), glm::dot(c, u) / (glm::dot(u, u) * z)};
}

// Every scene the CLI can make, plus the camera path's frame and the minify sweep's form.
std::vector<SceneParams> scenes_to_check()
{
    std::vector<SceneParams> scenes;
    for (SceneKind kind : all_scenes()) {
        scenes.push_back(make_scene(kind, 64, 48, 256));
        scenes.push_back(scene_at_frame(make_scene(kind, 256, 256, 300), 12345, 300));
    }
    scenes.push_back(make_minified_scene(128, 96, 256, 37.5));
    return scenes;
}

std::string golden_case_text(const GoldenCase& c) { return c.name + " (thresholds from golden/manifest.txt)"; }

const GoldenCase& manifest_case(const std::string& name)
{
    static const std::vector<GoldenCase> cases = read_manifest(TF_GOLDEN_DIR "/manifest.txt");
    for (const GoldenCase& c : cases)
        if (c.name == name)
            return c;
    throw Error("golden/manifest.txt has no case " + name);
}

} // namespace

TEST_SUITE_BEGIN("reference");

// 1. The scene's own camera changes nothing, to the bit, in every scene (float basis -> double -> float).
TEST_CASE("identity-every-scene")
{
    for (const SceneParams& scene : scenes_to_check()) {
        Camera own = camera_of(scene);
        CHECK(own.yaw == 0.0 && own.pitch == 0.0 && own.position == d3(scene.origin));
        CHECK(same_bits(with_camera(scene, own), scene), "scene id " + std::to_string(scene.kind_size.x) + ", " +
                                                             std::to_string(scene.kind_size.y) + " pixels wide");
        // A zero fly or turn is the identity too.
        CHECK(same_bits(with_camera(scene, turn(fly(own, scene, glm::dvec3(0.0)), 0.0, 0.0)), scene));
    }
}

// 2. to_string / parse_camera read back every bit: random cameras over many magnitudes, signed zeros,
//    subnormals, the pitch limits' neighbours.
TEST_CASE("text-round-trip")
{
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-300.0, 6.0);
    auto value = [&](double limit) {
        double v = std::copysign(std::pow(10.0, exponent(random)), unit(random));
        return std::abs(v) > limit ? unit(random) * limit : v;
    };
    std::vector<Camera> cameras = {{{0.0, -0.0, 0.0}, -0.0, 0.0},
                                   {{4.9406564584124654e-324, -2.2250738585072014e-308, 1e6}, -1e6, 89.999999999999986},
                                   {{0.1, 0.2, 0.3}, 1.0 / 3.0, -89.999999999999986}};
    for (int i = 0; i < 20000; ++i)
        cameras.push_back({{value(1e6), value(1e6), value(1e6)}, value(1e6), unit(random) * 89.99});
    int mismatches = 0;
    for (const Camera& c : cameras) {
        std::string text = to_string(c);
        if (!same_bits(parse_camera(text), c) && ++mismatches <= 5)
            CHECK(false, text);
    }
    CHECK_EQ(mismatches, 0);
    CHECK(to_string(Camera{{1.0, -0.0, 2.5}, 30.0, -10.0}) == "1,-0,2.5,30,-10", to_string(Camera{{1.0, -0.0, 2.5}, 30.0, -10.0}));
}

// 3. Bad camera text: a tf::Error that says what is wrong.
TEST_CASE("parse-errors")
{
    CHECK_THROWS_WITH(parse_camera(""), "expected 5 comma-separated numbers X,Y,Z,YAW,PITCH, got 1 field");
    CHECK_THROWS_WITH(parse_camera("1,2,3,4"), "got 4 fields");
    CHECK_THROWS_WITH(parse_camera("1,2,3,4,5,6"), "got 6 fields");
    CHECK_THROWS_WITH(parse_camera("1,,3,4,5"), "camera Y '' is not a number");
    CHECK_THROWS_WITH(parse_camera("1,2,3,abc,5"), "camera YAW 'abc' is not a number");
    CHECK_THROWS_WITH(parse_camera(" 1,2,3,4,5"), "camera X ' 1' is not a number");
    CHECK_THROWS_WITH(parse_camera("1,2,3,4,5x"), "camera PITCH '5x' is not a number");
    // core/numbers.h's grammar, as every numeric flag: decimal and finite.
    CHECK_THROWS_WITH(parse_camera("1,2,nan,4,5"), "camera Z 'nan' is not a number");
    CHECK_THROWS_WITH(parse_camera("1,2,3,-inf,5"), "camera YAW '-inf' is not a number");
    CHECK_THROWS_WITH(parse_camera("0x1,2,3,4,5"), "camera X '0x1' is not a number");
    CHECK_THROWS_WITH(parse_camera("1,2,3,4,90"), "camera PITCH = 90 degrees: must be inside (-90, 90)");
    CHECK_THROWS_WITH(parse_camera("1,2,3,4,-90.5"), "camera PITCH = -90.5 degrees");
    CHECK_THROWS_WITH(parse_camera("1e7,2,3,4,5"), "camera X = 10000000 is too large (at most 1e6 world units");
    CHECK_THROWS_WITH(parse_camera("1,2,3,-2e6,5"), "camera YAW = -2000000 is too large (at most 1e6 degrees");
    CHECK_THROWS_WITH(parse_camera("1,2,1e400,4,5"), "camera Z '1e400' is not a number");
    // with_camera refuses what parse_camera refuses.
    SceneParams plane = make_scene(SceneKind::plane, 64, 64, 256);
    CHECK_THROWS_WITH(with_camera(plane, Camera{{0.0, 1.0, 0.0}, 0.0, 90.0}), "camera PITCH = 90");
    CHECK_THROWS_WITH(with_camera(plane, Camera{{0.0, NAN, 0.0}, 0.0, 0.0}), "camera Y is nan");
}

// 4. turn keeps the position, clamps pitch to 89 and wraps yaw; yaw turns forward towards the scene's right
//    about its up (kept exactly), pitch towards the up; the field of view (|right|, |up|) is kept.
TEST_CASE("turn")
{
    SceneParams scene = make_scene(SceneKind::triangles, 64, 48, 256);
    Camera start = camera_of(scene);
    Camera turned = turn(start, 200.0, 120.0);
    CHECK(turned.position == start.position);
    CHECK_EQ(turned.pitch, 89.0);
    CHECK_EQ(turned.yaw, -160.0);
    CHECK_EQ(turn(turned, 0.0, -500.0).pitch, -89.0);
    CHECK_EQ(turn(start, 30.0, 0.0).yaw, 30.0); // no wrap inside [-180, 180]: exactly the sum

    glm::dvec3 f(scene.forward), r(scene.right), u(scene.up);
    SceneParams yawed = with_camera(scene, turn(start, 90.0, 0.0));
    CHECK_NEAR(glm::distance(d3(yawed.forward), glm::normalize(r)), 0.0, 1e-6);
    CHECK_NEAR(glm::distance(d3(yawed.right), -f * glm::length(r)), 0.0, 1e-6);
    CHECK(std::memcmp(&yawed.up, &scene.up, sizeof scene.up) == 0); // yaw is about up: up untouched

    SceneParams pitched = with_camera(scene, turn(start, 0.0, 30.0));
    glm::dvec3 expected = std::cos(M_PI / 6) * f + std::sin(M_PI / 6) * glm::normalize(u);
    CHECK_NEAR(glm::distance(d3(pitched.forward), expected), 0.0, 1e-6);
    CHECK(std::memcmp(&pitched.right, &scene.right, sizeof scene.right) == 0); // pitch is about right

    SceneParams both = with_camera(scene, Camera{start.position, -47.0, 61.0});
    CHECK_NEAR(glm::length(d3(both.right)), glm::length(r), 1e-6);
    CHECK_NEAR(glm::length(d3(both.up)), glm::length(u), 1e-6);
    CHECK_NEAR(glm::length(d3(both.forward)), 1.0, 1e-6);
    CHECK_NEAR(glm::dot(d3(both.forward), d3(both.right)), 0.0, 1e-6);
    CHECK_NEAR(glm::dot(d3(both.forward), d3(both.up)), 0.0, 1e-6);
    CHECK_NEAR(glm::dot(d3(both.right), d3(both.up)), 0.0, 1e-6);
}

// 5. fly moves in the camera's own frame: z along the (turned) forward, x along right, y along up.
TEST_CASE("fly")
{
    SceneParams scene = make_scene(SceneKind::plane, 64, 48, 256);
    Camera camera = turn(camera_of(scene), 35.0, -12.0);
    SceneParams view = with_camera(scene, camera);
    glm::dvec3 forward = glm::normalize(d3(view.forward)), right = glm::normalize(d3(view.right)),
               up = glm::normalize(d3(view.up));
    Camera ahead = fly(camera, scene, {0.0, 0.0, 2.5});
    CHECK_NEAR(glm::distance(ahead.position, camera.position + 2.5 * forward), 0.0, 1e-6);
    CHECK(ahead.yaw == camera.yaw && ahead.pitch == camera.pitch);
    CHECK_NEAR(glm::distance(fly(camera, scene, {-1.5, 0.0, 0.0}).position, camera.position - 1.5 * right), 0.0, 1e-6);
    CHECK_NEAR(glm::distance(fly(camera, scene, {0.0, 0.75, 0.0}).position, camera.position + 0.75 * up), 0.0, 1e-6);
    // What was straight ahead stays straight ahead after flying forward.
    glm::dvec3 point = camera.position + 10.0 * forward;
    CHECK_NEAR(glm::length(ndc_of(with_camera(scene, ahead), point)), 0.0, 1e-6);
}

// 6. orbit keeps the distance to the target (to double precision: a rotation of orthonormal frames) and
//    where the target is on screen (to the float-stored basis' precision); a pure yaw orbit rotates about
//    the scene's up through the target (the height along up is kept).
TEST_CASE("orbit")
{
    for (SceneKind kind : {SceneKind::plane, SceneKind::tunnel, SceneKind::zoom, SceneKind::mesh}) {
        SceneParams scene = make_scene(kind, 64, 48, 256);
        Camera camera = fly(turn(camera_of(scene), 10.0, 5.0), scene, {0.1, -0.05, 0.2});
        glm::dvec3 target = look_target(with_camera(scene, camera));
        glm::dvec2 seen = ndc_of(with_camera(scene, camera), target);
        glm::dvec3 up = glm::normalize(d3(scene.up));
        for (auto [yaw, pitch] : {std::pair{40.0, 0.0}, std::pair{0.0, -25.0}, std::pair{-130.0, 33.0}}) {
            Camera orbited = orbit(camera, scene, target, yaw, pitch);
            double before = glm::distance(camera.position, target), after = glm::distance(orbited.position, target);
            CHECK_NEAR(after, before, 1e-12 * before);
            CHECK_NEAR(orbited.yaw, turn(camera, yaw, pitch).yaw, 0.0);
            CHECK_NEAR(orbited.pitch, turn(camera, yaw, pitch).pitch, 0.0);
            glm::dvec2 now = ndc_of(with_camera(scene, orbited), target);
            CHECK_NEAR(glm::distance(now, seen), 0.0, 1e-5);
            if (pitch == 0.0) // the yaw axis is the float-stored up: kept to float precision (2^-24) of the distance
                CHECK_NEAR(glm::dot(orbited.position - target, up), glm::dot(camera.position - target, up),
                           before * 0x1p-23);
            CHECK(glm::distance(orbited.position, camera.position) > 0.1 * before, to_string(orbited));
        }
    }
}

// 7. look_target: the central ray's hit where there is one (plane: on y = 0; zoom: on the quad at z = 4;
//    mesh: on the panel at z = 6), else 4 units ahead (tunnel: the ray runs along the axis past the end).
TEST_CASE("look-target")
{
    glm::dvec3 plane = look_target(make_scene(SceneKind::plane, 64, 48, 256));
    CHECK_NEAR(plane.y, 0.0, 1e-6);
    CHECK(plane.z > 0.0, test::show(plane.z));
    CHECK_NEAR(look_target(make_scene(SceneKind::zoom, 64, 48, 256)).z, 4.0, 1e-6);
    glm::dvec3 tunnel = look_target(make_scene(SceneKind::tunnel, 64, 48, 256));
    CHECK_NEAR(glm::distance(tunnel, glm::dvec3(0.25, 0.1, 4.0)), 0.0, 1e-6);
    SceneParams mesh = make_scene(SceneKind::mesh, 64, 48, 256);
    glm::dvec3 hit = look_target(mesh);
    CHECK(hit.z > 1.5 && hit.z <= 30.0, test::show(hit.z));
    CHECK_NEAR(glm::length(ndc_of(mesh, hit)), 0.0, 1e-6); // on the central ray
    // Looking straight up from the plane's camera: no hit, 4 units ahead.
    SceneParams up = with_camera(make_scene(SceneKind::plane, 64, 48, 256), Camera{{0.0, 1.0, 0.0}, 0.0, 80.0});
    CHECK_NEAR(glm::distance(look_target(up), d3(up.origin) + 4.0 * glm::normalize(d3(up.forward))), 0.0, 1e-6);
}

TEST_SUITE_END();

TEST_SUITE_BEGIN("gpu");

// 8. A moved camera on the GPU vs the CPU reference, compared as the golden tests compare (the reference as
//    an 8-bit sRGB PNG, the GPU's float output sRGB-encoded, the case's thresholds from golden/manifest.txt):
//    a ray-cast scene and the rasterized mesh, whose projection, clipping and culling must follow the camera.
TEST_CASE("moved-camera-vs-reference")
{
    if (!image_io_available()) {
        MESSAGE("skipped: this build has no image I/O for the golden comparison's 8-bit PNG");
        return;
    }
    std::filesystem::path work = test::make_work_dir("camera");
    VulkanContext context = create_context(test::test_context_options());
    // Off the scene's own view in every way: turned, moved, an orbit about what is ahead.
    struct Move {
        const char* golden_case;
        double yaw, pitch;
        glm::dvec3 fly;
        double orbit_yaw, orbit_pitch;
    };
    for (const Move& m : {Move{"plane-checker-trilinear", 25.0, -20.0, {0.4, 0.3, -0.2}, -15.0, 5.0},
                          Move{"mesh-checker-trilinear", -10.0, -4.0, {0.2, 0.3, 0.8}, 12.0, 4.0}}) {
        const char* name = m.golden_case;
        const GoldenCase& c = manifest_case(name);
        MipChain chain = load_texture(c.texture, {needs_sat(c.sampler.filter), nullptr});
        SceneParams scene = make_scene(c.scene, c.width, c.height, chain.levels[0].width);
        Camera camera = fly(turn(camera_of(scene), m.yaw, m.pitch), scene, m.fly);
        camera = orbit(camera, scene, look_target(with_camera(scene, camera)), m.orbit_yaw, m.orbit_pitch);
        SceneParams moved = with_camera(scene, camera);
        Image gpu = with_texture(context, chain, false,
                                 [&](const GpuTexture& t) { return gpu_render(context, t, moved, c.sampler, c.render); });
        std::string golden_png = (work / (c.name + ".png")).string();
        write_image(golden_png, reference_render(moved, chain, c.sampler, c.render));
        Image golden = read_image_raw(golden_png);
        DiffResult result = diff_images(encode_srgb(gpu), golden, c.thresholds);
        std::printf("%s, camera %s:\n%s\n", name, to_string(camera).c_str(), describe(result, c.thresholds).c_str());
        CHECK(result.pass, golden_case_text(c) + ": max " + test::show(result.max_error) + ", " +
                               std::to_string(result.fail_count) + " pixels over " + test::show(c.thresholds.fail));
        // Else the check above says nothing about cameras: the moved view must differ from the scene's own.
        Image own = reference_render(scene, chain, c.sampler, c.render);
        DiffResult change = diff_images(encode_srgb(own), golden, c.thresholds);
        CHECK(change.fail_percent > 50.0, test::show(change.fail_percent));
    }
    destroy_context(context);
    CHECK_EQ(validation_message_count(), 0);
}

// 9. A CLI test (the command's flags): `texfilter render --camera ... --frame ...` gives the in-process render of with_camera(scene_at_frame(
//    make_scene(...))) to the bit (PFM: float32 as rendered), on the GPU (the mesh) and on the reference (a
//    ray-cast scene); and --camera with the scene's own camera is the render without it.
TEST_CASE("cli-camera-and-frame")
{
    std::filesystem::path work = test::make_work_dir("camera-cli");
    const int frame = 17, texture_size = 64, width = 64, height = 48;
    MipChain chain = load_texture(TextureSource{"checker", texture_size});
    SamplerOptions trilinear;
    trilinear.filter = Filter::trilinear;
    auto run_render = [&](SceneKind kind, const std::string& flags) {
        std::string out = test::new_file_in(work, "render-", ".pfm").string();
        std::string device = test::test_device().empty() ? "" : " --device '" + test::test_device() + "'";
        std::string command = "timeout 300 '" + test::texfilter_path() + "' render --validate" + device + " --scene " +
                              to_string(kind) + " --texture checker --texture-size " + std::to_string(texture_size) +
                              " --filter trilinear --size " + std::to_string(width) + "x" + std::to_string(height) +
                              " " + flags + " -o '" + out + "' > /dev/null";
        int status = std::system(command.c_str());
        CHECK_EQ(status, 0);
        MESSAGE(command);
        return status == 0 ? read_pfm(out) : Image{};
    };
    // Pixels whose RGB differ in any bit (PFM keeps no alpha).
    auto differing = [](const Image& a, const Image& b) {
        if (a.width != b.width || a.height != b.height)
            return -1;
        int count = 0;
        for (size_t i = 0; i < a.texels.size(); ++i)
            count += std::memcmp(&a.texels[i], &b.texels[i], 3 * sizeof(float)) != 0;
        return count;
    };
    VulkanContext context = create_context(test::test_context_options());
    for (auto [kind, backend] : {std::pair{SceneKind::mesh, std::string("")},
                                 std::pair{SceneKind::tunnel, std::string(" --backend reference")}}) {
        SceneParams own = make_scene(kind, width, height, texture_size);
        Camera camera = orbit(turn(camera_of(own), -8.0, 6.0), own, look_target(own), 20.0, -4.0);
        SceneParams scene = with_camera(scene_at_frame(own, frame, texture_size), camera);
        RenderOptions render = make_render_options(kind, Stage::fragment, Gradients::fine);
        Image expected = backend.empty() ? with_texture(context, chain, false,
                                                        [&](const GpuTexture& t) {
                                                            return gpu_render(context, t, scene, trilinear, render);
                                                        })
                                         : reference_render(scene, chain, trilinear, render);
        Image cli = run_render(kind, "--camera " + to_string(camera) + " --frame " + std::to_string(frame) + backend);
        CHECK_EQ(differing(cli, expected), 0);
        // The frame and the camera both count: without them the image is another.
        Image still = run_render(kind, "--camera " + to_string(camera) + backend);
        CHECK(differing(still, expected) > width * height / 4, std::to_string(differing(still, expected)));
    }
    // The scene's own camera, printed and read back, is no camera at all.
    SceneParams tunnel = make_scene(SceneKind::tunnel, width, height, texture_size);
    Image plain = run_render(SceneKind::tunnel, "--backend reference");
    Image own = run_render(SceneKind::tunnel, "--backend reference --camera " + to_string(camera_of(tunnel)));
    CHECK_EQ(differing(plain, own), 0);
    destroy_context(context);
    CHECK_EQ(validation_message_count(), 0);
}

TEST_SUITE_END();
